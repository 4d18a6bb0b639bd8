#include "imaging/ome_tiff_writer.h"

#include "imaging/tiff_read.h"

#include <tiffio.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sstream>

namespace imaging {

struct OmeTiffWriter::Level {
    int width = 0, height = 0;
    std::FILE* raw = nullptr;  ///< levels ≥ 1: rows waiting until the level above is written
    int rowsIn = 0;
    ~Level()
    {
        if (raw)
            std::fclose(raw);
    }
};

namespace {

TIFF* asTiff(void* p)
{
    return static_cast<TIFF*>(p);
}

std::string xmlNumber(double v)
{
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(10);
    s << v;
    return s.str();
}

std::string xmlEscape(const std::string& s)
{
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

/// Halves `rows` rows of `w` samples into (rows + 1) / 2 rows of (w + 1) / 2 (2 × 2 means;
/// an odd last row or column averages with itself).
std::vector<std::uint16_t> halve(const std::uint16_t* band, int w, int rows)
{
    const int w2 = (w + 1) / 2, r2 = (rows + 1) / 2;
    std::vector<std::uint16_t> out(static_cast<std::size_t>(w2) * static_cast<std::size_t>(r2));
    for (int y = 0; y < r2; ++y) {
        const std::uint16_t* a = band + static_cast<std::size_t>(2 * y) * static_cast<std::size_t>(w);
        const std::uint16_t* b = (2 * y + 1 < rows) ? a + w : a;
        std::uint16_t* d = out.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w2);
        for (int x = 0; x < w2; ++x) {
            const int x0 = 2 * x, x1 = std::min(2 * x + 1, w - 1);
            d[x] = static_cast<std::uint16_t>((static_cast<unsigned>(a[x0]) + a[x1] + b[x0] + b[x1] + 2) / 4);
        }
    }
    return out;
}

} // namespace

std::string OmeTiffWriter::omeXml(int width, int height, const OmeTiffOptions& o)
{
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>"
      << "<OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\""
      << " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
      << " xsi:schemaLocation=\"http://www.openmicroscopy.org/Schemas/OME/2016-06 http://www.openmicroscopy.org/Schemas/OME/2016-06/ome.xsd\""
      << " Creator=\"BenchPilot " << BP_VERSION << "\">"
      << "<Image ID=\"Image:0\" Name=\"" << xmlEscape(o.imageName) << "\">"
      << "<Pixels ID=\"Pixels:0\" DimensionOrder=\"XYZCT\" Type=\"" << (o.bitsPerSample == 8 ? "uint8" : "uint16") << "\""
      << " SizeX=\"" << width << "\" SizeY=\"" << height << "\" SizeZ=\"1\" SizeC=\"1\" SizeT=\"1\" BigEndian=\"false\"";
    if (o.pixelSizeUm > 0)
        x << " PhysicalSizeX=\"" << xmlNumber(o.pixelSizeUm) << "\" PhysicalSizeXUnit=\"µm\""
          << " PhysicalSizeY=\"" << xmlNumber(o.pixelSizeUm) << "\" PhysicalSizeYUnit=\"µm\"";
    x << "><Channel ID=\"Channel:0:0\" SamplesPerPixel=\"1\"><LightPath/></Channel>"
      << "<TiffData IFD=\"0\" PlaneCount=\"1\"/>";
    x << "<Plane TheZ=\"0\" TheT=\"0\" TheC=\"0\"";
    if (o.stageXMm && o.stageYMm)
        x << " PositionX=\"" << xmlNumber(*o.stageXMm) << "\" PositionXUnit=\"mm\" PositionY=\"" << xmlNumber(*o.stageYMm)
          << "\" PositionYUnit=\"mm\"";
    x << "/></Pixels></Image></OME>";
    return x.str();
}

motion::msg::Checked<std::shared_ptr<OmeTiffWriter>> OmeTiffWriter::open(const std::string& path, int width, int height, const OmeTiffOptions& o)
{
    using Result = motion::msg::Checked<std::shared_ptr<OmeTiffWriter>>;
    quietTiff();
    std::shared_ptr<OmeTiffWriter> w(new OmeTiffWriter);
    w->m_path = path;
    w->m_tempPath = path + ".partial";
    w->m_width = width;
    w->m_height = height;
    w->m_options = o;
    if (width <= 0 || height <= 0 || (o.bitsPerSample != 8 && o.bitsPerSample != 16) || o.tileSize % 16 || o.tileSize <= 0)
        return Result::fail(motion::msg::make("imaging.mosaic.bad_size", {motion::msg::integer("width", width, motion::msg::Unit::None),
                                                                   motion::msg::integer("height", height, motion::msg::Unit::None)}));
    // Levels: the full size, then halvings until the longer side fits.
    int lw = width, lh = height;
    do {
        auto level = std::make_unique<Level>();
        level->width = lw;
        level->height = lh;
        w->m_levels.push_back(std::move(level));
        lw = (lw + 1) / 2;
        lh = (lh + 1) / 2;
    } while (std::max(w->m_levels.back()->width, w->m_levels.back()->height) > o.smallestLevelPx);
    for (std::size_t k = 1; k < w->m_levels.size(); ++k) {
        w->m_levels[k]->raw = std::tmpfile();
        if (!w->m_levels[k]->raw)
            return Result::refused({motion::msg::Problem(path, 0, 0, "", motion::msg::make("imaging.mosaic.write_failed",
                                   {motion::msg::verbatim("file", path), motion::msg::verbatim("reason", std::strerror(errno))}))});
    }
    const double bytes = static_cast<double>(width) * height * (o.bitsPerSample / 8) * 4.0 / 3.0;
    const bool big = o.forceBigTiff || bytes > 2.0e9;
    std::remove(w->m_tempPath.c_str());
    w->m_tif = TIFFOpen(w->m_tempPath.c_str(), big ? "w8" : "w");
    if (!w->m_tif)
        return Result::refused({motion::msg::Problem(path, 0, 0, "", motion::msg::make("imaging.mosaic.cannot_create",
                               {motion::msg::verbatim("file", path), motion::msg::verbatim("reason", lastTiffMessage())}))});
    TIFF* t = asTiff(w->m_tif);
    const std::string xml = omeXml(width, height, o);
    auto fields = [&](int level) {
        const Level& l = *w->m_levels[static_cast<std::size_t>(level)];
        TIFFSetField(t, TIFFTAG_SUBFILETYPE, level == 0 ? 0 : FILETYPE_REDUCEDIMAGE);
        TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(l.width));
        TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(l.height));
        TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, static_cast<uint16_t>(o.bitsPerSample));
        TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, static_cast<uint16_t>(1));
        TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
        TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
        TIFFSetField(t, TIFFTAG_TILEWIDTH, static_cast<uint32_t>(o.tileSize));
        TIFFSetField(t, TIFFTAG_TILELENGTH, static_cast<uint32_t>(o.tileSize));
        if (o.pixelSizeUm > 0) {
            const double perCm = 1e4 / (o.pixelSizeUm * (1 << level));
            TIFFSetField(t, TIFFTAG_XRESOLUTION, perCm);
            TIFFSetField(t, TIFFTAG_YRESOLUTION, perCm);
            TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, RESUNIT_CENTIMETER);
        }
        TIFFSetField(t, TIFFTAG_SOFTWARE, "BenchPilot " BP_VERSION);
    };
    fields(0);
    TIFFSetField(t, TIFFTAG_IMAGEDESCRIPTION, xml.c_str());
    if (w->m_levels.size() > 1) {
        std::vector<toff_t> offsets(w->m_levels.size() - 1, 0);
        TIFFSetField(t, TIFFTAG_SUBIFD, static_cast<uint16_t>(offsets.size()), offsets.data());
    }
    w->m_band.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(o.tileSize), 0);
    return Result::ok(std::move(w));
}

