#include "device/files/plates/labware_file.h"

#include "device/files/plates/json_path.h"

#include <cmath>

namespace dev::files::plates {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::plates::Labware;
using motion::plates::Well;
using motion::plates::WellShape;

namespace {

constexpr double kLabwareBig = 1e6;

/// The model validator's problems, placed in the document.
void addModelProblems(const Value& root, const motion::msg::Problems& found, dev::files::json::Problems& out)
{
    for (const motion::msg::Problem& p : found)
        out.add(positionOfPath(root, p.path), p.path, p.message, p.severity);
}

std::optional<WellShape> readShape(ObjectReader& o, const char* key)
{
    const auto s = o.oneOf(key, false, {"circular", "rectangular"});
    if (!s)
        return o.value().find(key) ? std::nullopt : std::optional<WellShape>(WellShape::Circular);
    return *s == "circular" ? WellShape::Circular : WellShape::Rectangular;
}

/// Size fields shared by a grid and a single well; false when any is wrong.
bool readWellSize(ObjectReader& o, Well& w)
{
    const auto shape = readShape(o, "shape");
    const auto depth = o.number("depth_mm", true, 0, kLabwareBig);
    const auto bottom = o.number("bottom_z_mm", false, 0, kLabwareBig);
    const auto volume = o.number("volume_ul", true, 0, 1e9);
    bool ok = shape && depth && volume && (bottom || !o.value().find("bottom_z_mm"));
    if (shape)
        w.shape = *shape;
    if (w.shape == WellShape::Circular) {
        const auto d = o.number("diameter_mm", true, 0, kLabwareBig);
        ok = ok && d;
        w.diameterMm = d.value_or(0);
    } else {
        const auto x = o.number("size_x_mm", true, 0, kLabwareBig), y = o.number("size_y_mm", true, 0, kLabwareBig);
        ok = ok && x && y;
        w.sizeXMm = x.value_or(0);
        w.sizeYMm = y.value_or(0);
    }
    w.depthMm = depth.value_or(0);
    w.bottomZMm = bottom.value_or(0);
    w.volumeUl = volume.value_or(0);
    return ok;
}

std::optional<Labware> readOurs(const Value& root, dev::files::json::Problems& problems)
{
    const std::size_t before = problems.size();
    ObjectReader o(root, "", problems);
    o.refuseUnknown({"schema", "version", "id", "name", "brand", "length_mm", "width_mm", "height_mm", "rows", "columns", "grid", "wells"});
    Labware lw;
    lw.id = o.string("id", true).value_or("");
    lw.displayName = o.string("name", false).value_or(lw.id);
    lw.brand = o.string("brand", false).value_or("");
    lw.lengthMm = o.number("length_mm", false, 0, kLabwareBig).value_or(motion::plates::kSbsLengthMm);
    lw.widthMm = o.number("width_mm", false, 0, kLabwareBig).value_or(motion::plates::kSbsWidthMm);
    lw.heightMm = o.number("height_mm", true, 0, kLabwareBig).value_or(0);
    lw.rows = static_cast<int>(o.integer("rows", true, 1, motion::plates::kMaxRows).value_or(0));
    lw.columns = static_cast<int>(o.integer("columns", true, 1, motion::plates::kMaxColumns).value_or(0));
    const Value* grid = o.get("grid", Value::Type::Object, false);
    const Value* wells = o.get("wells", Value::Type::Array, false);
    if (grid && wells)
        problems.add(*wells, "wells", motion::msg::make("plate.file.grid_and_wells"));
    else if (!grid && !wells && o.valid())
        problems.add(root, "grid", motion::msg::make("plate.file.no_grid"));
    if (grid) {
        ObjectReader g(*grid, "grid", problems);
        g.refuseUnknown({"a1_x_mm", "a1_y_mm", "pitch_x_mm", "pitch_y_mm", "shape", "diameter_mm", "size_x_mm", "size_y_mm",
                         "depth_mm", "bottom_z_mm", "volume_ul"});
        motion::plates::GridSpec s;
        s.a1XMm = g.number("a1_x_mm", true, -kLabwareBig, kLabwareBig).value_or(0);
        s.a1YMm = g.number("a1_y_mm", true, -kLabwareBig, kLabwareBig).value_or(0);
        s.pitchXMm = g.number("pitch_x_mm", lw.columns > 1, 0, kLabwareBig).value_or(0);
        s.pitchYMm = g.number("pitch_y_mm", lw.rows > 1, 0, kLabwareBig).value_or(0);
        Well w;
        if (readWellSize(g, w) && lw.rows > 0 && lw.columns > 0) {
            s.rows = lw.rows;
            s.columns = lw.columns;
            s.shape = w.shape;
            s.diameterMm = w.diameterMm;
            s.sizeXMm = w.sizeXMm;
            s.sizeYMm = w.sizeYMm;
            s.depthMm = w.depthMm;
            s.bottomZMm = w.bottomZMm;
            s.volumeUl = w.volumeUl;
            lw.wells = motion::plates::gridLabware(s).wells;
        }
    }
    if (wells) {
        for (std::size_t k = 0; k < wells->items().size() && k < 4096; ++k) {
            ObjectReader wr(wells->items()[k], dev::files::json::childPath("wells", k), problems);
            wr.refuseUnknown({"well", "x_mm", "y_mm", "shape", "diameter_mm", "size_x_mm", "size_y_mm", "depth_mm", "bottom_z_mm", "volume_ul"});
            Well w;
            const auto name = wr.string("well", true);
            const auto id = name ? motion::plates::parseWellName(*name) : std::nullopt;
            if (name && !id)
                problems.add(*wells->items()[k].find("well"), wr.pathOf("well"), motion::msg::make("plate.file.not_a_well_name", {motion::msg::verbatim("text", name->substr(0, 20))}));
            const auto x = wr.number("x_mm", true, -kLabwareBig, kLabwareBig), y = wr.number("y_mm", true, -kLabwareBig, kLabwareBig);
            if (readWellSize(wr, w) && id && x && y) {
                w.id = *id;
                w.xMm = *x;
                w.yMm = *y;
                lw.wells.push_back(w);
            }
        }
        if (wells->items().size() > 4096)
            problems.add(*wells, "wells", motion::msg::make("plate.file.too_many_wells", {motion::msg::integer("max", 4096)}));
    }
    if (problems.size() != before)
        return std::nullopt;
    lw.sortWells();
    return lw;
}

} // namespace

std::optional<Labware> readOpentronsLabware(const Value& root, dev::files::json::Problems& problems)
{
    const std::size_t before = problems.size();
    ObjectReader o(root, "", problems);
    if (!o.valid())
        return std::nullopt;
    const auto schemaVersion = o.integer("schemaVersion", true, 0, 1000);
    if (schemaVersion && *schemaVersion != 2)
        problems.add(*root.find("schemaVersion"), "schemaVersion", motion::msg::make("plate.file.opentrons_schema", {motion::msg::integer("value", *schemaVersion, motion::msg::Unit::None)}));
    Labware lw;
    if (const Value* params = o.get("parameters", Value::Type::Object, true)) {
        ObjectReader p(*params, "parameters", problems);
        lw.id = p.string("loadName", true).value_or("");
        if (p.boolean("isTiprack", false).value_or(false))
            problems.add(*params->find("isTiprack"), "parameters.isTiprack", motion::msg::make("plate.file.tip_rack"));
    }
    if (const Value* meta = o.get("metadata", Value::Type::Object, false)) {
        ObjectReader m(*meta, "metadata", problems);
        lw.displayName = m.string("displayName", false).value_or("");
    }
    if (const Value* brand = o.get("brand", Value::Type::Object, false)) {
        ObjectReader b(*brand, "brand", problems);
        lw.brand = b.string("brand", false).value_or("");
    }
    if (lw.displayName.empty())
        lw.displayName = lw.id;
    double yDim = 0;
    if (const Value* dims = o.get("dimensions", Value::Type::Object, true)) {
        ObjectReader d(*dims, "dimensions", problems);
        lw.lengthMm = d.number("xDimension", true, 0, kLabwareBig).value_or(0);
        yDim = d.number("yDimension", true, 0, kLabwareBig).value_or(0);
        lw.widthMm = yDim;
        lw.heightMm = d.number("zDimension", true, 0, kLabwareBig).value_or(0);
    }
    // The grid is the ordering: one array per column, wells front to back in it.
    if (const Value* ordering = o.get("ordering", Value::Type::Array, true)) {
        lw.columns = static_cast<int>(ordering->items().size());
        for (std::size_t c = 0; c < ordering->items().size(); ++c) {
            const Value& col = ordering->items()[c];
            if (!col.isArray()) {
                problems.add(col, dev::files::json::childPath("ordering", c), motion::msg::make("plate.file.ordering_not_names"));
                continue;
            }
            lw.rows = std::max(lw.rows, static_cast<int>(col.items().size()));
        }
        if (lw.columns > motion::plates::kMaxColumns || lw.rows > motion::plates::kMaxRows)
            problems.add(*ordering, "ordering", motion::msg::make("plate.labware.grid_size", {motion::msg::integer("max_rows", motion::plates::kMaxRows),
                                                                                   motion::msg::integer("max_columns", motion::plates::kMaxColumns),
                                                                                   motion::msg::integer("rows", lw.rows), motion::msg::integer("columns", lw.columns)}));
    }
    if (const Value* wells = o.get("wells", Value::Type::Object, true)) {
        for (const dev::files::json::Member& m : wells->members()) {
            if (lw.wells.size() >= 4096) {
                problems.add(*wells, "wells", motion::msg::make("plate.file.too_many_wells", {motion::msg::integer("max", 4096)}));
                break;
            }
            const std::string path = dev::files::json::childPath("wells", m.key);
            const auto id = motion::plates::parseWellName(m.key);
            if (!id) {
                problems.add(m.keyPosition, path, motion::msg::make("plate.file.not_a_well_name", {motion::msg::verbatim("text", m.key.substr(0, 20))}));
                continue;
            }
            ObjectReader w(m.value, path, problems);
            Well well;
            well.id = *id;
            const auto shape = w.oneOf("shape", true, {"circular", "rectangular"});
            const auto x = w.number("x", true, -kLabwareBig, kLabwareBig), y = w.number("y", true, -kLabwareBig, kLabwareBig), z = w.number("z", true, -kLabwareBig, kLabwareBig);
            const auto depth = w.number("depth", true, 0, kLabwareBig);
            const auto volume = w.number("totalLiquidVolume", true, 0, 1e9);
            if (shape && *shape == "rectangular") {
                well.shape = WellShape::Rectangular;
                well.sizeXMm = w.number("xDimension", true, 0, kLabwareBig).value_or(0);
                well.sizeYMm = w.number("yDimension", true, 0, kLabwareBig).value_or(0);
            } else if (shape) {
                well.diameterMm = w.number("diameter", true, 0, kLabwareBig).value_or(0);
            }
            if (x && y && z && depth && volume) {
                well.xMm = *x;
                well.yMm = yDim - *y;  // front-left origin, y to the back → back-left origin, y to the front
                well.bottomZMm = *z;
                well.depthMm = *depth;
                well.volumeUl = *volume;
                lw.wells.push_back(well);
            }
        }
    }
    if (problems.size() != before)
        return std::nullopt;
    lw.sortWells();
    return lw;
}

LabwareRead parseLabware(std::string_view text)
{
    LabwareRead r;
    const std::optional<Value> parsed = parseOrReport(text, r.problems);
    if (!parsed)
        return r;
    const Value& root = *parsed;
    std::optional<Labware> lw;
    if (root.isObject() && root.find("schemaVersion") && !root.find("schema")) {
        r.opentrons = true;
        lw = readOpentronsLabware(root, r.problems);
    } else if (dev::files::json::checkSchema(root, kLabwareSchema, kLabwareVersion, r.problems)) {
        lw = readOurs(root, r.problems);
    }
    if (!lw)
        return r;
    motion::msg::Problems found = motion::plates::validateLabware(*lw);
    if (r.opentrons)
        for (motion::msg::Problem& p : found)
            p.path = "wells";  // Opentrons keys wells by name; the message names the well
    addModelProblems(root, found, r.problems);
    if (r.problems.empty())
        r.labware = std::move(lw);
    return r;
}

namespace {
bool isRegularGrid(const Labware& lw, motion::plates::GridSpec* spec)
{
    if (lw.wells.size() != static_cast<std::size_t>(lw.rows) * static_cast<std::size_t>(lw.columns) || lw.wells.empty())
        return false;
    const Well& a1 = lw.wells.front();
    spec->rows = lw.rows;
    spec->columns = lw.columns;
    spec->a1XMm = a1.xMm;
    spec->a1YMm = a1.yMm;
    spec->pitchXMm = lw.columns > 1 ? lw.well({0, 1})->xMm - a1.xMm : 0;
    spec->pitchYMm = lw.rows > 1 ? lw.well({1, 0})->yMm - a1.yMm : 0;
    spec->shape = a1.shape;
    spec->diameterMm = a1.diameterMm;
    spec->sizeXMm = a1.sizeXMm;
    spec->sizeYMm = a1.sizeYMm;
    spec->depthMm = a1.depthMm;
    spec->bottomZMm = a1.bottomZMm;
    spec->volumeUl = a1.volumeUl;
    const Labware regular = motion::plates::gridLabware(*spec);
    for (std::size_t k = 0; k < lw.wells.size(); ++k) {
        const Well& a = lw.wells[k];
        const Well& b = regular.wells[k];
        // Exactly the same numbers once written and read: positions to the written precision.
        if (!(a.id == b.id) || std::abs(a.xMm - b.xMm) > 1e-9 || std::abs(a.yMm - b.yMm) > 1e-9 || a.shape != b.shape
            || a.diameterMm != b.diameterMm || a.sizeXMm != b.sizeXMm || a.sizeYMm != b.sizeYMm || a.depthMm != b.depthMm
            || a.bottomZMm != b.bottomZMm || a.volumeUl != b.volumeUl)
            return false;
    }
    return true;
}

void writeSize(Value& v, const Well& w)
{
    v.set("shape", motion::plates::wellShapeName(w.shape));
    if (w.shape == WellShape::Circular) {
        v.set("diameter_mm", w.diameterMm);
    } else {
        v.set("size_x_mm", w.sizeXMm);
        v.set("size_y_mm", w.sizeYMm);
    }
    v.set("depth_mm", w.depthMm);
    v.set("bottom_z_mm", w.bottomZMm);
    v.set("volume_ul", w.volumeUl);
}
} // namespace

std::string writeLabware(const Labware& lw)
{
    Value v = dev::files::json::schemaObject(kLabwareSchema, kLabwareVersion);
    v.set("id", lw.id);
    v.set("name", lw.displayName);
    if (!lw.brand.empty())
        v.set("brand", lw.brand);
    v.set("length_mm", lw.lengthMm);
    v.set("width_mm", lw.widthMm);
    v.set("height_mm", lw.heightMm);
    v.set("rows", lw.rows);
    v.set("columns", lw.columns);
    motion::plates::GridSpec spec;
    if (isRegularGrid(lw, &spec)) {
        Value g = Value::object();
        g.set("a1_x_mm", spec.a1XMm);
        g.set("a1_y_mm", spec.a1YMm);
        if (lw.columns > 1)
            g.set("pitch_x_mm", spec.pitchXMm);
        if (lw.rows > 1)
            g.set("pitch_y_mm", spec.pitchYMm);
        writeSize(g, lw.wells.front());
        v.set("grid", std::move(g));
    } else {
        Value wells = Value::array();
        for (const Well& w : lw.wells) {
            Value x = Value::object();
            x.set("well", motion::plates::wellName(w.id));
            x.set("x_mm", w.xMm);
            x.set("y_mm", w.yMm);
            writeSize(x, w);
            wells.push(std::move(x));
        }
        v.set("wells", std::move(wells));
    }
    return dev::files::json::write(v);
}

} // namespace dev::files::plates
