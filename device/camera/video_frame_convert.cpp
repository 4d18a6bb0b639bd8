#include "device/camera/video_frame_convert.h"

#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace dev::camera {

namespace {

using PF = QVideoFrameFormat::PixelFormat;

/// YUV → RGB in fixed point (×256): R = Y' + rv·V, G = Y' + gu·U + gv·V, B = Y' + bu·U,
/// with Y' = ky·(Y − yOffset) and U, V centred on 128.
struct YuvToRgb {
    int yOffset = 16;
    int ky = 298, rv = 409, gu = -100, gv = -208, bu = 516;

    static std::uint8_t clamp8(int v) { return static_cast<std::uint8_t>(std::clamp(v, 0, 255)); }
    void put(int y, int u, int v, std::uint8_t* rgb) const
    {
        const int c = ky * (y - yOffset) + 128;
        const int d = u - 128, e = v - 128;
        rgb[0] = clamp8((c + rv * e) >> 8);
        rgb[1] = clamp8((c + gu * d + gv * e) >> 8);
        rgb[2] = clamp8((c + bu * d) >> 8);
    }
};

YuvToRgb yuvFor(const QVideoFrameFormat& format, bool fullByDefault)
{
    // Kr, Kb of the colour space; limited range stretches 16..235 (Y) and 16..240 (U, V).
    const bool bt709 = format.colorSpace() == QVideoFrameFormat::ColorSpace_BT709;
    const double kr = bt709 ? 0.2126 : 0.299, kb = bt709 ? 0.0722 : 0.114, kg = 1 - kr - kb;
    const bool full = format.colorRange() == QVideoFrameFormat::ColorRange_Full
                      || (fullByDefault && format.colorRange() == QVideoFrameFormat::ColorRange_Unknown);
    const double ys = full ? 1.0 : 255.0 / 219.0, cs = full ? 1.0 : 255.0 / 224.0;
    auto fixed = [](double v) { return static_cast<int>(std::lround(v * 256)); };
    YuvToRgb t;
    t.yOffset = full ? 0 : 16;
    t.ky = fixed(ys);
    t.rv = fixed(2 * (1 - kr) * cs);
    t.bu = fixed(2 * (1 - kb) * cs);
    t.gu = fixed(-2 * kb * (1 - kb) / kg * cs);
    t.gv = fixed(-2 * kr * (1 - kr) / kg * cs);
    return t;
}

/// Where each colour sits in a 4-byte pixel of the RGB formats (Qt names them in byte order).
struct Rgb32Layout {
    int r, g, b;
};

std::optional<Rgb32Layout> rgb32Layout(PF f)
{
    switch (f) {
    case PF::Format_ARGB8888:
    case PF::Format_ARGB8888_Premultiplied:
    case PF::Format_XRGB8888: return Rgb32Layout{1, 2, 3};
    case PF::Format_BGRA8888:
    case PF::Format_BGRA8888_Premultiplied:
    case PF::Format_BGRX8888: return Rgb32Layout{2, 1, 0};
    case PF::Format_ABGR8888:
    case PF::Format_XBGR8888: return Rgb32Layout{3, 2, 1};
    case PF::Format_RGBA8888:
    case PF::Format_RGBX8888: return Rgb32Layout{0, 1, 2};
    default: return std::nullopt;
    }
}

motion::msg::Message problem(const char* id, const QVideoFrame& v)
{
    return motion::msg::make(id, {motion::msg::verbatim("format", videoFormatName(v.pixelFormat())), motion::msg::integer("width", v.width(), motion::msg::Unit::None),
                                  motion::msg::integer("height", v.height(), motion::msg::Unit::None)});
}

/// A mapped frame's planes, read row by row in the order the picture runs top to bottom.
class Planes {
public:
    Planes(const QVideoFrame& mapped, int height) : m_frame(mapped), m_height(height)
    {
        m_flip = mapped.surfaceFormat().scanLineDirection() == QVideoFrameFormat::BottomToTop;
    }
    /// Row `row` of the picture (0 = top) in a plane of `rows` rows.
    const std::uint8_t* row(int plane, int row, int rows) const
    {
        const int r = m_flip ? rows - 1 - row : row;
        return m_frame.bits(plane) + static_cast<std::ptrdiff_t>(r) * m_frame.bytesPerLine(plane);
    }
    /// True when `plane` holds `rows` rows of at least `rowBytes` each.
    bool holds(int plane, int rows, int rowBytes) const
    {
        if (plane >= m_frame.planeCount() || !m_frame.bits(plane) || m_frame.bytesPerLine(plane) < rowBytes)
            return false;
        const qint64 need = static_cast<qint64>(m_frame.bytesPerLine(plane)) * (rows - 1) + rowBytes;
        return m_frame.mappedBytes(plane) >= need;
    }
    int height() const { return m_height; }

private:
    const QVideoFrame& m_frame;
    int m_height;
    bool m_flip = false;
};

Frame emptyFrame(int w, int h, PixelFormat format, int bitDepth)
{
    Frame f;
    f.width = w;
    f.height = h;
    f.format = format;
    f.bitDepth = bitDepth;
    f.pixels.resize(static_cast<std::size_t>(w) * h * bytesPerPixel(format));
    return f;
}

/// 4:2:0 and 4:2:2, planar or semi-planar: Y in plane 0, chroma `chromaRows` rows of half width.
struct ChromaPlanes {
    int uPlane, vPlane;
    int uOffset, vOffset;  ///< byte of U / V in a chroma sample
    int step;              ///< bytes from one chroma sample to the next along a row
    bool halfHeight;
};

std::optional<ChromaPlanes> chromaPlanes(PF f)
{
    switch (f) {
    case PF::Format_NV12: return ChromaPlanes{1, 1, 0, 1, 2, true};
    case PF::Format_NV21: return ChromaPlanes{1, 1, 1, 0, 2, true};
    case PF::Format_YUV420P: return ChromaPlanes{1, 2, 0, 0, 1, true};
    case PF::Format_YV12: return ChromaPlanes{2, 1, 0, 0, 1, true};
    case PF::Format_YUV422P: return ChromaPlanes{1, 2, 0, 0, 1, false};
    default: return std::nullopt;
    }
}

bool convertChromaPlanes(const Planes& p, const ChromaPlanes& c, const YuvToRgb& yuv, Frame* out)
{
    const int w = out->width, h = out->height;
    const int cw = (w + 1) / 2, ch = c.halfHeight ? (h + 1) / 2 : h;
    if (!p.holds(0, h, w) || !p.holds(c.uPlane, ch, cw * c.step) || !p.holds(c.vPlane, ch, cw * c.step))
        return false;
    for (int y = 0; y < h; ++y) {
        const int cy = c.halfHeight ? y / 2 : y;
        const std::uint8_t* ys = p.row(0, y, h);
        const std::uint8_t* us = p.row(c.uPlane, cy, ch) + c.uOffset;
        const std::uint8_t* vs = p.row(c.vPlane, cy, ch) + c.vOffset;
        std::uint8_t* d = out->pixels.data() + static_cast<std::size_t>(y) * w * 3;
        for (int x = 0; x < w; ++x, d += 3)
            yuv.put(ys[x], us[(x / 2) * c.step], vs[(x / 2) * c.step], d);
    }
    return true;
}

bool convertPacked422(const Planes& p, bool uyvy, const YuvToRgb& yuv, Frame* out)
{
    const int w = out->width, h = out->height;
    const int pairs = (w + 1) / 2;
    if (!p.holds(0, h, pairs * 4))
        return false;
    // YUYV: Y0 U Y1 V; UYVY: U Y0 V Y1.
    const int y0 = uyvy ? 1 : 0, y1 = uyvy ? 3 : 2, u = uyvy ? 0 : 1, v = uyvy ? 2 : 3;
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* s = p.row(0, y, h);
        std::uint8_t* d = out->pixels.data() + static_cast<std::size_t>(y) * w * 3;
        for (int x = 0; x < w; ++x, d += 3) {
            const std::uint8_t* pair = s + (x / 2) * 4;
            yuv.put(pair[(x & 1) ? y1 : y0], pair[u], pair[v], d);
        }
    }
    return true;
}

