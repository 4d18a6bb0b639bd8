// ISO 230-2:2014 evaluation on readings whose answers are worked out by hand
// (docs/accuracy.md shows the same table): every figure to 1e-9 mm, the mirror
// image of a data set (only B̄ changes sign), a data set whose R comes from
// 2s↑ + 2s↓ + |B| rather than from 4s, a unidirectional test, and the refusals.
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/linear/tolerances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace motion::metrology;

namespace {

constexpr double kExact = 1e-9;

/// Deviations in µm per target and direction, cycles 1…n in order.
struct Row {
    double targetMm;
    std::vector<double> upUm;
    std::vector<double> downUm;
};

std::vector<Reading> readingsOf(const std::vector<Row>& rows, double sign = 1)
{
    std::vector<Reading> out;
    for (const Row& r : rows) {
        for (std::size_t j = 0; j < r.upUm.size(); ++j)
            out.push_back({r.targetMm, Direction::Up, static_cast<int>(j + 1), r.targetMm + sign * r.upUm[j] * 1e-3});
        for (std::size_t j = 0; j < r.downUm.size(); ++j)
            out.push_back({r.targetMm, Direction::Down, static_cast<int>(j + 1), r.targetMm + sign * r.downUm[j] * 1e-3});
    }
    return out;
}

// Worked by hand:
//   10 mm  ↑ 1 2 3 µm: x̄ 2, s 1     ↓ 4 6 8: x̄ 6, s 2     x̄ 4    B −4   R = max(2+4+4, 4, 8) = 10
//   20 mm  ↑ −2 0 2:   x̄ 0, s 2     ↓ 0 1 2: x̄ 1, s 1     x̄ 0.5  B −1   R = max(4+2+1, 8, 4) = 8
//   30 mm  ↑ 3 3 3:    x̄ 3, s 0     ↓ 1 3 5: x̄ 3, s 2     x̄ 3    B 0    R = max(0+4+0, 0, 8) = 8
const std::vector<Row> kWorked = {
    {10, {1, 2, 3}, {4, 6, 8}},
    {20, {-2, 0, 2}, {0, 1, 2}},
    {30, {3, 3, 3}, {1, 3, 5}},
};

bool hasProblem(const Evaluation& e, const std::string& id, const std::string& path = {})
{
    for (const motion::msg::Problem& p : e.problems)
        if (p.message.id == id && (path.empty() || p.path == path))
            return true;
    return false;
}

} // namespace

TEST(Iso230_2, WorkedExampleGivesEveryFigureExactly)
{
    const Evaluation e = evaluate(readingsOf(kWorked));
    ASSERT_TRUE(e.ok());
    EXPECT_TRUE(e.bidirectional);
    EXPECT_EQ(e.cycles, 3);
    ASSERT_EQ(e.targets.size(), 3u);

    const TargetStatistics& t1 = e.targets[0];
    EXPECT_NEAR(t1.meanUpMm, 0.002, kExact);
    EXPECT_NEAR(t1.sUpMm, 0.001, kExact);
    EXPECT_NEAR(*t1.meanDownMm, 0.006, kExact);
    EXPECT_NEAR(*t1.sDownMm, 0.002, kExact);
    EXPECT_NEAR(t1.meanMm, 0.004, kExact);
    EXPECT_NEAR(*t1.reversalMm, -0.004, kExact);
    EXPECT_NEAR(t1.rUpMm, 0.004, kExact);
    EXPECT_NEAR(*t1.rDownMm, 0.008, kExact);
    EXPECT_NEAR(*t1.rMm, 0.010, kExact);
    EXPECT_NEAR(*e.targets[1].rMm, 0.008, kExact);
    EXPECT_NEAR(*e.targets[2].rMm, 0.008, kExact);
    EXPECT_NEAR(e.targets[1].meanMm, 0.0005, kExact);

    const Figures& f = e.figures;
    EXPECT_NEAR(f.rUpMm, 0.008, kExact);
    EXPECT_NEAR(*f.rDownMm, 0.008, kExact);
    EXPECT_NEAR(*f.rMm, 0.010, kExact);
    EXPECT_NEAR(*f.bMm, 0.004, kExact);
    EXPECT_NEAR(*f.bMeanMm, -0.005 / 3, kExact);
    EXPECT_NEAR(f.eUpMm, 0.003, kExact);
    EXPECT_NEAR(*f.eDownMm, 0.005, kExact);
    EXPECT_NEAR(*f.eMm, 0.006, kExact);
    EXPECT_NEAR(*f.mMm, 0.0035, kExact);
    EXPECT_NEAR(f.aUpMm, 0.008, kExact);   // max(x̄↑+2s↑) 4 µm at 10 and 20 mm, min(x̄↑−2s↑) −4 µm at 20 mm
    EXPECT_NEAR(*f.aDownMm, 0.011, kExact); // 10 µm at 10 mm, −1 µm at 20 and 30 mm
    EXPECT_NEAR(*f.aMm, 0.014, kExact);    // 10 µm (↓ at 10 mm) − (−4 µm) (↑ at 20 mm)
}

