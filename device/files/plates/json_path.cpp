#include "device/files/plates/json_path.h"

#include <cctype>
#include <string>

namespace dev::files::plates {

std::optional<dev::files::json::Value> parseOrReport(std::string_view text, dev::files::json::Problems& problems)
{
    dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed)
        problems.add(parsed.error.position, "", parsed.error.message);
    return std::move(parsed.value);
}

dev::files::json::Position positionOfPath(const dev::files::json::Value& root, std::string_view path)
{
    const dev::files::json::Value* at = &root;
    std::size_t i = 0;
    while (i < path.size()) {
        if (path[i] == '.') {
            ++i;
            continue;
        }
        if (path[i] == '[') {
            std::size_t j = i + 1, index = 0;
            bool digits = false;
            while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j]))) {
                index = index * 10 + static_cast<std::size_t>(path[j] - '0');
                digits = true;
                if (index > 1000000000)
                    break;
                ++j;
            }
            if (!digits || j >= path.size() || path[j] != ']' || !at->isArray() || index >= at->items().size())
                break;
            at = &at->items()[index];
            i = j + 1;
            continue;
        }
        std::size_t j = i;
        while (j < path.size() && path[j] != '.' && path[j] != '[')
            ++j;
        const dev::files::json::Value* next = at->find(path.substr(i, j - i));
        if (!next)
            break;
        at = next;
        i = j;
    }
    return at->position();
}

} // namespace dev::files::plates
