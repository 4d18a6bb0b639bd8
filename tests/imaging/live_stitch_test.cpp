// The live stitch (imaging/live_stitch.h): tiles one at a time, in any order, give the
// batch stitch's result; pairs are registered as soon as both tiles exist; memory stays
// within its bound; a cancelled or incomplete live stitch places nothing.
#include "grid.h"
#include "imaging/live_stitch.h"
#include "imaging/tiff_write.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <Eigen/Geometry>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <numeric>
#include <set>
#include <unistd.h>

namespace {

std::string liveScratch(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "imaging_live_" + std::to_string(::getpid()) + "_" + name;
    EXPECT_EQ(std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str()), 0);
    return dir;
}

std::vector<imaging::StitchTile> writeLiveGrid(const imagingtest::Grid& g, const std::string& dir)
{
    std::vector<imaging::StitchTile> tiles;
    for (std::size_t i = 0; i < g.tiles.size(); ++i) {
        const std::string name = "tile_" + std::to_string(100 + i).substr(1) + ".tif";
        EXPECT_TRUE(imaging::writeTiff(dir + "/" + name, g.tiles[i]).empty());
        tiles.push_back({name, dir + "/" + name, g.stagePx[i]});
    }
    return tiles;
}

/// The plan's positions: the stage's, each off by up to 2 px as a real stage would be.
std::vector<imaging::StitchTile> planned(std::vector<imaging::StitchTile> tiles)
{
    for (std::size_t i = 0; i < tiles.size(); ++i)
        tiles[i].stagePx += Eigen::Vector2d((i % 3) - 1.0, ((i / 3) % 3) - 1.0) * 2.0;
    return tiles;
}

imaging::StitchResult batch(const std::vector<imaging::StitchTile>& tiles)
{
    imaging::StitchOptions o;
    o.threads = 2;
    auto r = imaging::stitch(tiles, o);
    EXPECT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    return r.ok() ? r.take() : imaging::StitchResult{};
}

void expectSameAsBatch(const imaging::StitchResult& live, const imaging::StitchResult& b)
{
    ASSERT_EQ(live.tiles.size(), b.tiles.size());
    ASSERT_EQ(live.pairs.size(), b.pairs.size());
    for (std::size_t k = 0; k < b.pairs.size(); ++k) {
        EXPECT_EQ(live.pairs[k].a, b.pairs[k].a);
        EXPECT_EQ(live.pairs[k].b, b.pairs[k].b);
        EXPECT_EQ(live.pairs[k].reg.status, b.pairs[k].reg.status) << "pair " << k;
    }
    for (std::size_t i = 0; i < b.tiles.size(); ++i) {
        EXPECT_LT((live.placement.positionsPx[i] - b.placement.positionsPx[i]).norm(), 0.05) << "tile " << i;
        EXPECT_EQ(live.placement.placedByStage[i], b.placement.placedByStage[i]) << "tile " << i;
    }
    EXPECT_EQ(live.frame.originPx, b.frame.originPx);
    EXPECT_EQ(live.frame.width, b.frame.width);
    EXPECT_EQ(live.tileWidth, b.tileWidth);
}

/// Feeds the tiles in `order`, each with its image, and finishes.
imaging::StitchResult feed(const imagingtest::Grid& g, const std::vector<imaging::StitchTile>& tiles, const std::vector<int>& order,
                           imaging::LiveStitchOptions o = {})
{
    imaging::LiveStitcher live(planned(tiles), o);
    for (int i : order)
        EXPECT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx,
                             std::make_shared<const imaging::TileImage>(imaging::TileImage{g.tiles[static_cast<std::size_t>(i)], imaging::SampleKind::Grey16})));
    auto r = live.finish();
    EXPECT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    return r.ok() ? r.take() : imaging::StitchResult{};
}

} // namespace

