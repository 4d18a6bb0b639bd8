// Axis test definitions (ISO 230-2's standard test): the targets a grid gives,
// the irregular spacing that keeps periodic errors out of phase, the validator's
// refusals and warnings, and the order of the stops a runner visits.
#include "motion/metrology/linear/axis_test.h"
#include "motion/metrology/linear/run_sequence.h"
#include "motion/metrology/contour/xy_line_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <set>

using namespace motion::metrology;

namespace {

/// A copy, so a problem of a temporary list can be kept.
std::optional<motion::msg::Problem> find(const motion::msg::Problems& ps, const std::string& id, const std::string& path = {})
{
    for (const motion::msg::Problem& p : ps)
        if (p.message.id == id && (path.empty() || p.path == path))
            return p;
    return std::nullopt;
}

AxisTest threeTargets()
{
    AxisTest t;
    t.targetsMm = {10, 20, 30};
    t.cycles = 2;
    t.overrunMm = 2;
    return t;
}

} // namespace

TEST(AccuracyDefinition, GridGivesEvenTargetsToTheNanometre)
{
    EXPECT_EQ(gridTargets({10, 90, 9, false}), (std::vector<double>{10, 20, 30, 40, 50, 60, 70, 80, 90}));
    // 0.1 × 3 is 0.30000000000000004 in binary: rounded to the nanometre, it is 0.3.
    EXPECT_EQ(gridTargets({0, 0.3, 4, false})[3], 0.3);
    EXPECT_EQ(gridTargets({0, 0.3, 4, false})[1], 0.1);
}

TEST(AccuracyDefinition, IrregularSpacingSamplesAScrewPitchAtScatteredPhases)
{
    // 41 targets over 0–400 mm: every 10 mm, a whole number of 5 mm screw pitches,
    // so a regular grid sees the pitch error at one phase only.
    const TargetGrid g{0, 400, 41, true};
    const std::vector<double> p = gridTargets(g);
    ASSERT_EQ(p.size(), 41u);
    EXPECT_EQ(p.front(), 0.0);
    EXPECT_EQ(p.back(), 400.0) << "the ends stay where they were asked for";
    std::set<long long> offsetsUm, phases;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        const double r = p[i] - 10.0 * static_cast<double>(i);
        EXPECT_LT(std::fabs(r), 2.5) << "within ±p/4";
        EXPECT_GT(p[i] - p[i - 1], 5.0 - 1e-9) << "at least p/2 apart";
        EXPECT_NEAR(p[i] * 1000, std::round(p[i] * 1000), 1e-6) << "whole micrometres, a target people can type";
        offsetsUm.insert(std::llround(r * 1000));
        phases.insert(std::llround(std::fmod(p[i], 5.0) * 2));  // half-millimetre bins of the 5 mm pitch
    }
    EXPECT_EQ(offsetsUm.size(), 39u) << "no two targets share an offset";
    EXPECT_GE(phases.size(), 9u) << "the pitch is sampled at most of its phases";
    EXPECT_EQ(gridTargets(g), p) << "deterministic: the same file gives the same targets";
    AxisTest t;
    t.grid = g;
    EXPECT_FALSE(hasErrors(validate(t)));
    EXPECT_EQ(targetsOf(t), p);
}

