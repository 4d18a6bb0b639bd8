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

std::string num(double v)
{
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

class Checker {
public:
    explicit Checker(std::vector<PlanProblem>& out) : m_out(out) {}
    void add(std::string field, std::string message) { m_out.push_back({std::move(field), std::move(message)}); }
    /// Finite and inside [lo, hi]; `what` describes the range in words when it is not plain.
    bool range(const std::string& field, double v, double lo, double hi, const std::string& unit = {})
    {
        if (std::isfinite(v) && v >= lo && v <= hi)
            return true;
        add(field, "must be from " + num(lo) + " to " + num(hi) + unit + " (got " + num(v) + unit + ")");
        return false;
    }
    bool positive(const std::string& field, double v, double hi, const std::string& unit = {})
    {
        if (std::isfinite(v) && v > 0 && v <= hi)
            return true;
        add(field, "must be above 0 and at most " + num(hi) + unit + " (got " + num(v) + unit + ")");
        return false;
    }
    bool finitePoint(const std::string& field, Point2 p)
    {
        if (std::isfinite(p.xMm) && std::isfinite(p.yMm) && std::fabs(p.xMm) < 1e6 && std::fabs(p.yMm) < 1e6)
            return true;
        add(field, "must be a finite position in mm");
        return false;
    }

private:
    std::vector<PlanProblem>& m_out;
};

void checkRegion(const Region& r, Checker& c)
{
    switch (r.kind) {
    case RegionKind::Corners: {
        if (!c.finitePoint("region.corners_mm[0]", r.cornerA) || !c.finitePoint("region.corners_mm[1]", r.cornerB))
            return;
        const Rect b = rectFromCorners(r.cornerA, r.cornerB);
        if (b.widthMm() <= 0 || b.heightMm() <= 0)
            c.add("region.corners_mm", "the region has zero size (" + num(b.widthMm()) + " × " + num(b.heightMm())
                                           + " mm): the corners must differ in both X and Y");
        return;
    }
    case RegionKind::CentreSize:
        c.finitePoint("region.centre_mm", r.centre);
        if (!(std::isfinite(r.widthMm) && std::isfinite(r.heightMm) && r.widthMm > 0 && r.heightMm > 0))
            c.add("region.size_mm", "the region has zero size (" + num(r.widthMm) + " × " + num(r.heightMm)
                                        + " mm): width and height must be above 0");
        return;
    case RegionKind::Polygon: {
        if (r.vertices.size() < 3) {
            c.add("region.vertices_mm", "a polygon needs at least 3 vertices (got " + std::to_string(r.vertices.size()) + ")");
            return;
        }
        if (r.vertices.size() > kMaxPolygonVertices) {
            c.add("region.vertices_mm", "at most " + std::to_string(kMaxPolygonVertices) + " vertices (got "
                                            + std::to_string(r.vertices.size()) + ")");
            return;
        }
        bool finite = true;
        for (std::size_t i = 0; i < r.vertices.size(); ++i)
            finite = c.finitePoint("region.vertices_mm[" + std::to_string(i) + "]", r.vertices[i]) && finite;
        if (!finite)
            return;
        if (std::fabs(signedArea(r.vertices)) <= 0) {
            c.add("region.vertices_mm", "the polygon has zero area");
            return;
        }
        if (selfIntersects(r.vertices))
            c.add("region.vertices_mm", "the outline crosses or touches itself; draw it without crossings");
        return;
    }
    }
}

void checkCamera(const Camera& cam, Checker& c)
{
    if (cam.source == FieldSource::Sensor) {
        c.range("camera.sensor_px[0]", cam.sensorWidthPx, 1, 100000, " px");
        c.range("camera.sensor_px[1]", cam.sensorHeightPx, 1, 100000, " px");
        c.positive("camera.sensor_pixel_um", cam.sensorPixelUm, 1000, " µm");
        c.positive("camera.magnification", cam.magnification, 10000);
    } else {
        c.positive("camera.pixel_um", cam.samplePixelUm, 1000, " µm");
    }
    const std::string fieldPath = cam.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm";
    const double w = fieldWidthMm(cam), h = fieldHeightMm(cam);
    if (!(std::isfinite(w) && std::isfinite(h) && w >= 1e-3 && h >= 1e-3))
        c.add(fieldPath, "the field at the sample must be at least 0.001 mm each way (got " + num(w) + " × " + num(h) + " mm)");
    c.range("camera.rotation_deg", cam.rotationDeg, -180, 180, "°");
}

} // namespace

