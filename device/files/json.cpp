#include "device/files/json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

namespace dev::files::json {

Value Value::array()
{
    Value v;
    v.m_type = Type::Array;
    return v;
}

Value Value::object()
{
    Value v;
    v.m_type = Type::Object;
    return v;
}

const Value* Value::find(std::string_view key) const
{
    for (const Member& m : m_members)
        if (m.key == key)
            return &m.value;
    return nullptr;
}

Value& Value::set(std::string_view key, Value v)
{
    m_type = Type::Object;
    for (Member& m : m_members)
        if (m.key == key) {
            m.value = std::move(v);
            return *this;
        }
    m_members.push_back(Member{std::string(key), std::move(v), {}});
    return *this;
}

Value& Value::push(Value v)
{
    m_type = Type::Array;
    m_items.push_back(std::move(v));
    return *this;
}

const char* typeName(Value::Type t)
{
    switch (t) {
    case Value::Type::Null: return "null";
    case Value::Type::Bool: return "true or false";
    case Value::Type::Number: return "a number";
    case Value::Type::String: return "a string";
    case Value::Type::Array: return "an array";
    case Value::Type::Object: return "an object";
    }
    return "?";
}

const char* typeTerm(Value::Type t)
{
    switch (t) {
    case Value::Type::Null: return "json.type.null";
    case Value::Type::Bool: return "json.type.bool";
    case Value::Type::Number: return "json.type.number";
    case Value::Type::String: return "json.type.string";
    case Value::Type::Array: return "json.type.array";
    case Value::Type::Object: return "json.type.object";
    }
    return "json.type.null";
}

namespace {

class Parser {
public:
    explicit Parser(std::string_view text) : m_s(text) {}

    ParseResult run()
    {
        ParseResult r;
        if (m_s.size() > kMaxTextBytes) {
            r.error = {motion::msg::make("file.json.too_large", {motion::msg::integer("max", static_cast<long long>(kMaxTextBytes / (1024 * 1024)), motion::msg::Unit::None)}), {}};
            return r;
        }
        if (m_s.size() >= 3 && std::memcmp(m_s.data(), "\xEF\xBB\xBF", 3) == 0)
            m_i = 3;
        skipSpace();
        Value v;
        if (!parseValue(v, 0))
            return fail();
        skipSpace();
        if (m_i != m_s.size()) {
            error(motion::msg::make("file.json.text_after_end"));
            return fail();
        }
        r.value = std::move(v);
        return r;
    }

private:
    ParseResult fail()
    {
        ParseResult r;
        r.error = m_error;
        return r;
    }

    bool error(motion::msg::Message message) { return errorAt(std::move(message), here()); }
    bool errorAt(motion::msg::Message message, Position p)
    {
        if (!m_failed) {
            m_failed = true;
            m_error = {std::move(message), p};
        }
        return false;
    }

    Position here() const { return {m_line, static_cast<int>(m_i - m_lineStart - m_continuations) + 1}; }

    bool atEnd() const { return m_i >= m_s.size(); }
    char peek() const { return atEnd() ? '\0' : m_s[m_i]; }

    void skipSpace()
    {
        while (!atEnd()) {
            const char c = m_s[m_i];
            if (c == '\n') {
                ++m_i;
                ++m_line;
                m_lineStart = m_i;
                m_continuations = 0;
            } else if (c == ' ' || c == '\t' || c == '\r') {
                ++m_i;
            } else {
                break;
            }
        }
    }

    /// What stood where something else was expected, as the `found` argument.
    static motion::msg::Arg describe(char c)
    {
        if (c == '\0')
            return motion::msg::nested("found", motion::msg::make("file.json.found_end"));
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            return motion::msg::nested("found", motion::msg::make("file.json.found_byte", {motion::msg::verbatim("byte", "0x" + hex(static_cast<unsigned char>(c)))}));
        return motion::msg::nested("found", motion::msg::make("file.json.found_char", {motion::msg::verbatim("char", std::string(1, c))}));
    }
    static motion::msg::Message expected(const char* id, char c) { return motion::msg::make(id, {describe(c)}); }
    static std::string hex(unsigned v)
    {
        const char* d = "0123456789ABCDEF";
        return std::string{d[(v >> 4) & 15], d[v & 15]};
    }