OmeTiffWriter::~OmeTiffWriter()
{
    if (!m_finished)
        discard();
}

void OmeTiffWriter::discard()
{
    if (m_tif) {
        TIFFClose(asTiff(m_tif));
        m_tif = nullptr;
    }
    std::remove(m_tempPath.c_str());
    m_failed = true;
}

motion::msg::Problems OmeTiffWriter::failure(const char* what)
{
    const std::string reason = lastTiffMessage().empty() ? std::string(what) : lastTiffMessage();
    discard();
    return {motion::msg::Problem(m_path, 0, 0, "", motion::msg::make("imaging.mosaic.write_failed", {motion::msg::verbatim("file", m_path), motion::msg::verbatim("reason", reason)}))};
}

// Writes a band of `rows` rows (at most one tile high) of level `level` at the
// current row of that level, and passes its halving down to the next level's file.
motion::msg::Problems OmeTiffWriter::writeBand(int level, const std::uint16_t* band, int rows)
{
    Level& l = *m_levels[static_cast<std::size_t>(level)];
    const int ts = m_options.tileSize;
    TIFF* t = asTiff(m_tif);
    const std::size_t tileSamples = static_cast<std::size_t>(ts) * static_cast<std::size_t>(ts);
    std::vector<std::uint16_t> tile16(tileSamples);
    std::vector<std::uint8_t> tile8(m_options.bitsPerSample == 8 ? tileSamples : 0);
    for (int x0 = 0; x0 < l.width; x0 += ts) {
        std::fill(tile16.begin(), tile16.end(), 0);
        const int cw = std::min(ts, l.width - x0);
        for (int r = 0; r < rows; ++r)
            std::copy(band + static_cast<std::size_t>(r) * static_cast<std::size_t>(l.width) + x0,
                      band + static_cast<std::size_t>(r) * static_cast<std::size_t>(l.width) + x0 + cw,
                      tile16.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(ts));
        void* data = tile16.data();
        if (m_options.bitsPerSample == 8) {
            std::transform(tile16.begin(), tile16.end(), tile8.begin(), [](std::uint16_t v) { return static_cast<std::uint8_t>(std::min<unsigned>(v, 255)); });
            data = tile8.data();
        }
        if (TIFFWriteTile(t, data, static_cast<uint32_t>(x0), static_cast<uint32_t>(l.rowsIn), 0, 0) < 0)
            return failure("cannot write a tile");
    }
    l.rowsIn += rows;
    if (static_cast<std::size_t>(level) + 1 < m_levels.size()) {
        Level& next = *m_levels[static_cast<std::size_t>(level) + 1];
        const std::vector<std::uint16_t> half = halve(band, l.width, rows);
        if (std::fwrite(half.data(), sizeof(std::uint16_t), half.size(), next.raw) != half.size())
            return failure(std::strerror(errno));
    }
    return {};
}