TEST(AccuracyDefinition, RefusesTooFewTargetsOrCyclesAndWarnsBelowIso)
{
    AxisTest t = threeTargets();
    motion::msg::Problems ps = validate(t);
    EXPECT_FALSE(hasErrors(ps));
    const std::optional<motion::msg::Problem> w = find(ps, "accuracy.fewer_cycles_than_iso", "cycles");
    ASSERT_NE(w, std::nullopt);
    EXPECT_TRUE(w->isWarning());
    EXPECT_EQ(w->message.integer("recommended"), 5);
    ASSERT_NE(find(ps, "accuracy.fewer_targets_than_iso", "targets_mm"), std::nullopt);

    t.cycles = 1;
    t.targetsMm = {10};
    ps = validate(t);
    EXPECT_TRUE(hasErrors(ps));
    const std::optional<motion::msg::Problem> c = find(ps, "accuracy.too_few_cycles", "cycles");
    ASSERT_NE(c, std::nullopt);
    EXPECT_FALSE(c->isWarning());
    EXPECT_EQ(c->message.integer("count"), 1);
    EXPECT_EQ(c->message.integer("min"), 2);
    EXPECT_NE(find(ps, "accuracy.too_few_targets", "targets_mm"), std::nullopt);
    EXPECT_TRUE(runSequence(t).empty()) << "no stops for a test with errors";
}

TEST(AccuracyDefinition, RefusesTargetsOutOfOrderNaNAndOutsideTheSoftLimits)
{
    AxisTest t = threeTargets();
    t.targetsMm = {10, 30, 30, std::nan(""), 95};
    AxisLimits limits;
    limits.minMm = 0;
    limits.maxMm = 90;
    motion::msg::Problems ps = validate(t, limits);
    const std::optional<motion::msg::Problem> order = find(ps, "accuracy.targets_not_increasing", "targets_mm[2]");
    ASSERT_NE(order, std::nullopt);
    EXPECT_EQ(order->message.number("previous"), 30);
    EXPECT_NE(find(ps, "accuracy.value_not_finite", "targets_mm[3]"), std::nullopt);

    t.targetsMm = {10, 50, 95};
    ps = validate(t, limits);
    const std::optional<motion::msg::Problem> above = find(ps, "accuracy.target_above_limit", "targets_mm[2]");
    ASSERT_NE(above, std::nullopt);
    EXPECT_EQ(above->message.number("limit"), 90);
    EXPECT_EQ(above->message.arg("value")->unit, motion::msg::Unit::Mm);

    // The overrun goes below the first target: 1 mm − 2 mm is outside a 0 mm limit.
    t.targetsMm = {1, 50, 80};
    ps = validate(t, limits);
    const std::optional<motion::msg::Problem> overrun = find(ps, "accuracy.overrun_below_limit", "overrun_mm");
    ASSERT_NE(overrun, std::nullopt);
    EXPECT_EQ(overrun->message.number("position"), -1);
}

TEST(AccuracyDefinition, RefusesAbsurdFeedsAndContradictorySettling)
{
    AxisTest t = threeTargets();
    t.feedMmS = 0;
    EXPECT_NE(find(validate(t), "accuracy.value_not_positive", "feed_mm_s"), std::nullopt);
    t.feedMmS = 5000;
    const std::optional<motion::msg::Problem> p = find(validate(t), "accuracy.value_above", "feed_mm_s");
    ASSERT_NE(p, std::nullopt);
    EXPECT_EQ(p->message.number("max"), kMaxFeedMmS);
    AxisLimits limits;
    limits.maxFeedMmS = 25;
    t.feedMmS = 30;
    EXPECT_EQ(find(validate(t, limits), "accuracy.value_above", "feed_mm_s")->message.number("max"), 25);
    t.feedMmS = std::nan("");
    EXPECT_NE(find(validate(t), "accuracy.value_not_finite", "feed_mm_s"), std::nullopt);

    t = threeTargets();
    t.settle.windowS = 2;
    t.settle.timeoutS = 1;
    EXPECT_NE(find(validate(t), "accuracy.settle_timeout_below_window", "settle.timeout_s"), std::nullopt);
    t = threeTargets();
    t.tolerances.aMm = -0.1;
    EXPECT_NE(find(validate(t), "accuracy.value_not_positive", "tolerances.a_mm"), std::nullopt);
    t = threeTargets();
    t.axis = "x1";
    EXPECT_NE(find(validate(t), "accuracy.axis_name_invalid", "axis"), std::nullopt);
    t = threeTargets();
    t.grid = TargetGrid{0, 10, 3, false};
    EXPECT_NE(find(validate(t), "accuracy.targets_and_grid", "grid"), std::nullopt);
    t.targetsMm.clear();
    t.grid = TargetGrid{10, 10, 3, false};
    EXPECT_NE(find(validate(t), "accuracy.grid_end_not_after_start", "grid.end_mm"), std::nullopt);
    t.grid = TargetGrid{0, 0.01, 5, false};
    EXPECT_NE(find(validate(t), "accuracy.grid_spacing_too_small", "grid.count"), std::nullopt);
}

