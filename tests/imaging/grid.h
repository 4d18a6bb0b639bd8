#pragma once
// A small synthetic scan for the imaging tests: a cols × rows grid of tiles cut from
// one texture at true positions, with stage positions that may be wrong.
#include "imaging/placement.h"
#include "synthetic.h"

#include <vector>

namespace imagingtest {

struct Grid {
    int cols = 4, rows = 3, tileW = 128, tileH = 112;
    double stepX = 110, stepY = 96;
    std::vector<Eigen::Vector2d> truePx, stagePx;
    std::vector<imaging::ImageU16> tiles;

    int index(int c, int r) const { return r * cols + c; }
};

inline Grid makeGrid(const Texture& tex, double noise = 40, unsigned seed = 1)
{
    Grid g;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> err(-1.5, 1.5);
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            const Eigen::Vector2d stage(c * g.stepX, r * g.stepY);
            const Eigen::Vector2d truth = stage + Eigen::Vector2d(err(rng), err(rng));
            g.stagePx.push_back(stage);
            g.truePx.push_back(truth);
        }
    for (std::size_t i = 0; i < g.truePx.size(); ++i)
        g.tiles.push_back(cutTile(tex, 300 + g.truePx[i].x(), 200 + g.truePx[i].y(), g.tileW, g.tileH, noise, seed * 1000 + static_cast<unsigned>(i)));
    return g;
}

/// Every right and lower neighbour pair, registered.
inline std::vector<imaging::TilePair> registerGrid(const Grid& g, const imaging::RegistrationOptions& o = {})
{
    std::vector<imaging::TilePair> pairs;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c)
            for (int k = 0; k < 2; ++k) {
                const int c2 = c + (k == 0), r2 = r + (k == 1);
                if (c2 >= g.cols || r2 >= g.rows)
                    continue;
                const int a = g.index(c, r), b = g.index(c2, r2);
                imaging::TilePair p{a, b, {}};
                p.reg = imaging::registerPair(g.tiles[static_cast<std::size_t>(a)], g.tiles[static_cast<std::size_t>(b)],
                                              g.stagePx[static_cast<std::size_t>(b)] - g.stagePx[static_cast<std::size_t>(a)], o);
                pairs.push_back(p);
            }
    return pairs;
}

/// The worst error of the placed positions against the truth, both taken relative to tile 0.
inline double worstRelativeError(const std::vector<Eigen::Vector2d>& placed, const std::vector<Eigen::Vector2d>& truth)
{
    double worst = 0;
    for (std::size_t i = 0; i < placed.size(); ++i)
        worst = std::max(worst, ((placed[i] - placed[0]) - (truth[i] - truth[0])).norm());
    return worst;
}

/// The RMS of the same errors, after removing their mean (only relative placement matters).
inline double rmsRelativeError(const std::vector<Eigen::Vector2d>& placed, const std::vector<Eigen::Vector2d>& truth)
{
    Eigen::Vector2d mean(0, 0);
    for (std::size_t i = 0; i < placed.size(); ++i)
        mean += placed[i] - truth[i];
    mean /= static_cast<double>(placed.size());
    double sum2 = 0;
    for (std::size_t i = 0; i < placed.size(); ++i)
        sum2 += (placed[i] - truth[i] - mean).squaredNorm();
    return std::sqrt(sum2 / static_cast<double>(placed.size()));
}

} // namespace imagingtest
