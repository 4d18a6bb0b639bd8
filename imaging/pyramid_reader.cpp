#include "imaging/pyramid_reader.h"

#include "imaging/tiff_read.h"

#include <tiffio.h>

#include <algorithm>
#include <cstring>
#include <locale>
#include <sstream>

namespace imaging {
namespace {

TIFF* pyramidTiff(void* p) { return static_cast<TIFF*>(p); }

motion::msg::Problem pyramidProblem(const std::string& file, const char* id, std::vector<motion::msg::Arg> extra = {})
{
    std::vector<motion::msg::Arg> args{motion::msg::verbatim("file", file)};
    for (auto& a : extra)
        args.push_back(std::move(a));
    return motion::msg::Problem(file, 0, 0, "", motion::msg::make(id, std::move(args)));
}

// A mosaic's side beyond this is no stage's scan (a million 1 µm pixels is a metre);
// a block beyond this many bytes is refused, which bounds what a hostile header can
// make the reader allocate.
constexpr std::uint32_t kMaxSidePx = 1u << 20;
constexpr std::uint64_t kMaxBlockBytes = 64ull << 20;

} // namespace

std::optional<double> xmlAttributeNumber(const std::string& xml, const std::string& name)
{
    const std::string key = " " + name + "=\"";
    const std::size_t at = xml.find(key);
    if (at == std::string::npos)
        return std::nullopt;
    const std::size_t start = at + key.size();
    const std::size_t end = xml.find('"', start);
    if (end == std::string::npos)
        return std::nullopt;
    std::istringstream s(xml.substr(start, end - start));
    s.imbue(std::locale::classic());
    double v = 0;
    if (!(s >> v) || !s.eof())
        return std::nullopt;
    return v;
}

motion::msg::Checked<std::shared_ptr<PyramidReader>> PyramidReader::open(const std::string& path, const std::string& shownName)
{
    using Result = motion::msg::Checked<std::shared_ptr<PyramidReader>>;
    quietTiff();
    const std::string shown = shownName.empty() ? path : shownName;
    std::shared_ptr<PyramidReader> r(new PyramidReader);
    r->m_path = path;
    r->m_shown = shown;
    r->m_tif = TIFFOpen(path.c_str(), "rm");  // "m": no memory-mapping, so a file cut short fails a read rather than faulting
    if (!r->m_tif)
        return Result::refused({pyramidProblem(shown, "imaging.tiff.unreadable", {motion::msg::verbatim("reason", lastTiffMessage())})});
    TIFF* t = pyramidTiff(r->m_tif);

    // The level's shape, checked: grey, 8 or 16 bits, one sample, sizes and blocks bounded.
    auto describe = [&](int level, PyramidLevel* out, bool* tiled, std::string* why) {
        uint32_t w = 0, h = 0;
        uint16_t bits = 0, spp = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG, photometric = PHOTOMETRIC_MINISBLACK;
        TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &w);
        TIFFGetField(t, TIFFTAG_IMAGELENGTH, &h);
        TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &bits);
        TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &spp);
        TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLEFORMAT, &format);
        TIFFGetFieldDefaulted(t, TIFFTAG_PLANARCONFIG, &planar);
        TIFFGetField(t, TIFFTAG_PHOTOMETRIC, &photometric);
        if (spp != 1 || (bits != 8 && bits != 16) || format != SAMPLEFORMAT_UINT || photometric != PHOTOMETRIC_MINISBLACK) {
            if (level == 0)
                return 2;  // the file is not a grey mosaic: said with its bits and samples
            *why = "not 8- or 16-bit grey";
            return 1;
        }
        if (w == 0 || h == 0 || w > kMaxSidePx || h > kMaxSidePx) {
            *why = std::to_string(w) + " x " + std::to_string(h) + " px";
            return 1;
        }
        *tiled = TIFFIsTiled(t) != 0;
        uint32_t bw = w, bh = 0;
        if (*tiled) {
            TIFFGetField(t, TIFFTAG_TILEWIDTH, &bw);
            TIFFGetField(t, TIFFTAG_TILELENGTH, &bh);
        } else {
            TIFFGetFieldDefaulted(t, TIFFTAG_ROWSPERSTRIP, &bh);
            bh = std::min(bh, h);
        }
        if (bw == 0 || bh == 0 || std::uint64_t(bw) * bh * (bits / 8) > kMaxBlockBytes) {
            *why = "blocks of " + std::to_string(bw) + " x " + std::to_string(bh) + " px";
            return 1;
        }
        out->width = static_cast<int>(w);
        out->height = static_cast<int>(h);
        out->blockWidth = static_cast<int>(bw);
        out->blockHeight = static_cast<int>(bh);
        r->m_bits = bits;
        return 0;
    };

    PyramidLevel full;
    std::string why;
    bool tiled = true;
    const int first = describe(0, &full, &tiled, &why);
    if (first == 2) {
        uint16_t bits = 0, spp = 1;
        TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &bits);
        TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &spp);
        return Result::refused({pyramidProblem(shown, "imaging.pyramid.unsupported", {motion::msg::integer("bits", bits, motion::msg::Unit::None),
                                                                                      motion::msg::integer("samples", spp, motion::msg::Unit::None)})});
    }
    if (first != 0)
        return Result::refused({pyramidProblem(shown, "imaging.pyramid.bad_level", {motion::msg::integer("level", 0, motion::msg::Unit::None),
                                                                                    motion::msg::verbatim("reason", why)})});
    const int bits0 = r->m_bits;
    r->m_levels.push_back(full);
    r->m_tiled = tiled;
    char* desc = nullptr;
    if (TIFFGetField(t, TIFFTAG_IMAGEDESCRIPTION, &desc) && desc) {
        const std::string xml = desc;
        if (xml.find("<OME") != std::string::npos) {
            if (auto um = xmlAttributeNumber(xml, "PhysicalSizeX"); um && *um > 0 && *um < 1e6)
                r->m_pixelUm = *um;
            const auto x = xmlAttributeNumber(xml, "PositionX"), y = xmlAttributeNumber(xml, "PositionY");
            if (x && y)
                r->m_stageMm = Eigen::Vector2d(*x, *y);
        }
    }
    if (r->m_pixelUm == 0) {
        float res = 0;
        uint16_t unit = RESUNIT_NONE;
        TIFFGetFieldDefaulted(t, TIFFTAG_RESOLUTIONUNIT, &unit);
        if (TIFFGetField(t, TIFFTAG_XRESOLUTION, &res) && res > 0 && (unit == RESUNIT_CENTIMETER || unit == RESUNIT_INCH))
            r->m_pixelUm = (unit == RESUNIT_CENTIMETER ? 1e4 : 25400.0) / res;
    }

    uint16_t count = 0;
    toff_t* offsets = nullptr;
    if (TIFFGetField(t, TIFFTAG_SUBIFD, &count, &offsets) && offsets)
        r->m_subIfdOffsets.assign(offsets, offsets + count);
    for (std::size_t k = 0; k < r->m_subIfdOffsets.size(); ++k) {
        const int level = static_cast<int>(k) + 1;
        auto bad = [&](const std::string& reason) {
            return Result::refused({pyramidProblem(shown, "imaging.pyramid.bad_level", {motion::msg::integer("level", level, motion::msg::Unit::None),
                                                                                        motion::msg::verbatim("reason", reason)})});
        };
        if (!TIFFSetSubDirectory(t, r->m_subIfdOffsets[k]))
            return bad(lastTiffMessage().empty() ? "its directory cannot be read" : lastTiffMessage());
        PyramidLevel l;
        bool levelTiled = true;
        if (describe(level, &l, &levelTiled, &why) != 0)
            return bad(why);
        const PyramidLevel& above = r->m_levels.back();
        // Each level is smaller than the one above it, of the same depth and storage.
        if (l.width >= above.width && l.height >= above.height && !(above.width == 1 && above.height == 1))
            return bad("not smaller than the level above");
        if (r->m_bits != bits0 || levelTiled != r->m_tiled)
            return bad("stored unlike the full resolution");
        l.scale = double(full.width) / l.width;
        r->m_levels.push_back(l);
    }
    r->m_bits = bits0;
    r->m_current = -1;
    return Result::ok(std::move(r));
}

