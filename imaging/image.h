#pragma once
// Grey images as plain value types: a plane of samples, row-major, no padding.
// Tiles keep their 16-bit (or 8-bit, widened) samples; registration works on float
// copies of the parts it needs. Plain C++ (no Qt), like the rest of imaging/.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imaging {

template <class T>
struct Plane {
    int width = 0;
    int height = 0;
    std::vector<T> px;  ///< width × height samples, row after row

    Plane() = default;
    Plane(int w, int h, T fill = T{}) : width(w), height(h), px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

    bool empty() const { return width <= 0 || height <= 0; }
    T& at(int x, int y) { return px[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
    const T& at(int x, int y) const { return px[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
    T* row(int y) { return px.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width); }
    const T* row(int y) const { return px.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width); }
};

using ImageF = Plane<float>;
using ImageU16 = Plane<std::uint16_t>;

/// What a file held, so a set of tiles can refuse a mix and the mosaic keeps the depth.
enum class SampleKind {
    Grey8,   ///< 8-bit grey (samples 0 … 255)
    Grey16,  ///< 16-bit grey
    Rgb8,    ///< 8-bit RGB, kept as its luminance (0 … 255) for registration and fusion
};

const char* sampleKindName(SampleKind kind);  ///< "grey8", "grey16", "rgb8"

/// A tile as read: its samples widened to 16 bits, and what the file held.
struct TileImage {
    ImageU16 grey;
    SampleKind kind = SampleKind::Grey16;
};

/// A float copy of a rectangle of `src` (clipped to it).
ImageF toFloat(const ImageU16& src);
ImageF crop(const ImageF& src, int x0, int y0, int w, int h);

} // namespace imaging
