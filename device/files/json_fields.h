#pragma once
// Reading a parsed JSON document into a data model while collecting every
// problem at once, each with its line, column and the path of the field at
// fault ("steps[3].volume_ul"), so a person fixes a file in one pass.
// Plain C++, like json.h.
#include "device/files/json.h"
#include "motion/problem.h"

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::json {

/// Collects a reader's problems (motion::msg::Problem, motion/problem.h) with the line and
/// column of the value each is about.
class Problems {
public:
    void add(Position at, std::string path, motion::msg::Message message, motion::msg::Severity severity = motion::msg::Severity::Error);
    void add(const Value& at, std::string path, motion::msg::Message message, motion::msg::Severity severity = motion::msg::Severity::Error)
    {
        add(at.position(), std::move(path), std::move(message), severity);
    }
    bool empty() const { return m_list.empty(); }
    std::size_t size() const { return m_list.size(); }
    bool hasErrors() const { return motion::msg::hasErrors(m_list); }
    /// The file as a whole could not be read (file.cannot_open, …): line 0, no field.
    void addFileProblem(motion::msg::Message message) { add(Position{0, 0}, "", std::move(message)); }
    /// Without the file's name: appendSorted adds it.
    const motion::msg::Problems& list() const { return m_list; }
    /// One line per problem: "FILE:LINE:COLUMN: PATH: id{args}" — for logs, fuzzers and
    /// test failures. People read ui::words::problem (widgets/wording/wording.h).
    std::string format(std::string_view fileName) const;

private:
    motion::msg::Problems m_list;
};

/// Every problem of `found`, in the order of the file (line, then column), with
/// `file` (the name a person knows it by: "sampling-96.recipe.json"), for lists that
/// span several files (a recipe and the labware files it names).
void appendSorted(motion::msg::Problems& out, const Problems& found, const std::string& file);

/// "steps" + 3 → "steps[3]"; "steps[3]" + "volume_ul" → "steps[3].volume_ul".
std::string childPath(std::string_view parent, std::string_view key);
std::string childPath(std::string_view parent, std::size_t index);

/// Typed access to one object's members. A missing required member, a member of
/// the wrong type or out of range is recorded in `problems` and read as nullopt,
/// so a reader goes on and reports everything wrong with the file.
class ObjectReader {
public:
    /// `object` that is not an object is itself recorded as a problem.
    ObjectReader(const Value& object, std::string path, Problems& problems);

    bool valid() const { return m_valid; }
    const std::string& path() const { return m_path; }
    std::string pathOf(std::string_view key) const { return childPath(m_path, key); }
    const Value& value() const { return m_obj; }
    Problems& problems() { return m_problems; }

    /// The member if present and of `type`; otherwise nullptr (and a problem when
    /// it is required or present with the wrong type).
    const Value* get(std::string_view key, Value::Type type, bool required);
    std::optional<double> number(std::string_view key, bool required, double min, double max);
    /// A whole number in [min, max].
    std::optional<long long> integer(std::string_view key, bool required, long long min, long long max);
    std::optional<std::string> string(std::string_view key, bool required);
    std::optional<bool> boolean(std::string_view key, bool required);
    /// A string that must be one of `allowed`; the message lists them.
    std::optional<std::string> oneOf(std::string_view key, bool required, std::initializer_list<std::string_view> allowed);
    /// Records every member whose name is not in `known`, suggesting the nearest known name.
    void refuseUnknown(std::initializer_list<std::string_view> known);
    void refuseUnknown(const std::vector<std::string_view>& known);

private:
    const Value& m_obj;
    std::string m_path;
    Problems& m_problems;
    bool m_valid;
};

/// The header every BenchPilot file carries: `"schema": NAME, "version": N`.
/// Records a problem and returns nullopt unless the schema is `name` and the version
/// is a whole number from 1 to `newestVersion` (a newer file says so: "written by a
/// newer BenchPilot"). Returns the version.
std::optional<int> checkSchema(const Value& root, std::string_view name, int newestVersion, Problems& problems);
/// Starts an object with the header, for writers.
Value schemaObject(std::string_view name, int version);

/// file.json.wrong_type {expected, actual} (terms json.type.*).
motion::msg::Message wrongType(Value::Type expected, Value::Type actual);
/// file.json.out_of_range {value, min, max}, or below_min / above_max when one side is open.
motion::msg::Message outOfRange(double value, double min, double max);

/// A number for logs: up to 6 significant digits, no trailing zeros.
std::string formatNumber(double v);

} // namespace dev::files::json
