// Fuzz target "json": the reader under every file format. Invariants: parse
// never crashes; an accepted text writes out and reads back to the same text;
// a refusal has a message and a position inside the text; the field reader
// walks any document without crashing.
#include "fuzz_files.h"

#include "device/files/json.h"
#include "device/files/json_fields.h"

#include <algorithm>

namespace {

std::vector<std::string> seeds()
{
    std::vector<std::string> s = {
        "{\n  \"schema\": \"benchpilot.example\",\n  \"version\": 1,\n  \"name\": \"plate \\u00e9\",\n"
        "  \"xy_mm\": [14.38, 11.24],\n  \"items\": [\n    {\"type\": \"a\", \"n\": 3},\n    {\"type\": \"b\", \"ok\": true, \"x\": null}\n  ]\n}\n",
        "[1, -2.5e-3, \"x\", [], {}, [[1], {\"a\": [true, false]}]]",
        "\"\\ud83d\\ude00 \\\" \\\\ \\/ \\b\\f\\n\\r\\t\"",
    };
    for (auto& e : fuzzfiles::exampleFiles(".json"))
        s.push_back(std::move(e));
    return s;
}

void walk(const dev::files::json::Value& v, const std::string& path, dev::files::json::Problems& p, int depth)
{
    if (depth > dev::files::json::kMaxDepth + 1)
        fuzzfiles::fail("a parsed document is deeper than the reader allows");
    if (v.isObject()) {
        dev::files::json::ObjectReader o(v, path, p);
        for (const auto& m : v.members()) {
            o.number(m.key, false, -1e6, 1e6);
            o.integer(m.key, false, -1000, 1000);
            o.string(m.key, false);
            o.oneOf(m.key, false, {"a", "b"});
            walk(m.value, dev::files::json::childPath(path, m.key), p, depth + 1);
        }
        o.refuseUnknown({"schema", "version", "name", "type"});
    } else if (v.isArray()) {
        for (std::size_t k = 0; k < v.items().size(); ++k)
            walk(v.items()[k], dev::files::json::childPath(path, k), p, depth + 1);
    }
}

void check(std::string_view input)
{
    const dev::files::json::ParseResult r = dev::files::json::parse(input);
    if (!r) {
        if (r.error.message.empty())
            fuzzfiles::fail("a refusal without a message");
        const long lines = 1 + std::count(input.begin(), input.end(), '\n');
        if (r.error.position.line < 1 || r.error.position.line > lines || r.error.position.column < 1)
            fuzzfiles::fail("error position outside the text: line " + std::to_string(r.error.position.line));
        return;
    }
    const std::string once = dev::files::json::write(*r.value);
    const dev::files::json::ParseResult again = dev::files::json::parse(once);
    if (!again)
        fuzzfiles::fail("written text does not read back: " + motion::msg::debugString(again.error.message));
    if (dev::files::json::write(*again.value) != once)
        fuzzfiles::fail("write → read → write changed the text");
    if (dev::files::json::write(*again.value, false) != dev::files::json::write(*r.value, false))
        fuzzfiles::fail("compact and pretty writing disagree");
    dev::files::json::Problems p;
    walk(*r.value, "", p, 0);
    dev::files::json::checkSchema(*r.value, "benchpilot.example", 1, p);
    (void)p.format("fuzz.json");
}

} // namespace

BP_FUZZ_FILE_TARGET({"json", seeds, check});
