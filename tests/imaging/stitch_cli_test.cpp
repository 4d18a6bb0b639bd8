// benchpilot-cli stitch as a process: a scan folder (tiles + the run log) in, the
// mosaic, the registered TileConfiguration and the report out; bad folders refused
// with the file named and nothing written under the mosaic's name.
#include "grid.h"
#include "imaging/tiff_write.h"
#include "imaging/tile_configuration.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct CliRun {
    int code = -1;
    std::string out, err;
};

std::string readAll(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

CliRun cli(const std::string& args, const std::string& scratch)
{
    const char* bin = std::getenv("BP_BIN_DIR");
    const std::string program = std::string(bin ? bin : BP_SOURCE_DIR "/build-release/app") + "/benchpilot-cli";
    const std::string o = scratch + "/cli.out", e = scratch + "/cli.err";
    const int status = std::system((program + " " + args + " >" + o + " 2>" + e).c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readAll(o);
    r.err = readAll(e);
    return r;
}

bool exists(const std::string& path)
{
    return std::ifstream(path).good();
}

std::string scratchDir(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "stitch_cli_" + std::to_string(::getpid()) + "_" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "/scan' '" + dir + "/out'").c_str()), 0);
    return dir;
}

// A 4 × 3 scan at 0.65 µm a pixel, image y along stage −Y (the default), written as
// the camera writes it: tile TIFFs and a run log whose lines carry "image" and "sha256".
void writeScan(const imagingtest::Grid& g, const std::string& dir, double yMmPerPx = -0.00065)
{
    std::ostringstream log;
    log << "{\"schema\":\"benchpilot.scan-run\",\"version\":1,\"plan\":\"test\",\"fingerprint\":\"0123456789abcdef\",\"tiles\":"
        << g.tiles.size() << "}\n";
    for (std::size_t i = 0; i < g.tiles.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "tile_%03zu.tif", i + 1);
        EXPECT_TRUE(imaging::writeTiff(dir + "/" + name, g.tiles[i]).empty());
        // The stage's reading, in mm: image +x is stage +X, image +y is stage −Y.
        const double xmm = 20 + g.stagePx[i].x() * 0.00065, ymm = 40 + g.stagePx[i].y() * yMmPerPx;
        log.precision(10);
        log << "{\"tile\":" << i << ",\"label\":\"" << name << "\",\"planned_mm\":[0,0],\"commanded_mm\":[0,0],\"measured_mm\":[" << xmm << ","
            << ymm << "],\"device_time_us\":1,\"settle_s\":0.01,\"image\":\"" << name << "\",\"sha256\":\"00\"}\n";
    }
    std::ofstream(dir + "/scan-run.jsonl") << log.str();
}

} // namespace

TEST(StitchCli, AScanFolderBecomesAMosaicWithItsReport)
{
    const imagingtest::Texture tex(51);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = scratchDir("ok");
    writeScan(g, dir + "/scan");
    const CliRun r = cli("stitch " + dir + "/scan --pixel-um 0.65 --max-shift-px 20 --out " + dir + "/out/slide.ome.tif --json", dir);
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_TRUE(exists(dir + "/out/slide.ome.tif"));
    EXPECT_FALSE(exists(dir + "/out/slide.ome.tif.partial"));
    EXPECT_TRUE(exists(dir + "/out/slide.stitch.json"));
    EXPECT_NE(r.out.find("\"file\":\"tile_001.tif\""), std::string::npos) << r.out.substr(0, 300);
    EXPECT_NE(r.out.find("\"stage_px\":["), std::string::npos);
    EXPECT_NE(r.out.find("\"expected_px\":[110,0]"), std::string::npos) << "mm → px through 0.65 µm and image y along stage −Y";
    EXPECT_NE(r.out.find("\"placed_by\":\"registration\""), std::string::npos);
    EXPECT_EQ(r.out.find("\"placed_by\":\"stage\""), std::string::npos);
    EXPECT_NE(r.out.find("\"rms_correction_px\":"), std::string::npos);
    auto tc = imaging::parseTileConfiguration(readAll(dir + "/scan/TileConfiguration.registered.txt"), "registered");
    ASSERT_TRUE(tc.ok());
    ASSERT_EQ(tc->size(), g.tiles.size());
    std::vector<Eigen::Vector2d> placed;
    for (const imaging::TileEntry& e : *tc)
        placed.push_back(e.positionPx);
    EXPECT_LT(imagingtest::rmsRelativeError(placed, g.truePx), 0.3);
}

