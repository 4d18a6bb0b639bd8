// Flat-field correction (imaging/flat_field.h): a vignetted camera's tiles divided by
// its blank image come back to the scene's own brightness, a stitched mosaic loses
// the repeating dark corners, and a blank that cannot serve is refused naming it.
#include "grid.h"
#include "imaging/flat_field.h"
#include "imaging/stitch.h"
#include "imaging/tiff_read.h"
#include "imaging/tiff_write.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace {

/// Light falling to 55 % at the corners, as a widefield microscope's often does.
double vignette(int x, int y, int w, int h)
{
    const double dx = (x - (w - 1) / 2.0) / (w / 2.0), dy = (y - (h - 1) / 2.0) / (h / 2.0);
    return 1.0 - 0.225 * (dx * dx + dy * dy);
}

constexpr double kDark = 100;  // the camera's offset: what a closed shutter reads

imaging::ImageU16 shaded(const imaging::ImageU16& scene)
{
    imaging::ImageU16 out = scene;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            out.at(x, y) = static_cast<std::uint16_t>(std::lround(kDark + scene.at(x, y) * vignette(x, y, out.width, out.height)));
    return out;
}

imaging::TileImage tile16(imaging::ImageU16 grey)
{
    return {std::move(grey), imaging::SampleKind::Grey16};
}

std::string scratchDir(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "imaging_flat_" + std::to_string(::getpid()) + "_" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str()), 0);
    return dir;
}

/// Largest over smallest ratio of the mosaic to the reference mosaic of unshaded
/// tiles, each averaged over 24 × 24 px windows on a few rows: 1 when the shading is gone.
double ratioSwing(const imaging::ImageU16& m, const imaging::ImageU16& ref)
{
    const int half = 12;
    double lo = 1e18, hi = 0;
    for (int y = half; y + half < std::min(m.height, ref.height); y += 20)
        for (int x = half; x + half < std::min(m.width, ref.width); x += 4) {
            double a = 0, b = 0;
            for (int j = -half; j < half; ++j)
                for (int k = -half; k < half; ++k) {
                    a += m.at(x + k, y + j) - kDark;
                    b += ref.at(x + k, y + j);
                }
            lo = std::min(lo, a / b);
            hi = std::max(hi, a / b);
        }
    return hi / lo;
}

} // namespace

TEST(FlatField, ATileDividedByTheBlankHasTheScenesBrightnessEverywhere)
{
    const imagingtest::Texture tex(7);
    const imaging::ImageU16 scene = imagingtest::cutTile(tex, 50, 60, 96, 80, 0, 1);
    const auto flat = imaging::FlatField::fromBlank(shaded(imagingtest::blankTile(96, 80, 20000, 0, 2)), kDark, "blank.tif");
    ASSERT_TRUE(flat.ok()) << motion::msg::debugFormat(flat.problems());
    EXPECT_NEAR(flat->maxGain(), 1.0 / 0.55 * (1 - 0.225 * 0.67), 0.15);  // corner gain against the mean

    imaging::TileImage t = tile16(shaded(scene));
    double before = 0;
    for (std::size_t i = 0; i < scene.px.size(); ++i)
        before = std::max(before, std::abs(double(t.grey.px[i]) - scene.px[i]) / scene.px[i]);
    ASSERT_TRUE(flat->apply(t, "tile.tif").empty());
    // The correction gives the scene scaled by the blank's mean shading (one factor for the tile).
    const double k = double(t.grey.px[0]) / scene.px[0];
    double worst = 0;
    for (std::size_t i = 0; i < scene.px.size(); ++i)
        worst = std::max(worst, std::abs(t.grey.px[i] - k * scene.px[i]) / (k * scene.px[i]));
    EXPECT_GT(before, 0.3);
    EXPECT_LT(worst, 0.002);
}

TEST(FlatField, An8BitTileIsClippedAt255NotWrappedOrWidened)
{
    imaging::ImageU16 blank(4, 4, 200);
    blank.at(0, 0) = 100;  // one dim corner: a gain near 2
    const auto flat = imaging::FlatField::fromBlank(blank, 0, "blank.tif");
    ASSERT_TRUE(flat.ok());
    imaging::TileImage t{imaging::ImageU16(4, 4, 250), imaging::SampleKind::Grey8};
    ASSERT_TRUE(flat->apply(t, "t.tif").empty());
    EXPECT_EQ(t.grey.at(0, 0), 255);
}

