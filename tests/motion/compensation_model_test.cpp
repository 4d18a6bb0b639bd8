// The compensation a device applies: a model maps the position a person asks for
// to the one commanded. Checked against a simulated axis with a known error curve
// and backlash: with the model's command the axis stops on the target.
#include "motion/metrology/compensation/compensation_model.h"
#include "motion/metrology/linear/iso230_2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace motion::metrology;

namespace {

/// An axis whose work point lands at c + e(c)/1000 ∓ b/2000: stopping short by half
/// the lost motion coming from below, overshooting by as much from above.
struct Axis {
    motion::ErrorPolynomial error;
    double backlashUm = 0;
    double stopsAtMm(double commandMm, Direction from) const
    {
        return commandMm + (error.errorUm(commandMm) + (from == Direction::Up ? -backlashUm / 2 : backlashUm / 2)) * 1e-3;
    }
};

const Axis kAxis{{{1.021, 0.6397, 0.0168}}, 6};  // seed 002's Y curve and 6 µm of backlash

std::vector<Reading> measure(const Axis& axis, const std::vector<double>& targets, int cycles)
{
    std::vector<Reading> out;
    for (int c = 1; c <= cycles; ++c)
        for (double t : targets)
            for (Direction d : {Direction::Up, Direction::Down})
                out.push_back({t, d, c, axis.stopsAtMm(t, d) + 1e-5 * ((c % 2) ? 1 : -1)});
    return out;
}

bool has(const motion::msg::Problems& ps, const std::string& id, const std::string& path)
{
    for (const motion::msg::Problem& p : ps)
        if (p.message.id == id && p.path == path)
            return true;
    return false;
}

} // namespace

TEST(CompensationModel, BacklashIsTheNegatedMeanReversal)
{
    const Evaluation e = evaluate(measure(kAxis, {0, 25, 50, 75, 100}, 4));
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(*e.figures.bMeanMm, -0.006, 1e-12) << "from below the axis stops 6 µm short of where it stops from above";
    EXPECT_NEAR(backlashUmFrom(e), 6, 1e-9);
}

TEST(CompensationModel, PolynomialWithBacklashPutsTheAxisOnTheTargetFromBothSides)
{
    const CompensationModel m = polynomialModel("Y", kAxis.error, 0, 100, kAxis.backlashUm);
    EXPECT_TRUE(validate(m).empty());
    for (double target = 0.5; target <= 99.5; target += 3.3)
        for (Direction d : {Direction::Up, Direction::Down})
            EXPECT_NEAR(kAxis.stopsAtMm(m.commandMm(target, d), d), target, 1e-12) << target;
    // Seed 002's Y error at 100 mm is 233 µm, 230 µm from below with half the backlash
    // off, and the slope there (4 µm/mm) takes another 0.4 %: the command is 229.08 µm short.
    EXPECT_NEAR(m.correctionUm(100, Direction::Up), -229.08, 0.01);
    // The two sides differ by the backlash over the slope factor 1 + e′/1000 at 50 mm.
    EXPECT_NEAR(m.commandMm(50, Direction::Up) - m.commandMm(50, Direction::Down), 0.006 / (1 + 2.3197e-3), 1e-7);
    EXPECT_NEAR(m.meanCommandMm(50), (m.commandMm(50, Direction::Up) + m.commandMm(50, Direction::Down)) / 2, 1e-9);
}

TEST(CompensationModel, PolynomialIsHeldAtItsEndsOutsideTheFittedRange)
{
    const CompensationModel m = polynomialModel("X", motion::ErrorPolynomial{{0, 0, 0, 0, 0, 1e-8}}, 0, 100, 0);
    // x⁵·1e-8 is 100 µm at 100 mm but 3.2 mm at 200 mm: beyond the data it is held at 100 µm.
    EXPECT_NEAR(m.correctionUm(200, Direction::Up), -100, 1e-6);
    EXPECT_NEAR(m.correctionUm(-50, Direction::Up), 0, 1e-9);
}