TEST(LiveStitch, TilesInScanOrderGiveTheBatchStitchOfTheSameFolder)
{
    const imagingtest::Texture tex(51);
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    // A blank tile: flagged and placed by the stage in both.
    g.tiles[5] = imagingtest::blankTile(g.tileW, g.tileH, 20000, 40, 3);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("rows"));
    const imaging::StitchResult b = batch(tiles);
    std::vector<int> rows(g.tiles.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = static_cast<int>(i);
    const imaging::StitchResult live = feed(g, tiles, rows);
    expectSameAsBatch(live, b);
    EXPECT_TRUE(live.placement.placedByStage[5]);
    // The same report: its tiles by name, at the measured (not the planned) positions.
    EXPECT_EQ(imaging::registeredTileConfiguration(live), imaging::registeredTileConfiguration(b));
}

TEST(LiveStitch, SnakeOrderAndTilesBeforeTheirNeighboursGiveTheSameResult)
{
    const imagingtest::Texture tex(52);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("snake"));
    const imaging::StitchResult b = batch(tiles);
    std::vector<int> snake;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c)
            snake.push_back(g.index(r % 2 ? g.cols - 1 - c : c, r));
    expectSameAsBatch(feed(g, tiles, snake), b);
    // Backwards, then shuffled: every tile may come before the neighbours it pairs with.
    std::vector<int> backwards(snake.rbegin(), snake.rend());
    expectSameAsBatch(feed(g, tiles, backwards), b);
    std::vector<int> shuffled = snake;
    std::mt19937 rng(5);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    expectSameAsBatch(feed(g, tiles, shuffled), b);
}

TEST(LiveStitch, APairIsRegisteredAsSoonAsItsSecondTileIsThere)
{
    const imagingtest::Texture tex(53);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("asap"));
    std::mutex m;
    std::condition_variable cv;
    std::vector<std::pair<int, int>> seen;
    std::set<int> thumbs;
    imaging::LiveStitchEvents events;
    events.pairRegistered = [&](const imaging::TilePair& p) {
        std::lock_guard<std::mutex> lock(m);
        seen.emplace_back(p.a, p.b);
        cv.notify_all();
    };
    events.tileRead = [&](int tile, int w, int, std::shared_ptr<const imaging::ImageU16> t) {
        std::lock_guard<std::mutex> lock(m);
        if (t && t->width > 0 && t->width <= 96 && w == g.tileW)
            thumbs.insert(tile);
    };
    imaging::LiveStitcher live(planned(tiles), {}, events);
    auto add = [&](int i) { return live.add(i, tiles[static_cast<std::size_t>(i)].stagePx); };  // read from its file
    auto waitFor = [&](std::size_t n) {
        std::unique_lock<std::mutex> lock(m);
        // Not a timing assertion: the wait ends as soon as the pairs are there.
        cv.wait_for(lock, std::chrono::seconds(60), [&] { return seen.size() >= n; });
        return seen;
    };
    ASSERT_TRUE(add(0));
    ASSERT_TRUE(add(2));  // not a neighbour of 0: nothing to register yet
    ASSERT_TRUE(add(1));  // pairs with 0 and with 2
    EXPECT_EQ(waitFor(2), (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
    ASSERT_TRUE(add(5));  // below 1
    EXPECT_EQ(waitFor(3).back(), std::make_pair(1, 5));
    EXPECT_EQ(live.pairsRegistered(), 3);
    EXPECT_FALSE(live.add(5, tiles[5].stagePx)) << "a tile is given once";
    EXPECT_FALSE(live.add(99, {0, 0}));
    for (int i = 0; i < static_cast<int>(tiles.size()); ++i) {
        if (i != 0 && i != 1 && i != 2 && i != 5) {
            ASSERT_TRUE(add(i));
        }
    }
    auto r = live.finish();
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r->pairs.size(), 17u);
    EXPECT_EQ(live.pairsRegistered(), 17);
    EXPECT_EQ(thumbs.size(), tiles.size());
}

