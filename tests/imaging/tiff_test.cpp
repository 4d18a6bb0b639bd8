// Reading tiles (imaging/tiff_read.h) and writing the pyramidal OME-TIFF mosaic
// (imaging/ome_tiff_writer.h, imaging/fusion.h), read back with libtiff itself.
#include "imaging/fusion.h"
#include "imaging/ome_tiff_writer.h"
#include "imaging/tiff_read.h"
#include "imaging/tiff_write.h"
#include "synthetic.h"

#include <gtest/gtest.h>
#include <tiffio.h>

#include <cstdio>
#include <fstream>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

namespace {

std::string scratch(const std::string& name)
{
    const std::string dir = ::testing::TempDir() + "imaging_tiff_" + std::to_string(::getpid());
    std::string cmd = "mkdir -p '" + dir + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return dir + "/" + name;
}

bool exists(const std::string& path)
{
    return std::ifstream(path).good();
}

} // namespace

TEST(TiffRead, ReadsGrey16Grey8AndRgbAsGrey)
{
    imaging::ImageU16 img(40, 30);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x)
            img.at(x, y) = static_cast<std::uint16_t>(x * 1000 + y);
    const std::string p16 = scratch("g16.tif"), p8 = scratch("g8.tif"), prgb = scratch("rgb.tif");
    ASSERT_TRUE(imaging::writeTiff(p16, img, 16).empty());
    ASSERT_TRUE(imaging::writeTiff(p8, img, 8).empty());
    std::vector<std::uint8_t> rgb(40 * 30 * 3);
    for (std::size_t i = 0; i < 40 * 30; ++i) {
        rgb[3 * i] = 200;
        rgb[3 * i + 1] = 100;
        rgb[3 * i + 2] = 50;
    }
    ASSERT_TRUE(imaging::writeTiffSamples(prgb, 40, 30, 3, 8, rgb.data()).empty());

    auto g16 = imaging::readTiff(p16);
    ASSERT_TRUE(g16.ok());
    EXPECT_EQ(g16->kind, imaging::SampleKind::Grey16);
    EXPECT_EQ(g16->grey.at(17, 9), 17009);
    auto g8 = imaging::readTiff(p8);
    ASSERT_TRUE(g8.ok());
    EXPECT_EQ(g8->kind, imaging::SampleKind::Grey8);
    EXPECT_EQ(g8->grey.at(0, 9), 9);
    auto c = imaging::readTiff(prgb);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->kind, imaging::SampleKind::Rgb8);
    EXPECT_EQ(c->grey.at(5, 5), 124);  // 0.299·200 + 0.587·100 + 0.114·50
}

TEST(TiffRead, ATruncatedOrForeignFileIsAProblemNamingIt)
{
    imaging::ImageU16 img(64, 64, 1234);
    const std::string good = scratch("whole.tif"), cut = scratch("cut.tif"), text = scratch("notes.tif");
    ASSERT_TRUE(imaging::writeTiff(good, img).empty());
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(cut, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    std::ofstream(text) << "not an image\n";
    for (const std::string& path : {cut, text}) {
        auto r = imaging::readTiff(path, "shown-name.tif");
        ASSERT_FALSE(r.ok()) << path;
        EXPECT_EQ(r.problems().front().file, "shown-name.tif");
        EXPECT_EQ(r.error().text("file"), "shown-name.tif");
        EXPECT_EQ(r.error().id.rfind("imaging.tiff.", 0), 0u) << r.error().id;
    }
}

TEST(OmeTiff, AFusedMosaicReadsBackWithItsPixelSizeAndPyramid)
{
    const imagingtest::Texture tex(31);
    std::vector<Eigen::Vector2d> pos = {{0, 0}, {100.4, 0}, {0, 90}, {100, 90.6}};
    std::vector<imaging::ImageU16> tiles;
    for (const auto& p : pos)
        tiles.push_back(imagingtest::cutTile(tex, p.x(), p.y(), 120, 110, 0, 1));
    const std::string path = scratch("mosaic.ome.tif");
    imaging::OmeTiffOptions o;
    o.pixelSizeUm = 0.65;
    o.stageXMm = 20.5;
    o.stageYMm = 41.25;
    o.smallestLevelPx = 64;  // so this small mosaic still has a pyramid
    o.tileSize = 64;
    const imaging::MosaicFrame f = imaging::mosaicFrame(pos, 120, 110);
    EXPECT_EQ(f.width, 220);
    EXPECT_EQ(f.height, 201);
    auto w = imaging::OmeTiffWriter::open(path, f.width, f.height, o);
    ASSERT_TRUE(w.ok());
    imaging::FusionOptions fo;
    fo.bandRows = 50;  // several bands, not a multiple of the tile height
    const motion::msg::Problems p = imaging::fuseTiles(pos, 120, 110,
                                               [&](int i) { return motion::msg::Checked<imaging::TileImage>::ok({tiles[static_cast<std::size_t>(i)], imaging::SampleKind::Grey16}); },
                                               **w, fo);
    ASSERT_TRUE(p.empty()) << motion::msg::debugFormat(p);
    EXPECT_FALSE(exists(path + ".partial"));

    TIFF* t = TIFFOpen(path.c_str(), "r");
    ASSERT_NE(t, nullptr);
    uint32_t width = 0, height = 0;
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(t, TIFFTAG_IMAGELENGTH, &height);
    EXPECT_EQ(width, 220u);
    EXPECT_EQ(height, 201u);
    char* desc = nullptr;
    ASSERT_TRUE(TIFFGetField(t, TIFFTAG_IMAGEDESCRIPTION, &desc));
    const std::string xml = desc;
    // Plain finds, not std::regex: GCC 12 warns inside <regex> at -O1 with the sanitizers.
    const std::string sizeKey = " PhysicalSizeX=\"";
    const auto at = xml.find(sizeKey);
    ASSERT_NE(at, std::string::npos) << xml;
    EXPECT_DOUBLE_EQ(std::stod(xml.substr(at + sizeKey.size())), 0.65);
    EXPECT_NE(xml.find("PhysicalSizeXUnit=\"µm\""), std::string::npos);
    EXPECT_NE(xml.find(" SizeX=\"220\" SizeY=\"201\""), std::string::npos);
    EXPECT_NE(xml.find("PositionX=\"20.5\" PositionXUnit=\"mm\""), std::string::npos);
    // The pyramid: SubIFDs of the full resolution, each half the size.
    uint16_t nsub = 0;
    toff_t* offs = nullptr;
    ASSERT_TRUE(TIFFGetField(t, TIFFTAG_SUBIFD, &nsub, &offs));
    ASSERT_EQ(nsub, 2);  // 110 × 101, then 55 × 51
    std::vector<toff_t> subs(offs, offs + nsub);
    // A pixel in the middle of an overlap is the texture there (no noise was added).
    std::vector<std::uint16_t> tileBuf(static_cast<std::size_t>(TIFFTileSize(t) / 2));
    ASSERT_GE(TIFFReadTile(t, tileBuf.data(), 64, 64, 0, 0), 0);
    const int mx = 110, my = 95;  // in tiles 0..3's overlap
    EXPECT_NEAR(tileBuf[static_cast<std::size_t>((my - 64) * 64 + (mx - 64))], tex(mx, my), 120.0);
    ASSERT_TRUE(TIFFSetSubDirectory(t, subs[0]));
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(t, TIFFTAG_IMAGELENGTH, &height);
    EXPECT_EQ(width, 110u);
    EXPECT_EQ(height, 101u);
    uint32_t kind = 0;
    TIFFGetField(t, TIFFTAG_SUBFILETYPE, &kind);
    EXPECT_EQ(kind, static_cast<uint32_t>(FILETYPE_REDUCEDIMAGE));
    ASSERT_TRUE(TIFFSetSubDirectory(t, subs[1]));
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &width);
    EXPECT_EQ(width, 55u);
    TIFFClose(t);
}

