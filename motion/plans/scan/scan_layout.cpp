#include "motion/plans/scan/scan_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motion::scan {

long tilesAlong(double regionMm, double fieldMm, double overlap)
{
    const double step = fieldMm * (1.0 - overlap);
    const double steps = (regionMm - fieldMm) / step;
    if (!(steps > 0))
        return 1;  // the field covers the region (or the input is unusable: validate() says so)
    if (!std::isfinite(steps) || steps > 1e12)
        return std::numeric_limits<long>::max() / 4;
    // W − F a whole number of steps must not gain a column from rounding in the division.
    const double slack = 1e-9 * std::max(1.0, steps);
    return static_cast<long>(std::ceil(steps - slack)) + 1;
}

GridSize gridSize(const ScanPlan& plan)
{
    const Rect r = regionBounds(plan.region);
    GridSize g;
    g.fieldWidthMm = fieldWidthMm(plan.camera);
    g.fieldHeightMm = fieldHeightMm(plan.camera);
    g.columns = static_cast<int>(std::min<long>(tilesAlong(r.widthMm(), g.fieldWidthMm, plan.overlapX), kMaxTiles + 1));
    g.rows = static_cast<int>(std::min<long>(tilesAlong(r.heightMm(), g.fieldHeightMm, plan.overlapY), kMaxTiles + 1));
    g.stepXMm = g.fieldWidthMm * (1.0 - plan.overlapX);
    g.stepYMm = g.fieldHeightMm * (1.0 - plan.overlapY);
    return g;
}

namespace {

bool startsTop(StartCorner c) { return c == StartCorner::TopLeft || c == StartCorner::TopRight; }
bool startsLeft(StartCorner c) { return c == StartCorner::TopLeft || c == StartCorner::BottomLeft; }

int signOf(double v, double eps) { return v > eps ? 1 : (v < -eps ? -1 : 0); }

/// Grid places in visiting order (row, col), over the kept ones only.
std::vector<std::pair<int, int>> visitingOrder(const ScanPlan& plan, const GridSize& g, const std::vector<char>& kept)
{
    const bool byRows = plan.order == ScanOrder::Rows || plan.order == ScanOrder::SnakeRows;
    const bool snake = plan.order == ScanOrder::SnakeRows || plan.order == ScanOrder::SnakeColumns;
    const int outerCount = byRows ? g.rows : g.columns;
    const int innerCount = byRows ? g.columns : g.rows;
    // Rows count from the top, columns from the left; a start at the bottom or the
    // right walks them backwards.
    const bool outerForward = byRows ? startsTop(plan.start) : startsLeft(plan.start);
    const bool firstInnerForward = byRows ? startsLeft(plan.start) : startsTop(plan.start);
    auto isKept = [&](int outer, int inner) {
        const int row = byRows ? outer : inner;
        const int col = byRows ? inner : outer;
        return kept[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.columns) + static_cast<std::size_t>(col)] != 0;
    };
    std::vector<std::pair<int, int>> order;
    bool innerForward = firstInnerForward;
    int lastInner = -1;  // where the previous line ended, −1 before the first
    for (int o = 0; o < outerCount; ++o) {
        const int outer = outerForward ? o : outerCount - 1 - o;
        int lo = innerCount, hi = -1;
        for (int k = 0; k < innerCount; ++k)
            if (isKept(outer, k)) {
                lo = std::min(lo, k);
                hi = std::max(hi, k);
            }
        if (hi < 0)
            continue;  // a line the polygon left empty
        if (snake && lastInner >= 0) {
            // A snake enters each line at the end nearer to where the last one ended:
            // on a rectangle that is the turn of a serpentine; on a polygon whose lines
            // differ in length it avoids a crossing of the whole line. Ties alternate.
            const int toLo = std::abs(lastInner - lo), toHi = std::abs(hi - lastInner);
            innerForward = toLo == toHi ? !innerForward : toLo < toHi;
        }
        for (int k = 0; k < innerCount; ++k) {
            const int inner = innerForward ? k : innerCount - 1 - k;
            if (!isKept(outer, inner))
                continue;
            order.emplace_back(byRows ? outer : inner, byRows ? inner : outer);
            lastInner = inner;
        }
    }
    return order;
}

} // namespace

