// A USB camera's frames as BenchPilot takes them: every pixel format the conversion accepts,
// built here as a synthetic QVideoFrame (no camera, no GStreamer), checked pixel by pixel;
// a format it does not accept is refused by name.
#if BP_WITH_UVC
#include "device/camera/video_frame_convert.h"
#include "widgets/wording/wording.h"

#include <QBuffer>
#include <QImage>

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <functional>

namespace cam = dev::camera;
using PF = QVideoFrameFormat::PixelFormat;

namespace {

struct Yuv {
    int y, u, v;
};
struct Rgb {
    int r, g, b;
};

// The 4 × 4 test picture: four 2 × 2 blocks, so every chroma sample of 4:2:0 and 4:2:2
// has its own colour and a chroma row or column taken from the wrong place shows.
//   red   blue
//   green white
constexpr int kW = 4, kH = 4;
int blockOf(int x, int y) { return (y / 2) * 2 + (x / 2); }

// BT.601 limited range ("video levels"): the standard values of the primaries.
const std::array<Yuv, 4> kYuv601 = {{{81, 90, 240}, {41, 240, 110}, {145, 54, 34}, {235, 128, 128}}};
const std::array<Rgb, 4> kRgb = {{{255, 0, 0}, {0, 0, 255}, {0, 255, 0}, {255, 255, 255}}};

/// A frame of `format` and `size`, filled by `fill` with its planes mapped for writing.
QVideoFrame makeFrame(QVideoFrameFormat format, const std::function<void(QVideoFrame&)>& fill)
{
    QVideoFrame frame(format);
    EXPECT_TRUE(frame.map(QVideoFrame::WriteOnly));
    for (int p = 0; p < frame.planeCount(); ++p)
        std::memset(frame.bits(p), 0xEE, static_cast<std::size_t>(frame.mappedBytes(p)));  // padding is not picture
    fill(frame);
    frame.unmap();
    return frame;
}

QVideoFrameFormat formatOf(PF pf, int w = kW, int h = kH) { return QVideoFrameFormat(QSize(w, h), pf); }

std::uint8_t* rowOf(QVideoFrame& f, int plane, int y) { return f.bits(plane) + static_cast<std::ptrdiff_t>(y) * f.bytesPerLine(plane); }

/// Fills a 4:2:0 or 4:2:2 frame from the block picture's YUV.
void fillChroma(QVideoFrame& f, PF pf, const std::array<Yuv, 4>& yuv)
{
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            rowOf(f, 0, y)[x] = static_cast<std::uint8_t>(yuv[blockOf(x, y)].y);
    const bool half = pf != PF::Format_YUV422P;
    const int rows = half ? kH / 2 : kH;
    for (int cy = 0; cy < rows; ++cy)
        for (int cx = 0; cx < kW / 2; ++cx) {
            const Yuv& c = yuv[blockOf(cx * 2, half ? cy * 2 : cy)];
            switch (pf) {
            case PF::Format_NV12:
                rowOf(f, 1, cy)[cx * 2] = static_cast<std::uint8_t>(c.u);
                rowOf(f, 1, cy)[cx * 2 + 1] = static_cast<std::uint8_t>(c.v);
                break;
            case PF::Format_NV21:
                rowOf(f, 1, cy)[cx * 2] = static_cast<std::uint8_t>(c.v);
                rowOf(f, 1, cy)[cx * 2 + 1] = static_cast<std::uint8_t>(c.u);
                break;
            case PF::Format_YV12:
                rowOf(f, 2, cy)[cx] = static_cast<std::uint8_t>(c.u);
                rowOf(f, 1, cy)[cx] = static_cast<std::uint8_t>(c.v);
                break;
            default:  // YUV420P, YUV422P: U then V
                rowOf(f, 1, cy)[cx] = static_cast<std::uint8_t>(c.u);
                rowOf(f, 2, cy)[cx] = static_cast<std::uint8_t>(c.v);
                break;
            }
        }
}

void fillPacked422(QVideoFrame& f, bool uyvy, const std::array<Yuv, 4>& yuv)
{
    for (int y = 0; y < kH; ++y)
        for (int pair = 0; pair < kW / 2; ++pair) {
            const Yuv& c = yuv[blockOf(pair * 2, y)];
            std::uint8_t* d = rowOf(f, 0, y) + pair * 4;
            const std::uint8_t yy = static_cast<std::uint8_t>(c.y), u = static_cast<std::uint8_t>(c.u), v = static_cast<std::uint8_t>(c.v);
            if (uyvy) {
                d[0] = u, d[1] = yy, d[2] = v, d[3] = yy;
            } else {
                d[0] = yy, d[1] = u, d[2] = yy, d[3] = v;
            }
        }
}

/// Every pixel of `f` is the block picture's colour, within `slack` a channel.
void expectBlocks(const cam::Frame& f, int slack, const std::array<Rgb, 4>& want = kRgb)
{
    ASSERT_EQ(f.format, cam::PixelFormat::Rgb8);
    ASSERT_EQ(f.width, kW);
    ASSERT_EQ(f.height, kH);
    ASSERT_EQ(f.pixels.size(), std::size_t(kW * kH * 3));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const std::uint8_t* p = &f.pixels[static_cast<std::size_t>((y * kW + x) * 3)];
            const Rgb& w = want[blockOf(x, y)];
            EXPECT_NEAR(p[0], w.r, slack) << "R at " << x << "," << y;
            EXPECT_NEAR(p[1], w.g, slack) << "G at " << x << "," << y;
            EXPECT_NEAR(p[2], w.b, slack) << "B at " << x << "," << y;
        }
}

} // namespace