namespace {

// Runs in the death-test child: writes a mosaic that cannot fit and exits 3 when the
// writer said so, naming the file.
[[noreturn]] void writeOntoAFullDisk(const std::string& path)
{
    signal(SIGXFSZ, SIG_IGN);
    rlimit lim{64 * 1024, 64 * 1024};
    setrlimit(RLIMIT_FSIZE, &lim);
    imaging::OmeTiffOptions o;
    auto w = imaging::OmeTiffWriter::open(path, 600, 600, o);
    if (!w.ok())
        std::exit(4);
    std::vector<std::uint16_t> rows(600 * 600, 777);
    motion::msg::Problems p = (*w)->writeRows(rows.data(), 600);
    if (p.empty())
        p = (*w)->finish();
    const bool named = !p.empty() && p.front().message.id == "imaging.mosaic.write_failed" && p.front().file == path;
    std::exit(named ? 3 : 5);
}

} // namespace

TEST(OmeTiff, AFullDiskLeavesNoMosaicUnderTheOutputName)
{
    const std::string path = scratch("full-disk.ome.tif");
    std::remove(path.c_str());
    // A child process whose files may not grow past 64 kB stands for a disk that fills.
    EXPECT_EXIT(writeOntoAFullDisk(path), ::testing::ExitedWithCode(3), "");
    EXPECT_FALSE(exists(path));
    EXPECT_FALSE(exists(path + ".partial"));
}

TEST(OmeTiff, ABigTiffMosaicReadsBackTheSame)
{
    const std::string path = scratch("big.ome.tif");
    imaging::OmeTiffOptions o;
    o.pixelSizeUm = 0.325;
    o.forceBigTiff = true;  // what a mosaic past 2 GB gets
    auto w = imaging::OmeTiffWriter::open(path, 300, 200, o);
    ASSERT_TRUE(w.ok());
    std::vector<std::uint16_t> rows(300 * 200);
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = static_cast<std::uint16_t>(i % 60000);
    ASSERT_TRUE((*w)->writeRows(rows.data(), 200).empty());
    ASSERT_TRUE((*w)->finish().empty());
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    EXPECT_EQ(magic[0], 'I');
    EXPECT_EQ(magic[2], 43);  // BigTIFF's version number (classic TIFF is 42)
    TIFF* t = TIFFOpen(path.c_str(), "r");
    ASSERT_NE(t, nullptr);
    std::vector<std::uint16_t> tile(static_cast<std::size_t>(TIFFTileSize(t) / 2));
    ASSERT_GE(TIFFReadTile(t, tile.data(), 0, 0, 0, 0), 0);
    EXPECT_EQ(tile[5 * 256 + 7], rows[5 * 300 + 7]);
    TIFFClose(t);
    EXPECT_NE(imaging::readImageDescription(path).find("PhysicalSizeX=\"0.325\""), std::string::npos);
}