    bool parseValue(Value& out, int depth)
    {
        if (depth > kMaxDepth)
            return error(motion::msg::make("file.json.too_deep", {motion::msg::integer("max", kMaxDepth, motion::msg::Unit::None)}));
        const Position start = here();
        bool ok = false;
        switch (peek()) {
        case '{': ok = parseObject(out, depth); break;
        case '[': ok = parseArray(out, depth); break;
        case '"': {
            std::string s;
            ok = parseString(s);
            if (ok)
                out = Value(std::move(s));
            break;
        }
        case 't': ok = literal("true") && (out = Value(true), true); break;
        case 'f': ok = literal("false") && (out = Value(false), true); break;
        case 'n': ok = literal("null") && (out = Value(nullptr), true); break;
        default:
            if (peek() == '-' || (peek() >= '0' && peek() <= '9'))
                ok = parseNumber(out);
            else if (peek() == '/')
                return error(motion::msg::make("file.json.comment"));
            else
                return error(expected("file.json.expected_value", peek()));
        }
        if (ok)
            out.setPosition(start);
        return ok;
    }

    bool literal(const char* word)
    {
        const std::size_t n = std::strlen(word);
        if (m_s.substr(m_i, n) != word)
            return error(expected("file.json.expected_value", peek()));
        m_i += n;
        return true;
    }

    bool parseNumber(Value& out)
    {
        const std::size_t start = m_i;
        if (peek() == '-')
            ++m_i;
        if (peek() == '0') {
            ++m_i;
            if (peek() >= '0' && peek() <= '9')
                return error(motion::msg::make("file.json.leading_zero"));
        } else if (peek() >= '1' && peek() <= '9') {
            while (peek() >= '0' && peek() <= '9')
                ++m_i;
        } else {
            return error(expected("file.json.expected_digit", peek()));
        }
        if (peek() == '.') {
            ++m_i;
            if (!(peek() >= '0' && peek() <= '9'))
                return error(expected("file.json.expected_fraction_digit", peek()));
            while (peek() >= '0' && peek() <= '9')
                ++m_i;
        }
        if (peek() == 'e' || peek() == 'E') {
            ++m_i;
            if (peek() == '+' || peek() == '-')
                ++m_i;
            if (!(peek() >= '0' && peek() <= '9'))
                return error(expected("file.json.expected_exponent_digit", peek()));
            while (peek() >= '0' && peek() <= '9')
                ++m_i;
        }
        double v = 0;
        // from_chars, not strtod: a GUI's locale may use a decimal comma.
        const auto [ptr, ec] = std::from_chars(m_s.data() + start, m_s.data() + m_i, v);
        if (ec == std::errc::result_out_of_range || !std::isfinite(v)) {
            m_i = start;
            return error(motion::msg::make("file.json.number_too_large"));
        }
        if (ec != std::errc() || ptr != m_s.data() + m_i) {
            m_i = start;
            return error(motion::msg::make("file.json.malformed_number"));
        }
        out = Value(v);
        return true;
    }

    bool hex4(unsigned& out)
    {
        out = 0;
        for (int k = 0; k < 4; ++k) {
            const char c = peek();
            unsigned d;
            if (c >= '0' && c <= '9')
                d = static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f')
                d = static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                d = static_cast<unsigned>(c - 'A' + 10);
            else
                return error(motion::msg::make("file.json.bad_unicode_escape"));
            out = out * 16 + d;
            ++m_i;
        }
        return true;
    }