TEST(UvcConvert, EveryPlanarAndSemiPlanarYuvFormatGivesThePicture)
{
    for (PF pf : {PF::Format_NV12, PF::Format_NV21, PF::Format_YUV420P, PF::Format_YV12, PF::Format_YUV422P}) {
        SCOPED_TRACE(cam::videoFormatName(pf));
        const QVideoFrame frame = makeFrame(formatOf(pf), [&](QVideoFrame& f) { fillChroma(f, pf, kYuv601); });
        const auto got = cam::frameFromVideo(frame);
        ASSERT_TRUE(got.ok()) << ui::words::text(got.error()).toStdString();
        EXPECT_EQ(got->bitDepth, 8);
        expectBlocks(*got, 3);
    }
}

TEST(UvcConvert, PackedYuyvAndUyvyGiveThePicture)
{
    for (PF pf : {PF::Format_YUYV, PF::Format_UYVY}) {
        SCOPED_TRACE(cam::videoFormatName(pf));
        const QVideoFrame frame = makeFrame(formatOf(pf), [&](QVideoFrame& f) { fillPacked422(f, pf == PF::Format_UYVY, kYuv601); });
        const auto got = cam::frameFromVideo(frame);
        ASSERT_TRUE(got.ok()) << ui::words::text(got.error()).toStdString();
        expectBlocks(*got, 3);
    }
}

TEST(UvcConvert, TheLumaOfEachPixelIsKeptNotOnlyItsBlocks)
{
    // A ramp in Y under neutral chroma: each pixel's own brightness comes through, in order.
    const QVideoFrame frame = makeFrame(formatOf(PF::Format_YUYV), [](QVideoFrame& f) {
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                rowOf(f, 0, y)[x * 2] = static_cast<std::uint8_t>(16 + (y * kW + x) * 14);
                rowOf(f, 0, y)[x * 2 + 1] = 128;
            }
    });
    const auto got = cam::frameFromVideo(frame);
    ASSERT_TRUE(got.ok());
    for (int i = 0; i < kW * kH; ++i) {
        const int want = static_cast<int>(std::lround((i * 14) * 255.0 / 219.0));
        EXPECT_NEAR(got->pixels[static_cast<std::size_t>(i * 3)], std::min(want, 255), 1) << i;
        EXPECT_EQ(got->pixels[static_cast<std::size_t>(i * 3)], got->pixels[static_cast<std::size_t>(i * 3 + 2)]) << "grey stays grey at " << i;
    }
}

