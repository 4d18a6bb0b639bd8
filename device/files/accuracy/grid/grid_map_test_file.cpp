#include "device/files/accuracy/grid/grid_map_test_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::metrology::GridMapTest;

namespace {
// Wide bounds here: the reader takes any number, the test's validator says what is wrong.
constexpr double kGridTestAny = 1e12;

Value gridPair(const char* a, double x, const char* b, double y)
{
    Value v = Value::object();
    v.set(a, x);
    v.set(b, y);
    return v;
}
} // namespace

std::string gridMapTestToJson(const GridMapTest& t)
{
    Value root = dev::files::json::schemaObject(kGridMapTestSchema, kGridMapTestVersion);
    root.set("name", Value(t.name));
    root.set("pitch_mm", gridPair("x", t.pitchXMm, "y", t.pitchYMm));
    Value n = Value::object();
    n.set("columns", static_cast<double>(t.columns));
    n.set("rows", static_cast<double>(t.rows));
    root.set("nodes", n);
    if (t.startXMm && t.startYMm)
        root.set("start_mm", gridPair("x_mm", *t.startXMm, "y_mm", *t.startYMm));
    root.set("plate_pitch_mm", t.platePitchMm);
    root.set("feed_mm_s", t.feedMmS);
    root.set("dwell_s", t.dwellS);
    root.set("approach_mm", t.approachMm);
    root.set("on_failure", Value(std::string(t.stopOnFailure ? "stop" : "go-on")));
    // Written only when bidirectional: a one-way test stays the file every reader of
    // version 1 has read.
    if (t.bidirectional)
        root.set("passes", Value(std::string("bidirectional")));
    return dev::files::json::write(root);
}

GridMapTestRead gridMapTestFromJson(std::string_view text, std::string_view fileName)
{
    motion::msg::Problems problems;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        problems.push_back(fromParseError(parsed.error, fileName));
        return GridMapTestRead::refused(std::move(problems));
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kGridMapTestSchema, kGridMapTestVersion, p)) {
        addJsonProblems(p, fileName, problems);
        return GridMapTestRead::refused(std::move(problems));
    }
    GridMapTest t;
    ObjectReader o(root, "", p);
    if (auto v = o.string("name", false))
        t.name = *v;
    if (const Value* v = o.get("pitch_mm", Value::Type::Object, true)) {
        ObjectReader po(*v, "pitch_mm", p);
        if (auto x = po.number("x", true, -kGridTestAny, kGridTestAny))
            t.pitchXMm = *x;
        if (auto y = po.number("y", true, -kGridTestAny, kGridTestAny))
            t.pitchYMm = *y;
        po.refuseUnknown({"x", "y"});
    }
    if (const Value* v = o.get("nodes", Value::Type::Object, true)) {
        ObjectReader no(*v, "nodes", p);
        if (auto c = no.integer("columns", true, -1000000, 1000000))
            t.columns = static_cast<int>(*c);
        if (auto r = no.integer("rows", true, -1000000, 1000000))
            t.rows = static_cast<int>(*r);
        no.refuseUnknown({"columns", "rows"});
    }
    if (const Value* v = o.get("start_mm", Value::Type::Object, false)) {
        ObjectReader so(*v, "start_mm", p);
        t.startXMm = so.number("x_mm", true, -kGridTestAny, kGridTestAny);
        t.startYMm = so.number("y_mm", true, -kGridTestAny, kGridTestAny);
        so.refuseUnknown({"x_mm", "y_mm"});
        if (!t.startXMm || !t.startYMm)
            t.startXMm.reset(), t.startYMm.reset();
    }
    if (auto v = o.number("plate_pitch_mm", false, -kGridTestAny, kGridTestAny))
        t.platePitchMm = *v;
    if (auto v = o.number("feed_mm_s", false, -kGridTestAny, kGridTestAny))
        t.feedMmS = *v;
    if (auto v = o.number("dwell_s", false, -kGridTestAny, kGridTestAny))
        t.dwellS = *v;
    if (auto v = o.number("approach_mm", false, -kGridTestAny, kGridTestAny))
        t.approachMm = *v;
    if (auto v = o.oneOf("on_failure", false, {"go-on", "stop"}))
        t.stopOnFailure = *v == "stop";
    if (auto v = o.oneOf("passes", false, {"forward", "bidirectional"}))
        t.bidirectional = *v == "bidirectional";
    (void)o.string("note", false);  // free text for the record
    o.refuseUnknown({"schema", "version", "name", "pitch_mm", "nodes", "start_mm", "plate_pitch_mm", "feed_mm_s", "dwell_s",
                     "approach_mm", "on_failure", "passes", "note"});
    addJsonProblems(p, fileName, problems);
    addModelProblems(motion::metrology::validate(t), root, fileName, problems);
    return GridMapTestRead::from(t, std::move(problems));
}

GridMapTestRead loadGridMapTestFile(const QString& path)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = loadText(path, name, problems);
    return text ? gridMapTestFromJson(*text, name) : GridMapTestRead::refused(std::move(problems));
}

bool saveGridMapTestFile(const QString& path, const GridMapTest& t, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, gridMapTestToJson(t), error);
}

motion::msg::Problems placeGridMapTestProblems(const QString& path, const motion::msg::Problems& found)
{
    motion::msg::Problems out;
    std::string name;
    const auto text = loadText(path, name, out);
    if (!text)
        return found;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(*text);
    if (!parsed)
        return found;
    addModelProblems(found, *parsed.value, name, out);
    return out;
}

} // namespace dev::files::accuracy
