// The grid map's decomposition recovers a stage's errors that the fitting code is
// not told: maps are built from motion/metrology/grid/stage_errors.h (the model the
// simulator applies), with a plate lying at an offset and a rotation of its own and
// a dot finder's noise, and the figures are compared with what the errors imply,
// worked out here in closed form.
#include "motion/metrology/grid/compensation_table_2d.h"
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/grid/stage_errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion::metrology;

namespace {

struct Plate {
    double offsetXUm = 0, offsetYUm = 0, rotationUrad = 0;
    double noiseUm = 0;
};

/// What a camera reading a grid plate's dots would report at the nodes: the stage's
/// error at each node, plus the plate's own lie (offset and rotation about the
/// origin), plus noise.
GridMapInput mapOf(const StageErrors& stage, std::size_t n, double pitchMm, const Plate& plate, bool bothWays,
                   std::uint64_t seed = 7)
{
    GridMapInput in;
    for (std::size_t k = 0; k < n; ++k) {
        in.xMm.push_back(static_cast<double>(k) * pitchMm);
        in.yMm.push_back(static_cast<double>(k) * pitchMm);
    }
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0, plate.noiseUm > 0 ? plate.noiseUm : 1e-12);
    auto pass = [&](Direction d, std::vector<double>& ex, std::vector<double>& ey) {
        for (double y : in.yMm)
            for (double x : in.xMm) {
                const ErrorVectorUm e = stageErrorUm(stage, x, y, d, d);
                ex.push_back(e.xUm + plate.offsetXUm - plate.rotationUrad * y * 1e-3 + noise(rng));
                ey.push_back(e.yUm + plate.offsetYUm + plate.rotationUrad * x * 1e-3 + noise(rng));
            }
    };
    pass(Direction::Up, in.exUm, in.eyUm);
    if (bothWays)
        pass(Direction::Down, in.reverseExUm, in.reverseEyUm);
    return in;
}

// Closed forms over a grid symmetric about its middle m (0…L): the least-squares
// slope of c1·t + c2·t² is c1 + 2·c2·m; with the line removed c2·t² leaves a
// parabola whose peak to valley, on a grid with a node at the middle, is |c2|·m².
double slopeOf(const std::vector<double>& c, double m) { return (c.size() > 1 ? c[1] : 0) + (c.size() > 2 ? 2 * c[2] * m : 0); }
double pvOf(const std::vector<double>& c, double m) { return c.size() > 2 ? std::abs(c[2]) * m * m : 0; }

} // namespace

TEST(GridMap, RecoversTheIssuesStageErrorsThroughThePlatesPlacementAndNoise)
{
    StageErrors stage;  // the stage-errors file's example
    stage.x.pitchPolyUm = {0, 0.5, -0.004};
    stage.x.straightnessPolyUm = {0, 0, 0.002};
    stage.y.pitchPolyUm = {0, 0.3};
    stage.y.straightnessPolyUm = {0, 0, -0.003};
    stage.squarenessUrad = 40;
    stage.backlashXUm = 1.5;
    stage.backlashYUm = 2.0;
    const Plate plate{12, -7, 150, 0.05};
    const auto r = analyseGridMap(mapOf(stage, 19, 5, plate, true));
    ASSERT_TRUE(r);
    const double m = 45;
    EXPECT_NEAR(r->figures.scaleXPpm, slopeOf(stage.x.pitchPolyUm, m) * 1e3, 2);  // 140 ppm
    EXPECT_NEAR(r->figures.scaleYPpm, 300, 2);
    // ISO 230-1's squareness is the angle between the two axes' least-squares lines:
    // the straightness curves' own slopes over the travel (0.18 and −0.27 µm/mm) tilt
    // those lines, so 40 + 180 − 270 µrad.
    EXPECT_NEAR(r->figures.squarenessUrad,
                40 + (slopeOf(stage.x.straightnessPolyUm, m) + slopeOf(stage.y.straightnessPolyUm, m)) * 1e3, 5);
    EXPECT_NEAR(r->figures.straightnessXUm, pvOf(stage.x.straightnessPolyUm, m), 0.5);  // 4.05 µm
    EXPECT_NEAR(r->figures.straightnessYUm, pvOf(stage.y.straightnessPolyUm, m), 0.5);  // 6.075 µm
    // Both passes: the backlash is the reversal at every node.
    ASSERT_EQ(r->nodes.size(), 19u * 19u);
    for (const auto& n : r->nodes) {
        ASSERT_TRUE(n.reversalXUm && n.reversalYUm);
        EXPECT_NEAR(*n.reversalXUm, -1.5, 0.3);
        EXPECT_NEAR(*n.reversalYUm, -2.0, 0.3);
    }
    ASSERT_TRUE(r->figures.maxReversalUm);
    EXPECT_NEAR(*r->figures.maxReversalUm, 2.5, 0.3);
}

