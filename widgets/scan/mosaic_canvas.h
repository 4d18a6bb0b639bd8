#pragma once
// The mosaic viewer's picture: the pyramidal OME-TIFF drawn at any zoom, reading only
// the part in view from the pyramid level that matches the zoom (the coarsest whose
// pixel is no larger than a screen pixel), in blocks kept in a bounded cache; over it
// the tiles' outlines, the quality overlay (each tile's correction from its stage
// position as an arrow, magnified so the longest is half a tile but never more than
// 100 times; tiles placed by the
// stage hatched orange), the stage's field of view where the stage is now, and a scale
// bar. Wheel zooms about the cursor, a drag pans, the arrow keys pan by a tenth of the
// view, a double-click asks to go there (doubleClicked). Reads run on the GUI thread:
// the mosaic is uncompressed and tiled, so a block is one read of 64–128 kB, and a
// view needs a few dozen at most, fetched once.
#include "imaging/pyramid_reader.h"
#include "widgets/scan/mosaic_stage_frame.h"

#include <QCache>
#include <QImage>
#include <QPointF>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace ui {

class MosaicCanvas : public QWidget {
    Q_OBJECT
public:
    explicit MosaicCanvas(QWidget* parent = nullptr);

    /// What to draw; a null reader clears the picture.
    void setMosaic(std::shared_ptr<imaging::PyramidReader> reader, const MosaicStageFrame& frame);
    bool hasMosaic() const { return m_reader != nullptr; }
    const MosaicStageFrame& frame() const { return m_frame; }

    double zoom() const { return m_zoom; }  ///< screen pixels per mosaic pixel
    QPointF centre() const { return m_centre; }  ///< the mosaic pixel at the middle of the view
    int level() const { return m_level; }  ///< the pyramid level the view reads
    void fit();
    void zoomBy(double factor, const QPointF& anchor);  ///< keeps the mosaic point under `anchor` still
    void zoomBy(double factor) { zoomBy(factor, QPointF(width() / 2.0, height() / 2.0)); }
    void panBy(const QPointF& screenPx);
    QPointF toMosaic(const QPointF& widgetPoint) const;
    QPointF toWidget(const QPointF& mosaicPx) const;

    bool showsTiles() const { return m_showTiles; }
    bool showsQuality() const { return m_showQuality; }
    void setShowTiles(bool on);
    void setShowQuality(bool on);
    /// Where the stage is (mm), or nothing when not known (not homed, not connected).
    void setStageMm(const std::optional<QPointF>& mm);
    const std::optional<QPointF>& stageMm() const { return m_stageMm; }
    /// The scale bar as drawn: its length in µm (0: no pixel size).
    double scaleBarUm() const;
    /// Cached blocks, and blocks read from the file since setMosaic.
    int cachedBlocks() const { return m_cache.size(); }
    long blocksRead() const { return m_blocksRead; }

    QSize sizeHint() const override { return {640, 480}; }
    QSize minimumSizeHint() const override { return {240, 180}; }

signals:
    void doubleClicked(const QPointF& mosaicPx);
    void cursorMoved(const std::optional<QPointF>& mosaicPx);
    void viewChanged();
    void problem(const motion::msg::Problems& problems);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void chooseLevel();
    void clampView();
    double fitZoom() const;
    /// The block (bx, by) of `level` as 8-bit grey, from the cache or the file; null on a read error.
    const QImage* block(int level, int bx, int by);
    void drawMosaic(QPainter& p);
    void drawOverlay(QPainter& p) const;
    void drawScaleBar(QPainter& p) const;

    std::shared_ptr<imaging::PyramidReader> m_reader;
    MosaicStageFrame m_frame;
    QCache<quint64, QImage> m_cache;
    double m_zoom = 1;
    QPointF m_centre;
    int m_level = 0;
    bool m_fitted = false;     ///< the view follows resizes until the operator zooms or pans
    bool m_showTiles = true;
    bool m_showQuality = true;
    bool m_readFailed = false; ///< one problem per mosaic, not one per paint
    std::optional<QPointF> m_stageMm;
    std::optional<QPoint> m_dragFrom;
    long m_blocksRead = 0;
    quint16 m_low = 0, m_high = 65535;  ///< the display stretch, from the smallest level
    std::vector<uchar> m_lut;           ///< sample → grey for that stretch
    double m_arrowScale = 1;
};

} // namespace ui
