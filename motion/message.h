#pragma once
// A sentence for a person, kept as data: an id that names the sentence and typed
// arguments that fill it. motion/ and device/ build these and never assemble
// English text themselves; widgets/ and app/ word them in the operator's language
// at the moment they are shown, so a language switch rewords a message that is
// already on screen, and numbers follow the locale there.
//
// Ids are stable, dotted and lower case ("pattern.value_above", "gauge.no_answer"):
// JSON output carries them unchanged in every language, and scripts may key on them.
// Renaming an id is a breaking change of the CLI's and the API's JSON.
//
// Plain C++ (no Qt), like the rest of motion/.
#include <initializer_list>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace motion::msg {

/// How a number is shown: its unit symbol (SI, the same in every language) and
/// the precision that suits it. Count and None have no symbol.
enum class Unit {
    None,
    Count,     ///< a whole number of things (wells, tiles, steps, cycles)
    Mm,
    Um,
    Nm,
    MmPerS,
    MmPerS2,
    MmPerS3,
    MmPerMin,  ///< GRBL's feed and rate unit
    Ul,
    UlPerS,
    S,
    Ms,
    Us,
    Hz,
    Percent,
    Deg,
    Rad,
    PerS,      ///< Ki in 1/s
    Baud,
    Byte,
};

struct Message;

/// Text shown as it is, in every language: a well name, a file name, a field path,
/// an axis letter, a line a device sent.
struct Verbatim {
    std::string text;
};
/// A word the wording layer translates by itself: an id of a short term
/// ("direction.up", "end_reason.settled") rather than a sentence.
struct Term {
    std::string id;
};

struct Arg {
    std::string name;  ///< "value", "limit", "axis", "field", "well", "reason"
    std::variant<std::monostate, long long, double, Verbatim, Term, std::shared_ptr<const Message>> value;
    Unit unit = Unit::None;
};

struct Message {
    std::string id;
    std::vector<Arg> args;

    bool empty() const { return id.empty(); }
    /// The argument called `name`, or nullptr.
    const Arg* arg(const std::string& name) const;
    /// Convenience readers; `fallback` when absent or of another type.
    double number(const std::string& name, double fallback = 0) const;
    long long integer(const std::string& name, long long fallback = 0) const;
    std::string text(const std::string& name) const;  ///< Verbatim text or Term id
};

// Builders, so call sites read like the sentence they stand for:
//   motion::msg::make("pattern.value_above", {motion::msg::real("min", 0, motion::msg::Unit::Mm), motion::msg::real("value", r, motion::msg::Unit::Mm)})
Arg real(std::string name, double value, Unit unit = Unit::None);
Arg integer(std::string name, long long value, Unit unit = Unit::Count);
Arg verbatim(std::string name, std::string text);
Arg term(std::string name, std::string id);
Arg nested(std::string name, Message inner);
Message make(std::string id, std::initializer_list<Arg> args = {});
Message make(std::string id, std::vector<Arg> args);

/// For logs, test failures and debuggers, never for people:
/// `pattern.value_above{min=0 mm, value=-2 mm}`.
std::string debugString(const Message& m);

bool operator==(const Message& a, const Message& b);
inline bool operator!=(const Message& a, const Message& b) { return !(a == b); }

} // namespace motion::msg
