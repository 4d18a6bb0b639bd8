#pragma once
// What every error:N and ALARM:N means, as GRBL 1.1's interface document and grblHAL's
// error and alarm lists describe it. The English meanings are data (grbl_codes.cpp), marked
// for Qt's lupdate with the context "grbl" so the wording layer translates them; this
// header and the table stay plain C++.
//
// A line from the device becomes a motion::msg::Message here, never a sentence:
//   grbl.error{code, line}    an error:N answering `line` (the line the streamer sent)
//   grbl.alarm{code}          an ALARM:N
// The wording layer finds the meaning with errorMeaning()/alarmMeaning(code) and
// translates it with QCoreApplication::translate("grbl", meaning->text); a code missing
// from the tables (a newer firmware) is worded as an unknown code with its number.
#include "motion/message.h"

#include <cstddef>
#include <string_view>

namespace dev::grbl {

struct CodeMeaning {
    int code = 0;
    const char* text = nullptr;  ///< English, untranslated (QT_TRANSLATE_NOOP("grbl", …))
    bool grblHalOnly = false;    ///< stock GRBL 1.1 never sends this code
};

/// nullptr when the code is in neither table.
const CodeMeaning* errorMeaning(int code);
const CodeMeaning* alarmMeaning(int code);

/// The whole tables, in code order (for a help screen and for tests).
const CodeMeaning* errorTable(std::size_t* count);
const CodeMeaning* alarmTable(std::size_t* count);

/// grbl.error{code, line}: `line` is the command that the error answers (may be empty
/// when the host no longer knows it, e.g. after a reset).
motion::msg::Message errorMessage(int code, std::string_view line);
/// grbl.alarm{code}.
motion::msg::Message alarmMessage(int code);

} // namespace dev::grbl
