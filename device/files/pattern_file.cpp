#include "device/files/pattern_file.h"

#include "device/files/text_file.h"

#include <QFileInfo>

#include <limits>

namespace dev::files {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::plans::Pattern;
using motion::plans::PatternShape;
using motion::path::Vec2;

namespace {

constexpr double kPatternAny = std::numeric_limits<double>::max();

/// Fields each shape has, beyond the common ones.
std::vector<std::string_view> shapeFields(PatternShape s)
{
    switch (s) {
    case PatternShape::Line: return {"start_mm", "end_mm"};
    case PatternShape::Rectangle: return {"corner_mm", "width_mm", "height_mm", "direction"};
    case PatternShape::Circle: return {"center_mm", "radius_mm", "start_deg", "direction"};
    case PatternShape::Arc: return {"center_mm", "radius_mm", "start_deg", "sweep_deg", "direction"};
    case PatternShape::Sine:
    case PatternShape::Cosine: return {"origin_mm", "amplitude_mm", "wavelength_mm", "length_mm", "angle_deg", "tolerance_mm"};
    case PatternShape::Spiral: return {"center_mm", "start_radius_mm", "pitch_mm", "turns", "start_deg", "direction"};
    case PatternShape::Raster: return {"corner_mm", "width_mm", "height_mm", "spacing_mm", "passes_along"};
    }
    return {};
}

struct Reader {
    ObjectReader& o;
    void num(std::string_view key, bool required, double& into)
    {
        if (auto v = o.number(key, required, -kPatternAny, kPatternAny))
            into = *v;
    }
    void point(std::string_view key, Vec2& into)
    {
        const Value* v = o.get(key, Value::Type::Array, true);
        if (!v)
            return;
        const auto& items = v->items();
        if (items.size() != 2 || !items[0].isNumber() || !items[1].isNumber()) {
            o.problems().add(*v, o.pathOf(key), motion::msg::make("file.json.array_of_numbers", {motion::msg::integer("count", 2)}));
            return;
        }
        into = {items[0].asNumber(), items[1].asNumber()};
    }
    void direction(bool& clockwise)
    {
        if (auto d = o.oneOf("direction", false, {"ccw", "cw"}))
            clockwise = *d == "cw";
    }
};

Value pointValue(Vec2 p)
{
    Value a = Value::array();
    a.push(Value(p.x));
    a.push(Value(p.y));
    return a;
}

} // namespace

PatternReadResult parsePattern(std::string_view text)
{
    PatternReadResult out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.add(parsed.error.position, "", parsed.error.message);
        return out;
    }
    const Value& root = *parsed.value;
    if (!dev::files::json::checkSchema(root, kPatternSchema, kPatternVersion, out.problems))
        return out;
    ObjectReader o(root, "", out.problems);
    Pattern p;
    if (auto n = o.string("name", false))
        p.name = *n;
    std::vector<std::string_view> known = {"schema", "version", "name", "shape", "feed_mm_s", "z_mm"};
    const auto shapeWord = o.oneOf("shape", true, {"line", "rectangle", "circle", "arc", "sine", "cosine", "spiral", "raster"});
    if (shapeWord)
        p.shape = *motion::plans::shapeFromName(*shapeWord);
    Reader r{o};
    r.num("feed_mm_s", true, p.feedMmS);
    if (auto z = o.number("z_mm", false, -kPatternAny, kPatternAny))
        p.zMm = *z;
    if (shapeWord) {
        for (auto f : shapeFields(p.shape))
            known.push_back(f);
        switch (p.shape) {
        case PatternShape::Line:
            r.point("start_mm", p.line.startMm);
            r.point("end_mm", p.line.endMm);
            break;
        case PatternShape::Rectangle:
            r.point("corner_mm", p.rectangle.cornerMm);
            r.num("width_mm", true, p.rectangle.widthMm);
            r.num("height_mm", true, p.rectangle.heightMm);
            r.direction(p.rectangle.clockwise);
            break;
        case PatternShape::Circle:
            r.point("center_mm", p.circle.centerMm);
            r.num("radius_mm", true, p.circle.radiusMm);
            r.num("start_deg", false, p.circle.startDeg);
            r.direction(p.circle.clockwise);
            break;
        case PatternShape::Arc:
            r.point("center_mm", p.arc.centerMm);
            r.num("radius_mm", true, p.arc.radiusMm);
            r.num("start_deg", false, p.arc.startDeg);
            r.num("sweep_deg", true, p.arc.sweepDeg);
            r.direction(p.arc.clockwise);
            break;
        case PatternShape::Sine:
        case PatternShape::Cosine:
            r.point("origin_mm", p.wave.originMm);
            r.num("amplitude_mm", true, p.wave.amplitudeMm);
            r.num("wavelength_mm", true, p.wave.wavelengthMm);
            r.num("length_mm", true, p.wave.lengthMm);
            r.num("angle_deg", false, p.wave.angleDeg);
            r.num("tolerance_mm", false, p.wave.toleranceMm);
            break;
        case PatternShape::Spiral:
            r.point("center_mm", p.spiral.centerMm);
            r.num("start_radius_mm", true, p.spiral.startRadiusMm);
            r.num("pitch_mm", true, p.spiral.pitchMm);
            r.num("turns", true, p.spiral.turns);
            r.num("start_deg", false, p.spiral.startDeg);
            r.direction(p.spiral.clockwise);
            break;
        case PatternShape::Raster:
            r.point("corner_mm", p.raster.cornerMm);
            r.num("width_mm", true, p.raster.widthMm);
            r.num("height_mm", true, p.raster.heightMm);
            r.num("spacing_mm", true, p.raster.spacingMm);
            if (auto a = o.oneOf("passes_along", false, {"x", "y"}))
                p.raster.alongY = *a == "y";
            break;
        }
    }
    o.refuseUnknown(known);
    if (!out.problems.empty())
        return out;
    // The pattern's own rules, placed at the field they are about.
    for (const auto& problem : motion::plans::validate(p)) {
        const Value* at = root.find(problem.path);
        out.problems.add(at ? *at : root, problem.path, problem.message);
    }
    if (out.problems.empty())
        out.pattern = std::move(p);
    return out;
}