TEST(GridMap, RecoversRandomStageErrorsItIsNotTold)
{
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> c1(-1, 1), c2(-0.006, 0.006), sq(-200, 200);
    for (int trial = 0; trial < 20; ++trial) {
        StageErrors s;
        s.x.pitchPolyUm = {c1(rng) * 3, c1(rng), c2(rng)};
        s.y.pitchPolyUm = {c1(rng) * 3, c1(rng), c2(rng)};
        s.x.straightnessPolyUm = {0, c1(rng) * 0.2, c2(rng)};
        s.y.straightnessPolyUm = {0, c1(rng) * 0.2, c2(rng)};
        s.squarenessUrad = sq(rng);
        const Plate plate{c1(rng) * 50, c1(rng) * 50, sq(rng) * 5, 0.05};
        const auto r = analyseGridMap(mapOf(s, 19, 5, plate, false, static_cast<std::uint64_t>(trial)));
        ASSERT_TRUE(r);
        SCOPED_TRACE(trial);
        EXPECT_NEAR(r->figures.scaleXPpm, slopeOf(s.x.pitchPolyUm, 45) * 1e3, 2);
        EXPECT_NEAR(r->figures.scaleYPpm, slopeOf(s.y.pitchPolyUm, 45) * 1e3, 2);
        // A straightness's own slope is a rotation of that axis: it joins the squareness.
        EXPECT_NEAR(r->figures.squarenessUrad,
                    s.squarenessUrad + (slopeOf(s.x.straightnessPolyUm, 45) + slopeOf(s.y.straightnessPolyUm, 45)) * 1e3, 5);
        EXPECT_NEAR(r->figures.straightnessXUm, pvOf(s.x.straightnessPolyUm, 45), 0.5);
        EXPECT_NEAR(r->figures.straightnessYUm, pvOf(s.y.straightnessPolyUm, 45), 0.5);
        EXPECT_FALSE(r->figures.maxReversalUm);
    }
}

TEST(GridMap, APerfectStageOnATurnedPlateHasNoError)
{
    const auto r = analyseGridMap(mapOf(StageErrors{}, 5, 10, Plate{30, -20, 800, 0}, false));
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->figures.rmsErrorUm, 0, 1e-9);
    EXPECT_NEAR(r->figures.maxErrorUm, 0, 1e-9);
    EXPECT_NEAR(r->figures.squarenessUrad, 0, 1e-9);
    EXPECT_NEAR(r->placement.rotationUrad, 800, 1e-6);
    EXPECT_NEAR(r->placement.offsetXUm, 30 - 800 * 20 * 1e-3, 1e-6);  // the offset at the grid's centre (20, 20)
}