motion::msg::Problems OmeTiffWriter::writeRows(const std::uint16_t* rows, int count)
{
    if (m_failed || m_finished)
        return {};
    const int ts = m_options.tileSize;
    for (int r = 0; r < count && m_rowsDone < m_height; ++r, ++m_rowsDone) {
        std::copy(rows + static_cast<std::size_t>(r) * static_cast<std::size_t>(m_width),
                  rows + static_cast<std::size_t>(r + 1) * static_cast<std::size_t>(m_width),
                  m_band.data() + static_cast<std::size_t>(m_bandRows) * static_cast<std::size_t>(m_width));
        if (++m_bandRows == ts) {
            motion::msg::Problems p = writeBand(0, m_band.data(), m_bandRows);
            m_bandRows = 0;
            if (!p.empty())
                return p;
        }
    }
    return {};
}

motion::msg::Problems OmeTiffWriter::finish()
{
    if (m_failed || m_finished)
        return {};
    if (m_rowsDone < m_height) {
        // Rows never given are written as zeros, so the file is whole; the caller's
        // bug, not the disk's.
        std::vector<std::uint16_t> zeros(static_cast<std::size_t>(m_width), 0);
        while (m_rowsDone < m_height) {
            motion::msg::Problems p = writeRows(zeros.data(), 1);
            if (!p.empty())
                return p;
        }
    }
    if (m_bandRows > 0) {
        motion::msg::Problems p = writeBand(0, m_band.data(), m_bandRows);
        m_bandRows = 0;
        if (!p.empty())
            return p;
    }
    TIFF* t = asTiff(m_tif);
    if (!TIFFWriteDirectory(t))
        return failure("cannot write the directory");
    const int ts = m_options.tileSize;
    for (std::size_t k = 1; k < m_levels.size(); ++k) {
        Level& l = *m_levels[k];
        const OmeTiffOptions& o = m_options;
        TIFFSetField(t, TIFFTAG_SUBFILETYPE, FILETYPE_REDUCEDIMAGE);
        TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(l.width));
        TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(l.height));
        TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, static_cast<uint16_t>(o.bitsPerSample));
        TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, static_cast<uint16_t>(1));
        TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
        TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
        TIFFSetField(t, TIFFTAG_TILEWIDTH, static_cast<uint32_t>(ts));
        TIFFSetField(t, TIFFTAG_TILELENGTH, static_cast<uint32_t>(ts));
        if (o.pixelSizeUm > 0) {
            const double perCm = 1e4 / (o.pixelSizeUm * static_cast<double>(1u << k));
            TIFFSetField(t, TIFFTAG_XRESOLUTION, perCm);
            TIFFSetField(t, TIFFTAG_YRESOLUTION, perCm);
            TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, RESUNIT_CENTIMETER);
        }
        std::rewind(l.raw);
        std::vector<std::uint16_t> band(static_cast<std::size_t>(l.width) * static_cast<std::size_t>(ts));
        for (int y0 = 0; y0 < l.height; y0 += ts) {
            const int rows = std::min(ts, l.height - y0);
            const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(l.width);
            if (std::fread(band.data(), sizeof(std::uint16_t), n, l.raw) != n)
                return failure("cannot read back a pyramid level");
            motion::msg::Problems p = writeBand(static_cast<int>(k), band.data(), rows);
            if (!p.empty())
                return p;
        }
        std::fclose(l.raw);
        l.raw = nullptr;
        if (!TIFFWriteDirectory(t))
            return failure("cannot write the directory");
    }
    if (!TIFFFlush(t))
        return failure("cannot flush the file");
    TIFFClose(t);
    m_tif = nullptr;
    if (std::rename(m_tempPath.c_str(), m_path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(m_tempPath.c_str());
        m_failed = true;
        return {motion::msg::Problem(m_path, 0, 0, "", motion::msg::make("imaging.mosaic.write_failed", {motion::msg::verbatim("file", m_path), motion::msg::verbatim("reason", reason)}))};
    }
    m_finished = true;
    return {};
}

std::string readImageDescription(const std::string& path)
{
    quietTiff();
    TIFF* t = TIFFOpen(path.c_str(), "r");
    if (!t)
        return {};
    char* desc = nullptr;
    std::string out;
    if (TIFFGetField(t, TIFFTAG_IMAGEDESCRIPTION, &desc) && desc)
        out = desc;
    TIFFClose(t);
    return out;
}

} // namespace imaging