PyramidReader::~PyramidReader()
{
    if (m_tif)
        TIFFClose(pyramidTiff(m_tif));
}

bool PyramidReader::selectLevel(int level)
{
    if (level == m_current)
        return true;
    TIFF* t = pyramidTiff(m_tif);
    const bool ok = level == 0 ? TIFFSetDirectory(t, 0) != 0 : TIFFSetSubDirectory(t, m_subIfdOffsets[static_cast<std::size_t>(level) - 1]) != 0;
    m_current = ok ? level : -1;
    return ok;
}

motion::msg::Checked<ImageU16> PyramidReader::readRegion(int level, int x, int y, int w, int h)
{
    using Result = motion::msg::Checked<ImageU16>;
    std::lock_guard<std::mutex> hold(m_lock);
    quietTiff();
    if (level < 0 || level >= static_cast<int>(m_levels.size()))
        return Result::refused({pyramidProblem(m_shown, "imaging.pyramid.bad_level", {motion::msg::integer("level", level, motion::msg::Unit::None),
                                                                                      motion::msg::verbatim("reason", "no such level")})});
    const PyramidLevel& l = m_levels[static_cast<std::size_t>(level)];
    const int x0 = std::clamp(x, 0, l.width), y0 = std::clamp(y, 0, l.height);
    const int x1 = std::clamp(x + std::max(w, 0), x0, l.width), y1 = std::clamp(y + std::max(h, 0), y0, l.height);
    ImageU16 out(x1 - x0, y1 - y0);
    if (out.empty())
        return Result::ok(std::move(out));
    auto damaged = [&] {
        m_current = -1;  // libtiff's state after a failed read is not trusted
        return Result::refused({pyramidProblem(m_shown, "imaging.tiff.damaged", {motion::msg::verbatim("reason", lastTiffMessage())})});
    };
    if (!selectLevel(level))
        return damaged();
    TIFF* t = pyramidTiff(m_tif);
    const int bytes = m_bits / 8;
    const std::size_t blockBytes = static_cast<std::size_t>(l.blockWidth) * static_cast<std::size_t>(l.blockHeight) * static_cast<std::size_t>(bytes);
    const tmsize_t libBytes = m_tiled ? TIFFTileSize(t) : TIFFStripSize(t);
    if (libBytes <= 0 || static_cast<std::size_t>(libBytes) < blockBytes)
        return damaged();
    std::vector<unsigned char> buf(static_cast<std::size_t>(libBytes));
    for (int by = y0 / l.blockHeight * l.blockHeight; by < y1; by += l.blockHeight) {
        for (int bx = x0 / l.blockWidth * l.blockWidth; bx < x1; bx += l.blockWidth) {
            const int rows = std::min(l.blockHeight, l.height - by);
            tmsize_t got = 0;
            if (m_tiled)
                got = TIFFReadTile(t, buf.data(), static_cast<uint32_t>(bx), static_cast<uint32_t>(by), 0, 0);
            else
                got = TIFFReadEncodedStrip(t, TIFFComputeStrip(t, static_cast<uint32_t>(by), 0), buf.data(), libBytes);
            const std::size_t need = m_tiled ? blockBytes : static_cast<std::size_t>(rows) * static_cast<std::size_t>(l.blockWidth) * static_cast<std::size_t>(bytes);
            if (got < 0 || static_cast<std::size_t>(got) < need)
                return damaged();
            ++m_blocksRead;
            const int cx0 = std::max(x0, bx), cx1 = std::min(x1, bx + l.blockWidth);
            const int cy0 = std::max(y0, by), cy1 = std::min(y1, by + rows);
            for (int yy = cy0; yy < cy1; ++yy) {
                const unsigned char* src = buf.data() + (static_cast<std::size_t>(yy - by) * static_cast<std::size_t>(l.blockWidth) + static_cast<std::size_t>(cx0 - bx)) * static_cast<std::size_t>(bytes);
                std::uint16_t* dst = out.row(yy - y0) + (cx0 - x0);
                if (bytes == 1) {
                    for (int i = 0; i < cx1 - cx0; ++i)
                        dst[i] = src[i];
                } else {
                    std::memcpy(dst, src, static_cast<std::size_t>(cx1 - cx0) * 2);
                }
            }
        }
    }
    return Result::ok(std::move(out));
}

} // namespace imaging