TEST(GridMap, RmsAndMaxAreTheErrorVectorsLengthsAndTheResidualIsWhatNoLineExplains)
{
    StageErrors s;
    s.x.pitchPolyUm = {0, 0.2};
    s.y.pitchPolyUm = {0, -0.1};
    s.squarenessUrad = 30;
    const auto r = analyseGridMap(mapOf(s, 7, 10, Plate{}, false));
    ASSERT_TRUE(r);
    double sum = 0, mx = 0;
    for (const auto& n : r->nodes) {
        const double l = std::hypot(n.exUm, n.eyUm);
        sum += l * l;
        mx = std::max(mx, l);
    }
    EXPECT_NEAR(r->figures.rmsErrorUm, std::sqrt(sum / 49), 1e-12);
    EXPECT_NEAR(r->figures.maxErrorUm, mx, 1e-12);
    EXPECT_GT(r->figures.rmsErrorUm, 3);
    EXPECT_NEAR(r->figures.rmsResidualUm, 0, 1e-9);  // scales and squareness are all there is
    // A twist (ex growing with x·y) is none of the figures: it stays in the residual.
    GridMapInput twisted = mapOf(StageErrors{}, 7, 10, Plate{}, false);
    for (std::size_t j = 0; j < 7; ++j)
        for (std::size_t i = 0; i < 7; ++i)
            twisted.exUm[j * 7 + i] += 1e-3 * twisted.xMm[i] * twisted.yMm[j];
    const auto t = analyseGridMap(twisted);
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->figures.rmsResidualUm, 1e-3 * 20 * 20, 1e-9);  // 1e-3 · σx · σy
}

TEST(GridMap, RefusesEveryProblemAtOnce)
{
    GridMapInput in;
    in.xMm = {0, 5, 5};
    in.yMm = {0, 5, 10};
    in.exUm.assign(9, 0);
    in.eyUm.assign(8, 0);
    in.exUm[4] = std::nan("");
    in.reverseExUm.assign(9, 0);
    const auto p = validate(in);
    ASSERT_EQ(p.size(), 4u) << motion::msg::debugFormat(p);
    EXPECT_EQ(p[0].path, "x_mm[2]");
    EXPECT_EQ(p[0].message.id, "grid.positions_not_increasing");
    EXPECT_EQ(p[1].path, "ex_um[4]");
    EXPECT_EQ(p[2].path, "ey_um");
    EXPECT_EQ(p[2].message.id, "grid.node_count_wrong");
    EXPECT_EQ(p[3].path, "reverse_ey_um");
    EXPECT_FALSE(analyseGridMap(in));
    GridMapInput small;
    small.xMm = {0, 1};
    small.yMm = {0, 1, 2};
    EXPECT_EQ(validate(small).at(0).message.id, "grid.too_few_nodes");
}

TEST(StageErrors, FollowTheFormulaOfTheFileWithBacklashAgainstTheApproach)
{
    StageErrors s;
    s.x.pitchPolyUm = {0, 0.5, -0.004};
    s.x.straightnessPolyUm = {0, 0, 0.002};
    s.y.pitchPolyUm = {0, 0.3};
    s.y.straightnessPolyUm = {0, 0, -0.003};
    s.squarenessUrad = 40;
    s.backlashXUm = 1.5;
    s.backlashYUm = 2.0;
    // At (10, 20) mm: x: 5 − 0.4 − 1.2 + 0.8 = 4.2 µm; y: 6 + 0.2 = 6.2 µm.
    const auto e = stageErrorUm(s, 10, 20);
    EXPECT_NEAR(e.xUm, 4.2, 1e-12);
    EXPECT_NEAR(e.yUm, 6.2, 1e-12);
    const auto up = stageErrorUm(s, 10, 20, Direction::Up, Direction::Down);
    EXPECT_NEAR(up.xUm, 4.2 - 0.75, 1e-12);
    EXPECT_NEAR(up.yUm, 6.2 + 1.0, 1e-12);
    EXPECT_TRUE(validate(s).empty());
    s.x.pitchPolyUm = {0, 0, 0, 0, 0, 0, 1};
    s.squarenessUrad = std::nan("");
    s.backlashYUm = -1;
    const auto p = validate(s);
    ASSERT_EQ(p.size(), 3u) << motion::msg::debugFormat(p);
    EXPECT_EQ(p[0].message.id, "stage_errors.too_many_coefficients");
    EXPECT_EQ(p[1].path, "squareness_urad");
    EXPECT_EQ(p[2].path, "backlash_um.y");
}

