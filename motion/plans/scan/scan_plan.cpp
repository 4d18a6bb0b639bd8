#include "motion/plans/scan/scan_plan.h"

#include "motion/plans/scan/scan_layout.h"
#include "motion/plans/scan/scan_naming.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace motion::scan {

Rect regionBounds(const Region& r)
{
    switch (r.kind) {
    case RegionKind::Corners:
        return rectFromCorners(r.cornerA, r.cornerB);
    case RegionKind::CentreSize:
        return rectFromCentre(r.centre, r.widthMm, r.heightMm);
    case RegionKind::Polygon:
        return boundingBox(r.vertices);
    }
    return {};
}

double fieldWidthMm(const Camera& c)
{
    return c.source == FieldSource::Sensor ? c.sensorWidthPx * c.sensorPixelUm / c.magnification * 1e-3 : c.fieldWidthMm;
}

double fieldHeightMm(const Camera& c)
{
    return c.source == FieldSource::Sensor ? c.sensorHeightPx * c.sensorPixelUm / c.magnification * 1e-3 : c.fieldHeightMm;
}

double pixelAtSampleUm(const Camera& c)
{
    return c.source == FieldSource::Sensor ? c.sensorPixelUm / c.magnification : c.samplePixelUm;
}

Point2 commandedTarget(const ScanPlan& plan, Point2 planned)
{
    (void)plan;  // the device applies its own compensation to what it is sent
    return planned;
}

const char* orderName(ScanOrder o)
{
    switch (o) {
    case ScanOrder::Rows: return "rows";
    case ScanOrder::Columns: return "cols";
    case ScanOrder::SnakeRows: return "snake-rows";
    case ScanOrder::SnakeColumns: return "snake-cols";
    }
    return "?";
}

const char* startCornerName(StartCorner c)
{
    switch (c) {
    case StartCorner::TopLeft: return "top-left";
    case StartCorner::TopRight: return "top-right";
    case StartCorner::BottomLeft: return "bottom-left";
    case StartCorner::BottomRight: return "bottom-right";
    }
    return "?";
}

std::optional<ScanOrder> orderFromName(const std::string& name)
{
    for (ScanOrder o : {ScanOrder::Rows, ScanOrder::Columns, ScanOrder::SnakeRows, ScanOrder::SnakeColumns})
        if (name == orderName(o))
            return o;
    return std::nullopt;
}

std::optional<StartCorner> startCornerFromName(const std::string& name)
{
    for (StartCorner c : {StartCorner::TopLeft, StartCorner::TopRight, StartCorner::BottomLeft, StartCorner::BottomRight})
        if (name == startCornerName(c))
            return c;
    return std::nullopt;
}

