#include "imaging/tiff_write.h"

#include "imaging/tiff_read.h"

#include <tiffio.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace imaging {

motion::msg::Problems writeTiffSamples(const std::string& path, int width, int height, int samples, int bits, const void* data)
{
    quietTiff();
    const std::string temp = path + ".partial";
    auto failed = [&](std::string reason) {
        std::remove(temp.c_str());
        return motion::msg::Problems{motion::msg::Problem(path, 0, 0, "", motion::msg::make("imaging.mosaic.write_failed",
                                                                  {motion::msg::verbatim("file", path), motion::msg::verbatim("reason", std::move(reason))}))};
    };
    TIFF* t = TIFFOpen(temp.c_str(), "w");
    if (!t)
        return failed(lastTiffMessage());
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(width));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(height));
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, static_cast<uint16_t>(bits));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, static_cast<uint16_t>(samples));
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, samples == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(t, 0));
    const std::size_t rowBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(samples) * static_cast<std::size_t>(bits / 8);
    std::vector<unsigned char> row(rowBytes);
    for (int y = 0; y < height; ++y) {
        std::memcpy(row.data(), static_cast<const unsigned char*>(data) + rowBytes * static_cast<std::size_t>(y), rowBytes);
        if (TIFFWriteScanline(t, row.data(), static_cast<uint32_t>(y), 0) < 0) {
            TIFFClose(t);
            return failed(lastTiffMessage());
        }
    }
    const bool flushed = TIFFFlush(t) == 1;
    TIFFClose(t);
    if (!flushed)
        return failed(lastTiffMessage());
    if (std::rename(temp.c_str(), path.c_str()) != 0)
        return failed(std::strerror(errno));
    return {};
}

motion::msg::Problems writeTiff(const std::string& path, const ImageU16& image, int bits)
{
    if (bits == 16)
        return writeTiffSamples(path, image.width, image.height, 1, 16, image.px.data());
    std::vector<std::uint8_t> narrow(image.px.size());
    std::transform(image.px.begin(), image.px.end(), narrow.begin(), [](std::uint16_t v) { return static_cast<std::uint8_t>(std::min<unsigned>(v, 255)); });
    return writeTiffSamples(path, image.width, image.height, 1, 8, narrow.data());
}

} // namespace imaging