TEST(LiveStitch, WithAFlatFieldItFlattensAsTheBatchStitchDoesAndRefusesABlankOfAnotherSize)
{
    const imagingtest::Texture tex(57);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("flat"));
    // A blank brighter in the middle than at the edges, as a lamp's would be.
    imaging::ImageU16 blank(g.tileW, g.tileH);
    for (int y = 0; y < g.tileH; ++y)
        for (int x = 0; x < g.tileW; ++x)
            blank.at(x, y) = static_cast<std::uint16_t>(30000 - 40 * std::abs(x - g.tileW / 2) - 40 * std::abs(y - g.tileH / 2));
    auto flat = imaging::FlatField::fromBlank(blank, 100, "blank.tif");
    ASSERT_TRUE(flat.ok()) << motion::msg::debugFormat(flat.problems());
    imaging::StitchOptions so;
    so.flatField = std::make_shared<const imaging::FlatField>(flat.take());
    auto b = imaging::stitch(tiles, so);
    ASSERT_TRUE(b.ok()) << motion::msg::debugFormat(b.problems());
    imaging::LiveStitchOptions o;
    o.flatField = so.flatField;
    std::vector<int> rows(tiles.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = static_cast<int>(i);
    // Half handed in as taken, half read from their files: both are flattened.
    imaging::LiveStitcher live(planned(tiles), o);
    for (int i : rows)
        ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx,
                             i % 2 ? nullptr : std::make_shared<const imaging::TileImage>(imaging::TileImage{g.tiles[static_cast<std::size_t>(i)], imaging::SampleKind::Grey16})));
    auto r = live.finish();
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    expectSameAsBatch(*r, *b);

    auto small = imaging::FlatField::fromBlank(imaging::ImageU16(32, 32, 20000), 100, "small.tif");
    ASSERT_TRUE(small.ok());
    o.flatField = std::make_shared<const imaging::FlatField>(small.take());
    imaging::LiveStitcher wrong(planned(tiles), o);
    for (int i : rows)
        ASSERT_TRUE(wrong.add(i, tiles[static_cast<std::size_t>(i)].stagePx));
    auto refused = wrong.finish();
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().id, "imaging.flat.size");
}

TEST(LiveStitch, KeepsWithinItsMemoryByReadingTilesAgainFromTheirFiles)
{
    const imagingtest::Texture tex(54);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("memory"));
    const imaging::StitchResult b = batch(tiles);
    const double tileMb = g.tileW * g.tileH * 2 / 1e6;
    imaging::LiveStitchOptions o;
    o.memoryMegabytes = 2.5 * tileMb;
    imaging::LiveStitcher live(planned(tiles), o);
    // Columns first: a row-major neighbour waits a whole column, more than the bound holds.
    for (int c = 0; c < g.cols; ++c)
        for (int r = 0; r < g.rows; ++r) {
            const int i = g.index(c, r);
            ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx,
                                 std::make_shared<const imaging::TileImage>(imaging::TileImage{g.tiles[static_cast<std::size_t>(i)], imaging::SampleKind::Grey16})));
        }
    auto r = live.finish();
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    expectSameAsBatch(*r, b);
    // The bound, plus the tile being registered and the neighbour read for it.
    EXPECT_LE(live.peakHeldMegabytes(), o.memoryMegabytes + 2 * tileMb + 1e-9);
}

TEST(LiveStitch, CancelledOrIncompleteItPlacesNothing)
{
    const imagingtest::Texture tex(55);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch("cancel"));
    {
        imaging::LiveStitcher live(planned(tiles), {});
        for (int i = 0; i < 5; ++i)
            ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx));
        auto r = live.finish();
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().id, "imaging.live.incomplete");
        EXPECT_FALSE(live.add(5, tiles[5].stagePx)) << "finished";
    }
    {
        imaging::LiveStitcher live(planned(tiles), {});
        for (int i = 0; i < 6; ++i)
            ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx));
        live.cancel();
        EXPECT_FALSE(live.add(6, tiles[6].stagePx));
        auto r = live.finish();
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().id, "imaging.live.cancelled");
    }
    // Dropped with work queued: the worker stops, nothing is left running.
    {
        imaging::LiveStitcher live(planned(tiles), {});
        for (int i = 0; i < static_cast<int>(tiles.size()); ++i)
            ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx));
    }
}

