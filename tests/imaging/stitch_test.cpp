// The whole stitch over files (imaging/stitch.h) and Fiji's TileConfiguration
// (imaging/tile_configuration.h).
#include "grid.h"
#include "imaging/stitch.h"
#include "imaging/tile_configuration.h"
#include "imaging/tiff_write.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <unistd.h>

namespace {

std::string scratchDir(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "imaging_stitch_" + std::to_string(::getpid()) + "_" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str()), 0);
    return dir;
}

bool exists(const std::string& path)
{
    return std::ifstream(path).good();
}

std::vector<imaging::StitchTile> writeGrid(const imagingtest::Grid& g, const std::string& dir)
{
    std::vector<imaging::StitchTile> tiles;
    for (std::size_t i = 0; i < g.tiles.size(); ++i) {
        const std::string name = "tile_" + std::to_string(100 + i).substr(1) + ".tif";
        EXPECT_TRUE(imaging::writeTiff(dir + "/" + name, g.tiles[i]).empty());
        tiles.push_back({name, dir + "/" + name, g.stagePx[i]});
    }
    return tiles;
}

} // namespace

TEST(Stitch, AFolderOfTilesBecomesAMosaicAReportAndATileConfiguration)
{
    const imagingtest::Texture tex(41);
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    const int blank = g.index(2, 1);
    g.tiles[static_cast<std::size_t>(blank)] = imagingtest::blankTile(g.tileW, g.tileH, 20000, 40, 9);
    const std::string dir = scratchDir("ok");
    imaging::StitchOptions o;
    o.mosaicPath = dir + "/mosaic.ome.tif";
    o.mosaic.pixelSizeUm = 0.65;
    o.threads = 2;
    auto r = imaging::stitch(writeGrid(g, dir), o);
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_TRUE(exists(o.mosaicPath));
    EXPECT_EQ(r->pairs.size(), 17u);  // 3 × 3 across, 4 × 2 down
    EXPECT_TRUE(r->placement.placedByStage[static_cast<std::size_t>(blank)]);
    std::vector<Eigen::Vector2d> placed, truth;
    for (std::size_t i = 0; i < g.tiles.size(); ++i)
        if (static_cast<int>(i) != blank) {
            placed.push_back(r->placement.positionsPx[i]);
            truth.push_back(g.truePx[i]);
        }
    EXPECT_LT(imagingtest::rmsRelativeError(placed, truth), 0.3);

    const std::string json = imaging::stitchJson(*r, 1.5, "mosaic.ome.tif");
    // Positions are in mosaic pixels: the stage's, moved by the mosaic's origin.
    const std::size_t at = json.find("{\"file\":\"tile_06.tif\",\"stage_px\":[");
    ASSERT_NE(at, std::string::npos) << json.substr(0, 400);
    const std::string tile6 = json.substr(at, json.find('}', at) - at);
    EXPECT_NE(tile6.find("\"placed_by\":\"stage\""), std::string::npos) << tile6;
    const Eigen::Vector2i o6 = Eigen::Vector2i(220, 96) - r->frame.originPx;
    EXPECT_NE(tile6.find("\"stage_px\":[" + std::to_string(o6.x()) + "," + std::to_string(o6.y()) + "]"), std::string::npos) << tile6;
    EXPECT_NE(json.find("\"rms_correction_px\":"), std::string::npos);
    EXPECT_NE(json.find("\"status\":\"low_score\""), std::string::npos);

    // The registered TileConfiguration reads back (Fiji's rules) with the same positions.
    const std::string tc = imaging::registeredTileConfiguration(*r);
    auto back = imaging::parseTileConfiguration(tc, "TileConfiguration.registered.txt");
    ASSERT_TRUE(back.ok()) << motion::msg::debugFormat(back.problems());
    ASSERT_EQ(back->size(), g.tiles.size());
    EXPECT_EQ((*back)[static_cast<std::size_t>(blank)].file, "tile_06.tif");
    const Eigen::Vector2d origin = r->frame.originPx.cast<double>();
    for (std::size_t i = 0; i < back->size(); ++i)
        EXPECT_LT(((*back)[i].positionPx - (r->placement.positionsPx[i] - origin)).norm(), 0.001);
}

