// The stitching scan's tile grid: the count rule, centring, overlap between
// neighbours in every order and from every corner, polygon clipping, the
// unidirectional approach, and which order travels least.
#include "motion/plans/scan/scan_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace motion::scan;

namespace {

ScanPlan rectPlan(double x0, double y0, double x1, double y1, double fieldW, double fieldH, double ox, double oy)
{
    ScanPlan p;
    p.region.kind = RegionKind::Corners;
    p.region.cornerA = {x0, y0};
    p.region.cornerB = {x1, y1};
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = fieldW;
    p.camera.fieldHeightMm = fieldH;
    p.overlapX = ox;
    p.overlapY = oy;
    return p;
}

const ScanOrder kOrders[] = {ScanOrder::Rows, ScanOrder::Columns, ScanOrder::SnakeRows, ScanOrder::SnakeColumns};
const StartCorner kCorners[] = {StartCorner::TopLeft, StartCorner::TopRight, StartCorner::BottomLeft, StartCorner::BottomRight};

double overlapShare(double a0, double a1, double b0, double b1, double field)
{
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)) / field;
}

std::string what(const ScanPlan& p)
{
    return std::string(orderName(p.order)) + " from " + startCornerName(p.start);
}

} // namespace

TEST(ScanGrid, TileCountFollowsTheRule)
{
    // n = max(1, ceil((W − F) / (F(1 − o))) + 1)
    EXPECT_EQ(tilesAlong(10, 1, 0.1), 11);     // (10 − 1)/0.9 = 10 steps exactly: no extra column from rounding
    EXPECT_EQ(tilesAlong(10.0001, 1, 0.1), 12);
    EXPECT_EQ(tilesAlong(9.9999, 1, 0.1), 11);
    EXPECT_EQ(tilesAlong(1, 1, 0.5), 1);        // the field covers the region
    EXPECT_EQ(tilesAlong(0.3, 1, 0.5), 1);
    EXPECT_EQ(tilesAlong(1.01, 1, 0.5), 2);
    EXPECT_EQ(tilesAlong(25, 2, 0), 13);        // 23/2 = 11.5 → 12 steps
    EXPECT_EQ(tilesAlong(99.11, 1.1, 0.1), 100);
}

TEST(ScanGrid, GridIsCentredOnTheRegionAndCoversIt)
{
    for (double o : {0.0, 0.1, 0.25, 0.5, 0.9}) {
        const ScanPlan p = rectPlan(12.3, 20.1, 31.7, 27.4, 1.7, 1.2, o, o / 2);
        const ScanLayout l = layoutScan(p);
        ASSERT_FALSE(l.tiles.empty());
        const Rect r = regionBounds(p.region);
        EXPECT_NEAR(l.gridBounds.centre().xMm, r.centre().xMm, 1e-9);
        EXPECT_NEAR(l.gridBounds.centre().yMm, r.centre().yMm, 1e-9);
        // Covers the region, overhanging by less than half a step on each side.
        EXPECT_LE(l.gridBounds.x0Mm, r.x0Mm + 1e-9);
        EXPECT_GE(l.gridBounds.x1Mm, r.x1Mm - 1e-9);
        EXPECT_LT(r.x0Mm - l.gridBounds.x0Mm, 0.5 * l.grid.stepXMm + 1e-9);
        EXPECT_LT(r.y0Mm - l.gridBounds.y0Mm, 0.5 * l.grid.stepYMm + 1e-9);
        EXPECT_EQ(static_cast<int>(l.tiles.size()), l.grid.columns * l.grid.rows);
        for (const Tile& t : l.tiles)
            EXPECT_TRUE(r.contains(t.centre)) << "a field centre outside the region: the stage would leave it";
    }
}

