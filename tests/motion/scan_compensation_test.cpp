// Seed 002's positioning error polynomials (§3.3) and the compensation the scan
// applies with them. The seed's own numbers are checked here: its fitted curves,
// its SSE and R² for X, and how it cancels the error.
#include "motion/calibration/error_polynomial.h"
#include "motion/plans/scan/scan_plan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using motion::ErrorPolynomial;

namespace {

const ErrorPolynomial kSeedX{{1.563, 0.9473, -0.0006}};  // y = −0.0006x² + 0.9473x + 1.563
const ErrorPolynomial kSeedY{{1.021, 0.6397, 0.0168}};   // y = 0.0168x² + 0.6397x + 1.021

/// Σ(ŷ − mean ŷ)² of a fitted curve over the measuring points: for a least-squares
/// fit with a constant term, SST = this + SSE, so R² = this / (this + SSE).
double explainedSumOfSquares(const ErrorPolynomial& e, const std::vector<double>& xs)
{
    double mean = 0;
    for (double x : xs)
        mean += e.errorUm(x);
    mean /= static_cast<double>(xs.size());
    double ssr = 0;
    for (double x : xs)
        ssr += (e.errorUm(x) - mean) * (e.errorUm(x) - mean);
    return ssr;
}

std::vector<double> points(double from, double to, double step)
{
    std::vector<double> xs;
    for (double x = from; x <= to + 1e-9; x += step)
        xs.push_back(x);
    return xs;
}

} // namespace

TEST(SeedCompensation, TheSeedsCurvesAsPrinted)
{
    const motion::scan::Compensation c;
    EXPECT_FALSE(c.enabled) << "compensation is the operator's choice";
    // The curves as printed, at points of the seed's measuring grid.
    EXPECT_NEAR(kSeedX.errorUm(10), 10.976, 1e-9);
    EXPECT_NEAR(kSeedX.errorUm(90), 81.96, 1e-9);
    EXPECT_NEAR(kSeedY.errorUm(10), 9.098, 1e-9);
    EXPECT_NEAR(kSeedY.errorUm(100), 232.991, 1e-9);
}

TEST(SeedCompensation, SeedsXFitStatisticsAgreeWithMeasuringFrom0To100mm)
{
    // Seed 002 §3.2 says it measured "0 ~ 100 mm … from 10 mm to 90 mm every 10 mm"
    // and gives, for X, SSE = 36.41 with R² = 0.9958 (quadratic) and SSE = 39.81 with
    // R² = 0.9954 (straight line). The printed quadratic reproduces both R² only over
    // the eleven points 0, 10, …, 100 mm; over the nine points 10 … 90 mm it would
    // give 0.9924. So the fit used 0 … 100 mm; "10 … 90" describes the inner points.
    const auto eleven = points(0, 100, 10), nine = points(10, 90, 10);
    const double ssr = explainedSumOfSquares(kSeedX, eleven);
    const double sst = ssr + 36.41;
    EXPECT_NEAR(ssr / sst, 0.9958, 0.00005);
    EXPECT_NEAR(1.0 - 39.81 / sst, 0.9954, 0.00005) << "the same data under the straight line";
    const double ssr9 = explainedSumOfSquares(kSeedX, nine);
    EXPECT_NEAR(ssr9 / (ssr9 + 36.41), 0.9924, 0.00005);
    // The straight line's extra SSE is the quadratic term's share it cannot follow:
    // c2²·Σ(x² − its straight-line fit)². 39.81 − 36.41 = 3.40 needs |c2| = 0.00063 on
    // 0 … 100 mm — the printed −0.0006 to its one digit — but 0.00105 on 10 … 90 mm.
    auto quadraticResidual = [](const std::vector<double>& xs) {
        double mx = 0, mq = 0;
        for (double x : xs) {
            mx += x;
            mq += x * x;
        }
        mx /= static_cast<double>(xs.size());
        mq /= static_cast<double>(xs.size());
        double sxx = 0, sxq = 0;
        for (double x : xs) {
            sxx += (x - mx) * (x - mx);
            sxq += (x - mx) * (x * x - mq);
        }
        double r = 0;
        for (double x : xs) {
            const double fit = mq + sxq / sxx * (x - mx);
            r += (x * x - fit) * (x * x - fit);
        }
        return r;
    };
    const double c2Eleven = std::sqrt((39.81 - 36.41) / quadraticResidual(eleven));
    const double c2Nine = std::sqrt((39.81 - 36.41) / quadraticResidual(nine));
    EXPECT_NEAR(c2Eleven, 0.00063, 0.00001);
    EXPECT_LT(std::fabs(c2Eleven - 0.0006), 0.00005) << "rounds to the printed coefficient";
    EXPECT_GT(std::fabs(c2Nine - 0.0006), 0.0004) << "would not";
}

TEST(SeedCompensation, CommandPutsTheWorkPointOnTheTarget)
{
    for (const ErrorPolynomial& e : {kSeedX, kSeedY})
        for (double target = 0.5; target <= 100; target += 4.5) {
            const double c = motion::compensatedCommandMm(e, target);
            EXPECT_NEAR(c + e.errorUm(c) * 1e-3, target, 1e-12) << "target " << target;
        }
}

TEST(SeedCompensation, SeedsOneStepRuleLeavesAlmostAMicrometreOnY)
{
    // §3.1: "the error at 10 mm is +20 µm, so 20 µm worth of pulses are subtracted
    // from the command" — c = target − e(target). The work point then sits at
    // c + e(c), off by e(target) − e(c) ≈ e′·e.
    const double target = 100;
    const double oneStep = target - kSeedY.errorUm(target) * 1e-3;
    const double missUm = (oneStep + kSeedY.errorUm(oneStep) * 1e-3 - target) * 1e3;
    EXPECT_NEAR(missUm, -0.93, 0.01);
    const double newton = motion::compensatedCommandMm(kSeedY, target);
    EXPECT_NEAR((newton + kSeedY.errorUm(newton) * 1e-3 - target) * 1e3, 0.0, 1e-9);
    // The seed's worked example (+20 µm at 10 mm) is illustrative: its own curves give 11.0 (X) and 9.1 µm (Y) there.
    EXPECT_GT(std::fabs(kSeedX.errorUm(10) - 20), 8);
}

TEST(SeedCompensation, ThePlanCommandsWhatItPlansAndLeavesTheCorrectionToTheDevice)
{
    // No error curve in the planner; the stage's own compensation moves the
    // target on the device (tests/integration/scan_run_test.cpp, ScanRun.TheDevicesCompensation…).
    motion::scan::ScanPlan p;
    const motion::scan::Point2 planned{50, 80};
    for (bool on : {false, true}) {
        p.compensation.enabled = on;
        const auto c = motion::scan::commandedTarget(p, planned);
        EXPECT_EQ(c.xMm, 50);
        EXPECT_EQ(c.yMm, 80);
    }
}
