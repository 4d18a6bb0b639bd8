// Teaching a slot: three wells, a restricted least-squares fit, the residual
// that shows a bad teach.
#include "motion/message_print.h"
#include "motion/plans/plates/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion::plates;

namespace {

std::vector<TeachPoint> taught(const PlateTransform& truth, const Labware& lw, double noiseMm = 0, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, noiseMm);
    std::vector<TeachPoint> pts = teachWells(lw);
    for (auto& t : pts) {
        t.machineMm = truth.apply(t.plateMm);
        if (noiseMm > 0) {
            t.machineMm.x += noise(rng);
            t.machineMm.y += noise(rng);
        }
    }
    return pts;
}

} // namespace

TEST(PlateCalibration, TeachesA1TheEndOfRowAAndTheStartOfTheLastRow)
{
    const auto pts = teachWells(*findBuiltinLabware("sbs-96"));
    ASSERT_EQ(pts.size(), 3u);
    EXPECT_EQ(pts[0].well, "A1");
    EXPECT_EQ(pts[1].well, "A12");
    EXPECT_EQ(pts[2].well, "H1");
    EXPECT_NEAR(pts[1].plateMm.x - pts[0].plateMm.x, 99.0, 1e-9);
    EXPECT_NEAR(pts[2].plateMm.y - pts[0].plateMm.y, 63.0, 1e-9);
    EXPECT_EQ(teachWells(*findBuiltinLabware("sbs-384"))[1].well, "A24");
    EXPECT_EQ(teachWells(*findBuiltinLabware("sbs-384"))[2].well, "P1");
}

TEST(PlateCalibration, RecoversOffsetRotationAndScaleExactly)
{
    const Labware lw = *findBuiltinLabware("sbs-96");
    const PlateTransform truth = PlateTransform::make(9.3, 7.1, 0.8, 1.0004, 1.0004);
    motion::msg::Message error;
    const auto fit = fitCalibration(taught(truth, lw), FitModel::Similarity, &error);
    ASSERT_TRUE(fit) << error;
    EXPECT_NEAR(fit->rotationDeg, 0.8, 1e-9);
    EXPECT_NEAR(fit->scaleX, 1.0004, 1e-12);
    EXPECT_NEAR(fit->transform.txMm, 9.3, 1e-9);
    EXPECT_NEAR(fit->transform.tyMm, 7.1, 1e-9);
    EXPECT_LT(fit->maxResidualMm, 1e-9);
    EXPECT_TRUE(fit->warnings.empty());
    // Any well lands where the true transform puts it.
    const PointMm h12 = fit->transform.apply({lw.wellNamed("H12")->xMm, lw.wellNamed("H12")->yMm});
    const PointMm want = truth.apply({lw.wellNamed("H12")->xMm, lw.wellNamed("H12")->yMm});
    EXPECT_NEAR(h12.x, want.x, 1e-9);
    EXPECT_NEAR(h12.y, want.y, 1e-9);
}

TEST(PlateCalibration, ScaledAxesRecoversTwoScales)
{
    const Labware lw = *findBuiltinLabware("sbs-96");
    const PlateTransform truth = PlateTransform::make(12, 110, -1.5, 1.002, 0.997);
    motion::msg::Message error;
    const auto fit = fitCalibration(taught(truth, lw), FitModel::ScaledAxes, &error);
    ASSERT_TRUE(fit) << error;
    EXPECT_NEAR(fit->scaleX, 1.002, 1e-9);
    EXPECT_NEAR(fit->scaleY, 0.997, 1e-9);
    EXPECT_NEAR(fit->rotationDeg, -1.5, 1e-7);
    EXPECT_LT(fit->maxResidualMm, 1e-7);
    // The similarity model cannot follow two scales: it leaves a residual.
    const auto sim = fitCalibration(taught(truth, lw), FitModel::Similarity, &error);
    EXPECT_GT(sim->maxResidualMm, 0.05);
}

TEST(PlateCalibration, TeachingNoiseWithinRepeatabilityGivesNoWarning)
{
    // Seed 000 Table 1: the analyzer repeats XY to 0.2 mm; a careful teach is a
    // few hundredths off.
    const Labware lw = *findBuiltinLabware("sbs-96");
    const PlateTransform truth = PlateTransform::make(8.2, 8.4, 0.3);
    for (unsigned seed = 1; seed <= 20; ++seed) {
        motion::msg::Message error;
        const auto fit = fitCalibration(taught(truth, lw, 0.02, seed), FitModel::Similarity, &error);
        ASSERT_TRUE(fit) << error;
        EXPECT_LT(fit->maxResidualMm, kResidualWarnMm) << "seed " << seed;
        EXPECT_TRUE(fit->warnings.empty()) << motion::msg::debugString(fit->warnings.front());
        EXPECT_NEAR(fit->rotationDeg, 0.3, 0.05);
    }
}

TEST(PlateCalibration, AWellTaughtOffCentreShowsInItsResidual)
{
    const Labware lw = *findBuiltinLabware("sbs-96");
    auto pts = taught(PlateTransform::make(8, 8, 0), lw);
    pts[2].machineMm.y += 1.2;  // H1 taught 1.2 mm toward the front
    motion::msg::Message error;
    const auto fit = fitCalibration(pts, FitModel::Similarity, &error);
    ASSERT_TRUE(fit) << error;
    ASSERT_EQ(fit->residualMm.size(), 3u);
    EXPECT_GT(fit->maxResidualMm, kResidualWarnMm);
    // Least squares shares the 1.2 mm among the points (about 0.5 mm each here):
    // the warning gives all three residuals.
    for (double r : fit->residualMm)
        EXPECT_GT(r, 0.05);
    ASSERT_FALSE(fit->warnings.empty());
    EXPECT_NE(motion::msg::debugString(fit->warnings.front()).find("plate.calibration.large_residual{max=0.51 mm, list=\"A1 0.51, A12 0.27, H1 0.43"),
              std::string::npos)
        << motion::msg::debugString(fit->warnings.front());
}

