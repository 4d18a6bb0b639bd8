#pragma once
// The stitch's quality map on the Mosaic tab: the picture of widgets/report/
// stitch_quality_drawing.h (the tile grid, each tile's correction as a magnified arrow,
// the pairs coloured by how far they were trusted, the tiles placed by the stage hatched;
// while a scan runs, the mosaic growing). A click on a tile selects it (tileClicked);
// render() draws the same into an image for the PNG.
#include "widgets/report/stitch_quality_drawing.h"

#include <QWidget>

namespace ui {

class StitchQualityMap : public QWidget {
    Q_OBJECT
public:
    explicit StitchQualityMap(QWidget* parent = nullptr);

    /// What to draw (copied); an empty result clears the map.
    void setResult(const imaging::StitchResult& result);
    void clear();
    bool isEmpty() const { return m_drawing.isEmpty(); }
    int tileCount() const { return m_drawing.tileCount(); }
    /// The arrows' magnification as drawn (1 when nothing moved).
    double magnification() const { return m_drawing.magnification(); }
    int selectedTile() const { return m_drawing.selectedTile(); }
    void selectTile(int index);
    /// The tile under a point of the widget, or −1.
    int tileAt(const QPointF& point) const { return m_drawing.tileAt(point, size()); }
    /// The growing mosaic: the plan's tiles (top-left, image px) of about `tileSize`, none taken.
    void beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize);
    /// A tile read: where it was taken, its true size, and its thumbnail.
    void setLiveTile(int index, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail);
    /// A pair registered.
    void setLivePair(const imaging::TilePair& pair);
    int picturedTiles() const { return m_drawing.picturedTiles(); }
    int pairCount() const { return m_drawing.pairCount(); }
    /// The map drawn at `size` on white under `legend`'s lines (the PNG beside the mosaic).
    QImage render(const QSize& size, const QStringList& legend) const { return m_drawing.render(size, legend); }

    QSize sizeHint() const override { return {480, 360}; }
    QSize minimumSizeHint() const override { return {200, 150}; }

signals:
    void tileClicked(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    StitchQualityDrawing m_drawing;
};

} // namespace ui