TEST(AccuracyDefinition, EveryProblemIsReportedAtOnce)
{
    AxisTest t;
    t.axis = "";
    t.targetsMm = {5, 4};
    t.cycles = 0;
    t.feedMmS = -1;
    t.dwellS = -1;
    t.settle.toleranceUm = 0;
    const motion::msg::Problems ps = validate(t);
    for (const char* path : {"axis", "targets_mm[1]", "cycles", "feed_mm_s", "dwell_s", "settle.tolerance_um"})
        EXPECT_TRUE(std::any_of(ps.begin(), ps.end(), [&](const motion::msg::Problem& p) { return p.path == path && !p.isWarning(); })) << path;
}

TEST(AccuracyDefinition, StandardCycleApproachesEachTargetFromItsSideWithOverrun)
{
    const AxisTest t = threeTargets();
    const std::vector<Stop> s = runSequence(t);
    ASSERT_EQ(s.size(), readingCount(t));
    ASSERT_EQ(s.size(), 12u);  // 3 targets × 2 cycles × 2 directions
    // Cycle 1 ↑: below P1 by the overrun, then 10, 20, 30.
    EXPECT_EQ(s[0].direction, Direction::Up);
    EXPECT_EQ(s[0].targetMm, 10);
    EXPECT_EQ(*s[0].overrunMm, 8);
    EXPECT_EQ(s[0].approachFromMm, 8);
    EXPECT_FALSE(s[1].overrunMm);
    EXPECT_EQ(s[1].approachFromMm, 10);
    EXPECT_EQ(s[2].targetMm, 30);
    // Cycle 1 ↓: past P3 by the overrun, then 30, 20, 10.
    EXPECT_EQ(s[3].direction, Direction::Down);
    EXPECT_EQ(s[3].targetMm, 30);
    EXPECT_EQ(*s[3].overrunMm, 32);
    EXPECT_EQ(s[4].approachFromMm, 30);
    EXPECT_EQ(s[5].targetMm, 10);
    EXPECT_EQ(s[5].targetIndex, 0u);
    // Cycle 2 starts below P1 again.
    EXPECT_EQ(s[6].cycle, 2);
    EXPECT_EQ(*s[6].overrunMm, 8);
    for (const Stop& stop : s) {
        if (stop.direction == Direction::Up)
            EXPECT_LT(stop.approachFromMm, stop.targetMm);
        else
            EXPECT_GT(stop.approachFromMm, stop.targetMm);
    }
}

TEST(AccuracyDefinition, UnidirectionalCycleReturnsBelowTheFirstTarget)
{
    AxisTest t = threeTargets();
    t.bidirectional = false;
    const std::vector<Stop> s = runSequence(t);
    ASSERT_EQ(s.size(), 6u);
    for (const Stop& stop : s)
        EXPECT_EQ(stop.direction, Direction::Up);
    EXPECT_EQ(*s[3].overrunMm, 8);
    EXPECT_EQ(s[3].cycle, 2);
}

