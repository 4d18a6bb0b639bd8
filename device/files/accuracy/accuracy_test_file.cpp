#include "device/files/accuracy/accuracy_test_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using namespace motion::metrology;

namespace {

// Wide bounds here: the reader takes any number, the test's validator says what is wrong with it.
constexpr double kTestAny = 1e12;
constexpr long long kAnyCount = 1000000000;

Value point(const XyPoint& p)
{
    Value v = Value::object();
    v.set("x_mm", p.xMm);
    v.set("y_mm", p.yMm);
    return v;
}

Value settleValue(const SettleRule& s)
{
    Value v = Value::object();
    v.set("tolerance_um", s.toleranceUm);
    v.set("window_s", s.windowS);
    v.set("timeout_s", s.timeoutS);
    return v;
}

Value tolerancesValue(const AxisTolerances& t)
{
    Value v = Value::object();
    const std::pair<const char*, std::optional<double>> all[] = {{"a_mm", t.aMm}, {"r_mm", t.rMm}, {"e_mm", t.eMm}, {"m_mm", t.mMm}, {"b_mm", t.bMm}};
    for (const auto& [key, value] : all)
        if (value)
            v.set(key, *value);
    return v;
}

std::optional<XyPoint> readPoint(const Value& v, const std::string& path, dev::files::json::Problems& p)
{
    ObjectReader o(v, path, p);
    const auto x = o.number("x_mm", true, -kTestAny, kTestAny), y = o.number("y_mm", true, -kTestAny, kTestAny);
    o.refuseUnknown({"x_mm", "y_mm"});
    if (!x || !y)
        return std::nullopt;
    return XyPoint{*x, *y};
}

void readSettle(ObjectReader& o, SettleRule& s)
{
    const Value* v = o.get("settle", Value::Type::Object, false);
    if (!v)
        return;
    ObjectReader so(*v, "settle", o.problems());
    if (auto x = so.number("tolerance_um", false, -kTestAny, kTestAny))
        s.toleranceUm = *x;
    if (auto x = so.number("window_s", false, -kTestAny, kTestAny))
        s.windowS = *x;
    if (auto x = so.number("timeout_s", false, -kTestAny, kTestAny))
        s.timeoutS = *x;
    so.refuseUnknown({"tolerance_um", "window_s", "timeout_s"});
}

void readTolerances(ObjectReader& o, const char* key, AxisTolerances& t)
{
    const Value* v = o.get(key, Value::Type::Object, false);
    if (!v)
        return;
    ObjectReader to(*v, key, o.problems());
    t.aMm = to.number("a_mm", false, -kTestAny, kTestAny);
    t.rMm = to.number("r_mm", false, -kTestAny, kTestAny);
    t.eMm = to.number("e_mm", false, -kTestAny, kTestAny);
    t.mMm = to.number("m_mm", false, -kTestAny, kTestAny);
    t.bMm = to.number("b_mm", false, -kTestAny, kTestAny);
    to.refuseUnknown({"a_mm", "r_mm", "e_mm", "m_mm", "b_mm"});
}

template <typename T>
void readMotion(ObjectReader& o, T& t)
{
    if (auto x = o.integer("cycles", false, -kAnyCount, kAnyCount))
        t.cycles = static_cast<int>(*x);
    if (auto x = o.number("overrun_mm", false, -kTestAny, kTestAny))
        t.overrunMm = *x;
    if (auto x = o.number("feed_mm_s", false, -kTestAny, kTestAny))
        t.feedMmS = *x;
    if (auto x = o.number("dwell_s", false, -kTestAny, kTestAny))
        t.dwellS = *x;
    readSettle(o, t.settle);
}

AxisTest readAxis(ObjectReader& o)
{
    AxisTest t;
    if (auto x = o.string("axis", true))
        t.axis = *x;
    if (const Value* list = o.get("targets_mm", Value::Type::Array, false)) {
        for (std::size_t i = 0; i < list->items().size(); ++i) {
            const Value& item = list->items()[i];
            if (item.isNumber())
                t.targetsMm.push_back(item.asNumber());
            else
                o.problems().add(item, dev::files::json::childPath("targets_mm", i), dev::files::json::wrongType(Value::Type::Number, item.type()));
        }
    }
    if (const Value* g = o.get("grid", Value::Type::Object, false)) {
        ObjectReader go(*g, "grid", o.problems());
        TargetGrid grid;
        if (auto x = go.number("start_mm", true, -kTestAny, kTestAny))
            grid.startMm = *x;
        if (auto x = go.number("end_mm", true, -kTestAny, kTestAny))
            grid.endMm = *x;
        if (auto x = go.integer("count", true, -kAnyCount, kAnyCount))
            grid.count = static_cast<int>(*x);
        if (auto x = go.boolean("irregular", false))
            grid.irregular = *x;
        go.refuseUnknown({"start_mm", "end_mm", "count", "irregular"});
        t.grid = grid;
    }
    if (auto x = o.boolean("bidirectional", false))
        t.bidirectional = *x;
    readMotion(o, t);
    readTolerances(o, "tolerances", t.tolerances);
    o.refuseUnknown({"schema", "version", "kind", "name", "axis", "targets_mm", "grid", "cycles", "bidirectional", "overrun_mm", "feed_mm_s", "dwell_s",
                     "settle", "tolerances"});
    return t;
}

XyLineTest readXy(ObjectReader& o)
{
    XyLineTest t;
    if (const Value* list = o.get("points_mm", Value::Type::Array, false))
        for (std::size_t i = 0; i < list->items().size(); ++i)
            if (auto p = readPoint(list->items()[i], dev::files::json::childPath("points_mm", i), o.problems()))
                t.pointsMm.push_back(*p);
    if (const Value* v = o.get("from_mm", Value::Type::Object, false))
        t.fromMm = readPoint(*v, "from_mm", o.problems());
    if (const Value* v = o.get("to_mm", Value::Type::Object, false))
        t.toMm = readPoint(*v, "to_mm", o.problems());
    if (auto x = o.integer("count", false, -kAnyCount, kAnyCount))
        t.count = static_cast<int>(*x);
    readMotion(o, t);
    readTolerances(o, "contour_tolerances", t.contourTolerances);
    o.refuseUnknown({"schema", "version", "kind", "name", "points_mm", "from_mm", "to_mm", "count", "cycles", "overrun_mm", "feed_mm_s", "dwell_s",
                     "settle", "contour_tolerances"});
    return t;
}

CircularTest readCircle(ObjectReader& o)
{
    CircularTest t;
    if (auto x = o.string("axes", false))
        t.axes = *x;
    if (const Value* v = o.get("centre_mm", Value::Type::Object, true))
        if (auto p = readPoint(*v, "centre_mm", o.problems()))
            t.centreMm = *p;
    if (auto x = o.number("radius_mm", true, -kTestAny, kTestAny))
        t.radiusMm = *x;
    if (auto x = o.number("feed_mm_s", false, -kTestAny, kTestAny))
        t.feedMmS = *x;
    if (const Value* list = o.get("directions", Value::Type::Array, false)) {
        t.clockwise = t.counterClockwise = false;
        for (std::size_t i = 0; i < list->items().size(); ++i) {
            const Value& item = list->items()[i];
            if (item.isString() && item.asString() == "cw")
                t.clockwise = true;
            else if (item.isString() && item.asString() == "ccw")
                t.counterClockwise = true;
            else
                o.problems().add(item, dev::files::json::childPath("directions", i), motion::msg::make("file.json.not_one_of", {motion::msg::verbatim("value", item.isString() ? item.asString().substr(0, 60) : std::string()), motion::msg::verbatim("allowed", "\"cw\", \"ccw\"")}));
        }
    }
    if (auto x = o.number("lead_arc_deg", false, -kTestAny, kTestAny))
        t.leadArcDeg = *x;
    if (auto x = o.integer("samples_per_revolution", false, -kAnyCount, kAnyCount))
        t.samplesPerRevolution = static_cast<int>(*x);
    if (const Value* v = o.get("tolerances", Value::Type::Object, false)) {
        ObjectReader to(*v, "tolerances", o.problems());
        t.maxGMm = to.number("g_mm", false, -kTestAny, kTestAny);
        t.maxHMm = to.number("h_mm", false, -kTestAny, kTestAny);
        to.refuseUnknown({"g_mm", "h_mm"});
    }
    o.refuseUnknown({"schema", "version", "kind", "name", "axes", "centre_mm", "radius_mm", "feed_mm_s", "directions", "lead_arc_deg",
                     "samples_per_revolution", "tolerances"});
    return t;
}

} // namespace

