#pragma once
// Tests that read what a person reads, in English: a message or a file's problems
// worded by the wording layer as ui::words::englishText does (English whatever
// translators are installed), in the shape dev::files::json::Problems::format used to have.
#include "device/files/json_fields.h"
#include "widgets/wording/translators.h"
#include "motion/message_print.h"
#include "widgets/wording/wording.h"

#include <string>
#include <string_view>

namespace i18ntest {

inline std::string english(const motion::msg::Message& m) { return ui::words::englishText(m).toStdString(); }

/// "FILE:LINE:COLUMN: PATH: sentence", one a line, in the order found.
inline std::string englishFormat(const dev::files::json::Problems& problems, std::string_view file)
{
    const ui::words::EnglishScope inEnglish;
    std::string out;
    for (motion::msg::Problem p : problems.list()) {
        p.file = std::string(file);
        out += ui::words::problem(p).toStdString() + "\n";
    }
    return out;
}

inline std::string englishFormat(const motion::msg::Problems& problems)
{
    const ui::words::EnglishScope inEnglish;
    std::string out;
    for (const motion::msg::Problem& p : problems)
        out += ui::words::problem(p).toStdString() + "\n";
    return out;
}

} // namespace i18ntest