TEST(UvcConvert, FullRangeAndBt709AreReadAsTheFrameSays)
{
    // The same primaries in full-range BT.601 (Motion-JPEG's) and limited-range BT.709 (HD video's).
    const std::array<Yuv, 4> full601 = {{{76, 85, 255}, {29, 255, 107}, {150, 44, 21}, {255, 128, 128}}};
    const std::array<Yuv, 4> limited709 = {{{63, 102, 240}, {32, 240, 118}, {173, 42, 26}, {235, 128, 128}}};
    QVideoFrameFormat f601 = formatOf(PF::Format_NV12);
    f601.setColorRange(QVideoFrameFormat::ColorRange_Full);
    f601.setColorSpace(QVideoFrameFormat::ColorSpace_BT601);
    const auto a = cam::frameFromVideo(makeFrame(f601, [&](QVideoFrame& f) { fillChroma(f, PF::Format_NV12, full601); }));
    ASSERT_TRUE(a.ok());
    expectBlocks(*a, 4);
    QVideoFrameFormat f709 = formatOf(PF::Format_NV12);
    f709.setColorRange(QVideoFrameFormat::ColorRange_Video);
    f709.setColorSpace(QVideoFrameFormat::ColorSpace_BT709);
    const auto b = cam::frameFromVideo(makeFrame(f709, [&](QVideoFrame& f) { fillChroma(f, PF::Format_NV12, limited709); }));
    ASSERT_TRUE(b.ok());
    expectBlocks(*b, 4);
    // Read with the wrong rule, the red is visibly off: the test can tell the rules apart.
    const auto wrong = cam::frameFromVideo(makeFrame(formatOf(PF::Format_NV12), [&](QVideoFrame& f) { fillChroma(f, PF::Format_NV12, limited709); }));
    ASSERT_TRUE(wrong.ok());
    EXPECT_GT(std::abs(int(wrong->pixels[1]) - 0) + std::abs(int(wrong->pixels[0]) - 255), 8);
}

TEST(UvcConvert, EveryThirtyTwoBitRgbLayoutGivesThePicture)
{
    struct Layout {
        PF pf;
        int r, g, b, a;  ///< byte of each in the pixel (Qt names the formats in byte order)
    };
    const Layout layouts[] = {
        {PF::Format_ARGB8888, 1, 2, 3, 0}, {PF::Format_ARGB8888_Premultiplied, 1, 2, 3, 0}, {PF::Format_XRGB8888, 1, 2, 3, 0},
        {PF::Format_BGRA8888, 2, 1, 0, 3}, {PF::Format_BGRA8888_Premultiplied, 2, 1, 0, 3}, {PF::Format_BGRX8888, 2, 1, 0, 3},
        {PF::Format_ABGR8888, 3, 2, 1, 0}, {PF::Format_XBGR8888, 3, 2, 1, 0},                {PF::Format_RGBA8888, 0, 1, 2, 3},
        {PF::Format_RGBX8888, 0, 1, 2, 3},
    };
    // Distinct values per pixel and channel, so a swapped channel or pixel shows.
    auto value = [](int x, int y, int c) { return static_cast<std::uint8_t>(10 + 60 * c + 4 * (y * kW + x)); };
    for (const Layout& l : layouts) {
        SCOPED_TRACE(cam::videoFormatName(l.pf));
        const QVideoFrame frame = makeFrame(formatOf(l.pf), [&](QVideoFrame& f) {
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    std::uint8_t* p = rowOf(f, 0, y) + x * 4;
                    p[l.r] = value(x, y, 0);
                    p[l.g] = value(x, y, 1);
                    p[l.b] = value(x, y, 2);
                    p[l.a] = 255;
                }
        });
        const auto got = cam::frameFromVideo(frame);
        ASSERT_TRUE(got.ok()) << ui::words::text(got.error()).toStdString();
        ASSERT_EQ(got->format, cam::PixelFormat::Rgb8);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                for (int c = 0; c < 3; ++c)
                    ASSERT_EQ(got->pixels[static_cast<std::size_t>((y * kW + x) * 3 + c)], value(x, y, c)) << x << "," << y << " channel " << c;
    }
}

