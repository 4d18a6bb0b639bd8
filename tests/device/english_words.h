#pragma once
// Tests that read what a person reads, in English: a message or a file's problems
// worded by the wording layer as words::englishText does (English whatever
// translators are installed), in the shape jsonio::Problems::format used to have.
#include "device/files/json_fields.h"
#include "widgets/wording/translators.h"
#include "motion/message_print.h"
#include "widgets/wording/wording.h"

#include <string>
#include <string_view>

namespace i18ntest {

inline std::string english(const msg::Message& m) { return words::englishText(m).toStdString(); }

/// "FILE:LINE:COLUMN: PATH: sentence", one a line, in the order found.
inline std::string englishFormat(const jsonio::Problems& problems, std::string_view file)
{
    const words::EnglishScope inEnglish;
    std::string out;
    for (msg::Problem p : problems.list()) {
        p.file = std::string(file);
        out += words::problem(p).toStdString() + "\n";
    }
    return out;
}

inline std::string englishFormat(const msg::Problems& problems)
{
    const words::EnglishScope inEnglish;
    std::string out;
    for (const msg::Problem& p : problems)
        out += words::problem(p).toStdString() + "\n";
    return out;
}

} // namespace i18ntest