TEST(AccuracyDefinition, ReadingsAreCheckedAgainstThePlan)
{
    const AxisTest t = threeTargets();
    std::vector<Reading> r;
    for (const Stop& s : runSequence(t))
        r.push_back({s.targetMm, s.direction, s.cycle, s.targetMm});
    EXPECT_TRUE(checkAgainstPlan(t, r).empty());

    std::vector<Reading> shortRun(r.begin(), r.end() - 1);
    motion::msg::Problems ps = checkAgainstPlan(t, shortRun);
    const std::optional<motion::msg::Problem> count = find(ps, "accuracy.reading_count_wrong", "readings");
    ASSERT_NE(count, std::nullopt);
    EXPECT_EQ(count->message.integer("count"), 11);
    EXPECT_EQ(count->message.integer("expected"), 12);
    const std::optional<motion::msg::Problem> missing = find(ps, "accuracy.reading_missing");
    ASSERT_NE(missing, std::nullopt);
    EXPECT_EQ(missing->message.number("target"), 10);
    EXPECT_EQ(missing->message.integer("cycle"), 2);

    r[4].cycle = 3;
    ps = checkAgainstPlan(t, r);
    EXPECT_NE(find(ps, "accuracy.reading_not_in_plan", "readings[4]"), std::nullopt);
}

TEST(AccuracyDefinition, XyLineTargetsMustLieOnTheLine)
{
    XyLineTest t;
    t.pointsMm = {{30, 40}, {60, 80}, {90, 120}, {120, 160}, {150, 200}};
    EXPECT_FALSE(hasErrors(validate(t)));
    EXPECT_NEAR(lineAngleRad(t.pointsMm), std::atan2(4.0, 3.0), 1e-12);
    t.pointsMm[2].yMm += 0.01;
    const std::optional<motion::msg::Problem> off = find(validate(t), "accuracy.xy.point_off_line", "points_mm[2]");
    ASSERT_NE(off, std::nullopt);
    EXPECT_NEAR(off->message.number("distance"), 0.006, 1e-9);

    XyLineTest line;
    line.fromMm = XyPoint{30, 40};
    line.toMm = XyPoint{150, 200};
    line.count = 5;
    ASSERT_EQ(pointsOf(line).size(), 5u);
    EXPECT_EQ(pointsOf(line)[1].xMm, 60);
    EXPECT_EQ(pointsOf(line)[1].yMm, 80);
    XyLimits limits;
    limits.y.maxMm = 180;
    EXPECT_NE(find(validate(line, limits), "accuracy.target_above_limit", "count.y_mm"), std::nullopt);
    const auto stops = runSequence(line);
    ASSERT_EQ(stops.size(), 25u);
    EXPECT_NEAR(stops[0].overrunMm->xMm, 30 - 0.6, 1e-12);
    EXPECT_NEAR(stops[0].overrunMm->yMm, 40 - 0.8, 1e-12);
}

TEST(AccuracyDefinition, XyLineAlongOneAxisSkipsTheOtherWithAWarning)
{
    const std::vector<XyPoint> targets = {{10, 5}, {20, 5}, {30, 5}};
    std::vector<XyReading> r;
    for (int c = 1; c <= 3; ++c)
        for (std::size_t i = 0; i < 3; ++i)
            r.push_back({i, c, targets[i].xMm + 0.001 * c, 5 + 0.002 * c});
    const XyEvaluation e = evaluate(targets, r);
    EXPECT_TRUE(e.x.ok());
    EXPECT_TRUE(e.contour.ok());
    EXPECT_TRUE(e.y.targets.empty());
    ASSERT_NE(find(e.problems, "accuracy.xy.axis_does_not_move"), std::nullopt);
    EXPECT_EQ(find(e.problems, "accuracy.xy.axis_does_not_move")->message.text("axis"), "Y");
    // Along X, the contour error is the Y deviation.
    EXPECT_NEAR(e.contourMm[0], 0.002, 1e-12);
    r.push_back({7, 1, 0, 0});
    EXPECT_NE(find(evaluate(targets, r).problems, "accuracy.xy.no_such_point", "readings[9]"), std::nullopt);
}
