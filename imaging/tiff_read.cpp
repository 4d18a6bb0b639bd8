#include "imaging/tiff_read.h"

#include <tiffio.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <memory>
#include <mutex>

namespace imaging {
namespace {

thread_local std::string tlsTiffMessage;

void captureTiffMessage(const char* module, const char* fmt, va_list ap)
{
    char buf[512];
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    tlsTiffMessage = module ? std::string(module) + ": " + buf : std::string(buf);
}

void ignoreTiffWarning(const char*, const char*, va_list) {}

struct TiffCloser {
    void operator()(TIFF* t) const { TIFFClose(t); }
};
using TiffHandle = std::unique_ptr<TIFF, TiffCloser>;

motion::msg::Problem readProblem(const std::string& file, const char* id, std::vector<motion::msg::Arg> extra = {})
{
    std::vector<motion::msg::Arg> args{motion::msg::verbatim("file", file)};
    for (auto& a : extra)
        args.push_back(std::move(a));
    motion::msg::Problem p(file, 0, 0, "", motion::msg::make(id, std::move(args)));
    return p;
}

struct Opened {
    TiffHandle tif;
    TiffInfo info;
    int bits = 0;
    int samples = 0;
};

motion::msg::Checked<Opened> openTiff(const std::string& path, const std::string& shown)
{
    quietTiff();
    tlsTiffMessage.clear();
    Opened o;
    o.tif.reset(TIFFOpen(path.c_str(), "r"));
    if (!o.tif)
        return motion::msg::Checked<Opened>::refused({readProblem(shown, "imaging.tiff.unreadable", {motion::msg::verbatim("reason", lastTiffMessage())})});
    uint32_t w = 0, h = 0;
    uint16_t bits = 0, spp = 1, photometric = 0, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG;
    TIFFGetField(o.tif.get(), TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(o.tif.get(), TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(o.tif.get(), TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(o.tif.get(), TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(o.tif.get(), TIFFTAG_SAMPLEFORMAT, &format);
    TIFFGetFieldDefaulted(o.tif.get(), TIFFTAG_PLANARCONFIG, &planar);
    TIFFGetField(o.tif.get(), TIFFTAG_PHOTOMETRIC, &photometric);
    // A tile larger than 64k a side is no camera's frame; refusing it bounds what a
    // hostile header can make us allocate.
    if (w == 0 || h == 0 || w > 65536 || h > 65536)
        return motion::msg::Checked<Opened>::refused({readProblem(shown, "imaging.tiff.bad_size",
                                                         {motion::msg::integer("width", w, motion::msg::Unit::None), motion::msg::integer("height", h, motion::msg::Unit::None)})});
    const bool grey = spp == 1 && (photometric == PHOTOMETRIC_MINISBLACK || photometric == PHOTOMETRIC_MINISWHITE);
    const bool rgb = spp == 3 && photometric == PHOTOMETRIC_RGB && bits == 8 && planar == PLANARCONFIG_CONTIG;
    if (format != SAMPLEFORMAT_UINT || !((grey && (bits == 8 || bits == 16)) || rgb))
        return motion::msg::Checked<Opened>::refused({readProblem(shown, "imaging.tiff.unsupported",
                                                         {motion::msg::integer("bits", bits, motion::msg::Unit::None), motion::msg::integer("samples", spp, motion::msg::Unit::None)})});
    o.info.width = static_cast<int>(w);
    o.info.height = static_cast<int>(h);
    o.info.kind = rgb ? SampleKind::Rgb8 : bits == 8 ? SampleKind::Grey8 : SampleKind::Grey16;
    o.bits = bits;
    o.samples = spp;
    if (photometric == PHOTOMETRIC_MINISWHITE)
        o.bits = -bits;  // inverted below
    return motion::msg::Checked<Opened>::ok(std::move(o));
}

// One row of decoded samples into 16-bit grey. RGB uses Rec. 601 luma weights: any
// fixed weighting registers the same, and these match what ImageJ's 8-bit conversion gives.
void widenRow(const unsigned char* src, int width, int bits, int samples, std::uint16_t* dst)
{
    const int b = bits < 0 ? -bits : bits;
    for (int x = 0; x < width; ++x) {
        std::uint32_t v = 0;
        if (samples == 3) {
            const unsigned char* p = src + 3 * x;
            v = (299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u;
        } else if (b == 8) {
            v = src[x];
        } else {
            std::uint16_t s;
            std::memcpy(&s, src + 2 * x, 2);
            v = s;
        }
        if (bits < 0)
            v = (b == 8 ? 255u : 65535u) - v;
        dst[x] = static_cast<std::uint16_t>(v);
    }
}

} // namespace

void quietTiff()
{
    static std::once_flag once;
    std::call_once(once, [] {
        TIFFSetErrorHandler(&captureTiffMessage);
        TIFFSetWarningHandler(&ignoreTiffWarning);
    });
}

std::string lastTiffMessage()
{
    return tlsTiffMessage;
}

motion::msg::Checked<TiffInfo> readTiffInfo(const std::string& path, const std::string& shownName)
{
    auto o = openTiff(path, shownName.empty() ? path : shownName);
    if (!o)
        return motion::msg::Checked<TiffInfo>::refused(o.problems());
    return motion::msg::Checked<TiffInfo>::ok(o->info);
}

motion::msg::Checked<TileImage> readTiff(const std::string& path, const std::string& shownName)
{
    const std::string shown = shownName.empty() ? path : shownName;
    auto o = openTiff(path, shown);
    if (!o)
        return motion::msg::Checked<TileImage>::refused(o.problems());
    TIFF* tif = o->tif.get();
    TileImage out;
    out.kind = o->info.kind;
    out.grey = ImageU16(o->info.width, o->info.height);
    const int w = o->info.width, h = o->info.height;
    const std::size_t pixelBytes = static_cast<std::size_t>(o->samples) * static_cast<std::size_t>(std::abs(o->bits) / 8);
    auto broken = [&] {
        return motion::msg::Checked<TileImage>::refused({readProblem(shown, "imaging.tiff.damaged", {motion::msg::verbatim("reason", lastTiffMessage())})});
    };
    if (TIFFIsTiled(tif)) {
        uint32_t tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        if (tw == 0 || th == 0 || tw > 65536 || th > 65536)
            return broken();
        std::vector<unsigned char> buf(static_cast<std::size_t>(TIFFTileSize(tif)));
        if (buf.size() < tw * th * pixelBytes)
            return broken();
        std::vector<std::uint16_t> rowOut(tw);
        for (uint32_t ty = 0; ty < static_cast<uint32_t>(h); ty += th)
            for (uint32_t tx = 0; tx < static_cast<uint32_t>(w); tx += tw) {
                if (TIFFReadTile(tif, buf.data(), tx, ty, 0, 0) < 0)
                    return broken();
                const int cw = std::min<int>(static_cast<int>(tw), w - static_cast<int>(tx));
                const int ch = std::min<int>(static_cast<int>(th), h - static_cast<int>(ty));
                for (int r = 0; r < ch; ++r)
                    widenRow(buf.data() + static_cast<std::size_t>(r) * tw * pixelBytes, cw, o->bits, o->samples,
                             out.grey.row(static_cast<int>(ty) + r) + tx);
            }
    } else {
        const tmsize_t lineBytes = TIFFScanlineSize(tif);
        if (lineBytes < static_cast<tmsize_t>(static_cast<std::size_t>(w) * pixelBytes))
            return broken();
        std::vector<unsigned char> buf(static_cast<std::size_t>(lineBytes));
        for (int y = 0; y < h; ++y) {
            if (TIFFReadScanline(tif, buf.data(), static_cast<uint32_t>(y), 0) < 0)
                return broken();
            widenRow(buf.data(), w, o->bits, o->samples, out.grey.row(y));
        }
    }
    return motion::msg::Checked<TileImage>::ok(std::move(out));
}

} // namespace imaging
