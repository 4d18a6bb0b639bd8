// The simulated camera's images: deterministic for a shot, moving with the work point in
// the camera's geometry, the specimens where docs/camera.md puts them; the tile TIFF and
// the display conversion.
#include "device/camera/display_image.h"
#include "device/camera/sim_render.h"
#include "device/camera/specimen.h"
#include "device/camera/tile_tiff.h"
#include "device/files/scan_run_log.h"
#include "motion/message_print.h"

#include "phase_correlation.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace dev::camera;

namespace {

CameraGeometry smallSensor(int px = 256, double pixelUm = 1.0)
{
    CameraGeometry g;
    g.sensorWidthPx = g.sensorHeightPx = px;
    g.pixelUm = pixelUm;
    return g;
}

const Specimen& slide()
{
    static const Specimen s(SpecimenKind::Slide, 7);
    return s;
}

} // namespace

TEST(SimCameraRender, TheSameShotGivesTheSameImageAndAnotherShotAnother)
{
    const CameraGeometry g = smallSensor(128);
    const SimOptics o;
    const Frame a = renderSimFrame(slide(), g, o, 40.0, 60.0, 10, 3);
    const Frame b = renderSimFrame(slide(), g, o, 40.0, 60.0, 10, 3);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_NE(a.pixels, renderSimFrame(slide(), g, o, 40.0, 60.0, 10, 4).pixels) << "another seed, other noise";
    EXPECT_NE(a.pixels, renderSimFrame(slide(), g, o, 40.0, 60.0, 11, 3).pixels) << "another exposure";
    EXPECT_EQ(a.width, 128);
    EXPECT_EQ(a.format, PixelFormat::Grey16);
    // A specimen built again from its seed is the same specimen.
    const Specimen again(SpecimenKind::Slide, 7);
    EXPECT_EQ(renderSimFrame(again, g, o, 40.0, 60.0, 10, 3).pixels, a.pixels);
    SimOptics eight = o;
    eight.bitDepth = 8;
    const Frame e = renderSimFrame(slide(), g, eight, 40.0, 60.0, 10, 3);
    EXPECT_EQ(e.format, PixelFormat::Grey8);
    EXPECT_EQ(e.pixels.size(), 128u * 128u);
}

TEST(SimCameraRender, TheImageMovesWithTheWorkPointInTheCamerasGeometry)
{
    for (const double rotation : {0.0, 12.0}) {
        for (const bool minusY : {true, false}) {
            CameraGeometry g = smallSensor(256);
            g.rotationDeg = rotation;
            g.imageYAlongMinusY = minusY;
            const double dxMm = 0.041, dyMm = -0.027;  // the stage moves by this between the shots
            const Frame a = renderSimFrame(slide(), g, SimOptics{}, 30.0, 45.0, 10, 1);
            const Frame b = renderSimFrame(slide(), g, SimOptics{}, 30.0 + dxMm, 45.0 + dyMm, 10, 1);
            double exX, exY, eyX, eyY;
            g.axes(&exX, &exY, &eyX, &eyY);
            const double px2 = g.pixelUm * g.pixelUm * 1e-6;
            const double tx = (dxMm * exX + dyMm * exY) / px2, ty = (dxMm * eyX + dyMm * eyY) / px2;
            const camtest::Shift s = camtest::phaseCorrelate(a, b);
            EXPECT_NEAR(s.x, tx, 1.0) << "rotation " << rotation << " minus-y " << minusY;
            EXPECT_NEAR(s.y, ty, 1.0) << "rotation " << rotation << " minus-y " << minusY;
            EXPECT_GT(s.ncc, 0.5);
        }
    }
}

TEST(SimCameraRender, TheSpecimensLieWhereTheDocsSay)
{
    const Specimen plate(SpecimenKind::GridPlate, 1, 0.6);
    const double th = kGridPlateRotationDeg * M_PI / 180;
    // The dot (12, 34) of the plate: turned by the plate's rotation, moved by its offset.
    const double cx = kGridPlateOffsetXMm + 12 * std::cos(th) - 34 * std::sin(th);
    const double cy = kGridPlateOffsetYMm + 12 * std::sin(th) + 34 * std::cos(th);
    EXPECT_NEAR(plate.at(cx, cy), kChromeTransmittance, 1e-3);
    EXPECT_NEAR(plate.at(cx + 0.045, cy), kChromeTransmittance, 1e-3) << "0.1 mm across";
    EXPECT_NEAR(plate.at(cx + 0.056, cy), kGlassTransmittance, 1e-3);
    EXPECT_NEAR(plate.at(cx + 0.5, cy + 0.5), kGlassTransmittance, 1e-3);

    const Specimen scales(SpecimenKind::LineScales, 1, 0.6);
    EXPECT_NEAR(scales.at(12.3, 50.05), kChromeTransmittance, 1e-3) << "a graduation of the X scale";
    EXPECT_NEAR(scales.at(12.35, 50.05), kGlassTransmittance, 1e-3) << "between graduations";
    EXPECT_NEAR(scales.at(12.0, 50.25), kChromeTransmittance, 1e-3) << "every 1 mm a long line";
    EXPECT_NEAR(scales.at(12.1, 50.25), kGlassTransmittance, 1e-3) << "short lines end at 0.15 mm";
    EXPECT_NEAR(scales.at(12.3, 49.9), kGlassTransmittance, 1e-3) << "the lines start at Y = 50 mm";
    EXPECT_NEAR(scales.at(50.05, 37.4), kChromeTransmittance, 1e-3) << "a graduation of the Y scale";
    EXPECT_NEAR(scales.at(50.05, 37.45), kGlassTransmittance, 1e-3);

    EXPECT_NEAR(slide().at(kSlideGlassCentreXMm, kSlideGlassCentreYMm), kGlassTransmittance, 1e-6) << "bare glass";
    double mean = 0;
    for (int k = 0; k < 100; ++k)
        mean += slide().at(20 + 0.013 * k, 40 + 0.007 * k) / 100;
    EXPECT_LT(mean, kGlassTransmittance - 0.05) << "tissue elsewhere";
}