TEST(Stitch, MixedSizesOrAnUnreadableTileAreRefusedNamingTheFileAndWriteNothing)
{
    const imagingtest::Texture tex(42);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = scratchDir("bad");
    std::vector<imaging::StitchTile> tiles = writeGrid(g, dir);
    ASSERT_TRUE(imaging::writeTiff(dir + "/" + tiles[3].file, imaging::ImageU16(64, 64, 5)).empty());
    std::ofstream(dir + "/" + tiles[5].file) << "II*\0garbage";
    ASSERT_TRUE(imaging::writeTiff(dir + "/" + tiles[7].file, g.tiles[7], 8).empty());
    imaging::StitchOptions o;
    o.mosaicPath = dir + "/mosaic.ome.tif";
    auto r = imaging::stitch(tiles, o);
    ASSERT_FALSE(r.ok());
    std::map<std::string, std::string> byFile;
    for (const motion::msg::Problem& p : r.problems())
        byFile[p.file] = p.message.id;
    EXPECT_EQ(byFile["tile_03.tif"], "imaging.tiles.mixed_size");
    EXPECT_EQ(byFile["tile_05.tif"], "imaging.tiff.unreadable");
    EXPECT_EQ(byFile["tile_07.tif"], "imaging.tiles.mixed_kind");
    EXPECT_EQ(r.problems().size(), 3u);
    EXPECT_FALSE(exists(o.mosaicPath));
    EXPECT_FALSE(exists(o.mosaicPath + ".partial"));
}

TEST(TileConfiguration, ReadsWhatFijiReadsAndRefusesWhatItRefuses)
{
    const std::string ok =
        "# Define the number of dimensions we are working on\n"
        "dim = 2\n\n# Define the image coordinates\n"
        "tile_001.tif; ; (0.000, 0.000)\r\n"
        "  tile 002.tif;name;(1843.2,-5e-1)  \n"
        "x\n";
    auto r = imaging::parseTileConfiguration(ok, "TileConfiguration.txt");
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    ASSERT_EQ(r->size(), 2u);
    EXPECT_EQ((*r)[1].file, "tile 002.tif");
    EXPECT_DOUBLE_EQ((*r)[1].positionPx.x(), 1843.2);
    EXPECT_DOUBLE_EQ((*r)[1].positionPx.y(), -0.5);
    EXPECT_EQ((*r)[1].line, 6);

    const std::pair<const char*, const char*> bad[] = {
        {"tile_001.tif; ; (0, 0)\n", "imaging.tileconfig.no_dim"},
        {"dim = 2\ntile_001.tif; (0, 0)\n", "imaging.tileconfig.not_three_fields"},
        {"dim = 2\ntile_001.tif; ; 0, 0\n", "imaging.tileconfig.bad_position"},
        {"dim = 2\ntile_001.tif; ; (0, zero)\n", "imaging.tileconfig.bad_position"},
        {"dim = 2\ntile_001.tif; ; (0, 0, 0)\n", "imaging.tileconfig.bad_position"},
        {"dim = 2\n; ; (0, 0)\n", "imaging.tileconfig.no_file"},
        {"dim = 2\n", "imaging.tileconfig.no_tiles"},
        {"dim = four\n", "imaging.tileconfig.bad_dim"},
    };
    for (const auto& [text, id] : bad) {
        auto b = imaging::parseTileConfiguration(text, "t.txt");
        ASSERT_FALSE(b.ok()) << text;
        EXPECT_EQ(b.error().id, id) << text;
        EXPECT_EQ(b.problems().front().file, "t.txt");
    }
}