bool convertRgb32(const Planes& p, Rgb32Layout l, Frame* out)
{
    const int w = out->width, h = out->height;
    if (!p.holds(0, h, w * 4))
        return false;
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* s = p.row(0, y, h);
        std::uint8_t* d = out->pixels.data() + static_cast<std::size_t>(y) * w * 3;
        for (int x = 0; x < w; ++x, s += 4, d += 3) {
            d[0] = s[l.r];
            d[1] = s[l.g];
            d[2] = s[l.b];
        }
    }
    return true;
}

bool copyGrey(const Planes& p, int bytes, Frame* out)
{
    const int w = out->width, h = out->height;
    const int rowBytes = w * bytes;
    if (!p.holds(0, h, rowBytes))
        return false;
    for (int y = 0; y < h; ++y)
        std::memcpy(out->pixels.data() + static_cast<std::size_t>(y) * rowBytes, p.row(0, y, h), static_cast<std::size_t>(rowBytes));
    return true;
}

motion::msg::Checked<Frame> decodeJpeg(const QVideoFrame& mapped)
{
    QImage image = QImage::fromData(mapped.bits(0), mapped.mappedBytes(0), "JPEG");
    if (image.isNull())
        return motion::msg::Checked<Frame>::fail(problem("camera.uvc.jpeg_unreadable", mapped));
    const bool grey = image.isGrayscale();
    image = image.convertToFormat(grey ? QImage::Format_Grayscale8 : QImage::Format_RGB888);
    Frame f = emptyFrame(image.width(), image.height(), grey ? PixelFormat::Grey8 : PixelFormat::Rgb8, 8);
    const int rowBytes = image.width() * bytesPerPixel(f.format);
    for (int y = 0; y < image.height(); ++y)
        std::memcpy(f.pixels.data() + static_cast<std::size_t>(y) * rowBytes, image.constScanLine(y), static_cast<std::size_t>(rowBytes));
    return motion::msg::Checked<Frame>::ok(std::move(f));
}

} // namespace

