#include "motion/plans/plates/labware.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace motion::plates {

const char* wellShapeName(WellShape s) { return s == WellShape::Circular ? "circular" : "rectangular"; }

double Well::innerRadiusMm() const
{
    return shape == WellShape::Circular ? diameterMm / 2 : std::min(sizeXMm, sizeYMm) / 2;
}

const Well* Labware::well(const WellId& w) const
{
    if (w.row < 0 || w.column < 0 || w.row >= rows || w.column >= columns)
        return nullptr;
    // Full grids are stored row by row, so the well is at its grid index.
    const std::size_t at = static_cast<std::size_t>(w.row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(w.column);
    if (wells.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns) && wells[at].id == w)
        return &wells[at];
    for (const Well& x : wells)
        if (x.id == w)
            return &x;
    return nullptr;
}

const Well* Labware::wellNamed(const std::string& name) const
{
    const auto wid = parseWellName(name);
    return wid ? well(*wid) : nullptr;
}

std::string Labware::describe() const { return std::to_string(wells.size()) + "-well plate"; }

void Labware::sortWells()
{
    std::stable_sort(wells.begin(), wells.end(), [](const Well& a, const Well& b) { return a.id < b.id; });
}

Labware gridLabware(const GridSpec& s)
{
    Labware lw;
    lw.id = s.id;
    lw.displayName = s.displayName;
    lw.brand = s.brand;
    lw.lengthMm = s.lengthMm;
    lw.widthMm = s.widthMm;
    lw.heightMm = s.heightMm;
    lw.rows = s.rows;
    lw.columns = s.columns;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.columns; ++c) {
            Well w;
            w.id = {r, c};
            w.xMm = s.a1XMm + c * s.pitchXMm;
            w.yMm = s.a1YMm + r * s.pitchYMm;
            w.depthMm = s.depthMm;
            w.bottomZMm = s.bottomZMm;
            w.shape = s.shape;
            w.diameterMm = s.diameterMm;
            w.sizeXMm = s.sizeXMm;
            w.sizeYMm = s.sizeYMm;
            w.volumeUl = s.volumeUl;
            lw.wells.push_back(w);
        }
    return lw;
}

std::vector<Labware> builtinLabware()
{
    // 96 and 384: ANSI/SLAS 4-2004 positions (A1 14.38/11.24 mm and 12.13/8.99 mm
    // from the left and top edges, pitch 9 and 4.5 mm). 6–48: the Corning
    // Costar plates' published drawings as Opentrons lists them
    // (corning_N_wellplate_*_flat, schema 2), turned into the top-left frame:
    // A1 y = yDimension − y_opentrons. Well sizes, depths and volumes from the same.
    auto spec = [](const char* id, const char* name, int rows, int cols, double x, double y, double pitch, double height,
                   double diameter, double depth, double bottom, double volume) {
        GridSpec s;
        s.id = id;
        s.displayName = name;
        s.brand = "SBS standard";
        s.rows = rows;
        s.columns = cols;
        s.a1XMm = x;
        s.a1YMm = y;
        s.pitchXMm = s.pitchYMm = pitch;
        s.heightMm = height;
        s.diameterMm = diameter;
        s.depthMm = depth;
        s.bottomZMm = bottom;
        s.volumeUl = volume;
        return gridLabware(s);
    };
    return {
        spec("sbs-6", "6-well plate, 16.8 mL", 2, 3, 24.76, 23.19, 39.12, 20.27, 35.43, 17.40, 2.87, 16800),
        spec("sbs-12", "12-well plate, 6.9 mL", 3, 4, 24.94, 16.79, 26.01, 20.02, 22.73, 17.53, 2.49, 6900),
        spec("sbs-24", "24-well plate, 3.4 mL", 4, 6, 17.48, 13.80, 19.30, 20.27, 16.26, 17.40, 2.87, 3400),
        spec("sbs-48", "48-well plate, 1.6 mL", 6, 8, 18.16, 9.99, 13.08, 20.02, 11.56, 17.40, 2.62, 1600),
        spec("sbs-96", "96-well plate, 360 µL", 8, 12, 14.38, 11.24, 9.00, 14.22, 6.86, 10.67, 3.55, 360),
        spec("sbs-384", "384-well plate, 112 µL", 16, 24, 12.13, 8.99, 4.50, 14.22, 3.63, 11.43, 2.79, 112),
    };
}