std::string accuracyTestToJson(const AccuracyTest& test)
{
    Value root = dev::files::json::schemaObject(kAccuracyTestSchema, kAccuracyTestVersion);
    auto motionFields = [&](const auto& t) {
        root.set("cycles", t.cycles);
        root.set("overrun_mm", t.overrunMm);
        root.set("feed_mm_s", t.feedMmS);
        root.set("dwell_s", t.dwellS);
        root.set("settle", settleValue(t.settle));
    };
    if (const auto* a = std::get_if<AxisTest>(&test)) {
        root.set("kind", "axis");
        root.set("name", a->name);
        root.set("axis", a->axis);
        if (a->grid && a->targetsMm.empty()) {
            Value g = Value::object();
            g.set("start_mm", a->grid->startMm);
            g.set("end_mm", a->grid->endMm);
            g.set("count", a->grid->count);
            g.set("irregular", a->grid->irregular);
            root.set("grid", g);
        } else {
            Value list = Value::array();
            for (double x : a->targetsMm)
                list.push(x);
            root.set("targets_mm", list);
        }
        root.set("bidirectional", a->bidirectional);
        motionFields(*a);
        if (!a->tolerances.empty())
            root.set("tolerances", tolerancesValue(a->tolerances));
    } else if (const auto* x = std::get_if<XyLineTest>(&test)) {
        root.set("kind", "xy-line");
        root.set("name", x->name);
        if (x->pointsMm.empty() && x->fromMm && x->toMm) {
            root.set("from_mm", point(*x->fromMm));
            root.set("to_mm", point(*x->toMm));
            root.set("count", x->count);
        } else {
            Value list = Value::array();
            for (const XyPoint& p : x->pointsMm)
                list.push(point(p));
            root.set("points_mm", list);
        }
        motionFields(*x);
        if (!x->contourTolerances.empty())
            root.set("contour_tolerances", tolerancesValue(x->contourTolerances));
    } else {
        const auto& c = std::get<CircularTest>(test);
        root.set("kind", "circle");
        root.set("name", c.name);
        root.set("axes", c.axes);
        root.set("centre_mm", point(c.centreMm));
        root.set("radius_mm", c.radiusMm);
        root.set("feed_mm_s", c.feedMmS);
        Value dirs = Value::array();
        if (c.clockwise)
            dirs.push("cw");
        if (c.counterClockwise)
            dirs.push("ccw");
        root.set("directions", dirs);
        root.set("lead_arc_deg", c.leadArcDeg);
        root.set("samples_per_revolution", c.samplesPerRevolution);
        if (c.maxGMm || c.maxHMm) {
            Value t = Value::object();
            if (c.maxGMm)
                t.set("g_mm", *c.maxGMm);
            if (c.maxHMm)
                t.set("h_mm", *c.maxHMm);
            root.set("tolerances", t);
        }
    }
    return dev::files::json::write(root);
}