std::vector<PlanProblem> validate(const ScanPlan& plan)
{
    std::vector<PlanProblem> out;
    Checker c(out);
    checkRegion(plan.region, c);
    checkCamera(plan.camera, c);
    // Overlap is a share of the field: at 100 % the next tile would not move on.
    for (int axis = 0; axis < 2; ++axis) {
        const double o = axis == 0 ? plan.overlapX : plan.overlapY;
        if (!(std::isfinite(o) && o >= 0 && o <= kMaxOverlap))
            c.add(axis == 0 ? "overlap[0]" : "overlap[1]",
                  "must be from 0 to 0.9, a share of the field up to 90 % (got " + num(o) + (std::isfinite(o) ? " = " + num(o * 100) + " %)" : ")"));
    }
    if (plan.approach.unidirectional)
        c.positive("approach.overtravel_mm", plan.approach.overtravelMm, 10, " mm");
    c.range("motion.speed_mm_s", plan.speedMmS, 0.01, 1000, " mm/s");
    c.range("timing.settle_s", plan.settleS, 0, 60, " s");
    c.range("timing.exposure_s", plan.exposureS, 0, 3600, " s");
    c.range("timing.tolerance_um", plan.toleranceUm, 0.1, 1000, " µm");
    c.positive("timing.settle_timeout_s", plan.settleTimeoutS, 600, " s");
    if (auto why = checkFilePattern(plan.naming.filePattern))
        c.add("export.file_pattern", *why);
    c.range("export.first_index", plan.naming.firstIndex, 0, 1e6);
    if (plan.naming.mmXyStage.empty() || plan.naming.mmXyStage.find_first_of("\r\n\"") != std::string::npos)
        c.add("export.mm_xy_stage", "must name Micro-Manager's XY stage device (not empty, one line)");
    if (!out.empty())
        return out;
    // Only a sane region and field have a tile count worth stating.
    const GridSize g = gridSize(plan);
    const long tiles = static_cast<long>(g.columns) * static_cast<long>(g.rows);
    if (g.columns > kMaxTiles || g.rows > kMaxTiles || tiles > kMaxTiles)
        c.add(plan.camera.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm",
              "the field is so small for the region that the grid would have "
                  + (g.columns > kMaxTiles || g.rows > kMaxTiles ? std::string("over ") + std::to_string(kMaxTiles)
                                                                 : std::to_string(tiles))
                  + " tiles (at most " + std::to_string(kMaxTiles) + ")");
    return out;
}

std::vector<PlanProblem> validate(const ScanPlan& plan, const StageModel& stage)
{
    std::vector<PlanProblem> out = validate(plan);
    Checker c(out);
    const Rect t = stage.travel;
    const double w = fieldWidthMm(plan.camera), h = fieldHeightMm(plan.camera);
    if (std::isfinite(w) && std::isfinite(h) && (w > t.widthMm() || h > t.heightMm()))
        c.add(plan.camera.source == FieldSource::Sensor ? "camera.sensor_px" : "camera.field_mm",
              "the field " + num(w) + " × " + num(h) + " mm is larger than the stage's travel " + num(t.widthMm()) + " × "
                  + num(t.heightMm()) + " mm");
    const Rect r = regionBounds(plan.region);
    const std::string regionPath = plan.region.kind == RegionKind::Corners
        ? "region.corners_mm"
        : (plan.region.kind == RegionKind::CentreSize ? "region.centre_mm" : "region.vertices_mm");
    if (std::isfinite(r.x0Mm) && std::isfinite(r.x1Mm) && std::isfinite(r.y0Mm) && std::isfinite(r.y1Mm)
        && (r.x0Mm < t.x0Mm - 1e-9 || r.x1Mm > t.x1Mm + 1e-9 || r.y0Mm < t.y0Mm - 1e-9 || r.y1Mm > t.y1Mm + 1e-9))
        c.add(regionPath, "the region X " + num(r.x0Mm) + " … " + num(r.x1Mm) + ", Y " + num(r.y0Mm) + " … " + num(r.y1Mm)
                              + " mm reaches beyond the stage's travel X " + num(t.x0Mm) + " … " + num(t.x1Mm) + ", Y "
                              + num(t.y0Mm) + " … " + num(t.y1Mm) + " mm");
    const double vMax = std::min(stage.maxSpeedMmS[0], stage.maxSpeedMmS[1]);
    if (std::isfinite(plan.speedMmS) && plan.speedMmS > vMax + 1e-9)
        c.add("motion.speed_mm_s", "must be at most the stage's top speed " + num(vMax) + " mm/s (got " + num(plan.speedMmS) + ")");
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
        const std::string what = (wp.tile >= 0 ? "tile " : "the overtravel point before tile ") + std::to_string(tile + 1);
        c.add(wp.tile >= 0 ? regionPath : "approach.overtravel_mm",
              what + " (" + num(p.xMm) + ", " + num(p.yMm) + ") mm lies outside the stage's travel X " + num(t.x0Mm) + " … "
                  + num(t.x1Mm) + ", Y " + num(t.y0Mm) + " … " + num(t.y1Mm) + " mm; move the region inward");
        break;
    }
    return out;
}

} // namespace motion::scan