    static void appendUtf8(std::string& s, unsigned cp)
    {
        if (cp < 0x80) {
            s += static_cast<char>(cp);
        } else if (cp < 0x800) {
            s += static_cast<char>(0xC0 | (cp >> 6));
            s += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            s += static_cast<char>(0xE0 | (cp >> 12));
            s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            s += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            s += static_cast<char>(0xF0 | (cp >> 18));
            s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            s += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    /// Copies one UTF-8 encoded character, refusing overlong forms, surrogates and
    /// anything above U+10FFFF, so every string handed on is valid UTF-8.
    bool copyUtf8(std::string& s)
    {
        const auto b0 = static_cast<unsigned char>(m_s[m_i]);
        int n = 0;
        unsigned cp = 0, min = 0;
        if (b0 >= 0xC2 && b0 <= 0xDF) {
            n = 1; cp = b0 & 0x1Fu; min = 0x80;
        } else if (b0 >= 0xE0 && b0 <= 0xEF) {
            n = 2; cp = b0 & 0x0Fu; min = 0x800;
        } else if (b0 >= 0xF0 && b0 <= 0xF4) {
            n = 3; cp = b0 & 0x07u; min = 0x10000;
        } else {
            return error(motion::msg::make("file.json.invalid_utf8_byte", {motion::msg::verbatim("byte", "0x" + hex(b0))}));
        }
        if (m_i + static_cast<std::size_t>(n) >= m_s.size())
            return error(motion::msg::make("file.json.truncated_utf8"));
        for (int k = 1; k <= n; ++k) {
            const auto b = static_cast<unsigned char>(m_s[m_i + static_cast<std::size_t>(k)]);
            if ((b & 0xC0) != 0x80)
                return error(motion::msg::make("file.json.invalid_utf8"));
            cp = (cp << 6) | (b & 0x3Fu);
        }
        if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return error(motion::msg::make("file.json.invalid_utf8"));
        s.append(m_s.data() + m_i, static_cast<std::size_t>(n) + 1);
        m_i += static_cast<std::size_t>(n) + 1;
        m_continuations += static_cast<std::size_t>(n);
        return true;
    }

    bool parseString(std::string& out)
    {
        ++m_i;  // opening quote
        for (;;) {
            if (atEnd())
                return error(motion::msg::make("file.json.unterminated_string"));
            const char c = m_s[m_i];
            if (c == '"') {
                ++m_i;
                return true;
            }
            if (static_cast<unsigned char>(c) < 0x20)
                return error(motion::msg::make(c == '\n' ? "file.json.line_break_in_string" : "file.json.control_character"));
            if (static_cast<unsigned char>(c) >= 0x80) {
                if (!copyUtf8(out))
                    return false;
                continue;
            }
            if (c != '\\') {
                out += c;
                ++m_i;
                continue;
            }
            ++m_i;
            const char e = peek();
            ++m_i;
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                unsigned cp = 0;
                if (!hex4(cp))
                    return false;
                if (cp >= 0xD800 && cp <= 0xDBFF) {
                    unsigned lo = 0;
                    if (peek() != '\\' || m_s.substr(m_i, 2) != "\\u")
                        return error(motion::msg::make("file.json.lone_high_surrogate"));
                    m_i += 2;
                    if (!hex4(lo))
                        return false;
                    if (lo < 0xDC00 || lo > 0xDFFF)
                        return error(motion::msg::make("file.json.lone_high_surrogate"));
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
                    return error(motion::msg::make("file.json.lone_low_surrogate"));
                }
                appendUtf8(out, cp);
                break;
            }
            default:
                --m_i;
                return error(motion::msg::make("file.json.unknown_escape", {describe(e)}));
            }
        }
    }

    bool parseArray(Value& out, int depth)
    {
        ++m_i;
        out = Value::array();
        skipSpace();
        if (peek() == ']') {
            ++m_i;
            return true;
        }
        for (;;) {
            skipSpace();
            Value item;
            if (!parseValue(item, depth + 1))
                return false;
            out.items().push_back(std::move(item));
            skipSpace();
            if (peek() == ',') {
                ++m_i;
                skipSpace();
                if (peek() == ']')
                    return error(motion::msg::make("file.json.trailing_comma", {motion::msg::verbatim("bracket", "]")}));
                continue;
            }
            if (peek() == ']') {
                ++m_i;
                return true;
            }
            return error(expected("file.json.expected_array_comma", peek()));
        }
    }

