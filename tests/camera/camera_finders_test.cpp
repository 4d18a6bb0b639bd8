// The line and dot finders (imaging/line_finder.h, imaging/dot_finder.h) on frames of
// the simulated camera's line-scales and grid-plate, rendered at a known true position:
// what a camera reading of a glass scale or a grid plate will see.
#include "device/camera/sim_render.h"
#include "device/camera/specimen.h"
#include "imaging/dot_finder.h"
#include "imaging/line_finder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

using namespace dev::camera;

namespace {

CameraGeometry finderSensor()
{
    CameraGeometry g;
    g.sensorWidthPx = 256;
    g.sensorHeightPx = 256;
    g.pixelUm = 1.0;
    return g;
}

imaging::ImageU16 greyOf(const Frame& f)
{
    imaging::ImageU16 im(f.width, f.height);
    std::memcpy(im.px.data(), f.pixels.data(), im.px.size() * sizeof(std::uint16_t));
    return im;
}

// Where the stage point (xMm, yMm) lies in the image, from the centre, in pixels.
void imageOffsetOf(const CameraGeometry& g, double xMm, double yMm, double workXMm, double workYMm, double* u, double* v)
{
    double exX = 0, exY = 0, eyX = 0, eyY = 0;
    g.axes(&exX, &exY, &eyX, &eyY);
    const double dx = xMm - workXMm, dy = yMm - workYMm;
    const double det = exX * eyY - eyX * exY;
    *u = (dx * eyY - eyX * dy) / det;
    *v = (exX * dy - dx * exY) / det;
}

} // namespace

TEST(CameraFinders, FindTheSimulatedScalesGraduationsWhereTheyAre)
{
    const Specimen scales(SpecimenKind::LineScales, 1, 0.6);
    const CameraGeometry g = finderSensor();
    const SimOptics optics;
    // The X scale's graduation at 12.3 mm, the stage 12.3 µm and a bit to its right.
    {
        const double wx = 12.3 + 0.0123456, wy = 50.075;
        const auto found = imaging::findLine(greyOf(renderSimFrame(scales, g, optics, wx, wy, 10, 1)), {imaging::LineDirection::Vertical});
        ASSERT_TRUE(found.ok()) << found.error().id;
        double u = 0, v = 0;
        imageOffsetOf(g, 12.3, wy, wx, wy, &u, &v);
        std::printf("X scale: line at %.4f px, truth %.4f px\n", found->offsetPx, u);
        EXPECT_NEAR(found->offsetPx, u, 0.1);
        EXPECT_TRUE(found->dark);
    }
    // The Y scale's graduation at 37.4 mm, across the image rows.
    {
        const double wx = 50.075, wy = 37.4 + 0.0217;
        const auto found = imaging::findLine(greyOf(renderSimFrame(scales, g, optics, wx, wy, 10, 2)), {imaging::LineDirection::Horizontal});
        ASSERT_TRUE(found.ok()) << found.error().id;
        double u = 0, v = 0;
        imageOffsetOf(g, wx, 37.4, wx, wy, &u, &v);
        std::printf("Y scale: line at %.4f px, truth %.4f px\n", found->offsetPx, v);
        EXPECT_NEAR(found->offsetPx, v, 0.1);
    }
}

TEST(CameraFinders, FindTheSimulatedGridPlatesDotWhereItIs)
{
    const Specimen plate(SpecimenKind::GridPlate, 1, 0.6);
    const CameraGeometry g = finderSensor();
    const double th = kGridPlateRotationDeg * M_PI / 180;
    // The dot (12, 34) of the plate, the stage a little beside it.
    const double dx = kGridPlateOffsetXMm + 12 * std::cos(th) - 34 * std::sin(th);
    const double dy = kGridPlateOffsetYMm + 12 * std::sin(th) + 34 * std::cos(th);
    const double wx = dx + 0.0133, wy = dy - 0.0071;
    const auto found = imaging::findDot(greyOf(renderSimFrame(plate, g, SimOptics{}, wx, wy, 10, 3)));
    ASSERT_TRUE(found.ok()) << found.error().id;
    double u = 0, v = 0;
    imageOffsetOf(g, dx, dy, wx, wy, &u, &v);
    std::printf("grid plate: dot at (%.4f, %.4f) px, truth (%.4f, %.4f) px\n", found->xPx, found->yPx, u, v);
    EXPECT_NEAR(found->xPx, u, 0.1);
    EXPECT_NEAR(found->yPx, v, 0.1);
    EXPECT_NEAR(found->diameterPx, kGridPlateDotDiameterMm * 1000 / g.pixelUm, 5);
}
