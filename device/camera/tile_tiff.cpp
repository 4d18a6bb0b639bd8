#include "device/camera/tile_tiff.h"

#include "device/files/json_fields.h"

#include <QCryptographicHash>
#include <QFile>

#include <tiffio.h>

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <mutex>

#include <fcntl.h>
#include <unistd.h>

namespace dev::camera {

namespace {

/// libtiff reports through one process-wide handler: the last message of this thread is
/// kept for the error that follows it.
thread_local std::string t_tiffError;

void onTiffError(const char* module, const char* fmt, va_list ap)
{
    char buf[512];
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    t_tiffError = (module ? std::string(module) + ": " : std::string()) + buf;
}

void installTiffHandlers()
{
    static std::once_flag once;
    std::call_once(once, [] {
        TIFFSetErrorHandler(onTiffError);
        TIFFSetWarningHandler(nullptr);  // unknown tags of other writers are not news
    });
}

motion::msg::Message tiffProblem(const char* id, const std::string& path, const std::string& detail)
{
    return motion::msg::make(id, {motion::msg::verbatim("file", path), motion::msg::verbatim("detail", detail.empty() ? std::string("unknown") : detail)});
}

bool syncFile(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0)
        return false;
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    return ok;
}

} // namespace

std::string tileDescription(const Frame& f, const TileMetadata& meta)
{
    dev::files::json::Value v = dev::files::json::schemaObject("benchpilot.tile", 1);
    if (meta.tile >= 0)
        v.set("tile", dev::files::json::Value(meta.tile));
    if (!meta.label.empty())
        v.set("label", dev::files::json::Value(meta.label));
    if (meta.measuredMm.size() == 2) {
        dev::files::json::Value xy = dev::files::json::Value::array();
        xy.push(meta.measuredMm[0]);
        xy.push(meta.measuredMm[1]);
        v.set("measured_mm", xy);
    }
    if (meta.deviceTimeUs)
        v.set("device_time_us", dev::files::json::Value(static_cast<double>(*meta.deviceTimeUs)));
    v.set("exposure_ms", dev::files::json::Value(f.exposureMs));
    if (f.gain > 0)
        v.set("gain", dev::files::json::Value(f.gain));
    if (f.pixelUm > 0)
        v.set("pixel_um", dev::files::json::Value(f.pixelUm));
    v.set("bit_depth", dev::files::json::Value(f.bitDepth));
    if (!meta.source.empty())
        v.set("camera", dev::files::json::Value(meta.source));
    return dev::files::json::write(v, false);
}

bool writeTileTiff(const std::string& path, const Frame& f, const TileMetadata& meta, std::string* sha256Hex, motion::msg::Message* error)
{
    installTiffHandlers();
    if (f.isEmpty() || f.pixels.size() < static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height) * static_cast<std::size_t>(bytesPerPixel(f.format))) {
        *error = tiffProblem("camera.tiff.empty_frame", path, "");
        return false;
    }
    const std::string part = path + ".part";
    t_tiffError.clear();
    TIFF* t = TIFFOpen(part.c_str(), "w");
    if (!t) {
        *error = tiffProblem("camera.tiff.cannot_write", path, t_tiffError.empty() ? std::strerror(errno) : t_tiffError);
        return false;
    }
    const int spp = f.format == PixelFormat::Rgb8 ? 3 : 1;
    const int bps = f.format == PixelFormat::Grey16 ? 16 : 8;
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(f.width));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(f.height));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, static_cast<std::uint16_t>(spp));
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, static_cast<std::uint16_t>(bps));
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, spp == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
    TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, static_cast<std::uint32_t>(std::max(1, 65536 / (f.width * spp * bps / 8))));
    if (f.pixelUm > 0) {
        // Pixels per centimetre: the unit TIFF has that is closest to the microscope's.
        TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, RESUNIT_CENTIMETER);
        TIFFSetField(t, TIFFTAG_XRESOLUTION, static_cast<float>(1e4 / f.pixelUm));
        TIFFSetField(t, TIFFTAG_YRESOLUTION, static_cast<float>(1e4 / f.pixelUm));
    }
    const std::string description = tileDescription(f, meta);
    TIFFSetField(t, TIFFTAG_IMAGEDESCRIPTION, description.c_str());
    TIFFSetField(t, TIFFTAG_SOFTWARE, "BenchPilot " BP_VERSION);
    const std::size_t rowBytes = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(spp * bps / 8);
    std::vector<std::uint8_t> row(rowBytes);
    bool ok = true;
    for (int y = 0; y < f.height && ok; ++y) {
        std::memcpy(row.data(), f.pixels.data() + static_cast<std::size_t>(y) * rowBytes, rowBytes);
        ok = TIFFWriteScanline(t, row.data(), static_cast<std::uint32_t>(y), 0) == 1;
    }
    ok = ok && TIFFFlush(t) == 1;
    const std::string detail = t_tiffError;
    TIFFClose(t);
    const int savedErrno = errno;
    if (!ok || !syncFile(part)) {
        std::remove(part.c_str());
        *error = tiffProblem("camera.tiff.cannot_write", path, detail.empty() ? std::strerror(savedErrno) : detail);
        return false;
    }
    if (sha256Hex) {
        const auto sum = fileSha256(part);
        if (!sum) {
            std::remove(part.c_str());
            *error = tiffProblem("camera.tiff.cannot_write", path, std::strerror(errno));
            return false;
        }
        *sha256Hex = *sum;
    }
    // rename() replaces atomically: a reader sees the old file or the whole new one.
    if (std::rename(part.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(part.c_str());
        *error = tiffProblem("camera.tiff.cannot_write", path, why);
        return false;
    }
    return true;
}

