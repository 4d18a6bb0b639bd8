#pragma once
// The wording layer: structured messages (motion/message.h) from motion/ and device/
// become sentences in the operator's language here, at the moment they are shown.
// Qt Core only, so the GUI and the CLI (benchpilot-cli --lang) share one wording.
//
// Each area words its own ids in a file of its own (capability_words.cpp,
// accuracy_words.cpp, …) and is listed once in wording.cpp's table; see
// docs/wording.md for how to add ids.
#include "motion/message.h"

#include <QString>

namespace words {

/// The sentence for `m` in the current language (the translators installed in
/// QCoreApplication). An id no area knows comes back as msg::debugString, so
/// nothing is lost; tests/gui's pseudo-translation check and the id tests catch it.
QString text(const msg::Message& m);

/// One argument as text: a number in the current locale with its unit symbol (the
/// unit's precision), a Verbatim as it is, a Term worded by term(), a nested
/// message worded by text(). An absent argument gives an empty string.
QString arg(const msg::Message& m, const std::string& name);
QString value(const msg::Arg& a);

/// A number as the locale writes it, with the unit's symbol and precision.
QString number(double v, msg::Unit unit);
/// " mm", " µm", "°", "": the SI symbol with its leading space (none for degrees).
QString unitSymbol(msg::Unit unit);

/// A short term ("direction.up", "instrument.stage") in the current language; an
/// unknown term id comes back as it is.
QString term(const std::string& id);

} // namespace words

class QJsonObject;

namespace words {

/// A message as JSON for the CLI's --json output and the scripting API, the same
/// in every language: {"id": "...", "args": {"value": 2.5, "axis": "X", "reason":
/// "direction.up", "cause": {nested message}}, "units": {"value": "mm"},
/// "message": "the English sentence"}. "units" holds only arguments that have one;
/// a Term argument is its id. "message" is English whatever language is shown
/// (englishText()), so scripts can log it and key on "id".
QJsonObject toJson(const msg::Message& m);

/// The sentence in English (the source text) even while a translation is shown.
QString englishText(const msg::Message& m);

/// The unit's symbol for JSON, without the leading space: "mm", "µm", "" for none.
QString unitKey(msg::Unit unit);

} // namespace words