TEST(FlatField, ABlankThatCannotServeIsRefusedNamingIt)
{
    const auto dark = imaging::FlatField::fromBlank(imaging::ImageU16(8, 8, 90), kDark, "dark.tif");
    ASSERT_FALSE(dark.ok());
    EXPECT_EQ(dark.problems().front().message.id, "imaging.flat.dark");
    EXPECT_EQ(dark.problems().front().file, "dark.tif");

    const auto clipped = imaging::FlatField::fromBlank(imaging::ImageU16(8, 8, 65535), 0, "bright.tif");
    ASSERT_FALSE(clipped.ok());
    EXPECT_EQ(clipped.problems().front().message.id, "imaging.flat.clipped");

    imaging::ImageU16 holed(10, 10, 20000);
    for (int x = 0; x < 10; ++x)
        holed.at(x, 3) = 50;  // a tenth of the field black: a hole, not shading
    const auto holes = imaging::FlatField::fromBlank(holed, 0, "holed.tif");
    ASSERT_FALSE(holes.ok());
    EXPECT_EQ(holes.problems().front().message.id, "imaging.flat.holes");

    const auto flat = imaging::FlatField::fromBlank(imaging::ImageU16(8, 8, 20000), 0, "blank.tif");
    ASSERT_TRUE(flat.ok());
    imaging::TileImage wrong = tile16(imaging::ImageU16(8, 6, 100));
    const motion::msg::Problems size = flat->apply(wrong, "tile_3.tif");
    ASSERT_EQ(size.size(), 1u);
    EXPECT_EQ(size.front().message.id, "imaging.flat.size");
    EXPECT_EQ(size.front().file, "tile_3.tif");
    EXPECT_EQ(size.front().message.text("flat"), "blank.tif");
}

TEST(FlatField, AStitchWithTheBlankLosesTheRepeatingDarkCorners)
{
    const imagingtest::Texture tex(41);
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = scratchDir("stitch");
    std::vector<imaging::StitchTile> tiles, plain;
    for (std::size_t i = 0; i < g.tiles.size(); ++i) {
        const std::string name = "tile_" + std::to_string(i) + ".tif";
        ASSERT_TRUE(imaging::writeTiff(dir + "/" + name, shaded(g.tiles[i])).empty());
        ASSERT_TRUE(imaging::writeTiff(dir + "/plain_" + name, g.tiles[i]).empty());
        tiles.push_back({name, dir + "/" + name, g.stagePx[i]});
        plain.push_back({name, dir + "/plain_" + name, g.stagePx[i]});
    }
    auto mosaic = [&](const std::vector<imaging::StitchTile>& set, std::shared_ptr<const imaging::FlatField> flat, const std::string& name) {
        imaging::StitchOptions o;
        o.mosaicPath = dir + "/" + name;
        o.threads = 1;
        o.flatField = std::move(flat);
        auto r = imaging::stitch(set, o);
        EXPECT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
        auto m = imaging::readTiff(o.mosaicPath);
        EXPECT_TRUE(m.ok());
        return m ? m->grey : imaging::ImageU16();
    };
    const imaging::ImageU16 reference = mosaic(plain, nullptr, "reference.ome.tif");
    const auto flat = imaging::FlatField::fromBlank(shaded(imagingtest::blankTile(g.tileW, g.tileH, 20000, 30, 5)), kDark, "blank.tif");
    ASSERT_TRUE(flat.ok());
    const double without = ratioSwing(mosaic(tiles, nullptr, "shaded.ome.tif"), reference);
    const double with = ratioSwing(mosaic(tiles, std::make_shared<imaging::FlatField>(*flat), "flat.ome.tif"), reference);
    EXPECT_GT(without, 1.25) << "with the blank: " << with;
    EXPECT_LT(with, 1.03) << "without: " << without;

    // A blank of another size stops the stitch before any work, naming both files.
    const auto small = imaging::FlatField::fromBlank(imaging::ImageU16(64, 64, 20000), 0, "small-blank.tif");
    imaging::StitchOptions o;
    o.flatField = std::make_shared<imaging::FlatField>(*small);
    const auto refused = imaging::stitch(tiles, o);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.problems().front().message.id, "imaging.flat.size");
    EXPECT_EQ(refused.problems().front().message.text("flat"), "small-blank.tif");
}