TEST(ScanGrid, ConsecutiveTilesOverlapByTheAskedShareInEveryOrder)
{
    // Must hold: neighbours in the visiting order overlap by the share asked for, within 0.1 %.
    struct Case { double w, h, ox, oy; bool polygon; };
    const Case cases[] = {{1.0, 1.0, 0.1, 0.1, false}, {1.3312, 0.9984, 0.2, 0.15, false}, {2.5, 0.7, 0.0, 0.37, false},
                          {0.45, 0.45, 0.9, 0.9, false}, {1.2, 0.8, 0.3, 0.3, true}};
    for (const Case& c : cases)
        for (ScanOrder order : kOrders)
            for (StartCorner start : kCorners) {
                ScanPlan p = rectPlan(20, 30, 34.2, 39.9, c.w, c.h, c.ox, c.oy);
                if (c.polygon) {
                    p.region.kind = RegionKind::Polygon;
                    p.region.vertices = {{20, 30}, {34.2, 31}, {30, 39.9}, {26, 34}, {21, 39}};
                }
                p.order = order;
                p.start = start;
                const ScanLayout l = layoutScan(p);
                ASSERT_GT(l.tiles.size(), 4u) << what(p);
                int neighbours = 0;
                for (std::size_t k = 1; k < l.tiles.size(); ++k) {
                    const Tile& a = l.tiles[k - 1];
                    const Tile& b = l.tiles[k];
                    const Rect fa = tileField(l, a), fb = tileField(l, b);
                    const bool sideBySide = a.row == b.row && std::abs(a.col - b.col) == 1;
                    const bool stacked = a.col == b.col && std::abs(a.row - b.row) == 1;
                    if (!sideBySide && !stacked)
                        continue;  // a line change of a raster order: not neighbours
                    ++neighbours;
                    const double ox = overlapShare(fa.x0Mm, fa.x1Mm, fb.x0Mm, fb.x1Mm, c.w);
                    const double oy = overlapShare(fa.y0Mm, fa.y1Mm, fb.y0Mm, fb.y1Mm, c.h);
                    if (sideBySide) {
                        EXPECT_NEAR(ox, c.ox, 0.001) << what(p) << " tiles " << k << "/" << k + 1;
                        EXPECT_NEAR(oy, 1.0, 1e-9);
                    } else {
                        EXPECT_NEAR(oy, c.oy, 0.001) << what(p) << " tiles " << k << "/" << k + 1;
                        EXPECT_NEAR(ox, 1.0, 1e-9);
                    }
                }
                EXPECT_GT(neighbours, static_cast<int>(l.tiles.size()) / 2) << what(p);
                if (!c.polygon && (order == ScanOrder::SnakeRows || order == ScanOrder::SnakeColumns)) {
                    EXPECT_EQ(neighbours, static_cast<int>(l.tiles.size()) - 1) << "a snake only ever steps to a neighbour";
                }
            }
}

TEST(ScanGrid, EveryOrderVisitsEveryTileOnceFromTheAskedCorner)
{
    for (ScanOrder order : kOrders)
        for (StartCorner start : kCorners) {
            ScanPlan p = rectPlan(10, 10, 16, 13, 1, 1, 0.1, 0.1);
            p.order = order;
            p.start = start;
            const ScanLayout l = layoutScan(p);
            ASSERT_EQ(l.grid.columns, 7);
            ASSERT_EQ(l.grid.rows, 4);
            std::set<std::pair<int, int>> seen;
            for (std::size_t k = 0; k < l.tiles.size(); ++k) {
                EXPECT_EQ(l.tiles[k].index, static_cast<int>(k));
                seen.insert({l.tiles[k].row, l.tiles[k].col});
            }
            EXPECT_EQ(seen.size(), 28u) << what(p);
            const Tile& first = l.tiles.front();
            const bool top = start == StartCorner::TopLeft || start == StartCorner::TopRight;
            const bool left = start == StartCorner::TopLeft || start == StartCorner::BottomLeft;
            EXPECT_EQ(first.row, top ? 0 : 3) << what(p);
            EXPECT_EQ(first.col, left ? 0 : 6) << what(p);
            // Row 0 is the top (stage +Y); column 0 the left (stage −X).
            const Tile& second = l.tiles[1];
            if (order == ScanOrder::Rows || order == ScanOrder::SnakeRows)
                EXPECT_EQ(second.centre.xMm - first.centre.xMm > 0, left) << what(p);
            else
                EXPECT_EQ(second.centre.yMm - first.centre.yMm < 0, top) << what(p);
        }
}

