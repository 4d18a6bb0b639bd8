#include "widgets/scan/mosaic_stage_frame.h"

#include "device/files/scan_exports.h"
#include "widgets/report/stitch_quality_drawing.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ui {

MosaicStageFrame::MosaicStageFrame(const imaging::StitchResult& r, const motion::scan::Camera& camera)
{
    m_tileW = r.tileWidth;
    m_tileH = r.tileHeight;
    m_width = r.frame.width;
    m_height = r.frame.height;
    m_pixelUm = motion::scan::pixelAtSampleUm(camera);
    // The same mapping the stitch placed the tiles with (scan_exports' stageToPixels).
    const motion::scan::Point2 ex = dev::files::scan::stageToPixels(camera, {1, 0});
    const motion::scan::Point2 ey = dev::files::scan::stageToPixels(camera, {0, 1});
    m_pxPerMm << ex.xMm, ey.xMm, ex.yMm, ey.yMm;
    m_mmPerPx = m_pxPerMm.inverse();
    const Eigen::Vector2d origin = r.frame.originPx.cast<double>();
    const std::vector<Eigen::Vector2d> arrows = qualityArrowsPx(r);  // the quality map's arrows
    for (std::size_t i = 0; i < r.tiles.size() && i < r.placement.positionsPx.size(); ++i) {
        const Eigen::Vector2d& placed = r.placement.positionsPx[i];
        Tile t;
        // Fusion puts each tile at its rounded position (imaging/fusion.h).
        t.topLeftPx = Eigen::Vector2d(std::round(placed.x()), std::round(placed.y())) - origin;
        t.stagePx = r.tiles[i].stagePx;
        t.correctionPx = arrows[i];
        t.placedByStage = i < r.placement.placedByStage.size() && r.placement.placedByStage[i];
        m_tiles.push_back(t);
    }
}

double MosaicStageFrame::fieldMm() const { return std::max(m_tileW, m_tileH) * m_pixelUm / 1000.0; }

Eigen::Vector2d MosaicStageFrame::centreOffset() const { return {(m_tileW - 1) / 2.0, (m_tileH - 1) / 2.0}; }

int MosaicStageFrame::tileAt(const Eigen::Vector2d& m) const
{
    int best = -1, nearest = -1;
    double bestD = std::numeric_limits<double>::infinity(), nearestD = bestD;
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        const Eigen::Vector2d c = m_tiles[i].topLeftPx + centreOffset();
        const double d = (m - c).squaredNorm();
        const Eigen::Vector2d u = m - m_tiles[i].topLeftPx;
        const bool inside = u.x() >= -0.5 && u.y() >= -0.5 && u.x() < m_tileW - 0.5 && u.y() < m_tileH - 0.5;
        if (inside && d < bestD) {
            bestD = d;
            best = static_cast<int>(i);
        }
        if (d < nearestD) {
            nearestD = d;
            nearest = static_cast<int>(i);
        }
    }
    return best >= 0 ? best : nearest;
}

Eigen::Vector2d MosaicStageFrame::stageMmAt(const Eigen::Vector2d& m) const
{
    const int i = tileAt(m);
    if (i < 0)
        return Eigen::Vector2d::Zero();
    const Tile& t = m_tiles[static_cast<std::size_t>(i)];
    // The pixel's place in tile i's own image, put where the stage saw that image.
    const Eigen::Vector2d inTile = m - t.topLeftPx;
    return m_mmPerPx * (t.stagePx + inTile - centreOffset());
}

Eigen::Vector2d MosaicStageFrame::mosaicPxAt(const Eigen::Vector2d& stageMm) const
{
    const Eigen::Vector2d q = m_pxPerMm * stageMm;  // the field's top-left in the stage-pixel frame
    // Through the tile taken nearest to there, so the marker sits on what that tile shows.
    int nearest = -1;
    double nearestD = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        const double d = (q - m_tiles[i].stagePx).squaredNorm();
        if (d < nearestD) {
            nearestD = d;
            nearest = static_cast<int>(i);
        }
    }
    if (nearest < 0)
        return Eigen::Vector2d::Zero();
    const Tile& t = m_tiles[static_cast<std::size_t>(nearest)];
    return q + centreOffset() - t.stagePx + t.topLeftPx;
}

Eigen::Vector2d MosaicStageFrame::tileStageMm(int index) const
{
    return m_mmPerPx * m_tiles[static_cast<std::size_t>(index)].stagePx;
}

} // namespace ui