TEST(CompensationTable2D, InterpolatesBilinearlyAndHoldsTheEdge)
{
    CompensationTable2D t;
    t.columns = 2;
    t.rows = 2;
    t.originXMm = 10;
    t.originYMm = 20;
    t.pitchXMm = 10;
    t.pitchYMm = 10;
    t.correctionXUm = {0, 4, 8, 12};  // 0.4·(x − 10) + 0.8·(y − 20)
    t.correctionYUm = {1, 1, 1, 1};
    EXPECT_NEAR(t.correctionAt(15, 25).xUm, 6, 1e-12);
    EXPECT_NEAR(t.correctionAt(12.5, 20).xUm, 1, 1e-12);
    EXPECT_NEAR(t.correctionAt(-100, 25).xUm, 4, 1e-12);  // held at x = 10
    EXPECT_NEAR(t.correctionAt(100, 100).xUm, 12, 1e-12);
    EXPECT_NEAR(t.correctionAt(15, 25).yUm, 1, 1e-12);
    EXPECT_TRUE(validate(t).empty());
    t.columns = 50;
    t.pitchYMm = 0.01;
    const auto p = validate(t);
    ASSERT_EQ(p.size(), 3u) << motion::msg::debugFormat(p);
    EXPECT_EQ(p[0].message.id, "compensation2d.nodes_out_of_range");
    EXPECT_EQ(p[1].path, "grid.pitch_y_mm");
    EXPECT_EQ(p[2].message.id, "compensation2d.node_count_wrong");
}

TEST(CompensationTable2D, FromAMapCancelsTheErrorsAtEveryNodeAndBetween)
{
    StageErrors s;
    s.x.pitchPolyUm = {0, 0.5, -0.004};
    s.x.straightnessPolyUm = {0, 0, 0.002};
    s.y.pitchPolyUm = {0, 0.3};
    s.y.straightnessPolyUm = {0, 0, -0.003};
    s.squarenessUrad = 40;
    const auto before = analyseGridMap(mapOf(s, 19, 5, Plate{}, false));
    ASSERT_TRUE(before);
    const auto table = compensationFromMap(*before);
    ASSERT_TRUE(table);
    EXPECT_TRUE(validate(*table).empty());
    EXPECT_EQ(table->columns, 19);
    EXPECT_NEAR(table->pitchXMm, 5, 1e-12);
    // The stage commanded to n + k(n): the work point lands at n + k + e(n + k). The
    // map's errors are about its placement, so the compensated map is judged the same way.
    GridMapInput after;
    for (int k = 0; k < 19; ++k) {
        after.xMm.push_back(5.0 * k);
        after.yMm.push_back(5.0 * k);
    }
    for (double y : after.yMm)
        for (double x : after.xMm) {
            const auto k = table->correctionAt(x, y);
            const double cx = x + k.xUm * 1e-3, cy = y + k.yUm * 1e-3;
            const auto e = stageErrorUm(s, cx, cy);
            after.exUm.push_back((cx - x) * 1e3 + e.xUm);
            after.eyUm.push_back((cy - y) * 1e3 + e.yUm);
        }
    const auto r = analyseGridMap(after);
    ASSERT_TRUE(r);
    EXPECT_LT(r->figures.rmsErrorUm, before->figures.rmsErrorUm / 5);
    EXPECT_LT(r->figures.maxErrorUm, 0.05);
    // Between nodes the bilinear table leaves only the errors' curvature over a cell:
    // the work point lands where the plate's placement says (k + e = the placement's
    // displacement there), to a few tens of nanometres.
    const GridPlacement& p = before->placement;
    for (const auto& [x, y] : {std::pair{47.5, 47.5}, std::pair{2.5, 87.5}, std::pair{88.0, 1.0}}) {
        const auto k = table->correctionAt(x, y);
        const auto e = stageErrorUm(s, x + k.xUm * 1e-3, y + k.yUm * 1e-3);
        EXPECT_NEAR(k.xUm + e.xUm, p.offsetXUm - p.rotationUrad * (y - p.centreYMm) * 1e-3, 0.05) << x << ", " << y;
        EXPECT_NEAR(k.yUm + e.yUm, p.offsetYUm + p.rotationUrad * (x - p.centreXMm) * 1e-3, 0.05) << x << ", " << y;
    }
}
