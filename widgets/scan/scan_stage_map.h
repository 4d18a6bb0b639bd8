#pragma once
// The scan's stage map: the stage's 100 × 100 mm travel to scale (equal mm per
// pixel on both axes, +Y up), its soft limits, the region, every tile with its
// order number, the path between them, which tiles are taken, and where the stage
// is. Drag to draw a rectangle; in polygon mode click the outline's corners and
// double-click to close it (Backspace takes the last corner back). The wheel
// zooms at the pointer, a right- or middle-drag pans.
#include "motion/plans/scan/scan_layout.h"

#include <QWidget>

#include <optional>
#include <vector>

namespace ui {

class ScanStageMap : public QWidget {
    Q_OBJECT
public:
    enum class DrawMode { Rectangle, Polygon };

    explicit ScanStageMap(QWidget* parent = nullptr);

    void setTravel(const motion::scan::Rect& travel);
    void setSoftLimits(const std::optional<motion::scan::Rect>& limits);
    /// The plan's region and its tiles and path (empty layout: region only).
    void setPlan(const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout);
    /// Per tile (visiting order): taken or not; `current` is the tile in progress (−1: none).
    void setProgress(const std::vector<char>& taken, int current);
    void setStagePosition(const std::optional<motion::scan::Point2>& positionMm);
    void setDrawMode(DrawMode mode);
    DrawMode drawMode() const { return m_mode; }
    void setDrawingEnabled(bool enabled);

    /// Shows the whole travel, or the plan's grid with a margin.
    void fitStage();
    void fitPlan();
    /// The part of the stage shown, mm.
    motion::scan::Rect view() const { return m_view; }
    QPointF toWidget(motion::scan::Point2 mm) const;
    motion::scan::Point2 toStage(QPointF px) const;

signals:
    void rectangleDrawn(const motion::scan::Rect& regionMm);
    void polygonDrawn(const std::vector<motion::scan::Point2>& verticesMm);
    /// The stage position under the pointer (nullopt when it leaves), for a status line.
    void pointerMoved(const std::optional<motion::scan::Point2>& positionMm);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    QSize sizeHint() const override { return {640, 640}; }

private:
    struct Transform {
        double scale = 1;        ///< px per mm
        double originX = 0, originY = 0;  ///< widget px of stage (view.x0, view.y1)
    };
    Transform transform() const;
    void paintTiles(QPainter& p, const Transform& t);
    void paintRegion(QPainter& p);
    void paintAxes(QPainter& p, const Transform& t);
    void zoomAt(QPointF px, double factor);
    motion::scan::Point2 clampToTravel(motion::scan::Point2 p) const;

    motion::scan::Rect m_travel{0, 0, 100, 100};
    std::optional<motion::scan::Rect> m_softLimits;
    motion::scan::Rect m_view{-5, -5, 105, 105};
    motion::scan::ScanPlan m_plan;
    motion::scan::ScanLayout m_layout;
    std::vector<char> m_taken;
    int m_current = -1;
    std::optional<motion::scan::Point2> m_stage;

    DrawMode m_mode = DrawMode::Rectangle;
    bool m_drawingEnabled = true;
    std::optional<motion::scan::Point2> m_dragFrom, m_dragTo;  ///< rectangle being drawn
    std::vector<motion::scan::Point2> m_polygon;              ///< polygon being drawn
    std::optional<motion::scan::Point2> m_hover;
    std::optional<QPointF> m_panFrom;
};

} // namespace ui