const std::vector<QVideoFrameFormat::PixelFormat>& acceptedVideoFormats()
{
    static const std::vector<PF> kAccepted = {
        PF::Format_NV12,     PF::Format_NV21,     PF::Format_YUV420P,  PF::Format_YV12,
        PF::Format_YUV422P,  PF::Format_YUYV,     PF::Format_UYVY,     PF::Format_ARGB8888,
        PF::Format_ARGB8888_Premultiplied,        PF::Format_XRGB8888, PF::Format_BGRA8888,
        PF::Format_BGRA8888_Premultiplied,        PF::Format_BGRX8888, PF::Format_ABGR8888,
        PF::Format_XBGR8888, PF::Format_RGBA8888, PF::Format_RGBX8888, PF::Format_Y8,
        PF::Format_Y16,      PF::Format_Jpeg,
    };
    return kAccepted;
}

bool isAcceptedVideoFormat(QVideoFrameFormat::PixelFormat format)
{
    const auto& all = acceptedVideoFormats();
    return std::find(all.begin(), all.end(), format) != all.end();
}

std::string videoFormatName(QVideoFrameFormat::PixelFormat format)
{
    QString name = QVideoFrameFormat::pixelFormatToString(format);
    if (name.startsWith(QLatin1String("Format_")))
        name = name.mid(7);
    return name.toStdString();
}

motion::msg::Checked<Frame> frameFromVideo(const QVideoFrame& video)
{
    using Result = motion::msg::Checked<Frame>;
    const PF pf = video.pixelFormat();
    if (!isAcceptedVideoFormat(pf))
        return Result::fail(problem("camera.uvc.format_unsupported", video));
    const int w = video.width(), h = video.height();
    if (w <= 0 || h <= 0)
        return Result::fail(problem("camera.uvc.short_frame", video));
    QVideoFrame mapped = video;  // shares the buffer; mapping it does not touch the caller's frame
    if (!mapped.map(QVideoFrame::ReadOnly))
        return Result::fail(problem("camera.uvc.cannot_map", video));
    struct Unmap {
        QVideoFrame& f;
        ~Unmap() { f.unmap(); }
    } unmap{mapped};

    if (pf == PF::Format_Jpeg)
        return decodeJpeg(mapped);

    const Planes planes(mapped, h);
    const QVideoFrameFormat format = mapped.surfaceFormat();
    bool ok = false;
    Frame out;
    if (pf == PF::Format_Y8 || pf == PF::Format_Y16) {
        const bool wide = pf == PF::Format_Y16;
        out = emptyFrame(w, h, wide ? PixelFormat::Grey16 : PixelFormat::Grey8, wide ? 16 : 8);
        ok = copyGrey(planes, wide ? 2 : 1, &out);
    } else if (const auto layout = rgb32Layout(pf)) {
        out = emptyFrame(w, h, PixelFormat::Rgb8, 8);
        ok = convertRgb32(planes, *layout, &out);
    } else if (const auto chroma = chromaPlanes(pf)) {
        out = emptyFrame(w, h, PixelFormat::Rgb8, 8);
        ok = convertChromaPlanes(planes, *chroma, yuvFor(format, false), &out);
    } else if (pf == PF::Format_YUYV || pf == PF::Format_UYVY) {
        out = emptyFrame(w, h, PixelFormat::Rgb8, 8);
        ok = convertPacked422(planes, pf == PF::Format_UYVY, yuvFor(format, false), &out);
    }
    if (!ok)
        return Result::fail(problem("camera.uvc.short_frame", video));
    return Result::ok(std::move(out));
}

} // namespace dev::camera
