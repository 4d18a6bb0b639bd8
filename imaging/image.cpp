#include "imaging/image.h"

#include <algorithm>

namespace imaging {

const char* sampleKindName(SampleKind kind)
{
    switch (kind) {
    case SampleKind::Grey8:
        return "grey8";
    case SampleKind::Grey16:
        return "grey16";
    case SampleKind::Rgb8:
        return "rgb8";
    }
    return "grey16";
}

ImageF toFloat(const ImageU16& src)
{
    ImageF out(src.width, src.height);
    std::transform(src.px.begin(), src.px.end(), out.px.begin(), [](std::uint16_t v) { return static_cast<float>(v); });
    return out;
}

ImageF crop(const ImageF& src, int x0, int y0, int w, int h)
{
    const int xa = std::max(0, x0), ya = std::max(0, y0);
    const int xb = std::min(src.width, x0 + w), yb = std::min(src.height, y0 + h);
    if (xb <= xa || yb <= ya)
        return {};
    ImageF out(xb - xa, yb - ya);
    for (int y = ya; y < yb; ++y)
        std::copy(src.row(y) + xa, src.row(y) + xb, out.row(y - ya));
    return out;
}

} // namespace imaging
