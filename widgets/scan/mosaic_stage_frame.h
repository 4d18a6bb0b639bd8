#pragma once
// Where a point of the mosaic was on the stage: mosaic pixels ↔ stage millimetres, from
// the stitch (each tile's stage position and where registration put it) and the plan's
// camera (pixel size, rotation, image y) — docs/stitching.md, "The mosaic viewer".
//
// A tile's image was taken with the stage at its logged (grating) position, which the
// camera sees at the image's centre. A mosaic pixel lies in some tile; its offset from
// that tile's centre, turned into millimetres by the camera's axes, added to the tile's
// stage position, is where the stage must go to put that pixel under the objective.
// So a double-click on a tile's centre goes back exactly to where that tile was taken,
// whatever registration moved it by. Plain values; no Qt.
#include "imaging/stitch.h"
#include "motion/plans/scan/scan_plan.h"

#include <Eigen/Core>

#include <vector>

namespace ui {

class MosaicStageFrame {
public:
    struct Tile {
        Eigen::Vector2d topLeftPx;      ///< in the mosaic as fused (whole pixels)
        Eigen::Vector2d stagePx;        ///< the tile's top-left from the stage, in the stage-pixel frame
        Eigen::Vector2d correctionPx;   ///< the quality map's arrow: registered − stage, beyond the stage model (qualityArrowsPx)
        bool placedByStage = false;     ///< no trusted pair: flagged on the quality overlay
    };

    MosaicStageFrame() = default;
    /// From a finished stitch and the camera that took its tiles.
    MosaicStageFrame(const imaging::StitchResult& result, const motion::scan::Camera& camera);

    bool isEmpty() const { return m_tiles.empty(); }
    const std::vector<Tile>& tiles() const { return m_tiles; }
    int tileWidthPx() const { return m_tileW; }
    int tileHeightPx() const { return m_tileH; }
    int widthPx() const { return m_width; }
    int heightPx() const { return m_height; }
    double pixelUm() const { return m_pixelUm; }
    /// The larger side of one camera field (mm): moves farther than this ask first.
    double fieldMm() const;

    /// The tile holding `mosaicPx` whose centre is nearest, or the nearest tile when none holds it.
    int tileAt(const Eigen::Vector2d& mosaicPx) const;
    /// Where the stage goes to put `mosaicPx` under the objective (mm).
    Eigen::Vector2d stageMmAt(const Eigen::Vector2d& mosaicPx) const;
    /// Where the stage at `stageMm` looks in the mosaic (the centre of its field).
    Eigen::Vector2d mosaicPxAt(const Eigen::Vector2d& stageMm) const;
    /// The stage position (mm) at which tile `index` was taken.
    Eigen::Vector2d tileStageMm(int index) const;

private:
    Eigen::Vector2d centreOffset() const;  ///< image centre from its top-left corner, px

    std::vector<Tile> m_tiles;
    int m_tileW = 0, m_tileH = 0, m_width = 0, m_height = 0;
    double m_pixelUm = 0;
    Eigen::Matrix2d m_pxPerMm = Eigen::Matrix2d::Identity();  ///< stage mm → stage-pixel frame
    Eigen::Matrix2d m_mmPerPx = Eigen::Matrix2d::Identity();
};

} // namespace ui
