#include "imaging/fusion.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>

namespace imaging {
namespace {

Eigen::Vector2i rounded(const Eigen::Vector2d& p)
{
    return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

std::vector<float> ramp(int n)
{
    std::vector<float> r(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        r[static_cast<std::size_t>(i)] = static_cast<float>(std::min(i + 1, n - i));
    return r;
}

} // namespace

MosaicFrame mosaicFrame(const std::vector<Eigen::Vector2d>& positionsPx, int tileW, int tileH)
{
    MosaicFrame f;
    if (positionsPx.empty())
        return f;
    int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;
    for (const Eigen::Vector2d& p : positionsPx) {
        const Eigen::Vector2i q = rounded(p);
        x0 = std::min(x0, q.x());
        y0 = std::min(y0, q.y());
        x1 = std::max(x1, q.x() + tileW);
        y1 = std::max(y1, q.y() + tileH);
    }
    f.width = x1 - x0;
    f.height = y1 - y0;
    f.originPx = {x0, y0};
    return f;
}

motion::msg::Problems fuseTiles(const std::vector<Eigen::Vector2d>& positionsPx, int tileW, int tileH, const TileLoader& load,
                        OmeTiffWriter& out, const FusionOptions& o)
{
    const MosaicFrame frame = mosaicFrame(positionsPx, tileW, tileH);
    const int W = frame.width, H = frame.height;
    std::vector<Eigen::Vector2i> at;
    for (const Eigen::Vector2d& p : positionsPx)
        at.push_back(rounded(p) - frame.originPx);
    const std::vector<float> rx = ramp(tileW), ry = ramp(tileH);
    const int bandRows = std::max(1, o.bandRows);
    std::vector<float> sum(static_cast<std::size_t>(W) * static_cast<std::size_t>(bandRows));
    std::vector<float> weight(sum.size());
    std::vector<std::uint16_t> rows(sum.size());
    std::map<int, TileImage> held;  ///< tiles crossing the current band, by index
    for (int y0 = 0; y0 < H; y0 += bandRows) {
        const int y1 = std::min(H, y0 + bandRows);
        std::fill(sum.begin(), sum.end(), 0.f);
        std::fill(weight.begin(), weight.end(), 0.f);
        // Tiles wholly above this band are done with.
        for (auto it = held.begin(); it != held.end();)
            it = at[static_cast<std::size_t>(it->first)].y() + tileH <= y0 ? held.erase(it) : std::next(it);
        for (int i = 0; i < static_cast<int>(at.size()); ++i) {
            const Eigen::Vector2i p = at[static_cast<std::size_t>(i)];
            if (p.y() >= y1 || p.y() + tileH <= y0)
                continue;
            auto it = held.find(i);
            if (it == held.end()) {
                motion::msg::Checked<TileImage> t = load(i);
                if (!t)
                    return t.problems();
                if (t->grey.width != tileW || t->grey.height != tileH)
                    return {motion::msg::error("", motion::msg::make("imaging.mosaic.tile_changed", {motion::msg::integer("tile", i, motion::msg::Unit::None)}))};
                it = held.emplace(i, t.take()).first;
            }
            const ImageU16& img = it->second.grey;
            const int ya = std::max(y0, p.y()), yb = std::min(y1, p.y() + tileH);
            for (int y = ya; y < yb; ++y) {
                const int ty = y - p.y();
                const std::uint16_t* src = img.row(ty);
                float* s = sum.data() + static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(W) + p.x();
                float* w = weight.data() + static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(W) + p.x();
                if (o.blend == Blend::Overlay) {
                    for (int x = 0; x < tileW; ++x) {
                        s[x] = src[x];
                        w[x] = 1.f;
                    }
                } else {
                    const float wy = ry[static_cast<std::size_t>(ty)];
                    for (int x = 0; x < tileW; ++x) {
                        const float k = wy * rx[static_cast<std::size_t>(x)];
                        s[x] += k * src[x];
                        w[x] += k;
                    }
                }
            }
        }
        const std::size_t n = static_cast<std::size_t>(y1 - y0) * static_cast<std::size_t>(W);
        for (std::size_t k = 0; k < n; ++k)
            rows[k] = weight[k] > 0 ? static_cast<std::uint16_t>(std::min(65535.f, sum[k] / weight[k] + 0.5f)) : 0;
        motion::msg::Problems p = out.writeRows(rows.data(), y1 - y0);
        if (!p.empty())
            return p;
    }
    return out.finish();
}

} // namespace imaging