TEST(Iso230_2, RepeatabilityComesFromTheReversalWhenItOutweighsFourSigma)
{
    // At 10 mm: 2s↑ + 2s↓ + |B| = 2 + 4 + 4 = 10 µm, more than R↑ = 4 and R↓ = 8 µm:
    // an evaluation that took R as max 4s would report 8 µm.
    const Evaluation e = evaluate(readingsOf(kWorked));
    const TargetStatistics& t = e.targets[0];
    const double combined = 2 * t.sUpMm + 2 * *t.sDownMm + std::fabs(*t.reversalMm);
    EXPECT_GT(combined, t.rUpMm);
    EXPECT_GT(combined, *t.rDownMm);
    EXPECT_NEAR(*e.figures.rMm, combined, kExact);
    EXPECT_GT(*e.figures.rMm, std::max(e.figures.rUpMm, *e.figures.rDownMm) + 0.0019);
}

TEST(Iso230_2, MirroredDeviationsChangeOnlyTheSignOfTheMeanReversal)
{
    // Every deviation reflected about the target: means change sign, spreads do not,
    // so B̄ changes sign and every range-type figure stays exactly as it was.
    const Evaluation a = evaluate(readingsOf(kWorked)), b = evaluate(readingsOf(kWorked, -1));
    ASSERT_TRUE(a.ok());
    ASSERT_TRUE(b.ok());
    EXPECT_NEAR(*b.figures.bMeanMm, -*a.figures.bMeanMm, kExact);
    EXPECT_NE(*a.figures.bMeanMm, 0.0);
    const Figures &fa = a.figures, &fb = b.figures;
    EXPECT_NEAR(fb.aUpMm, fa.aUpMm, kExact);
    EXPECT_NEAR(*fb.aDownMm, *fa.aDownMm, kExact);
    EXPECT_NEAR(*fb.aMm, *fa.aMm, kExact);
    EXPECT_NEAR(fb.eUpMm, fa.eUpMm, kExact);
    EXPECT_NEAR(*fb.eDownMm, *fa.eDownMm, kExact);
    EXPECT_NEAR(*fb.eMm, *fa.eMm, kExact);
    EXPECT_NEAR(*fb.mMm, *fa.mMm, kExact);
    EXPECT_NEAR(fb.rUpMm, fa.rUpMm, kExact);
    EXPECT_NEAR(*fb.rDownMm, *fa.rDownMm, kExact);
    EXPECT_NEAR(*fb.rMm, *fa.rMm, kExact);
    EXPECT_NEAR(*fb.bMm, *fa.bMm, kExact);
}

TEST(Iso230_2, UnidirectionalTestReportsTheUpFiguresOnly)
{
    std::vector<Row> up = kWorked;
    for (Row& r : up)
        r.downUm.clear();
    const Evaluation e = evaluate(readingsOf(up));
    ASSERT_TRUE(e.ok());
    EXPECT_FALSE(e.bidirectional);
    EXPECT_NEAR(e.figures.aUpMm, 0.008, kExact);
    EXPECT_NEAR(e.figures.eUpMm, 0.003, kExact);
    EXPECT_NEAR(e.figures.rUpMm, 0.008, kExact);
    EXPECT_FALSE(e.figures.aMm || e.figures.aDownMm || e.figures.eMm || e.figures.eDownMm || e.figures.mMm || e.figures.rMm
                 || e.figures.rDownMm || e.figures.bMm || e.figures.bMeanMm);
    EXPECT_FALSE(e.targets[0].reversalMm);
    EXPECT_NEAR(e.targets[1].meanMm, 0.0, kExact) << "x̄i is x̄↑i when there is no ↓";

    // Judged on the ↑ figures, M and B limits skipped.
    AxisTolerances tol;
    tol.aMm = 0.0079;
    tol.rMm = 0.01;
    tol.bMm = 0.001;
    const auto verdicts = judge(e, tol);
    ASSERT_EQ(verdicts.size(), 2u);
    EXPECT_EQ(verdicts[0].figure, "A_up");
    EXPECT_FALSE(verdicts[0].pass);
    EXPECT_EQ(verdicts[1].figure, "R_up");
    EXPECT_TRUE(verdicts[1].pass);
    EXPECT_FALSE(allPass(verdicts));
}

