#pragma once
// What the plate and recipe validators return: every problem at once, each with
// the path of the field at fault ("steps[4].wells"), so the file layer can add
// the line and column and the GUI can point at the step. Messages are data
// (plate.*, recipe.*), worded in widgets/wording/.
#include "motion/message.h"

#include <string>
#include <vector>

namespace plates {

struct Problem {
    std::string path;     ///< "" for the whole document
    msg::Message message; ///< plate.unknown_well {well, wells}: "unknown well "I13" on a 96-well plate"
    bool warning = false; ///< a warning does not stop a run; an error does
};
using Problems = std::vector<Problem>;

inline bool hasErrors(const Problems& problems)
{
    for (const Problem& p : problems)
        if (!p.warning)
            return true;
    return false;
}

/// "steps" + 3 → "steps[3]"; "steps[3]" + "wells" → "steps[3].wells".
inline std::string fieldPath(const std::string& parent, const std::string& key)
{
    return parent.empty() ? key : parent + "." + key;
}
inline std::string indexPath(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

/// Numbers for logs and labels: up to 6 significant digits, no trailing zeros ("12.5", "1000").
std::string formatMm(double v);

/// Message arguments in the units the plate models use.
inline msg::Arg mmArg(std::string name, double v) { return msg::real(std::move(name), v, msg::Unit::Mm); }
inline msg::Arg ulArg(std::string name, double v) { return msg::real(std::move(name), v, msg::Unit::Ul); }
inline msg::Arg textArg(std::string name, std::string v) { return msg::verbatim(std::move(name), std::move(v)); }

} // namespace plates
