#pragma once
// The stitch's quality map: the tile grid where registration put each tile, each tile's
// correction from its stage position drawn as an arrow magnified so the largest is half
// a tile, the pairs between neighbours coloured by how far they were trusted (green by
// score, red when rejected as an outlier, grey dashed when not trusted), and the tiles
// no trusted pair placed (placed by the stage) hatched in orange. A click on a tile
// selects it (tileClicked); render() draws the same into an image for the PNG.
// While a scan runs it shows the mosaic growing: the plan's tiles outlined, each tile's
// thumbnail drawn where it was taken as it is read, and each pair coloured by its score
// as it registers; the result then keeps the thumbnails.
#include "imaging/stitch.h"

#include <QImage>
#include <QWidget>

#include <memory>
#include <vector>

namespace ui {

class StitchQualityMap : public QWidget {
    Q_OBJECT
public:
    explicit StitchQualityMap(QWidget* parent = nullptr);

    /// What to draw (copied); an empty result clears the map.
    void setResult(const imaging::StitchResult& result);
    void clear();
    bool isEmpty() const { return m_tiles.empty(); }
    int tileCount() const { return static_cast<int>(m_tiles.size()); }
    /// The arrows' magnification as drawn (1 when nothing moved).
    double magnification() const { return m_magnification; }
    int selectedTile() const { return m_selected; }
    void selectTile(int index);
    /// The tile under a point of the widget, or −1.
    int tileAt(const QPointF& point) const;
    /// The growing mosaic: the plan's tiles (top-left, image px) of about `tileSize`, none taken.
    void beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize);
    /// A tile read: where it was taken, its true size, and its thumbnail.
    void setLiveTile(int index, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail);
    /// A pair registered.
    void setLivePair(const imaging::TilePair& pair);
    int picturedTiles() const;  ///< tiles drawn with their thumbnail
    int pairCount() const { return static_cast<int>(m_pairs.size()); }
    /// The map drawn at `size` on white under `legend`'s lines (the PNG beside the mosaic).
    QImage render(const QSize& size, const QStringList& legend) const;

    QSize sizeHint() const override { return {480, 360}; }
    QSize minimumSizeHint() const override { return {200, 150}; }

signals:
    void tileClicked(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    struct Tile {
        QPointF stagePx, placedPx;
        QPointF correctionPx;  ///< the arrow: registered − stage (beyond the stage model when one is used), less the mean
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
    /// Mosaic pixels → the widget's (or image's) points, fitted with a margin.
    QTransform fit(const QSizeF& size) const;
    void draw(QPainter& p, const QSizeF& size) const;
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