namespace {

using motion::msg::Unit;
motion::msg::Arg mm(std::string name, double v) { return motion::msg::real(std::move(name), v, Unit::Mm); }

class Checker {
public:
    explicit Checker(motion::msg::Problems& out) : m_out(out) {}
    void add(std::string field, motion::msg::Message message) { m_out.push_back(motion::msg::error(std::move(field), std::move(message))); }
    /// Finite and inside [lo, hi].
    bool range(const std::string& field, double v, double lo, double hi, Unit unit = Unit::None)
    {
        if (std::isfinite(v) && v >= lo && v <= hi)
            return true;
        add(field, motion::msg::make("scan.out_of_range", {motion::msg::real("value", v, unit), motion::msg::real("min", lo, unit), motion::msg::real("max", hi, unit)}));
        return false;
    }
    bool positive(const std::string& field, double v, double hi, Unit unit = Unit::None)
    {
        if (std::isfinite(v) && v > 0 && v <= hi)
            return true;
        add(field, motion::msg::make("scan.not_positive_or_above", {motion::msg::real("value", v, unit), motion::msg::real("max", hi, unit)}));
        return false;
    }
    bool finitePoint(const std::string& field, Point2 p)
    {
        if (std::isfinite(p.xMm) && std::isfinite(p.yMm) && std::fabs(p.xMm) < 1e6 && std::fabs(p.yMm) < 1e6)
            return true;
        add(field, motion::msg::make("scan.not_a_position"));
        return false;
    }

private:
    motion::msg::Problems& m_out;
};

void checkRegion(const Region& r, Checker& c)
{
    switch (r.kind) {
    case RegionKind::Corners: {
        if (!c.finitePoint("region.corners_mm[0]", r.cornerA) || !c.finitePoint("region.corners_mm[1]", r.cornerB))
            return;
        const Rect b = rectFromCorners(r.cornerA, r.cornerB);
        if (b.widthMm() <= 0 || b.heightMm() <= 0)
            c.add("region.corners_mm", motion::msg::make("scan.region.corners_zero_size", {mm("width", b.widthMm()), mm("height", b.heightMm())}));
        return;
    }
    case RegionKind::CentreSize:
        c.finitePoint("region.centre_mm", r.centre);
        if (!(std::isfinite(r.widthMm) && std::isfinite(r.heightMm) && r.widthMm > 0 && r.heightMm > 0))
            c.add("region.size_mm", motion::msg::make("scan.region.size_zero", {mm("width", r.widthMm), mm("height", r.heightMm)}));
        return;
    case RegionKind::Polygon: {
        if (r.vertices.size() < 3) {
            c.add("region.vertices_mm", motion::msg::make("scan.region.too_few_vertices", {motion::msg::integer("count", static_cast<long long>(r.vertices.size()))}));
            return;
        }
        if (r.vertices.size() > kMaxPolygonVertices) {
            c.add("region.vertices_mm", motion::msg::make("scan.region.too_many_vertices", {motion::msg::integer("max", static_cast<long long>(kMaxPolygonVertices)),
                                                                                     motion::msg::integer("count", static_cast<long long>(r.vertices.size()))}));
            return;
        }
        bool finite = true;
        for (std::size_t i = 0; i < r.vertices.size(); ++i)
            finite = c.finitePoint("region.vertices_mm[" + std::to_string(i) + "]", r.vertices[i]) && finite;
        if (!finite)
            return;
        if (std::fabs(signedArea(r.vertices)) <= 0) {
            c.add("region.vertices_mm", motion::msg::make("scan.region.zero_area"));
            return;
        }
        if (selfIntersects(r.vertices))
            c.add("region.vertices_mm", motion::msg::make("scan.region.self_intersecting"));
        return;
    }
    }
}

void checkCamera(const Camera& cam, Checker& c)
{
    if (cam.source == FieldSource::Sensor) {
        c.range("camera.sensor_px[0]", cam.sensorWidthPx, 1, 100000);
        c.range("camera.sensor_px[1]", cam.sensorHeightPx, 1, 100000);
        c.positive("camera.sensor_pixel_um", cam.sensorPixelUm, 1000, Unit::Um);
        c.positive("camera.magnification", cam.magnification, 10000);
    } else {
        c.positive("camera.pixel_um", cam.samplePixelUm, 1000, Unit::Um);
    }
    const std::string fieldPath = cam.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm";
    const double w = fieldWidthMm(cam), h = fieldHeightMm(cam);
    if (!(std::isfinite(w) && std::isfinite(h) && w >= 1e-3 && h >= 1e-3))
        c.add(fieldPath, motion::msg::make("scan.camera.field_too_small", {mm("min", 1e-3), mm("width", w), mm("height", h)}));
    c.range("camera.rotation_deg", cam.rotationDeg, -180, 180, Unit::Deg);
}

} // namespace

motion::msg::Problems validate(const ScanPlan& plan)
{
    motion::msg::Problems out;
    Checker c(out);
    checkRegion(plan.region, c);
    checkCamera(plan.camera, c);
    // Overlap is a share of the field: at 100 % the next tile would not move on.
    for (int axis = 0; axis < 2; ++axis) {
        const double o = axis == 0 ? plan.overlapX : plan.overlapY;
        if (!(std::isfinite(o) && o >= 0 && o <= kMaxOverlap))
            c.add(axis == 0 ? "overlap[0]" : "overlap[1]",
                  motion::msg::make("scan.overlap_out_of_range", {motion::msg::real("value", o), motion::msg::real("max", kMaxOverlap)}));
    }
    if (plan.approach.unidirectional)
        c.positive("approach.overtravel_mm", plan.approach.overtravelMm, 10, Unit::Mm);
    c.range("motion.speed_mm_s", plan.speedMmS, 0.01, 1000, Unit::MmPerS);
    c.range("timing.settle_s", plan.settleS, 0, 60, Unit::S);
    c.range("timing.exposure_s", plan.exposureS, 0, 3600, Unit::S);
    c.range("timing.tolerance_um", plan.toleranceUm, 0.1, 1000, Unit::Um);
    c.positive("timing.settle_timeout_s", plan.settleTimeoutS, 600, Unit::S);
    if (auto why = checkFilePattern(plan.naming.filePattern))
        c.add("export.file_pattern", *why);
    c.range("export.first_index", plan.naming.firstIndex, 0, 1e6);
    if (plan.naming.mmXyStage.empty() || plan.naming.mmXyStage.find_first_of("\r\n\"") != std::string::npos)
        c.add("export.mm_xy_stage", motion::msg::make("scan.export.bad_stage_name"));
    if (!out.empty())
        return out;
    // Only a sane region and field have a tile count worth stating.
    const GridSize g = gridSize(plan);
    const long tiles = static_cast<long>(g.columns) * static_cast<long>(g.rows);
    if (g.columns > kMaxTiles || g.rows > kMaxTiles || tiles > kMaxTiles)
        c.add(plan.camera.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm",
              g.columns > kMaxTiles || g.rows > kMaxTiles
                  ? motion::msg::make("scan.too_many_tiles_over", {motion::msg::integer("max", kMaxTiles)})
                  : motion::msg::make("scan.too_many_tiles", {motion::msg::integer("count", tiles), motion::msg::integer("max", kMaxTiles)}));
    return out;
}