TEST(Iso230_2, SummaryFromTheTableGivesTheSameFigures)
{
    // What a result file keeps (targets, n, means, s) is enough to recompute it all.
    const Evaluation e = evaluate(readingsOf(kWorked));
    std::vector<TargetStatistics> primary;
    for (const TargetStatistics& t : e.targets) {
        TargetStatistics p;
        p.targetMm = t.targetMm;
        p.nUp = t.nUp;
        p.nDown = t.nDown;
        p.meanUpMm = t.meanUpMm;
        p.sUpMm = t.sUpMm;
        p.meanDownMm = t.meanDownMm;
        p.sDownMm = t.sDownMm;
        primary.push_back(p);
    }
    const Evaluation s = summarize(primary, true);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(*s.figures.aMm, *e.figures.aMm);
    EXPECT_EQ(*s.figures.rMm, *e.figures.rMm);
    EXPECT_EQ(*s.figures.bMeanMm, *e.figures.bMeanMm);
    EXPECT_EQ(s.cycles, 3);
    // A unidirectional summary ignores ↓ counts a table may still carry (found by fuzzing).
    primary[0].nDown = 96;
    EXPECT_EQ(summarize(primary, false).cycles, 3);
    std::swap(primary[0], primary[1]);
    EXPECT_TRUE(hasProblem(summarize(primary, true), "accuracy.targets_not_increasing", "targets[1].target_mm"));
}

TEST(Iso230_2, ReadingsInAnyOrderAndTargetsWrittenDifferentlyAreTheSameTest)
{
    std::vector<Reading> r = readingsOf(kWorked);
    std::reverse(r.begin(), r.end());
    r[0].targetMm += 1e-10;  // "30" and "30.0000000001": the same target to the nanometre
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok());
    EXPECT_EQ(e.targets.size(), 3u);
    EXPECT_NEAR(*e.figures.aMm, 0.014, 1e-9);
}

TEST(Iso230_2, RefusesFewerThanTwoCyclesOrTargets)
{
    std::vector<Row> one = {{10, {1}, {2}}, {20, {1}, {2}}};
    Evaluation e = evaluate(readingsOf(one));
    EXPECT_FALSE(e.ok());
    EXPECT_TRUE(hasProblem(e, "accuracy.too_few_cycles"));
    for (const motion::msg::Problem& p : e.problems)
        if (p.message.id == "accuracy.too_few_cycles") {
            EXPECT_EQ(p.message.integer("count"), 1);
            EXPECT_EQ(p.message.integer("min"), 2);
        }
    EXPECT_FALSE(e.figures.aMm);

    e = evaluate(readingsOf({{10, {1, 2, 3}, {2, 3, 4}}}));
    EXPECT_TRUE(hasProblem(e, "accuracy.too_few_targets", "readings"));
    EXPECT_TRUE(e.targets.empty());
    EXPECT_TRUE(hasProblem(evaluate({}), "accuracy.too_few_targets"));
}

TEST(Iso230_2, RefusesNaNDuplicatesMissingDirectionsAndUnequalCycles)
{
    std::vector<Reading> r = readingsOf(kWorked);
    r[4].measuredMm = std::nan("");
    r[7].targetMm = INFINITY;
    Evaluation e = evaluate(r);
    EXPECT_TRUE(hasProblem(e, "accuracy.value_not_finite", "readings[4].measured_mm"));
    EXPECT_TRUE(hasProblem(e, "accuracy.value_not_finite", "readings[7].target_mm"));

    r = readingsOf(kWorked);
    r.push_back(r[1]);
    e = evaluate(r);
    ASSERT_TRUE(hasProblem(e, "accuracy.duplicate_reading", "readings[18]"));
    EXPECT_EQ(e.problems.front().message.integer("first"), 1);

    std::vector<Row> rows = kWorked;
    rows[1].downUm.clear();
    EXPECT_TRUE(hasProblem(evaluate(readingsOf(rows)), "accuracy.direction_missing"));

    rows = kWorked;
    rows[2].upUm.pop_back();
    e = evaluate(readingsOf(rows));
    EXPECT_FALSE(e.ok());
    EXPECT_TRUE(hasProblem(e, "accuracy.cycle_counts_differ"));
    // A run in progress: the same readings are evaluated, with a warning.
    EvaluationOptions live;
    live.allowUnequalCycles = true;
    e = evaluate(readingsOf(rows), live);
    EXPECT_TRUE(e.ok());
    ASSERT_TRUE(hasProblem(e, "accuracy.cycle_counts_differ"));
    EXPECT_TRUE(e.problems.front().isWarning());
    EXPECT_TRUE(e.figures.aMm.has_value());
}
