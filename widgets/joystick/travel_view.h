#pragma once
// An instrument's XY travel drawn to scale (equal mm per pixel on both axes): the travel, the
// soft limits, the trail of measured positions and where the axes are now. Fed by the client's
// status polls; the trail is bounded (oldest points dropped).
#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <deque>

namespace ui {

class TravelView : public QWidget {
    Q_OBJECT
public:
    static constexpr std::size_t kMaxTrail = 4000;

    explicit TravelView(QWidget* parent = nullptr);
    /// Travel and soft limits in mm (x, y, width, height).
    void setTravel(const QRectF& travelMm, const QRectF& softLimitsMm);
    /// A new position: measured joins the trail, commanded is marked.
    void addPosition(QPointF measuredMm, QPointF commandedMm);
    void clearTrail();
    /// Whether the positions are live. Without the link the last one is still drawn, grey and
    /// labelled as the last known, never as where the axes are now.
    void setLive(bool live);
    bool showsLivePosition() const { return m_havePosition && m_live; }
    std::size_t trailSize() const { return m_trail.size(); }
    /// Pixel position of a point in mm (for tests and overlays).
    QPointF toPixel(QPointF mm) const;

    QSize sizeHint() const override { return {420, 420}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QRectF m_travel{0, 0, 100, 100};
    QRectF m_soft{0, 0, 100, 100};
    std::deque<QPointF> m_trail;
    QPointF m_measured, m_commanded;
    bool m_havePosition = false;
    bool m_live = true;
};

} // namespace ui