TEST(ScanGrid, SnakeTravelsLeastOnAWideRegion)
{
    // Must hold: on a wide region the snake's total travel is the shortest of the orders.
    for (StartCorner start : kCorners) {
        double travel[4];
        for (int k = 0; k < 4; ++k) {
            ScanPlan p = rectPlan(5, 40, 95, 52, 2, 2, 0.1, 0.1);  // 90 × 12 mm: 50 × 7 tiles
            p.order = kOrders[k];
            p.start = start;
            travel[k] = pathLengthMm(layoutScan(p));
        }
        const double rows = travel[0], cols = travel[1], snakeRows = travel[2], snakeCols = travel[3];
        EXPECT_LT(snakeRows, rows) << startCornerName(start);
        EXPECT_LT(snakeRows, cols) << startCornerName(start);
        EXPECT_LE(snakeRows, snakeCols + 1e-9) << startCornerName(start);
        // With equal steps both snakes take (tiles − 1) single steps: a tie, not a loss.
        EXPECT_NEAR(snakeRows, snakeCols, 1e-6);
        EXPECT_NEAR(snakeRows, (50 * 7 - 1) * 1.8, 1e-6);
        // A raster returns across the region after every line: rows cost 7 such returns.
        EXPECT_GT(rows, snakeRows + 6 * 49 * 1.8 * 0.9);
    }
}

TEST(ScanGrid, SnakeAlongTheShorterStepWhenStepsDiffer)
{
    // snakeRows − snakeCols = (sx − sy)(nx − 1)(ny − 1) whatever the region's shape
    // (docs/scan.md): with a field wider than tall, snaking by columns travels less.
    ScanPlan p = rectPlan(5, 40, 95, 52, 2.0, 1.0, 0.1, 0.1);
    p.order = ScanOrder::SnakeRows;
    const ScanLayout a = layoutScan(p);
    p.order = ScanOrder::SnakeColumns;
    const ScanLayout b = layoutScan(p);
    const double expected = (a.grid.stepXMm - a.grid.stepYMm) * (a.grid.columns - 1) * (a.grid.rows - 1);
    EXPECT_NEAR(pathLengthMm(a) - pathLengthMm(b), expected, 1e-6);
    EXPECT_GT(expected, 0);
}

TEST(ScanGrid, PolygonKeepsTheFieldsItOverlaps)
{
    // A right triangle over a 10 × 10 grid of 1 mm fields with no overlap: the field at
    // (col, row from the bottom) overlaps x + y < 10 with positive area iff col + row < 10.
    ScanPlan p = rectPlan(0, 0, 10, 10, 1, 1, 0, 0);
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{10, 10}, {20, 10}, {10, 20}};
    const ScanLayout l = layoutScan(p);
    ASSERT_EQ(l.grid.columns, 10);
    ASSERT_EQ(l.grid.rows, 10);
    EXPECT_EQ(l.tiles.size(), 55u);  // 10 + 9 + … + 1: a field touching the hypotenuse at one corner is left out
    for (const Tile& t : l.tiles) {
        const int fromBottom = 9 - t.row;
        EXPECT_LT(t.col + fromBottom, 10) << "row " << t.row << " col " << t.col;
    }
}

TEST(ScanGrid, AFieldHoldingTheWholePolygonIsKept)
{
    ScanPlan p = rectPlan(0, 0, 1, 1, 2, 2, 0.1, 0.1);
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{50, 50}, {50.4, 50.1}, {50.2, 50.3}};
    const ScanLayout l = layoutScan(p);
    ASSERT_EQ(l.tiles.size(), 1u);
    EXPECT_NEAR(l.tiles[0].centre.xMm, 50.2, 1e-12);
    EXPECT_NEAR(l.tiles[0].centre.yMm, 50.15, 1e-12);
}