std::optional<Labware> findBuiltinLabware(const std::string& id)
{
    for (Labware& lw : builtinLabware())
        if (lw.id == id)
            return std::move(lw);
    return std::nullopt;
}

motion::msg::Problems validateLabware(const Labware& lw)
{
    motion::msg::Problems out;
    auto bad = [](double v) { return !std::isfinite(v) || v <= 0; };
    if (lw.id.empty())
        out.push_back({"id", motion::msg::make("plate.empty")});
    if (bad(lw.lengthMm) || lw.lengthMm > 500)
        out.push_back({"length_mm", motion::msg::make("plate.size_out_of_range", {mmArg("value", lw.lengthMm), mmArg("max", 500)})});
    if (bad(lw.widthMm) || lw.widthMm > 500)
        out.push_back({"width_mm", motion::msg::make("plate.size_out_of_range", {mmArg("value", lw.widthMm), mmArg("max", 500)})});
    if (bad(lw.heightMm) || lw.heightMm > 200)
        out.push_back({"height_mm", motion::msg::make("plate.size_out_of_range", {mmArg("value", lw.heightMm), mmArg("max", 200)})});
    if (lw.rows < 1 || lw.rows > kMaxRows || lw.columns < 1 || lw.columns > kMaxColumns)
        out.push_back({"wells", motion::msg::make("plate.labware.grid_size", {motion::msg::integer("max_rows", kMaxRows), motion::msg::integer("max_columns", kMaxColumns),
                                                                      motion::msg::integer("rows", lw.rows), motion::msg::integer("columns", lw.columns)})});
    if (lw.wells.empty())
        out.push_back({"wells", motion::msg::make("plate.labware.no_wells")});
    std::set<WellId> seen;
    for (std::size_t k = 0; k < lw.wells.size(); ++k) {
        const Well& w = lw.wells[k];
        const std::string at = indexPath("wells", k);
        const std::string name = wellName(w.id);
        if (w.id.row >= lw.rows || w.id.column >= lw.columns || w.id.row < 0 || w.id.column < 0)
            out.push_back({at, motion::msg::make("plate.labware.well_outside_grid", {textArg("well", name), motion::msg::integer("rows", lw.rows), motion::msg::integer("columns", lw.columns)})});
        if (!seen.insert(w.id).second)
            out.push_back({at, motion::msg::make("plate.labware.well_twice", {textArg("well", name)})});
        const double rx = w.shape == WellShape::Circular ? w.diameterMm / 2 : w.sizeXMm / 2;
        const double ry = w.shape == WellShape::Circular ? w.diameterMm / 2 : w.sizeYMm / 2;
        if (w.shape == WellShape::Circular ? bad(w.diameterMm) : (bad(w.sizeXMm) || bad(w.sizeYMm)))
            out.push_back({at, motion::msg::make("plate.labware.well_no_size", {textArg("well", name)})});
        if (bad(w.depthMm) || !std::isfinite(w.bottomZMm) || w.bottomZMm < 0 || w.bottomZMm + w.depthMm > lw.heightMm + 1e-6)
            out.push_back({at, motion::msg::make("plate.labware.well_depth", {textArg("well", name), mmArg("bottom", w.bottomZMm), mmArg("depth", w.depthMm),
                                                                      mmArg("height", lw.heightMm)})});
        if (bad(w.volumeUl))
            out.push_back({at, motion::msg::make("plate.labware.well_no_volume", {textArg("well", name)})});
        if (!std::isfinite(w.xMm) || !std::isfinite(w.yMm) || w.xMm - rx < -1e-9 || w.yMm - ry < -1e-9
            || w.xMm + rx > lw.lengthMm + 1e-9 || w.yMm + ry > lw.widthMm + 1e-9)
            out.push_back({at, motion::msg::make("plate.labware.well_off_footprint", {textArg("well", name), mmArg("x", w.xMm), mmArg("y", w.yMm),
                                                                              mmArg("length", lw.lengthMm), mmArg("width", lw.widthMm)})});
        if (out.size() > 50) {
            out.push_back({"wells", motion::msg::make("plate.more_not_shown")});
            break;
        }
    }
    return out;
}

} // namespace motion::plates