TEST(UvcConvert, GreyStaysGreyAtItsOwnDepth)
{
    const QVideoFrame y8 = makeFrame(formatOf(PF::Format_Y8, 5, 3), [](QVideoFrame& f) {
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                rowOf(f, 0, y)[x] = static_cast<std::uint8_t>(y * 50 + x);
    });
    const auto a = cam::frameFromVideo(y8);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a->format, cam::PixelFormat::Grey8);
    EXPECT_EQ(a->bitDepth, 8);
    ASSERT_EQ(a->pixels.size(), 15u);
    EXPECT_EQ(a->pixels[0], 0);
    EXPECT_EQ(a->pixels[7], 52);  // row 1, column 2: the stride's padding is skipped
    EXPECT_EQ(a->pixels[14], 104);

    const QVideoFrame y16 = makeFrame(formatOf(PF::Format_Y16, 3, 2), [](QVideoFrame& f) {
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                const std::uint16_t v = static_cast<std::uint16_t>(y == 1 && x == 2 ? 65535 : 0x1234 + y * 0x1000 + x);
                std::memcpy(rowOf(f, 0, y) + x * 2, &v, 2);
            }
    });
    const auto b = cam::frameFromVideo(y16);
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(b->format, cam::PixelFormat::Grey16);
    EXPECT_EQ(b->bitDepth, 16);
    ASSERT_EQ(b->pixels.size(), 12u);
    auto at = [&](int i) {
        std::uint16_t v;
        std::memcpy(&v, &b->pixels[static_cast<std::size_t>(i * 2)], 2);
        return v;
    };
    EXPECT_EQ(at(0), 0x1234);
    EXPECT_EQ(at(4), 0x2235);
    EXPECT_EQ(at(5), 65535);
}

TEST(UvcConvert, AFrameStoredBottomUpComesOutTopRowFirst)
{
    QVideoFrameFormat format = formatOf(PF::Format_Y8, 2, 3);
    format.setScanLineDirection(QVideoFrameFormat::BottomToTop);
    const QVideoFrame frame = makeFrame(format, [](QVideoFrame& f) {
        for (int y = 0; y < 3; ++y)
            rowOf(f, 0, y)[0] = rowOf(f, 0, y)[1] = static_cast<std::uint8_t>(10 * (y + 1));  // stored row 0 is the picture's bottom
    });
    const auto got = cam::frameFromVideo(frame);
    ASSERT_TRUE(got.ok());
    EXPECT_EQ(got->pixels, (std::vector<std::uint8_t>{30, 30, 20, 20, 10, 10}));
}