TEST(ScanGrid, ConcavePolygonLeavesItsNotchEmptyAndSnakeSkipsIt)
{
    // An L: the notch (upper right quarter) has no tissue, so no field there.
    ScanPlan p = rectPlan(0, 0, 1, 1, 1, 1, 0, 0);
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{10, 10}, {20, 10}, {20, 15}, {15, 15}, {15, 20}, {10, 20}};
    p.order = ScanOrder::SnakeRows;
    const ScanLayout l = layoutScan(p);
    EXPECT_EQ(l.tiles.size(), 75u);  // 100 fields less the 5 × 5 notch
    for (const Tile& t : l.tiles)
        EXPECT_FALSE(t.centre.xMm > 15 && t.centre.yMm > 15) << "a field in the notch";
    for (std::size_t k = 1; k < l.tiles.size(); ++k)
        EXPECT_LE(std::abs(l.tiles[k].row - l.tiles[k - 1].row), 1) << "the snake skipped a row at tile " << k;
    // Each line starts at the end nearer the last tile: into the wide part of the L
    // the snake steps 4.1 mm back to the left edge instead of crossing to the right one.
    double longest = 0;
    for (std::size_t k = 1; k < l.tiles.size(); ++k)
        longest = std::max(longest, std::hypot(l.tiles[k].centre.xMm - l.tiles[k - 1].centre.xMm,
                                               l.tiles[k].centre.yMm - l.tiles[k - 1].centre.yMm));
    EXPECT_NEAR(longest, std::hypot(4, 1), 1e-9);
    p.order = ScanOrder::Rows;
    EXPECT_LT(pathLengthMm(l), pathLengthMm(layoutScan(p)));
}

TEST(ScanGrid, UnidirectionalApproachReachesEveryTileTheSameWay)
{
    for (ScanOrder order : kOrders)
        for (StartCorner start : kCorners) {
            ScanPlan p = rectPlan(30, 30, 36, 34, 1, 1, 0.2, 0.2);
            p.order = order;
            p.start = start;
            p.approach.unidirectional = true;
            p.approach.overtravelMm = 0.3;
            const ScanLayout l = layoutScan(p);
            ASSERT_FALSE(l.path.empty());
            EXPECT_EQ(l.path.front().tile, -1) << "the first tile is approached from its overtravel point";
            int lastX = 0, lastY = 0;
            for (std::size_t k = 1; k < l.path.size(); ++k) {
                const double dx = l.path[k].target.xMm - l.path[k - 1].target.xMm;
                const double dy = l.path[k].target.yMm - l.path[k - 1].target.yMm;
                if (std::fabs(dx) > 1e-9)
                    lastX = dx > 0 ? 1 : -1;
                if (std::fabs(dy) > 1e-9)
                    lastY = dy > 0 ? 1 : -1;
                if (l.path[k].tile < 0)
                    continue;
                EXPECT_EQ(lastX, l.approachSignX) << what(p) << " tile " << l.path[k].tile;
                EXPECT_EQ(lastY, l.approachSignY) << what(p) << " tile " << l.path[k].tile;
            }
        }
}

TEST(ScanGrid, UnidirectionalRowsAddOneOvertravelPerRow)
{
    ScanPlan p = rectPlan(30, 30, 36, 34, 1, 1, 0.2, 0.2);
    p.order = ScanOrder::Rows;
    p.approach.unidirectional = true;
    const ScanLayout l = layoutScan(p);
    EXPECT_EQ(l.path.size(), l.tiles.size() + static_cast<std::size_t>(l.grid.rows));
    p.approach.unidirectional = false;
    EXPECT_EQ(layoutScan(p).path.size(), l.tiles.size());
}