TEST(TileTiff, ATileRoundTripsWithItsPositionAndPixelSize)
{
    QTemporaryDir dir;
    const Frame f = renderSimFrame(slide(), smallSensor(64, 0.65), SimOptics{}, 40.0, 60.0, 10, 1);
    TileMetadata meta;
    meta.tile = 4;
    meta.label = "tile_005.tif";
    meta.measuredMm = {40.0005, 59.9995};
    meta.deviceTimeUs = 123456;
    meta.source = "sim";
    const std::string path = QDir(dir.path()).filePath(QStringLiteral("tile_005.tif")).toStdString();
    std::string sha;
    motion::msg::Message error;
    ASSERT_TRUE(writeTileTiff(path, f, meta, &sha, &error)) << error;
    EXPECT_EQ(sha, fileSha256(path).value_or(""));
    EXPECT_EQ(sha.size(), 64u);
    EXPECT_FALSE(QFile::exists(QString::fromStdString(path + ".part"))) << "the temporary name is gone";
    Frame back;
    std::string description;
    ASSERT_TRUE(readTiff(path, &back, &description, &error)) << error;
    EXPECT_EQ(back.pixels, f.pixels);
    EXPECT_EQ(back.format, PixelFormat::Grey16);
    EXPECT_NEAR(back.pixelUm, 0.65, 1e-4);
    EXPECT_NE(description.find("\"measured_mm\":[40.0005,59.9995]"), std::string::npos) << description;
    EXPECT_NE(description.find("\"device_time_us\":123456"), std::string::npos) << description;
    EXPECT_NE(description.find("\"exposure_ms\":10"), std::string::npos) << description;
    EXPECT_NE(description.find("\"tile\":4"), std::string::npos) << description;

    // A folder that is not there: a clear error naming the file, and nothing left behind.
    const std::string nowhere = QDir(dir.path()).filePath(QStringLiteral("missing/tile.tif")).toStdString();
    EXPECT_FALSE(writeTileTiff(nowhere, f, meta, &sha, &error));
    EXPECT_EQ(error.id, "camera.tiff.cannot_write");
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files).size(), 1);
}

TEST(TileTiff, RgbFramesAreWrittenAsRgb)
{
    QTemporaryDir dir;
    Frame f;
    f.width = 3;
    f.height = 2;
    f.format = PixelFormat::Rgb8;
    f.bitDepth = 8;
    f.pixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    const std::string path = QDir(dir.path()).filePath(QStringLiteral("rgb.tif")).toStdString();
    motion::msg::Message error;
    ASSERT_TRUE(writeTileTiff(path, f, {}, nullptr, &error)) << error;
    Frame back;
    ASSERT_TRUE(readTiff(path, &back, nullptr, &error)) << error;
    EXPECT_EQ(back.format, PixelFormat::Rgb8);
    EXPECT_EQ(back.pixels, f.pixels);
}

TEST(DisplayImage, SixteenBitImagesAreStretchedToWhatIsInThem)
{
    Frame f;
    f.width = 100;
    f.height = 100;
    f.format = PixelFormat::Grey16;
    f.bitDepth = 12;
    f.pixels.resize(2 * 100 * 100);
    for (int i = 0; i < 100 * 100; ++i) {
        const auto v = static_cast<std::uint16_t>(1000 + (i / 4 * 7 % 100) * 10);  // 1000 … 1990 of 4095
        std::memcpy(f.pixels.data() + 2 * i, &v, 2);
    }
    DisplayStretch used;
    const QImage img = toDisplayImage(f, true, &used);
    ASSERT_EQ(img.format(), QImage::Format_Grayscale8);
    EXPECT_EQ(used.low, 1000);
    EXPECT_GE(used.high, 1980);
    EXPECT_EQ(qGray(img.pixel(0, 0)), 0);
    EXPECT_GE(qGray(img.pixel(28, 2)), 250);  // pixel 228 holds 1990: 57 · 7 = 399
    // Without the stretch, 1990 of 12 bits is about half grey.
    const QImage raw = toDisplayImage(f, false);
    EXPECT_NEAR(qGray(raw.pixel(28, 2)), 1990 * 255 / 4095, 1);
}

TEST(ScanRunLogImages, ATilesImageAndChecksumRoundTripAndBadOnesAreRefused)
{
    motion::PositionRecord r;
    r.target = 2;
    r.label = "tile_003.tif";
    r.plannedMm = r.commandedMm = r.measuredMm = {1, 2};
    const std::string sha(64, 'a');
    const std::string text = dev::files::scan::runLogHeader("p", 1, 4) + dev::files::scan::runLogLine(r, {"tile_003.tif", sha});
    const auto log = dev::files::scan::parseRunLog(text);
    ASSERT_TRUE(log.log);
    ASSERT_EQ(log.log->images.size(), 1u);
    EXPECT_EQ(log.log->images[0].file, "tile_003.tif");
    EXPECT_EQ(log.log->images[0].sha256, sha);
    auto bad = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        return !dev::files::scan::parseRunLog(t).log;
    };
    EXPECT_TRUE(bad(sha, "abc")) << "a checksum that is not one";
    EXPECT_TRUE(bad("\"image\":\"tile_003.tif\"", "\"image\":\"../x.tif\"")) << "a file outside the folder";
    EXPECT_TRUE(bad(",\"sha256\":\"" + sha + "\"", "")) << "an image without its checksum";
}
