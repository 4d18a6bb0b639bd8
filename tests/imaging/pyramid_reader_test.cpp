// Reading regions of the pyramidal OME-TIFF the writer makes (imaging/pyramid_reader.h):
// each level's pixels are the writer's halvings, a region read decodes only the blocks it
// crosses, and a file cut short or not a mosaic is refused with a problem naming it.
#include "imaging/ome_tiff_writer.h"
#include "imaging/pyramid_reader.h"
#include "imaging/tiff_write.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace {

std::string pyramidScratch(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "imaging_pyramid_" + std::to_string(::getpid());
    const std::string cmd = "mkdir -p '" + dir + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return dir + "/" + name;
}

std::uint16_t sampleAt(int x, int y) { return static_cast<std::uint16_t>((x * 7 + y * 13) % 60000); }

/// A w × h mosaic of sampleAt(), tiles of 16 px, halved down to at most 40 px a side.
std::string writePyramid(const std::string& name, int w, int h, int bits = 16)
{
    const std::string path = pyramidScratch(name);
    imaging::OmeTiffOptions o;
    o.bitsPerSample = bits;
    o.pixelSizeUm = 0.65;
    o.stageXMm = 12.5;
    o.stageYMm = -3.25;
    o.tileSize = 16;
    o.smallestLevelPx = 40;
    auto writer = imaging::OmeTiffWriter::open(path, w, h, o);
    EXPECT_TRUE(writer.ok());
    std::vector<std::uint16_t> rows(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            rows[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] =
                bits == 8 ? static_cast<std::uint16_t>((x + y) % 256) : sampleAt(x, y);
    EXPECT_TRUE((*writer)->writeRows(rows.data(), h).empty());
    EXPECT_TRUE((*writer)->finish().empty());
    return path;
}

} // namespace

TEST(PyramidReader, ReadsARegionOfEachLevelAsTheWriterHalvedIt)
{
    const std::string path = writePyramid("mosaic.ome.tif", 150, 100);
    auto r = imaging::PyramidReader::open(path);
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    const auto& levels = (*r)->levels();
    ASSERT_EQ(levels.size(), 3u) << "150 × 100, 75 × 50, 38 × 25";
    EXPECT_EQ(levels[1].width, 75);
    EXPECT_EQ(levels[2].width, 38);
    EXPECT_EQ(levels[2].height, 25);
    EXPECT_EQ(levels[0].blockWidth, 16);
    EXPECT_DOUBLE_EQ(levels[1].scale, 2.0);
    EXPECT_DOUBLE_EQ((*r)->pixelSizeUm(), 0.65);
    ASSERT_TRUE((*r)->stageMm());
    EXPECT_DOUBLE_EQ((*r)->stageMm()->x(), 12.5);
    EXPECT_DOUBLE_EQ((*r)->stageMm()->y(), -3.25);

    // Full resolution: a region across block edges holds exactly the samples written.
    auto full = (*r)->readRegion(0, 13, 29, 40, 21);
    ASSERT_TRUE(full.ok());
    ASSERT_EQ(full->width, 40);
    ASSERT_EQ(full->height, 21);
    for (int y = 0; y < 21; ++y)
        for (int x = 0; x < 40; ++x)
            ASSERT_EQ(full->at(x, y), sampleAt(13 + x, 29 + y)) << x << ", " << y;

    // Level 1 pixel (x, y) is the rounded mean of full-resolution 2x .. 2x+1, 2y .. 2y+1.
    auto half = (*r)->readRegion(1, 30, 20, 10, 8);
    ASSERT_TRUE(half.ok());
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 10; ++x) {
            const int X = 2 * (30 + x), Y = 2 * (20 + y);
            const unsigned mean = (sampleAt(X, Y) + sampleAt(X + 1, Y) + sampleAt(X, Y + 1) + sampleAt(X + 1, Y + 1) + 2u) / 4u;
            ASSERT_EQ(half->at(x, y), mean) << x << ", " << y;
        }

    // A region past the edge is clipped; one wholly outside is empty.
    auto edge = (*r)->readRegion(2, 30, 20, 50, 50);
    ASSERT_TRUE(edge.ok());
    EXPECT_EQ(edge->width, 8);
    EXPECT_EQ(edge->height, 5);
    auto outside = (*r)->readRegion(0, 500, 0, 10, 10);
    ASSERT_TRUE(outside.ok());
    EXPECT_TRUE(outside->empty());
}

TEST(PyramidReader, ARegionDecodesOnlyTheBlocksItCrosses)
{
    const std::string path = writePyramid("blocks.ome.tif", 160, 160);
    auto r = imaging::PyramidReader::open(path);
    ASSERT_TRUE(r.ok());
    const long before = (*r)->blocksRead();
    // 20 × 20 px from (10, 10) crosses 16-px blocks 0 … 1 each way: four blocks of the 100.
    ASSERT_TRUE((*r)->readRegion(0, 10, 10, 20, 20).ok());
    EXPECT_EQ((*r)->blocksRead() - before, 4);
    // Switching levels back and forth keeps reading the right directory.
    auto l1 = (*r)->readRegion(1, 0, 0, 4, 4);
    auto l0 = (*r)->readRegion(0, 100, 100, 1, 1);
    ASSERT_TRUE(l1.ok() && l0.ok());
    EXPECT_EQ(l0->at(0, 0), sampleAt(100, 100));
}