TEST(UvcConvert, MotionJpegIsDecodedInColourAndInGrey)
{
    for (const bool grey : {false, true}) {
        SCOPED_TRACE(grey ? "grey" : "colour");
        QImage picture(16, 16, grey ? QImage::Format_Grayscale8 : QImage::Format_RGB888);
        picture.fill(Qt::black);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                picture.setPixelColor(x, y, grey ? QColor(x < 8 ? 40 : 200, x < 8 ? 40 : 200, x < 8 ? 40 : 200) : (x < 8 ? QColor(220, 30, 30) : QColor(30, 30, 220)));
        QByteArray jpeg;
        QBuffer buffer(&jpeg);
        buffer.open(QIODevice::WriteOnly);
        ASSERT_TRUE(picture.save(&buffer, "JPG", 95));
        const QVideoFrame frame = makeFrame(formatOf(PF::Format_Jpeg, 16, 16), [&](QVideoFrame& f) {
            ASSERT_GE(f.mappedBytes(0), jpeg.size());
            std::memcpy(f.bits(0), jpeg.constData(), static_cast<std::size_t>(jpeg.size()));
        });
        const auto got = cam::frameFromVideo(frame);
        ASSERT_TRUE(got.ok()) << ui::words::text(got.error()).toStdString();
        EXPECT_EQ(got->width, 16);
        EXPECT_EQ(got->height, 16);
        EXPECT_EQ(got->format, grey ? cam::PixelFormat::Grey8 : cam::PixelFormat::Rgb8);
        const int bpp = cam::bytesPerPixel(got->format);
        const std::uint8_t* left = &got->pixels[static_cast<std::size_t>((8 * 16 + 2) * bpp)];
        const std::uint8_t* right = &got->pixels[static_cast<std::size_t>((8 * 16 + 13) * bpp)];
        if (grey) {
            EXPECT_NEAR(left[0], 40, 8);
            EXPECT_NEAR(right[0], 200, 8);
        } else {
            EXPECT_NEAR(left[0], 220, 12);
            EXPECT_NEAR(left[2], 30, 12);
            EXPECT_NEAR(right[0], 30, 12);
            EXPECT_NEAR(right[2], 220, 12);
        }
    }
}

TEST(UvcConvert, AJpegFrameThatIsNotAJpegIsRefusedNotShownAsNoise)
{
    const QVideoFrame frame = makeFrame(formatOf(PF::Format_Jpeg, 8, 8), [](QVideoFrame&) {});
    const auto got = cam::frameFromVideo(frame);
    ASSERT_FALSE(got.ok());
    EXPECT_EQ(got.error().id, "camera.uvc.jpeg_unreadable");
}

TEST(UvcConvert, AFormatNotAcceptedIsRefusedByName)
{
    for (PF pf : {PF::Format_AYUV, PF::Format_P010, PF::Format_IMC1, PF::Format_YUV420P10}) {
        SCOPED_TRACE(cam::videoFormatName(pf));
        EXPECT_FALSE(cam::isAcceptedVideoFormat(pf));
        const QVideoFrame frame(formatOf(pf, 8, 4));
        const auto got = cam::frameFromVideo(frame);
        ASSERT_FALSE(got.ok());
        EXPECT_EQ(got.error().id, "camera.uvc.format_unsupported");
        const QString said = ui::words::text(got.error());
        EXPECT_TRUE(said.contains(QString::fromStdString(cam::videoFormatName(pf)))) << said.toStdString();
        EXPECT_TRUE(said.contains(QStringLiteral("8 × 4"))) << said.toStdString();
    }
    EXPECT_EQ(cam::videoFormatName(PF::Format_NV12), "NV12");
}

TEST(UvcConvert, EveryAcceptedFormatIsCoveredHere)
{
    // A format added to the accepted list without a test above would be taken untested.
    const std::vector<PF> tested = {PF::Format_NV12,     PF::Format_NV21,     PF::Format_YUV420P,  PF::Format_YV12,     PF::Format_YUV422P,
                                    PF::Format_YUYV,     PF::Format_UYVY,     PF::Format_ARGB8888, PF::Format_ARGB8888_Premultiplied,
                                    PF::Format_XRGB8888, PF::Format_BGRA8888, PF::Format_BGRA8888_Premultiplied, PF::Format_BGRX8888,
                                    PF::Format_ABGR8888, PF::Format_XBGR8888, PF::Format_RGBA8888, PF::Format_RGBX8888, PF::Format_Y8,
                                    PF::Format_Y16,      PF::Format_Jpeg};
    for (PF pf : cam::acceptedVideoFormats())
        EXPECT_NE(std::find(tested.begin(), tested.end(), pf), tested.end()) << cam::videoFormatName(pf);
    EXPECT_EQ(cam::acceptedVideoFormats().size(), tested.size());
}

#endif // BP_WITH_UVC