std::optional<std::string> fileSha256(const std::string& path)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&file))
        return std::nullopt;
    return hash.result().toHex().toStdString();
}

bool readTiff(const std::string& path, Frame* frame, std::string* description, motion::msg::Message* error)
{
    installTiffHandlers();
    t_tiffError.clear();
    TIFF* t = TIFFOpen(path.c_str(), "r");
    if (!t) {
        *error = tiffProblem("camera.tiff.cannot_read", path, t_tiffError.empty() ? std::strerror(errno) : t_tiffError);
        return false;
    }
    std::uint32_t w = 0, h = 0;
    std::uint16_t spp = 1, bps = 8, planar = PLANARCONFIG_CONTIG;
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(t, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &spp);
    TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &bps);
    TIFFGetFieldDefaulted(t, TIFFTAG_PLANARCONFIG, &planar);
    const bool known = w > 0 && h > 0 && planar == PLANARCONFIG_CONTIG
        && ((spp == 1 && (bps == 8 || bps == 16)) || (spp == 3 && bps == 8));
    if (!known) {
        TIFFClose(t);
        *error = tiffProblem("camera.tiff.unsupported", path, std::to_string(spp) + "×" + std::to_string(bps) + " bit");
        return false;
    }
    Frame f;
    f.width = static_cast<int>(w);
    f.height = static_cast<int>(h);
    f.format = spp == 3 ? PixelFormat::Rgb8 : (bps == 16 ? PixelFormat::Grey16 : PixelFormat::Grey8);
    f.bitDepth = bps;
    const std::size_t rowBytes = static_cast<std::size_t>(w) * spp * (bps / 8);
    f.pixels.resize(rowBytes * h);
    for (std::uint32_t y = 0; y < h; ++y)
        if (TIFFReadScanline(t, f.pixels.data() + rowBytes * y, y, 0) != 1) {
            TIFFClose(t);
            *error = tiffProblem("camera.tiff.cannot_read", path, t_tiffError);
            return false;
        }
    float xres = 0;
    std::uint16_t unit = RESUNIT_NONE;
    if (TIFFGetField(t, TIFFTAG_XRESOLUTION, &xres) && xres > 0) {
        TIFFGetFieldDefaulted(t, TIFFTAG_RESOLUTIONUNIT, &unit);
        f.pixelUm = unit == RESUNIT_CENTIMETER ? 1e4 / xres : (unit == RESUNIT_INCH ? 25400.0 / xres : 0.0);
    }
    char* desc = nullptr;
    if (description)
        *description = TIFFGetField(t, TIFFTAG_IMAGEDESCRIPTION, &desc) && desc ? desc : "";
    TIFFClose(t);
    *frame = std::move(f);
    return true;
}

} // namespace dev::camera