TEST(PyramidReader, An8BitMosaicAndAPlainTiffReadToo)
{
    const std::string path = writePyramid("grey8.ome.tif", 64, 48, 8);
    auto r = imaging::PyramidReader::open(path);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ((*r)->bitsPerSample(), 8);
    auto px = (*r)->readRegion(0, 60, 40, 4, 8);
    ASSERT_TRUE(px.ok());
    EXPECT_EQ(px->at(3, 7), (63 + 47) % 256);

    // A stripped TIFF of one image (what a camera writes) is a pyramid of one level.
    imaging::ImageU16 img(30, 20);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 30; ++x)
            img.at(x, y) = sampleAt(x, y);
    const std::string plain = pyramidScratch("plain.tif");
    ASSERT_TRUE(imaging::writeTiff(plain, img, 16).empty());
    auto p = imaging::PyramidReader::open(plain);
    ASSERT_TRUE(p.ok()) << motion::msg::debugFormat(p.problems());
    EXPECT_EQ((*p)->levels().size(), 1u);
    auto region = (*p)->readRegion(0, 25, 15, 5, 5);
    ASSERT_TRUE(region.ok());
    EXPECT_EQ(region->at(4, 4), sampleAt(29, 19));
}

TEST(PyramidReader, AFileCutShortOrNotAMosaicIsRefusedNamingIt)
{
    const std::string path = writePyramid("whole.ome.tif", 150, 100);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 1000u);

    // Cut at many places: never accepted with a wrong picture, never a crash; whatever
    // is refused names the file.
    int refusedAtOpen = 0, refusedAtRead = 0;
    for (std::size_t keep : {std::size_t(8), std::size_t(100), bytes.size() / 3, bytes.size() / 2, bytes.size() - 200, bytes.size() - 20}) {
        const std::string cut = pyramidScratch("cut.ome.tif");
        std::ofstream(cut, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(keep));
        auto r = imaging::PyramidReader::open(cut, "cut.ome.tif");
        if (!r.ok()) {
            ++refusedAtOpen;
            ASSERT_FALSE(r.problems().empty());
            EXPECT_EQ(r.problems().front().file, "cut.ome.tif");
            EXPECT_FALSE(r.problems().front().message.id.empty());
            continue;
        }
        bool whole = true;
        for (std::size_t k = 0; k < (*r)->levels().size(); ++k) {
            const auto& l = (*r)->levels()[k];
            auto px = (*r)->readRegion(static_cast<int>(k), 0, 0, l.width, l.height);
            if (!px.ok()) {
                whole = false;
                EXPECT_EQ(px.problems().front().message.id, "imaging.tiff.damaged");
                EXPECT_EQ(px.problems().front().file, "cut.ome.tif");
            }
        }
        refusedAtRead += !whole;
        EXPECT_FALSE(whole) << "a file cut to " << keep << " of " << bytes.size() << " bytes read whole";
    }
    EXPECT_GT(refusedAtOpen, 0);

    // A file that is no TIFF, and an RGB picture, are refused with what they are.
    const std::string text = pyramidScratch("notes.ome.tif");
    std::ofstream(text) << "not an image\n";
    auto notTiff = imaging::PyramidReader::open(text, "notes.ome.tif");
    ASSERT_FALSE(notTiff.ok());
    EXPECT_EQ(notTiff.problems().front().message.id, "imaging.tiff.unreadable");
    std::vector<std::uint8_t> rgb(8 * 8 * 3, 100);
    const std::string colour = pyramidScratch("colour.tif");
    ASSERT_TRUE(imaging::writeTiffSamples(colour, 8, 8, 3, 8, rgb.data()).empty());
    auto rgbRead = imaging::PyramidReader::open(colour, "colour.tif");
    ASSERT_FALSE(rgbRead.ok());
    EXPECT_EQ(rgbRead.problems().front().message.id, "imaging.pyramid.unsupported");
}

TEST(PyramidReader, XmlAttributesReadInTheCLocale)
{
    const std::string xml = "<Pixels PhysicalSizeX=\"0.325\" SizeX=\"12\"><Plane PositionX=\"-1e-3\" PositionY=\"x\"/>";
    EXPECT_DOUBLE_EQ(*imaging::xmlAttributeNumber(xml, "PhysicalSizeX"), 0.325);
    EXPECT_DOUBLE_EQ(*imaging::xmlAttributeNumber(xml, "PositionX"), -0.001);
    EXPECT_FALSE(imaging::xmlAttributeNumber(xml, "PositionY"));
    EXPECT_FALSE(imaging::xmlAttributeNumber(xml, "SizeZ"));
}
