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
    for (const jsonio::Problem& p : problems.list())
        out += words::fileProblem(QString::fromUtf8(file.data(), static_cast<qsizetype>(file.size())), p).toStdString() + "\n";
    return out;
}

inline std::string englishFormat(const jsonio::FileProblems& problems)
{
    const words::EnglishScope inEnglish;
    std::string out;
    for (const jsonio::FileProblem& p : problems)
        out += words::fileProblem(QString::fromStdString(p.file), p.problem).toStdString() + "\n";
    return out;
}

} // namespace i18ntest