    bool parseObject(Value& out, int depth)
    {
        ++m_i;
        out = Value::object();
        skipSpace();
        if (peek() == '}') {
            ++m_i;
            return true;
        }
        std::vector<Member> members;
        for (;;) {
            skipSpace();
            if (peek() != '"')
                return error(peek() == '}' ? motion::msg::make("file.json.trailing_comma", {motion::msg::verbatim("bracket", "}")})
                                           : expected("file.json.expected_member_name", peek()));
            Member m;
            m.keyPosition = here();
            if (!parseString(m.key))
                return false;
            skipSpace();
            if (peek() != ':')
                return error(motion::msg::make("file.json.expected_colon", {motion::msg::verbatim("member", m.key.substr(0, 60)), describe(peek())}));
            ++m_i;
            skipSpace();
            if (!parseValue(m.value, depth + 1))
                return false;
            members.push_back(std::move(m));
            skipSpace();
            if (peek() == ',') {
                ++m_i;
                continue;
            }
            if (peek() == '}') {
                ++m_i;
                break;
            }
            return error(expected("file.json.expected_object_comma", peek()));
        }
        // Duplicate keys: which one a reader keeps is undefined in JSON, so neither is.
        std::vector<std::size_t> order(members.size());
        for (std::size_t k = 0; k < order.size(); ++k)
            order[k] = k;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return members[a].key < members[b].key; });
        for (std::size_t k = 1; k < order.size(); ++k)
            if (members[order[k]].key == members[order[k - 1]].key) {
                const std::size_t second = std::max(order[k], order[k - 1]);
                return errorAt(motion::msg::make("file.json.duplicate_member", {motion::msg::verbatim("member", members[second].key.substr(0, 60))}), members[second].keyPosition);
            }
        out.members() = std::move(members);
        return true;
    }

    std::string_view m_s;
    std::size_t m_i = 0;
    int m_line = 1;
    std::size_t m_lineStart = 0;
    std::size_t m_continuations = 0;  ///< UTF-8 continuation bytes on this line so far
    bool m_failed = false;
    ParseError m_error;
};

void writeString(std::string& out, const std::string& s)
{
    out += '"';
    for (const char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                const char* d = "0123456789abcdef";
                out += "\\u00";
                out += d[(c >> 4) & 15];
                out += d[c & 15];
            } else {
                out += c;
            }
        }
    }
    out += '"';
}

void writeNumber(std::string& out, double v)
{
    if (!std::isfinite(v)) {
        out += "null";
        return;
    }
    if (v == 0) {
        out += "0";  // also for -0: a file never needs the sign of zero
        return;
    }
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

void writeValue(std::string& out, const Value& v, bool pretty, int indent)
{
    auto newline = [&](int level) {
        if (!pretty)
            return;
        out += '\n';
        out.append(static_cast<std::size_t>(level) * 2, ' ');
    };
    switch (v.type()) {
    case Value::Type::Null: out += "null"; return;
    case Value::Type::Bool: out += v.asBool() ? "true" : "false"; return;
    case Value::Type::Number: writeNumber(out, v.asNumber()); return;
    case Value::Type::String: writeString(out, v.asString()); return;
    case Value::Type::Array: {
        if (v.items().empty()) {
            out += "[]";
            return;
        }
        // Arrays of plain numbers stay on one line: coordinates read as (x, y).
        const bool flat = std::all_of(v.items().begin(), v.items().end(), [](const Value& i) { return i.isNumber(); });
        out += '[';
        for (std::size_t k = 0; k < v.items().size(); ++k) {
            if (k)
                out += pretty && flat ? ", " : ",";
            if (!flat)
                newline(indent + 1);
            writeValue(out, v.items()[k], pretty, indent + 1);
        }
        if (!flat)
            newline(indent);
        out += ']';
        return;
    }
    case Value::Type::Object: {
        if (v.members().empty()) {
            out += "{}";
            return;
        }
        out += '{';
        for (std::size_t k = 0; k < v.members().size(); ++k) {
            if (k)
                out += ',';
            newline(indent + 1);
            writeString(out, v.members()[k].key);
            out += pretty ? ": " : ":";
            writeValue(out, v.members()[k].value, pretty, indent + 1);
        }
        newline(indent);
        out += '}';
        return;
    }
    }
}

} // namespace

ParseResult parse(std::string_view text) { return Parser(text).run(); }

std::string write(const Value& v, bool pretty)
{
    std::string out;
    writeValue(out, v, pretty, 0);
    if (pretty)
        out += '\n';
    return out;
}

} // namespace dev::files::json