TEST(StitchCli, BadFoldersAreRefusedNamingTheFileAndNoMosaicIsLeft)
{
    const imagingtest::Texture tex(52);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    {
        // The log names a tile whose image is not there.
        const std::string dir = scratchDir("missing");
        writeScan(g, dir + "/scan");
        std::remove((dir + "/scan/tile_005.tif").c_str());
        const CliRun r = cli("stitch " + dir + "/scan --pixel-um 0.65 --out " + dir + "/out/m.ome.tif", dir);
        EXPECT_EQ(r.code, 1);
        EXPECT_NE(r.err.find("tile_005.tif"), std::string::npos) << r.err;
        EXPECT_FALSE(exists(dir + "/out/m.ome.tif"));
    }
    {
        // An image in the folder the positions do not name: a different count.
        const std::string dir = scratchDir("extra");
        writeScan(g, dir + "/scan");
        ASSERT_TRUE(imaging::writeTiff(dir + "/scan/stray.tif", g.tiles[0]).empty());
        const CliRun r = cli("stitch " + dir + "/scan --pixel-um 0.65 --out " + dir + "/out/m.ome.tif", dir);
        EXPECT_EQ(r.code, 1);
        EXPECT_NE(r.err.find("stray.tif"), std::string::npos) << r.err;
        EXPECT_FALSE(exists(dir + "/out/m.ome.tif"));
    }
    {
        // An unreadable tile and one of another size.
        const std::string dir = scratchDir("unreadable");
        writeScan(g, dir + "/scan");
        std::ofstream(dir + "/scan/tile_002.tif") << "MM\0*broken";
        ASSERT_TRUE(imaging::writeTiff(dir + "/scan/tile_007.tif", imaging::ImageU16(50, 50, 3)).empty());
        const CliRun r = cli("stitch " + dir + "/scan --pixel-um 0.65 --out " + dir + "/out/m.ome.tif", dir);
        EXPECT_EQ(r.code, 1);
        EXPECT_NE(r.err.find("tile_002.tif"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("tile_007.tif"), std::string::npos) << r.err;
        EXPECT_FALSE(exists(dir + "/out/m.ome.tif"));
        EXPECT_FALSE(exists(dir + "/out/m.ome.tif.partial"));
    }
    {
        // A run log without a pixel size cannot be turned into pixels.
        const std::string dir = scratchDir("nopixel");
        writeScan(g, dir + "/scan");
        const CliRun r = cli("stitch " + dir + "/scan --out " + dir + "/out/m.ome.tif", dir);
        EXPECT_EQ(r.code, 1);
        EXPECT_NE(r.err.find("--pixel-um"), std::string::npos) << r.err;
    }
}

TEST(StitchCli, TheCameraGeometryTurnsTheLogsMillimetresIntoPixels)
{
    // A camera whose image rows run along stage +Y: stitched as such, every pair holds;
    // stitched with the default (stage −Y) the rows come out mirrored, and the pairs
    // between rows find nothing where the stage puts them.
    const imagingtest::Texture tex(53);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = scratchDir("imagey");
    writeScan(g, dir + "/scan", +0.00065);
    const CliRun right = cli("stitch " + dir + "/scan --pixel-um 0.65 --image-y stage-plus-y --no-mosaic --json", dir);
    ASSERT_EQ(right.code, 0) << right.err;
    EXPECT_NE(right.out.find("\"tiles_placed_by_stage\":0"), std::string::npos) << right.out.substr(right.out.size() - 300);
    EXPECT_EQ(right.out.find("\"accepted\":false"), std::string::npos);
    const CliRun wrong = cli("stitch " + dir + "/scan --pixel-um 0.65 --no-mosaic --json", dir);
    ASSERT_EQ(wrong.code, 0) << wrong.err;
    EXPECT_NE(wrong.out.find("\"accepted\":false"), std::string::npos);
    EXPECT_FALSE(exists(dir + "/scan/mosaic.ome.tif"));
}

TEST(StitchCli, ABlankImageInTheFolderIsTheFlatFieldNotAnUnnamedTile)
{
    const imagingtest::Texture tex(52);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = scratchDir("flat");
    writeScan(g, dir + "/scan");
    ASSERT_TRUE(imaging::writeTiff(dir + "/scan/blank.tif", imagingtest::blankTile(g.tileW, g.tileH, 20000, 30, 3)).empty());

    // Without --flat the blank is one more image the log does not name.
    CliRun plain = cli("stitch '" + dir + "/scan' --pixel-um 0.65 --out '" + dir + "/out/m.ome.tif'", dir);
    EXPECT_EQ(plain.code, 1) << plain.err;
    EXPECT_NE(plain.err.find("blank.tif"), std::string::npos) << plain.err;

    CliRun ok = cli("stitch '" + dir + "/scan' --pixel-um 0.65 --flat '" + dir + "/scan/blank.tif' --dark 100 --out '" + dir + "/out/m.ome.tif'", dir);
    EXPECT_EQ(ok.code, 0) << ok.err;
    EXPECT_TRUE(exists(dir + "/out/m.ome.tif"));

    // A blank of another size: refused before any work, naming it; no mosaic.
    std::remove((dir + "/scan/blank.tif").c_str());
    ASSERT_TRUE(imaging::writeTiff(dir + "/small.tif", imagingtest::blankTile(64, 64, 20000, 30, 3)).empty());
    CliRun size = cli("stitch '" + dir + "/scan' --pixel-um 0.65 --flat '" + dir + "/small.tif' --out '" + dir + "/out/n.ome.tif'", dir);
    EXPECT_EQ(size.code, 1) << size.err;
    EXPECT_NE(size.err.find("small.tif"), std::string::npos) << size.err;
    EXPECT_FALSE(exists(dir + "/out/n.ome.tif"));

    CliRun darkAlone = cli("stitch '" + dir + "/scan' --pixel-um 0.65 --dark 100", dir);
    EXPECT_EQ(darkAlone.code, 1);
    EXPECT_NE(darkAlone.err.find("--flat"), std::string::npos) << darkAlone.err;
}
