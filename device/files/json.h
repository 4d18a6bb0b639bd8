#pragma once
// A strict JSON reader and writer (RFC 8259) that remembers where every value
// stood in its text, so the readers of the files people keep (recipes, plates,
// patterns, scan plans, tuning results) can name the file, line and column of
// the field at fault. Plain C++ with no Qt, so it can be fuzzed like the codec;
// its problems are messages (file.json.*), worded where the language is known.
#include "motion/message.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::json {

/// 1-based; the column counts characters (UTF-8 code points), as editors do.
struct Position {
    int line = 1;
    int column = 1;
};

struct Member;

class Value {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };

    Value() = default;
    Value(std::nullptr_t) {}
    Value(bool b) : m_type(Type::Bool), m_bool(b) {}
    Value(double n) : m_type(Type::Number), m_number(n) {}
    Value(int n) : m_type(Type::Number), m_number(n) {}
    Value(std::int64_t n) : m_type(Type::Number), m_number(static_cast<double>(n)) {}
    Value(std::size_t n) : m_type(Type::Number), m_number(static_cast<double>(n)) {}
    Value(const char* s) : m_type(Type::String), m_string(s) {}
    Value(std::string s) : m_type(Type::String), m_string(std::move(s)) {}
    Value(std::string_view s) : m_type(Type::String), m_string(s) {}
    static Value array();
    static Value object();

    Type type() const { return m_type; }
    bool isNull() const { return m_type == Type::Null; }
    bool isBool() const { return m_type == Type::Bool; }
    bool isNumber() const { return m_type == Type::Number; }
    bool isString() const { return m_type == Type::String; }
    bool isArray() const { return m_type == Type::Array; }
    bool isObject() const { return m_type == Type::Object; }

    /// The value, or a neutral one (false, 0, "", empty) when the type differs.
    bool asBool() const { return m_type == Type::Bool && m_bool; }
    double asNumber() const { return m_type == Type::Number ? m_number : 0.0; }
    const std::string& asString() const { return m_string; }
    const std::vector<Value>& items() const { return m_items; }
    std::vector<Value>& items() { return m_items; }
    const std::vector<Member>& members() const { return m_members; }
    std::vector<Member>& members() { return m_members; }

    /// An object's member, or nullptr (also when this is not an object).
    const Value* find(std::string_view key) const;
    /// Object: replaces the member of that key or appends it, keeping order. Returns *this.
    Value& set(std::string_view key, Value v);
    /// Array: appends. Returns *this.
    Value& push(Value v);

    /// Where the value began in the text it was parsed from; (1, 1) for built values.
    Position position() const { return m_pos; }
    void setPosition(Position p) { m_pos = p; }

private:
    Type m_type = Type::Null;
    bool m_bool = false;
    double m_number = 0;
    std::string m_string;
    std::vector<Value> m_items;
    std::vector<Member> m_members;
    Position m_pos;
};

struct Member {
    std::string key;
    Value value;
    Position keyPosition;
};

const char* typeName(Value::Type t);  ///< "a number": for logs and tests
const char* typeTerm(Value::Type t);  ///< "json.type.number": for people (ui::words::term)

/// Nesting deeper than this is refused (a reader's stack stays bounded on any input).
constexpr int kMaxDepth = 128;
/// Text longer than this is refused before parsing.
constexpr std::size_t kMaxTextBytes = 64u * 1024 * 1024;

struct ParseError {
    motion::msg::Message message;  ///< file.json.* (docs/wording.md; worded in widgets/wording/file_words.cpp)
    Position position;
};

struct ParseResult {
    std::optional<Value> value;
    ParseError error;  ///< when !value
    explicit operator bool() const { return value.has_value(); }
};

/// One JSON value, strictly: no comments, no trailing commas, no NaN, valid UTF-8,
/// a duplicate key is an error at its second occurrence. A UTF-8 byte-order mark
/// at the start is skipped (some Windows editors write one).
ParseResult parse(std::string_view text);

/// Two-space indentation (or compact), members in insertion order, numbers as the
/// shortest text that reads back to the same double (integers without a fraction).
/// Non-finite numbers, which JSON cannot hold, are written as null.
std::string write(const Value& v, bool pretty = true);

} // namespace dev::files::json