std::string writePattern(const Pattern& p)
{
    Value v = dev::files::json::schemaObject(kPatternSchema, kPatternVersion);
    v.set("name", Value(p.name));
    v.set("shape", Value(motion::plans::shapeName(p.shape)));
    v.set("feed_mm_s", Value(p.feedMmS));
    if (p.zMm)
        v.set("z_mm", Value(*p.zMm));
    auto dir = [](bool cw) { return Value(cw ? "cw" : "ccw"); };
    switch (p.shape) {
    case PatternShape::Line:
        v.set("start_mm", pointValue(p.line.startMm));
        v.set("end_mm", pointValue(p.line.endMm));
        break;
    case PatternShape::Rectangle:
        v.set("corner_mm", pointValue(p.rectangle.cornerMm));
        v.set("width_mm", Value(p.rectangle.widthMm));
        v.set("height_mm", Value(p.rectangle.heightMm));
        v.set("direction", dir(p.rectangle.clockwise));
        break;
    case PatternShape::Circle:
        v.set("center_mm", pointValue(p.circle.centerMm));
        v.set("radius_mm", Value(p.circle.radiusMm));
        v.set("start_deg", Value(p.circle.startDeg));
        v.set("direction", dir(p.circle.clockwise));
        break;
    case PatternShape::Arc:
        v.set("center_mm", pointValue(p.arc.centerMm));
        v.set("radius_mm", Value(p.arc.radiusMm));
        v.set("start_deg", Value(p.arc.startDeg));
        v.set("sweep_deg", Value(p.arc.sweepDeg));
        v.set("direction", dir(p.arc.clockwise));
        break;
    case PatternShape::Sine:
    case PatternShape::Cosine:
        v.set("origin_mm", pointValue(p.wave.originMm));
        v.set("amplitude_mm", Value(p.wave.amplitudeMm));
        v.set("wavelength_mm", Value(p.wave.wavelengthMm));
        v.set("length_mm", Value(p.wave.lengthMm));
        v.set("angle_deg", Value(p.wave.angleDeg));
        v.set("tolerance_mm", Value(p.wave.toleranceMm));
        break;
    case PatternShape::Spiral:
        v.set("center_mm", pointValue(p.spiral.centerMm));
        v.set("start_radius_mm", Value(p.spiral.startRadiusMm));
        v.set("pitch_mm", Value(p.spiral.pitchMm));
        v.set("turns", Value(p.spiral.turns));
        v.set("start_deg", Value(p.spiral.startDeg));
        v.set("direction", dir(p.spiral.clockwise));
        break;
    case PatternShape::Raster:
        v.set("corner_mm", pointValue(p.raster.cornerMm));
        v.set("width_mm", Value(p.raster.widthMm));
        v.set("height_mm", Value(p.raster.heightMm));
        v.set("spacing_mm", Value(p.raster.spacingMm));
        v.set("passes_along", Value(p.raster.alongY ? "y" : "x"));
        break;
    }
    return dev::files::json::write(v);
}

bool loadPatternFile(const QString& path, Pattern* pattern, dev::files::json::Problems* problems)
{
    std::string text;
    motion::msg::Message error;
    if (!readText(path, &text, &error)) {
        if (problems)
            problems->addFileProblem(error);
        return false;
    }
    PatternReadResult r = parsePattern(text);
    if (!r.pattern) {
        if (problems)
            *problems = std::move(r.problems);
        return false;
    }
    if (pattern)
        *pattern = std::move(*r.pattern);
    return true;
}

bool savePatternFile(const QString& path, const Pattern& pattern, motion::msg::Message* error)
{
    return writeAtomically(path, writePattern(pattern), error);
}

} // namespace dev::files
