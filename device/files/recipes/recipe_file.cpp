#include "device/files/recipes/recipe_file.h"

#include "device/files/plates/json_path.h"

#include <vector>

namespace dev::files::plates {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::plates::StepType;

namespace {

constexpr double kRecipeBig = 1e9;

/// The fields each step type takes besides "type" and "note".
std::vector<std::string_view> fieldsOf(StepType t)
{
    switch (t) {
    case StepType::Aspirate: return {"plate", "wells", "station", "volume_ul", "speed_ul_s"};
    case StepType::Dispense: return {"plate", "wells", "station", "volume_ul", "speed_ul_s", "source", "touch_off_mm"};
    case StepType::Mix: return {"plate", "wells", "volume_ul", "cycles", "speed_ul_s"};
    case StepType::Wash: return {"station", "volume_ul", "cycles", "speed_ul_s"};
    case StepType::AirGap: return {"volume_ul", "speed_ul_s"};
    case StepType::Wait: return {"seconds"};
    case StepType::TouchOff: return {"plate", "wells", "offset_mm"};
    }
    return {};
}

bool takes(StepType t, std::string_view field)
{
    for (std::string_view f : fieldsOf(t))
        if (f == field)
            return true;
    return false;
}

void readWells(ObjectReader& o, const Value& step, motion::plates::Step& s, dev::files::json::Problems& problems)
{
    const Value* w = step.find("wells");
    if (!w)
        return;
    if (w->isString()) {
        s.wells.push_back(w->asString());
    } else if (w->isArray()) {
        for (std::size_t k = 0; k < w->items().size(); ++k) {
            const Value& item = w->items()[k];
            if (!item.isString()) {
                problems.add(item, dev::files::json::childPath(o.pathOf("wells"), k), motion::msg::make("recipe.file.well_not_string", {motion::msg::term("actual", dev::files::json::typeTerm(item.type()))}));
                continue;
            }
            s.wells.push_back(item.asString());
        }
        if (w->items().empty())
            problems.add(*w, o.pathOf("wells"), motion::msg::make("plate.wells.none"));
    } else {
        problems.add(*w, o.pathOf("wells"), motion::msg::make("recipe.file.wells_wrong_type", {motion::msg::term("actual", dev::files::json::typeTerm(w->type()))}));
    }
}

motion::plates::Step readStep(const Value& v, const std::string& path, dev::files::json::Problems& problems)
{
    motion::plates::Step s;
    ObjectReader o(v, path, problems);
    if (!o.valid())
        return s;
    const auto type = o.string("type", true);
    const auto t = type ? motion::plates::stepTypeFromName(*type) : std::nullopt;
    if (type && !t) {
        problems.add(*v.find("type"), o.pathOf("type"), motion::msg::make("recipe.file.unknown_step_type", {motion::msg::verbatim("type", type->substr(0, 40)),
                                                                                                   motion::msg::verbatim("types", motion::plates::stepTypeList())}));
        s.type = StepType::Wait;  // a harmless stand-in keeps the later steps' indices
        s.seconds = 0;
        return s;
    }
    if (!t) {
        s.type = StepType::Wait;
        return s;
    }
    s.type = *t;
    std::vector<std::string_view> known = fieldsOf(*t);
    known.push_back("type");
    known.push_back("note");
    // A field of another step type gets a sentence of its own, not a spelling hint.
    for (const dev::files::json::Member& m : v.members()) {
        if (m.key == "type" || m.key == "note" || takes(*t, m.key))
            continue;
        for (int k = 0; k < motion::plates::kStepTypeCount; ++k)
            if (takes(static_cast<StepType>(k), m.key)) {
                problems.add(m.keyPosition, o.pathOf(m.key), motion::msg::make("recipe.file.field_of_other_step", {motion::msg::verbatim("type", *type), motion::msg::verbatim("field", m.key)}));
                known.push_back(m.key);
                break;
            }
    }
    o.refuseUnknown(known);
    s.note = o.string("note", false).value_or("");
    if (takes(*t, "plate"))
        s.plate = o.string("plate", false).value_or("");
    if (takes(*t, "wells"))
        readWells(o, v, s, problems);
    if (takes(*t, "station"))
        s.station = o.string("station", false).value_or("");
    if (takes(*t, "volume_ul"))
        s.volumeUl = o.number("volume_ul", true, -kRecipeBig, kRecipeBig).value_or(0);
    if (takes(*t, "speed_ul_s") && v.find("speed_ul_s"))
        s.speedUlS = o.number("speed_ul_s", false, -kRecipeBig, kRecipeBig);
    if (takes(*t, "cycles"))
        s.cycles = static_cast<int>(o.integer("cycles", false, -1000000, 1000000).value_or(1));
    if (takes(*t, "seconds"))
        s.seconds = o.number("seconds", true, -kRecipeBig, kRecipeBig).value_or(0);
    if (*t == StepType::TouchOff)
        s.offsetMm = o.number("offset_mm", true, -kRecipeBig, kRecipeBig).value_or(0);
    if (*t == StepType::Dispense)
        s.offsetMm = o.number("touch_off_mm", false, -kRecipeBig, kRecipeBig).value_or(0);
    if (takes(*t, "source"))
        if (const Value* src = o.get("source", Value::Type::Object, false)) {
            ObjectReader so(*src, o.pathOf("source"), problems);
            so.refuseUnknown({"plate", "well", "station"});
            s.source.plate = so.string("plate", false).value_or("");
            s.source.well = so.string("well", false).value_or("");
            s.source.station = so.string("station", false).value_or("");
            if (s.source.empty())
                problems.add(*src, o.pathOf("source"), motion::msg::make("recipe.file.source_empty"));
        }
    return s;
}

bool covers(const std::string& reported, const std::string& path)
{
    if (reported.empty() || path.size() < reported.size() || path.compare(0, reported.size(), reported) != 0)
        return false;
    return path.size() == reported.size() || path[reported.size()] == '.' || path[reported.size()] == '[';
}

} // namespace

bool isLabwareFile(const std::string& reference)
{
    return reference.size() > 5 && reference.compare(reference.size() - 5, 5, ".json") == 0;
}

RecipeRead parseRecipe(std::string_view text)
{
    RecipeRead r;
    r.root = parseOrReport(text, r.problems);
    if (!r.root)
        return r;
    const Value& root = *r.root;
    if (!dev::files::json::checkSchema(root, kRecipeSchema, kRecipeVersion, r.problems))
        return r;
    ObjectReader o(root, "", r.problems);
    o.refuseUnknown({"schema", "version", "name", "description", "travel_speed_mm_s", "z_speed_mm_s", "plates", "steps"});
    motion::plates::Recipe rec;
    rec.name = o.string("name", false).value_or("");
    rec.description = o.string("description", false).value_or("");
    if (root.find("travel_speed_mm_s"))
        rec.travelSpeedMmS = o.number("travel_speed_mm_s", false, -kRecipeBig, kRecipeBig);
    if (root.find("z_speed_mm_s"))
        rec.zSpeedMmS = o.number("z_speed_mm_s", false, -kRecipeBig, kRecipeBig);
    if (const Value* plates = o.get("plates", Value::Type::Array, true)) {
        for (std::size_t k = 0; k < plates->items().size() && k < 64; ++k) {
            ObjectReader p(plates->items()[k], dev::files::json::childPath("plates", k), r.problems);
            p.refuseUnknown({"name", "slot", "labware", "safe_z_mm", "depth_z_mm"});
            motion::plates::RecipePlate rp;
            rp.name = p.string("name", true).value_or("");
            rp.slot = p.string("slot", true).value_or("");
            rp.labware = p.string("labware", true).value_or("");
            rp.safeZMm = p.number("safe_z_mm", true, -kRecipeBig, kRecipeBig).value_or(0);
            rp.depthZMm = p.number("depth_z_mm", true, -kRecipeBig, kRecipeBig).value_or(0);
            rec.plates.push_back(rp);
        }
        if (plates->items().size() > 64)
            r.problems.add(*plates, "plates", motion::msg::make("recipe.file.too_many_plates", {motion::msg::integer("max", 64)}));
    }
    if (const Value* steps = o.get("steps", Value::Type::Array, true)) {
        const std::size_t n = std::min(steps->items().size(), motion::plates::kMaxSteps + 1);
        for (std::size_t k = 0; k < n; ++k)
            rec.steps.push_back(readStep(steps->items()[k], dev::files::json::childPath("steps", k), r.problems));
    }
    r.wellFormed = r.problems.empty();
    r.recipe = std::move(rec);
    return r;
}

void placeProblems(RecipeRead& read, const motion::msg::Problems& problems)
{
    const std::vector<motion::msg::Problem> before = read.problems.list();
    for (const motion::msg::Problem& p : problems) {
        bool dup = false;
        for (const motion::msg::Problem& q : before)
            dup = dup || covers(q.path, p.path);
        if (dup)
            continue;
        const dev::files::json::Position at = read.root ? positionOfPath(*read.root, p.path) : dev::files::json::Position{};
        read.problems.add(at, p.path, p.message, p.severity);
    }
}

namespace {
Value wellsJson(const std::vector<std::string>& wells)
{
    if (wells.size() == 1)
        return Value(wells.front());
    Value a = Value::array();
    for (const std::string& w : wells)
        a.push(w);
    return a;
}
} // namespace

std::string writeRecipe(const motion::plates::Recipe& rec)
{
    Value v = dev::files::json::schemaObject(kRecipeSchema, kRecipeVersion);
    v.set("name", rec.name);
    if (!rec.description.empty())
        v.set("description", rec.description);
    if (rec.travelSpeedMmS)
        v.set("travel_speed_mm_s", *rec.travelSpeedMmS);
    if (rec.zSpeedMmS)
        v.set("z_speed_mm_s", *rec.zSpeedMmS);
    Value plates = Value::array();
    for (const motion::plates::RecipePlate& p : rec.plates) {
        Value x = Value::object();
        x.set("name", p.name);
        x.set("slot", p.slot);
        x.set("labware", p.labware);
        x.set("safe_z_mm", p.safeZMm);
        x.set("depth_z_mm", p.depthZMm);
        plates.push(std::move(x));
    }
    v.set("plates", std::move(plates));
    Value steps = Value::array();
    for (const motion::plates::Step& s : rec.steps) {
        Value x = Value::object();
        x.set("type", motion::plates::stepTypeName(s.type));
        if (takes(s.type, "plate") && !s.plate.empty())
            x.set("plate", s.plate);
        if (takes(s.type, "wells") && !s.wells.empty())
            x.set("wells", wellsJson(s.wells));
        if (takes(s.type, "station") && !s.station.empty())
            x.set("station", s.station);
        if (takes(s.type, "volume_ul"))
            x.set("volume_ul", s.volumeUl);
        if (takes(s.type, "cycles"))
            x.set("cycles", s.cycles);
        if (takes(s.type, "speed_ul_s") && s.speedUlS)
            x.set("speed_ul_s", *s.speedUlS);
        if (s.type == StepType::Wait)
            x.set("seconds", s.seconds);
        if (s.type == StepType::TouchOff)
            x.set("offset_mm", s.offsetMm);
        if (s.type == StepType::Dispense && s.offsetMm != 0)
            x.set("touch_off_mm", s.offsetMm);
        if (s.type == StepType::Dispense && !s.source.empty()) {
            Value src = Value::object();
            if (!s.source.station.empty()) {
                src.set("station", s.source.station);
            } else {
                if (!s.source.plate.empty())
                    src.set("plate", s.source.plate);
                src.set("well", s.source.well);
            }
            x.set("source", std::move(src));
        }
        if (!s.note.empty())
            x.set("note", s.note);
        steps.push(std::move(x));
    }
    v.set("steps", std::move(steps));
    return dev::files::json::write(v);
}

} // namespace dev::files::plates
