#include "device/files/json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dev::files::json {

void Problems::add(Position at, std::string path, motion::msg::Message message, motion::msg::Severity severity)
{
    motion::msg::Problem p(std::move(path), std::move(message), severity);
    p.line = at.line;
    p.column = at.column;
    m_list.push_back(std::move(p));
}

std::string Problems::format(std::string_view fileName) const
{
    std::string out;
    for (motion::msg::Problem p : m_list) {
        p.file = std::string(fileName);
        out += motion::msg::debugString(p) + "\n";
    }
    return out;
}

void appendSorted(motion::msg::Problems& out, const Problems& found, const std::string& file)
{
    motion::msg::Problems sorted = found.list();
    std::stable_sort(sorted.begin(), sorted.end(), [](const motion::msg::Problem& a, const motion::msg::Problem& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
    for (motion::msg::Problem& p : sorted) {
        p.file = file;
        out.push_back(std::move(p));
    }
}

std::string childPath(std::string_view parent, std::string_view key)
{
    if (parent.empty())
        return std::string(key);
    return std::string(parent) + "." + std::string(key);
}

std::string childPath(std::string_view parent, std::size_t index)
{
    return std::string(parent) + "[" + std::to_string(index) + "]";
}

motion::msg::Message wrongType(Value::Type expected, Value::Type actual)
{
    return motion::msg::make("file.json.wrong_type", {motion::msg::term("expected", typeTerm(expected)), motion::msg::term("actual", typeTerm(actual))});
}

motion::msg::Message outOfRange(double value, double min, double max)
{
    if (min > -1e300 && max < 1e300)
        return motion::msg::make("file.json.out_of_range", {motion::msg::real("value", value), motion::msg::real("min", min), motion::msg::real("max", max)});
    if (min > -1e300)
        return motion::msg::make("file.json.below_min", {motion::msg::real("value", value), motion::msg::real("min", min)});
    return motion::msg::make("file.json.above_max", {motion::msg::real("value", value), motion::msg::real("max", max)});
}

std::string formatNumber(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

ObjectReader::ObjectReader(const Value& object, std::string path, Problems& problems)
    : m_obj(object), m_path(std::move(path)), m_problems(problems), m_valid(object.isObject())
{
    if (!m_valid)
        m_problems.add(object, m_path, wrongType(Value::Type::Object, object.type()));
}

const Value* ObjectReader::get(std::string_view key, Value::Type type, bool required)
{
    if (!m_valid)
        return nullptr;
    const Value* v = m_obj.find(key);
    if (!v) {
        if (required)
            m_problems.add(m_obj, pathOf(key), motion::msg::make("file.json.missing"));
        return nullptr;
    }
    if (v->type() != type) {
        m_problems.add(*v, pathOf(key), wrongType(type, v->type()));
        return nullptr;
    }
    return v;
}

std::optional<double> ObjectReader::number(std::string_view key, bool required, double min, double max)
{
    const Value* v = get(key, Value::Type::Number, required);
    if (!v)
        return std::nullopt;
    const double x = v->asNumber();
    if (x < min || x > max) {
        m_problems.add(*v, pathOf(key), outOfRange(x, min, max));
        return std::nullopt;
    }
    return x;
}

std::optional<long long> ObjectReader::integer(std::string_view key, bool required, long long min, long long max)
{
    const Value* v = get(key, Value::Type::Number, required);
    if (!v)
        return std::nullopt;
    const double x = v->asNumber();
    if (std::floor(x) != x) {
        m_problems.add(*v, pathOf(key), motion::msg::make("file.json.not_whole", {motion::msg::real("value", x)}));
        return std::nullopt;
    }
    if (x < static_cast<double>(min) || x > static_cast<double>(max)) {
        m_problems.add(*v, pathOf(key), outOfRange(x, static_cast<double>(min), static_cast<double>(max)));
        return std::nullopt;
    }
    return static_cast<long long>(x);
}

std::optional<std::string> ObjectReader::string(std::string_view key, bool required)
{
    const Value* v = get(key, Value::Type::String, required);
    if (!v)
        return std::nullopt;
    return v->asString();
}

std::optional<bool> ObjectReader::boolean(std::string_view key, bool required)
{
    const Value* v = get(key, Value::Type::Bool, required);
    if (!v)
        return std::nullopt;
    return v->asBool();
}

std::optional<std::string> ObjectReader::oneOf(std::string_view key, bool required, std::initializer_list<std::string_view> allowed)
{
    const Value* v = get(key, Value::Type::String, required);
    if (!v)
        return std::nullopt;
    for (std::string_view a : allowed)
        if (v->asString() == a)
            return v->asString();
    std::string list;
    for (std::string_view a : allowed)
        list += (list.empty() ? "" : ", ") + std::string("\"") + std::string(a) + "\"";
    m_problems.add(*v, pathOf(key), motion::msg::make("file.json.not_one_of", {motion::msg::verbatim("value", v->asString().substr(0, 60)), motion::msg::verbatim("allowed", list)}));
    return std::nullopt;
}

namespace {
std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}
} // namespace

void ObjectReader::refuseUnknown(std::initializer_list<std::string_view> known)
{
    refuseUnknown(std::vector<std::string_view>(known));
}

void ObjectReader::refuseUnknown(const std::vector<std::string_view>& known)
{
    if (!m_valid)
        return;
    for (const Member& m : m_obj.members()) {
        if (std::find(known.begin(), known.end(), m.key) != known.end())
            continue;
        // Suggest close misspellings, and a name that only lacks its unit ("volume"
        // for "volume_ul") or has one too many.
        std::string_view best;
        std::size_t bestD = 99;
        for (std::string_view k : known) {
            std::size_t d = m.key.size() > 64 ? 99 : editDistance(m.key, k);
            const std::string_view shorter = m.key.size() < k.size() ? std::string_view(m.key) : k;
            const std::string_view longer = m.key.size() < k.size() ? k : std::string_view(m.key);
            if (d > 2 && shorter.size() >= 3 && longer.substr(0, shorter.size()) == shorter)
                d = 2;
            if (d <= 2 && d < bestD) {
                bestD = d;
                best = k;
            }
        }
        m_problems.add(m.keyPosition, pathOf(m.key),
                       best.empty() ? motion::msg::make("file.json.unknown_field")
                                    : motion::msg::make("file.json.unknown_field_suggest", {motion::msg::verbatim("suggestion", std::string(best))}));
    }
}

std::optional<int> checkSchema(const Value& root, std::string_view name, int newestVersion, Problems& problems)
{
    if (!root.isObject()) {
        problems.add(root, "", motion::msg::make("file.json.document_not_object", {motion::msg::term("actual", typeTerm(root.type()))}));
        return std::nullopt;
    }
    const Value* schema = root.find("schema");
    if (!schema || !schema->isString()) {
        problems.add(schema ? *schema : root, "schema", motion::msg::make("file.json.schema_missing", {motion::msg::verbatim("schema", std::string(name))}));
        return std::nullopt;
    }
    if (schema->asString() != name) {
        problems.add(*schema, "schema", motion::msg::make("file.json.schema_wrong", {motion::msg::verbatim("value", schema->asString().substr(0, 60)), motion::msg::verbatim("schema", std::string(name))}));
        return std::nullopt;
    }
    const Value* version = root.find("version");
    if (!version || !version->isNumber() || std::floor(version->asNumber()) != version->asNumber() || version->asNumber() < 1) {
        problems.add(version ? *version : root, "version", motion::msg::make("file.json.version_invalid"));
        return std::nullopt;
    }
    if (version->asNumber() > newestVersion) {
        problems.add(*version, "version", motion::msg::make("file.json.version_newer", {motion::msg::real("value", version->asNumber()),
                                                                         motion::msg::integer("newest", newestVersion, motion::msg::Unit::None)}));
        return std::nullopt;
    }
    return static_cast<int>(version->asNumber());
}

Value schemaObject(std::string_view name, int version)
{
    Value v = Value::object();
    v.set("schema", Value(name));
    v.set("version", Value(version));
    return v;
}

} // namespace dev::files::json
