#include "motion/problem.h"

namespace motion::msg {

Problem error(std::string path, Message message) { return Problem(std::move(path), std::move(message)); }

Problem warning(std::string path, Message message) { return Problem(std::move(path), std::move(message), Severity::Warning); }

bool hasErrors(const Problems& problems)
{
    for (const Problem& p : problems)
        if (p.isError())
            return true;
    return false;
}

int errorCount(const Problems& problems)
{
    int n = 0;
    for (const Problem& p : problems)
        n += p.isError() ? 1 : 0;
    return n;
}

std::string fieldPath(const std::string& parent, const std::string& key)
{
    return parent.empty() ? key : parent + "." + key;
}

std::string indexPath(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

std::string debugString(const Problem& p)
{
    std::string out;
    if (!p.file.empty())
        out += p.file + ":";
    if (p.line > 0 || !p.file.empty())
        out += std::to_string(p.line) + ":" + std::to_string(p.column) + ": ";
    if (!p.path.empty())
        out += p.path + ": ";
    if (p.isWarning())
        out += "warning: ";
    return out + debugString(p.message);
}

std::string debugFormat(const Problems& problems)
{
    std::string out;
    for (const Problem& p : problems)
        out += debugString(p) + "\n";
    return out;
}

} // namespace motion::msg