motion::msg::Problems validate(const ScanPlan& plan, const StageModel& stage)
{
    motion::msg::Problems out = validate(plan);
    Checker c(out);
    const Rect t = stage.travel;
    const double w = fieldWidthMm(plan.camera), h = fieldHeightMm(plan.camera);
    if (std::isfinite(w) && std::isfinite(h) && (w > t.widthMm() || h > t.heightMm()))
        c.add(plan.camera.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm",
              motion::msg::make("scan.field_larger_than_travel", {mm("width", w), mm("height", h), mm("travel_x", t.widthMm()), mm("travel_y", t.heightMm())}));
    const Rect r = regionBounds(plan.region);
    const std::string regionPath = plan.region.kind == RegionKind::Corners
        ? "region.corners_mm"
        : (plan.region.kind == RegionKind::CentreSize ? "region.centre_mm" : "region.vertices_mm");
    if (std::isfinite(r.x0Mm) && std::isfinite(r.x1Mm) && std::isfinite(r.y0Mm) && std::isfinite(r.y1Mm)
        && (r.x0Mm < t.x0Mm - 1e-9 || r.x1Mm > t.x1Mm + 1e-9 || r.y0Mm < t.y0Mm - 1e-9 || r.y1Mm > t.y1Mm + 1e-9))
        c.add(regionPath, motion::msg::make("scan.region_beyond_travel", {mm("x0", r.x0Mm), mm("x1", r.x1Mm), mm("y0", r.y0Mm), mm("y1", r.y1Mm),
                                                                  mm("tx0", t.x0Mm), mm("tx1", t.x1Mm), mm("ty0", t.y0Mm), mm("ty1", t.y1Mm)}));
    const double vMax = std::min(stage.maxSpeedMmS[0], stage.maxSpeedMmS[1]);
    if (std::isfinite(plan.speedMmS) && plan.speedMmS > vMax + 1e-9)
        c.add("motion.speed_mm_s", motion::msg::make("scan.speed_above_stage", {motion::msg::real("value", plan.speedMmS, Unit::MmPerS), motion::msg::real("max", vMax, Unit::MmPerS)}));
    if (!out.empty())
        return out;
    // Every point the stage is sent to (overtravel points and tiles) must be inside the
    // travel, not only the region: name the first one that is not.
    const ScanLayout layout = layoutScan(plan);
    for (std::size_t k = 0; k < layout.path.size(); ++k) {
        const Waypoint& wp = layout.path[k];
        const Point2 p = commandedTarget(plan, wp.target);
        if (p.xMm >= t.x0Mm - 1e-9 && p.xMm <= t.x1Mm + 1e-9 && p.yMm >= t.y0Mm - 1e-9 && p.yMm <= t.y1Mm + 1e-9)
            continue;
        // An overtravel point always comes right before its tile.
        const int tile = wp.tile >= 0 ? wp.tile : (k + 1 < layout.path.size() ? layout.path[k + 1].tile : 0);
        c.add(wp.tile >= 0 ? regionPath : "approach.overtravel_mm",
              motion::msg::make(wp.tile >= 0 ? "scan.tile_outside_travel" : "scan.overtravel_outside_travel",
                        {motion::msg::integer("tile", tile + 1, Unit::None), mm("x", p.xMm), mm("y", p.yMm), mm("tx0", t.x0Mm), mm("tx1", t.x1Mm),
                         mm("ty0", t.y0Mm), mm("ty1", t.y1Mm)}));
        break;
    }
    return out;
}

} // namespace motion::scan