TEST(CompensationModel, TableFromAnEvaluationCancelsTheErrorAtEveryTarget)
{
    const std::vector<double> targets = {0, 12.5, 25, 37.5, 50, 62.5, 75, 87.5, 100};
    const Evaluation e = evaluate(measure(kAxis, targets, 4));
    ASSERT_TRUE(e.ok());
    for (bool perDirection : {false, true}) {
        const CompensationModel m = tableModel("Y", e, perDirection);
        EXPECT_TRUE(validate(m).empty());
        EXPECT_EQ(m.perDirection, perDirection);
        EXPECT_NEAR(m.backlashUm, perDirection ? 0 : 6, 1e-9);
        ASSERT_EQ(m.table.size(), targets.size());
        // The table takes the error as straight between targets. The command for a target
        // lies up to 0.23 mm from it, where the axis's curve has left its chord by
        // c2·δ·(h − δ) ≈ 0.0168 × 0.23 × 12.3 ≈ 0.05 µm; the single column adds the
        // backlash half on a curve of 4 µm/mm, 0.012 µm more. That, not 233 µm, is what is left.
        for (double t : targets)
            for (Direction d : {Direction::Up, Direction::Down})
                EXPECT_NEAR(kAxis.stopsAtMm(m.commandMm(t, d), d), t, 0.07e-3) << t << (perDirection ? " per direction" : "");
        // Between targets, the chord misses the parabola by at most c2·h²/4 (h = 12.5 mm):
        // 0.0168 × 156 / 4 ≈ 0.66 µm.
        EXPECT_LT(std::fabs(kAxis.stopsAtMm(m.commandMm(56.25, Direction::Up), Direction::Up) - 56.25), 0.0007);
    }
    const CompensationModel m = tableModel("Y", e, true);
    EXPECT_NEAR(m.table[4].correctionUpUm - m.table[4].correctionDownUm, 6 / (1 + 2.3197e-3), 0.01);
}

TEST(CompensationModel, SampledTableReproducesThePolynomial)
{
    const CompensationModel m = polynomialModel("Y", kAxis.error, 0, 100, kAxis.backlashUm);
    const auto table = sampleTable(m, {0, 50, 100});
    ASSERT_EQ(table.size(), 3u);
    EXPECT_NEAR(table[1].correctionUpUm, m.correctionUm(50, Direction::Up), 1e-12);
    EXPECT_NEAR(table[1].correctionUpUm - table[1].correctionDownUm, 6 / (1 + 2.3197e-3), 0.001);
}

TEST(CompensationModel, RefusesWhatADeviceCouldNotApply)
{
    CompensationModel m = polynomialModel("X", motion::ErrorPolynomial{{1, 2, 3, 4, 5, 6, 7}}, 10, 10, 0);
    motion::msg::Problems ps = validate(m);
    EXPECT_TRUE(has(ps, "compensation.too_many_coefficients", "polynomial.coefficients_um"));
    EXPECT_TRUE(has(ps, "compensation.range_too_short", "polynomial.valid_to_mm"));
    // Finite coefficients, but a curve no device could follow (found by fuzzing the file reader).
    m = polynomialModel("X", motion::ErrorPolynomial{{0, 0, -1e300}}, 0, 100, 0);
    EXPECT_TRUE(has(validate(m), "compensation.curve_too_large", "polynomial.coefficients_um"));
    m = polynomialModel("X", motion::ErrorPolynomial{{0, 0, -1e308}}, 0, 100, 0);
    EXPECT_TRUE(hasErrors(validate(m))) << "its slope overflows to NaN";
    m = polynomialModel("X", motion::ErrorPolynomial{{0, 150}}, 0, 10, 0);
    EXPECT_TRUE(has(validate(m), "compensation.curve_too_steep", "polynomial.coefficients_um")) << "a 15 % scale error";
    m.kind = CompensationModel::Kind::Table;
    m.table = {{0, 0, 0}, {0.0004, 0, 0}};
    EXPECT_TRUE(has(validate(m), "compensation.nominals_too_close", "table.points[1].nominal_mm")) << "LinuxCNC's nanometres could not keep them apart";
    m.table = {{0, 1, 1}, {0, 2, 2}, {5, std::nan(""), 0}};
    m.perDirection = true;
    m.backlashUm = 3;
    ps = validate(m);
    EXPECT_TRUE(has(ps, "compensation.nominals_not_increasing", "table.points[1].nominal_mm"));
    EXPECT_TRUE(has(ps, "accuracy.value_not_finite", "table.points[2].correction_up_um"));
    EXPECT_TRUE(has(ps, "compensation.backlash_with_directions", "backlash_um"));
    m.table.assign(kMaxTablePoints + 1, TablePoint{});
    for (std::size_t i = 0; i < m.table.size(); ++i)
        m.table[i].nominalMm = static_cast<double>(i);
    m.backlashUm = 0;
    ps = validate(m);
    ASSERT_EQ(ps.size(), 1u);
    EXPECT_EQ(ps[0].message.id, "compensation.too_many_table_points");
    EXPECT_EQ(ps[0].message.integer("max"), 256);
}