ScanLayout layoutScan(const ScanPlan& plan)
{
    ScanLayout out;
    if (!validate(plan).empty())
        return out;
    const GridSize g = gridSize(plan);
    out.grid = g;
    const Rect r = regionBounds(plan.region);
    const Point2 c = r.centre();
    const double gridW = (g.columns - 1) * g.stepXMm + g.fieldWidthMm;
    const double gridH = (g.rows - 1) * g.stepYMm + g.fieldHeightMm;
    out.gridBounds = rectFromCentre(c, gridW, gridH);
    const double firstX = c.xMm - 0.5 * (g.columns - 1) * g.stepXMm;  // column 0, left
    const double firstY = c.yMm + 0.5 * (g.rows - 1) * g.stepYMm;     // row 0, top
    auto centreOf = [&](int row, int col) { return Point2{firstX + col * g.stepXMm, firstY - row * g.stepYMm}; };

    const std::size_t cells = static_cast<std::size_t>(g.columns) * static_cast<std::size_t>(g.rows);
    std::vector<char> kept(cells, 1);
    if (plan.region.kind == RegionKind::Polygon) {
        // Positive overlap area, relative to the field so the test does not depend on units.
        const double minArea = 1e-9 * g.fieldWidthMm * g.fieldHeightMm;
        std::vector<Point2> scratch;
        for (int row = 0; row < g.rows; ++row)
            for (int col = 0; col < g.columns; ++col) {
                const Rect field = rectFromCentre(centreOf(row, col), g.fieldWidthMm, g.fieldHeightMm);
                kept[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.columns) + static_cast<std::size_t>(col)] =
                    intersectionArea(plan.region.vertices, field, &scratch) > minArea;
            }
    }

    const auto order = visitingOrder(plan, g, kept);
    out.tiles.reserve(order.size());
    for (const auto& [row, col] : order)
        out.tiles.push_back({static_cast<int>(out.tiles.size()), row, col, centreOf(row, col)});

    // The approach directions: the way the first line runs and the way lines follow
    // each other (both fixed by the start corner, whichever the order).
    out.approachSignX = startsLeft(plan.start) ? 1 : -1;
    out.approachSignY = startsTop(plan.start) ? -1 : 1;
    out.path.reserve(out.tiles.size() + (plan.approach.unidirectional ? out.tiles.size() / 2 + 1 : 0));
    const double eps = 1e-9 * std::max(g.stepXMm, g.stepYMm);
    int lastX = 0, lastY = 0;  // sign of the last motion per axis; 0 = not known yet
    Point2 at{};
    for (const Tile& t : out.tiles) {
        if (plan.approach.unidirectional) {
            const int dx = t.index == 0 ? 0 : signOf(t.centre.xMm - at.xMm, eps);
            const int dy = t.index == 0 ? 0 : signOf(t.centre.yMm - at.yMm, eps);
            const bool fixX = dx != 0 ? dx != out.approachSignX : lastX != out.approachSignX;
            const bool fixY = dy != 0 ? dy != out.approachSignY : lastY != out.approachSignY;
            if (fixX || fixY) {
                Point2 over = t.centre;
                if (fixX)
                    over.xMm -= out.approachSignX * plan.approach.overtravelMm;
                if (fixY)
                    over.yMm -= out.approachSignY * plan.approach.overtravelMm;
                out.path.push_back({over, -1});
            }
            lastX = out.approachSignX;  // the last move onto the tile runs the approach way
            lastY = out.approachSignY;
        }
        out.path.push_back({t.centre, t.index});
        at = t.centre;
    }
    return out;
}

Point2 overtravelPoint(const ScanLayout& layout, const ScanPlan& plan, Point2 tileCentre)
{
    return {tileCentre.xMm - layout.approachSignX * plan.approach.overtravelMm,
            tileCentre.yMm - layout.approachSignY * plan.approach.overtravelMm};
}

Rect tileField(const ScanLayout& layout, const Tile& tile)
{
    return rectFromCentre(tile.centre, layout.grid.fieldWidthMm, layout.grid.fieldHeightMm);
}

std::uint64_t layoutFingerprint(const ScanPlan& plan, const ScanLayout& layout)
{
    // FNV-1a over whole numbers, so the same tiles give the same value on any machine.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](std::int64_t v) {
        for (int b = 0; b < 8; ++b) {
            h ^= static_cast<std::uint64_t>(v >> (8 * b)) & 0xFFu;
            h *= 1099511628211ull;
        }
    };
    mix(static_cast<std::int64_t>(layout.tiles.size()));
    // With the stage's own compensation the work point lands elsewhere for the same
    // commands: a run of one is not continued as the other.
    if (plan.compensation.enabled)
        mix(-18);
    for (const Tile& t : layout.tiles) {
        const Point2 c = commandedTarget(plan, t.centre);
        mix(t.index);
        mix(t.row);
        mix(t.col);
        auto nm = [](double mm) { return std::isfinite(mm) && std::fabs(mm) < 1e9 ? std::llround(mm * 1e6) : -1; };
        mix(nm(c.xMm));
        mix(nm(c.yMm));
    }
    return h;
}

double pathLengthMm(const ScanLayout& layout)
{
    double sum = 0;
    for (std::size_t i = 1; i < layout.path.size(); ++i)
        sum += std::hypot(layout.path[i].target.xMm - layout.path[i - 1].target.xMm,
                          layout.path[i].target.yMm - layout.path[i - 1].target.yMm);
    return sum;
}

} // namespace motion::scan