TEST(LiveStitch, ATileOfAnotherSizeIsRefusedNamingItsFile)
{
    const imagingtest::Texture tex(56);
    const imagingtest::Grid g = imagingtest::makeGrid(tex);
    const std::string dir = liveScratch("mixed");
    std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, dir);
    ASSERT_TRUE(imaging::writeTiff(dir + "/" + tiles[4].file, imaging::ImageU16(64, 64, 5)).empty());
    imaging::LiveStitcher live(planned(tiles), {});
    for (int i = 0; i < static_cast<int>(tiles.size()); ++i)
        ASSERT_TRUE(live.add(i, tiles[static_cast<std::size_t>(i)].stagePx));
    auto r = live.finish();
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.problems().front().file, "tile_04.tif");
    EXPECT_EQ(r.error().id, "imaging.tiles.mixed_size");
}

TEST(LiveStitch, ChecksThePlansCameraAtTheEndAsTheBatchStitchDoes)
{
    // A camera whose rows run up the image where the plan says down, and one turned 3°:
    // after the last tile the live stitch names the setting to change, as Stitch does.
    const imagingtest::Texture tex(57);
    const Eigen::Matrix2d mirrored = Eigen::Vector2d(1, -1).asDiagonal();
    const Eigen::Matrix2d turned = Eigen::Rotation2Dd(3.0 * M_PI / 180).toRotationMatrix();
    for (const auto& [truth, id] : {std::pair{mirrored, "imaging.camera_check.mirrored"}, std::pair{turned, "imaging.camera_check.rotated"}}) {
        imagingtest::Grid g = imagingtest::makeGrid(tex);
        for (std::size_t i = 0; i < g.stagePx.size(); ++i) {
            g.truePx[i] = truth * g.stagePx[i];
            g.tiles[i] = imagingtest::cutTile(tex, 600 + g.truePx[i].x(), 600 + g.truePx[i].y(), g.tileW, g.tileH, 40, 700 + static_cast<unsigned>(i));
        }
        const std::vector<imaging::StitchTile> tiles = writeLiveGrid(g, liveScratch(std::string("camera_") + id));
        const imaging::PlanCameraGeometry plan{0.65, 0, false};
        imaging::StitchOptions bo;
        bo.threads = 2;
        bo.planCamera = plan;
        auto b = imaging::stitch(tiles, bo);
        ASSERT_TRUE(b.ok()) << motion::msg::debugFormat(b.problems());
        imaging::LiveStitchOptions lo;
        lo.planCamera = plan;
        lo.memoryMegabytes = 0.1;  // the pairs tried again are read back from the files
        std::vector<int> order(tiles.size());
        std::iota(order.begin(), order.end(), 0);
        const imaging::StitchResult live = feed(g, tiles, order, lo);
        ASSERT_TRUE(live.cameraCheck) << id;
        ASSERT_TRUE(live.planCamera);
        ASSERT_TRUE(live.cameraCheck->measured) << id;
        EXPECT_EQ(live.cameraCheck->mirrorOff, b->cameraCheck->mirrorOff) << id;
        EXPECT_EQ(live.cameraCheck->rotationOff, b->cameraCheck->rotationOff) << id;
        EXPECT_NEAR(live.cameraCheck->fit.rotationDeg, b->cameraCheck->fit.rotationDeg, 0.05) << id;
        const auto advice = imaging::geometryAdvice(*live.cameraCheck, *live.planCamera);
        ASSERT_FALSE(advice.empty()) << id;
        EXPECT_EQ(advice.front().id, id);
    }
}

TEST(LiveStitch, AThumbnailAveragesBlocksDownToItsSize)
{
    imaging::ImageU16 src(8, 4, 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            src.at(x, y) = static_cast<std::uint16_t>(x < 4 ? 100 : 300 + (y % 2) * 100);
    const imaging::ImageU16 t = imaging::thumbnail(src, 2);
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 1);
    EXPECT_EQ(t.at(0, 0), 100);
    EXPECT_EQ(t.at(1, 0), 350);
}
