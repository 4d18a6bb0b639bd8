#pragma once
// The wording layer: structured messages (motion/message.h) from motion/ and device/
// become sentences in the operator's language here, at the moment they are shown.
// Qt Core only, so the GUI and the CLI (benchpilot-cli --lang) share one wording.
//
// Each area words its own ids in a file of its own (capability_words.cpp,
// accuracy_words.cpp, …) and is listed once in wording.cpp's table; see
// docs/wording.md for how to add ids.
#include "motion/message.h"
#include "motion/problem.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace dev {
struct DeviceEvent;
struct DeviceIdentity;
}

namespace ui::words {

/// The sentence for `m` in the current language (the translators installed in
/// QCoreApplication). An id no area knows comes back as motion::msg::debugString, so
/// nothing is lost; tests/gui's pseudo-translation check and the id tests catch it.
QString text(const motion::msg::Message& m);
/// What a device event says beyond its kind: the backend's worded form (an event
/// reason, a GRBL alarm), or the device's own text where it has none.
QString eventDetail(const dev::DeviceEvent& e);
/// `text` as a sentence standing on its own (a banner, a dialog, a log line): its first
/// letter a capital. Sentences are worded to be embedded ("… stopped: the link to …"),
/// so they start in lower case; Chinese is unchanged.
QString sentence(const QString& text);

/// One argument as text: a number in the current locale with its unit symbol (the
/// unit's precision), a Verbatim as it is, a Term worded by term(), a nested
/// message worded by text(). An absent argument gives an empty string.
QString arg(const motion::msg::Message& m, const std::string& name);
QString value(const motion::msg::Arg& a);

/// A span of time as people read it: "8.5 s", "42 s", "2 min 53 s", "1 h 05 min"; "—"
/// when unknown (negative or not finite). Seconds from a minute on are read as minutes,
/// so number() words every Unit::S value of a minute or more this way.
QString duration(double seconds);

/// A number as the locale writes it, with the unit's symbol and precision.
QString number(double v, motion::msg::Unit unit);
/// " mm", " µm", "°", "": the SI symbol with its leading space (none for degrees).
QString unitSymbol(motion::msg::Unit unit);

/// A short term ("direction.up", "instrument.stage") in the current language; an
/// unknown term id comes back as it is.
QString term(const std::string& id);

/// A name from the files BenchPilot ships (the analyzer's deck: "back", "wash trough";
/// the built-in labware: "96-well plate, 360 µL") in the current language, for display
/// only; any other name, and every id, as it is. Files keep their names in English.
QString shippedName(const std::string& name);

/// The instrument's model for people: BenchPilot's own simulator named in the current
/// language from the kind it simulates; any other device's model as it gives it.
QString modelName(const dev::DeviceIdentity& id);

} // namespace ui::words

namespace dev::files::json {
class Problems;
} // namespace dev::files::json

namespace ui::words {

/// Every problem a reader found in `file`, in the order of the file, worded by problem().
QStringList fileProblems(const dev::files::json::Problems& problems, const QString& file);

/// A problem for a person, the one way the CLI, the API and the screens say it:
/// "FILE:LINE:COLUMN: PATH: sentence", each part only where known ("FILE: sentence" for
/// a file as a whole, "PATH: sentence" for a form), "warning: " before a warning's
/// sentence. A caller that knows the field by another name (a CLI option) puts that
/// name in `path` first.
QString problem(const motion::msg::Problem& p);
/// problem() of each, in the order given, one line each.
QStringList problems(const motion::msg::Problems& list);

/// How a tuning result stores a trial's or a verification's outcome ("decays",
/// "hit the envelope", an end reason's name such as "settled"), for a person; a
/// key this build does not know comes back as it is.
QString tuningOutcome(const std::string& key);

/// The instrument's model for people: BenchPilot's own simulator named in the current
/// language from the kind it simulates; any other device's model as it gives it.
QString modelName(const dev::DeviceIdentity& id);

} // namespace ui::words

class QJsonObject;

namespace ui::words {

/// A message as JSON for the CLI's --json output and the scripting API, the same
/// in every language: {"id": "...", "args": {"value": 2.5, "axis": "X", "reason":
/// "direction.up", "cause": {nested message}}, "units": {"value": "mm"},
/// "message": "the English sentence"}. "units" holds only arguments that have one;
/// a Term argument is its id. "message" is English whatever language is shown
/// (englishText()), so scripts can log it and key on "id".
QJsonObject toJson(const motion::msg::Message& m);
/// A problem: toJson of its message with "file", "line", "column" and "field" beside it
/// where known, and "warning": true for a warning.
QJsonObject toJson(const motion::msg::Problem& p);

/// The sentence in English (the source text, C-locale numbers) even while a
/// translation is shown.
QString englishText(const motion::msg::Message& m);
/// A term in English, for JSON values that are words ("state": "running").
QString englishTerm(const std::string& id);

/// The unit's symbol for JSON, without the leading space: "mm", "µm", "" for none.
QString unitKey(motion::msg::Unit unit);

/// The instrument's model for people: BenchPilot's own simulator named in the current
/// language from the kind it simulates; any other device's model as it gives it.
QString modelName(const dev::DeviceIdentity& id);

} // namespace ui::words