TEST(PlateCalibration, AFullAffineThroughThreePointsWouldHideThatMistake)
{
    // Why the fit is restricted: six unknowns through three points solve exactly,
    // whatever was taught, so the residual of a full affine is always zero.
    const Labware lw = *findBuiltinLabware("sbs-96");
    auto pts = taught(PlateTransform::make(8, 8, 0), lw);
    pts[2].machineMm.y += 1.2;
    // Solve machine = M·plate + t exactly from the three points.
    const auto& a = pts[0], &b = pts[1], &c = pts[2];
    const double ux = b.plateMm.x - a.plateMm.x, uy = b.plateMm.y - a.plateMm.y;
    const double vx = c.plateMm.x - a.plateMm.x, vy = c.plateMm.y - a.plateMm.y;
    const double det = ux * vy - uy * vx;
    PlateTransform affine;
    affine.m11 = ((b.machineMm.x - a.machineMm.x) * vy - (c.machineMm.x - a.machineMm.x) * uy) / det;
    affine.m12 = ((c.machineMm.x - a.machineMm.x) * ux - (b.machineMm.x - a.machineMm.x) * vx) / det;
    affine.m21 = ((b.machineMm.y - a.machineMm.y) * vy - (c.machineMm.y - a.machineMm.y) * uy) / det;
    affine.m22 = ((c.machineMm.y - a.machineMm.y) * ux - (b.machineMm.y - a.machineMm.y) * vx) / det;
    affine.txMm = a.machineMm.x - affine.m11 * a.plateMm.x - affine.m12 * a.plateMm.y;
    affine.tyMm = a.machineMm.y - affine.m21 * a.plateMm.x - affine.m22 * a.plateMm.y;
    for (const auto& p : pts) {
        const PointMm m = affine.apply(p.plateMm);
        EXPECT_NEAR(std::hypot(m.x - p.machineMm.x, m.y - p.machineMm.y), 0.0, 1e-9);
    }
    motion::msg::Message error;
    EXPECT_GT(fitCalibration(pts, FitModel::Similarity, &error)->maxResidualMm, kResidualWarnMm);
    // With a scale per axis, a point off along its column is taken up by the Y
    // scale: no residual either. That is why Similarity is the default.
    const auto scaled = fitCalibration(pts, FitModel::ScaledAxes, &error);
    EXPECT_LT(scaled->maxResidualMm, 1e-6);
    EXPECT_NEAR(scaled->scaleY, 1 + 1.2 / 63, 1e-6);
}

TEST(PlateCalibration, WarnsAboutTheWrongLabwareAndAPlateNotSeated)
{
    const Labware lw96 = *findBuiltinLabware("sbs-96");
    // Teaching a 384 plate's corner wells while the slot says 96: the points are
    // 103.5 mm apart where 99 were expected.
    const Labware lw384 = *findBuiltinLabware("sbs-384");
    auto pts = teachWells(lw96);
    const auto real = teachWells(lw384);
    for (std::size_t i = 0; i < pts.size(); ++i)
        pts[i].machineMm = {8 + real[i].plateMm.x, 8 + real[i].plateMm.y};
    motion::msg::Message error;
    auto fit = fitCalibration(pts, FitModel::Similarity, &error);
    ASSERT_TRUE(fit);
    bool scaleWarned = false;
    for (const auto& w : fit->warnings)
        scaleWarned = scaleWarned || w.id == "plate.calibration.scale_off";
    EXPECT_TRUE(scaleWarned);

    fit = fitCalibration(taught(PlateTransform::make(20, 5, 6), lw96), FitModel::Similarity, &error);
    ASSERT_TRUE(fit);
    ASSERT_EQ(fit->warnings.size(), 1u);
    EXPECT_EQ(motion::msg::debugString(fit->warnings[0]), "plate.calibration.turned{angle=6°}");
    // Relative to a slot built turned, not to the machine.
    fit = fitCalibration(taught(PlateTransform::make(150, 5, 90), lw96), FitModel::Similarity, &error, 90);
    EXPECT_TRUE(fit->warnings.empty());
}

TEST(PlateCalibration, RefusesPointsThatCannotFixAFit)
{
    motion::msg::Message error;
    EXPECT_FALSE(fitCalibration({}, FitModel::Similarity, &error));
    std::vector<TeachPoint> same = {{"A1", {14.38, 11.24}, {20, 20}}, {"A12", {113.38, 11.24}, {20.2, 20}}};
    EXPECT_FALSE(fitCalibration(same, FitModel::Similarity, &error));
    EXPECT_EQ(error.id, "plate.calibration.too_close");
    std::vector<TeachPoint> line = {{"A1", {0, 0}, {0, 0}}, {"A6", {50, 0}, {50, 0}}, {"A12", {100, 0}, {100, 0}}};
    EXPECT_TRUE(fitCalibration(line, FitModel::Similarity, &error));
    EXPECT_FALSE(fitCalibration(line, FitModel::ScaledAxes, &error));
    EXPECT_EQ(error.id, "plate.calibration.on_one_line");
}