AccuracyTestRead accuracyTestFromJson(std::string_view text, std::string_view fileName)
{
    AccuracyTestRead out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.push_back(fromParseError(parsed.error, fileName));
        return out;
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kAccuracyTestSchema, kAccuracyTestVersion, p)) {
        addJsonProblems(p, fileName, out.problems);
        return out;
    }
    ObjectReader o(root, "", p);
    const auto kind = o.oneOf("kind", true, {"axis", "xy-line", "circle"});
    const std::string name = o.string("name", false).value_or("");
    if (!kind) {
        addJsonProblems(p, fileName, out.problems);
        return out;
    }
    AccuracyTest test;
    motion::msg::Problems model;
    if (*kind == "axis") {
        AxisTest t = readAxis(o);
        t.name = name;
        model = validate(t);
        test = t;
    } else if (*kind == "xy-line") {
        XyLineTest t = readXy(o);
        t.name = name;
        model = validate(t);
        test = t;
    } else {
        CircularTest t = readCircle(o);
        t.name = name;
        model = validate(t);
        test = t;
    }
    addJsonProblems(p, fileName, out.problems);
    if (hasErrors(out.problems))
        return out;  // the model's problems would repeat what the reader already said
    addModelProblems(model, root, fileName, out.problems);
    if (!hasErrors(out.problems))
        out.test = test;
    return out;
}

AccuracyTestRead loadAccuracyTestFile(const QString& path)
{
    AccuracyTestRead out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? accuracyTestFromJson(*text, name) : out;
}

bool saveAccuracyTestFile(const QString& path, const AccuracyTest& test, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, accuracyTestToJson(test), error);
}

} // namespace dev::files::accuracy
