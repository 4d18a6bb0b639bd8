#pragma once
// The stitch's quality map as a picture (docs/stitching.md, "The quality map"): the tile
// grid where the stage put each tile, each tile's correction drawn as an arrow magnified
// so the largest is half a tile, the pairs between neighbours coloured by how far they
// were trusted (green by score, red when rejected as an outlier, grey dashed when not
// trusted), the tiles no trusted pair placed (placed by the stage) hatched in orange.
// While a scan runs it holds the growing mosaic: the plan's tiles outlined, each tile's
// thumbnail where it was taken, each pair as it registers.
//
// Qt Gui only (QPainter), so the Mosaic tab's map (widgets/scan/stitch_quality_map.h)
// and benchpilot-cli's live scan draw the same quality-map.png.
#include "imaging/stitch.h"

#include <Eigen/Core>

#include <QImage>
#include <QPointF>
#include <QSizeF>
#include <QStringList>

#include <memory>
#include <vector>

class QPainter;

namespace ui {

/// The quality map's file beside the mosaic, and its picture's size in pixels.
inline constexpr const char* kQualityMapFile = "quality-map.png";
inline constexpr int kQualityMapWidthPx = 1400, kQualityMapHeightPx = 1100;

/// Each tile's correction as the quality map and the mosaic viewer draw it: registered −
/// stage position, beyond the fitted stage model when placement used one (a grating
/// scale would otherwise draw every arrow pointing out of the mosaic), less the mean over
/// the tiles (placement may shift the whole mosaic). Pixels, one per tile.
std::vector<Eigen::Vector2d> qualityArrowsPx(const imaging::StitchResult& result);

/// The verdict on a pair, as a term (scan.pair.*: words::term words it).
const char* pairVerdictTerm(imaging::PairStatus status);

/// The quality map's lines of text for a finished stitch (the PNG's legend, the Mosaic tab's
/// summary): counts, corrections, the stage model, the mosaic's size, the camera check.
struct StitchSummaryFigures {
    double pixelUm = 0;          ///< at the sample, for the µm figures
    double magnification = 1;    ///< the arrows' as drawn
    double seconds = 0;          ///< from the start of the work (live: from the last tile) to the files
    bool live = false;
    double livePlacedAfterS = 0; ///< live: the placement's delay after the last tile
};
QStringList stitchSummaryLines(const imaging::StitchResult& result, const StitchSummaryFigures& figures);

class StitchQualityDrawing {
public:
    /// What to draw (copied); an empty result clears it. Thumbnails of a live scan of the
    /// same tiles are kept.
    void setResult(const imaging::StitchResult& result);
    void clear();
    bool isEmpty() const { return m_tiles.empty(); }
    int tileCount() const { return static_cast<int>(m_tiles.size()); }
    /// The arrows' magnification as drawn (1 when nothing moved).
    double magnification() const { return m_magnification; }
    int selectedTile() const { return m_selected; }
    void selectTile(int index);
    /// The tile under `point` of a picture `size` large, or −1.
    int tileAt(const QPointF& point, const QSizeF& size) const;
    /// The growing mosaic: the plan's tiles (top-left, image px) of about `tileSize`, none taken.
    void beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize);
    /// A tile read: where it was taken, its true size, and its thumbnail. False for an index out of range.
    bool setLiveTile(int index, QPointF stagePx, QSizeF size, std::shared_ptr<const imaging::ImageU16> thumbnail);
    void setLivePair(const imaging::TilePair& pair);
    int picturedTiles() const;  ///< tiles drawn with their thumbnail
    int pairCount() const { return static_cast<int>(m_pairs.size()); }

    void draw(QPainter& p, const QSizeF& size) const;
    /// The map drawn at `size` on white under `legend`'s lines (the PNG beside the mosaic).
    QImage render(const QSize& size, const QStringList& legend) const;

private:
    struct Tile {
        QPointF stagePx, placedPx;
        QPointF correctionPx;  ///< the arrow (qualityArrowsPx)
        bool byStage = false;
        bool taken = true;                             ///< false: a live scan has not taken it yet
        std::shared_ptr<const imaging::ImageU16> raw;  ///< its thumbnail as read
        QImage picture;                                ///< the same through the display window
    };
    struct Pair {
        int a = 0, b = 0;
        double ncc = 0;
        imaging::PairStatus status = imaging::PairStatus::NoOverlap;
    };
    /// Mosaic pixels → the picture's points, fitted with a margin.
    QTransform fit(const QSizeF& size) const;
    /// Widens the thumbnails' display window to `raw`'s 1–99 % range; redraws them if it moved.
    void widenWindow(const imaging::ImageU16& raw);
    QImage picture(const imaging::ImageU16& raw) const;

    std::vector<Tile> m_tiles;
    std::vector<Pair> m_pairs;
    QSizeF m_tileSize;
    double m_magnification = 1;
    int m_selected = -1;
    int m_windowLow = -1, m_windowHigh = -1;  ///< the thumbnails' grey levels shown black and white
};

} // namespace ui
