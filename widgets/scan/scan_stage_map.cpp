#include "widgets/scan/scan_stage_map.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace ui {

using motion::scan::Point2;
using motion::scan::Rect;

namespace {

const QColor kOutside(0xe4, 0xe6, 0xea);
const QColor kStage(0xfb, 0xfb, 0xfc);
const QColor kGrid(0xe3, 0xe7, 0xee);
const QColor kRegion(0x1e, 0x6f, 0xd9);
const QColor kTile(0x5a, 0x6b, 0x85);
const QColor kTaken(0x2e, 0x9d, 0x4f);
const QColor kCurrent(0xf0, 0x8c, 0x00);

/// 1, 2 or 5 × 10^k: the smallest such step at least `minimum`.
double niceStep(double minimum)
{
    const double p = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= minimum)
            return m * p;
    return 10 * p;
}

} // namespace

ScanStageMap::ScanStageMap(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(true);
    setFocusPolicy(Qt::ClickFocus);
    setMinimumSize(320, 320);
    setAccessibleName(tr("Stage map"));
    fitStage();
}

void ScanStageMap::setTravel(const Rect& travel)
{
    m_travel = travel;
    update();
}

void ScanStageMap::setSoftLimits(const std::optional<Rect>& limits)
{
    m_softLimits = limits;
    update();
}

void ScanStageMap::setPlan(const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout)
{
    m_plan = plan;
    m_layout = layout;
    m_taken.assign(layout.tiles.size(), 0);
    m_current = -1;
    update();
}

void ScanStageMap::setProgress(const std::vector<char>& taken, int current)
{
    m_taken = taken;
    m_current = current;
    update();
}

void ScanStageMap::setStagePosition(const std::optional<Point2>& positionMm)
{
    m_stage = positionMm;
    update();
}

void ScanStageMap::setDrawMode(DrawMode mode)
{
    m_mode = mode;
    m_polygon.clear();
    m_dragFrom.reset();
    setCursor(Qt::CrossCursor);
    update();
}

void ScanStageMap::setDrawingEnabled(bool enabled)
{
    m_drawingEnabled = enabled;
    m_polygon.clear();
    m_dragFrom.reset();
    setCursor(enabled ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

void ScanStageMap::fitStage()
{
    const double m = 0.04 * std::max(m_travel.widthMm(), m_travel.heightMm());
    m_view = {m_travel.x0Mm - m, m_travel.y0Mm - m, m_travel.x1Mm + m, m_travel.y1Mm + m};
    update();
}

void ScanStageMap::fitPlan()
{
    if (m_layout.tiles.empty()) {
        fitStage();
        return;
    }
    Rect b = m_layout.gridBounds;
    const Rect r = motion::scan::regionBounds(m_plan.region);
    b = {std::min(b.x0Mm, r.x0Mm), std::min(b.y0Mm, r.y0Mm), std::max(b.x1Mm, r.x1Mm), std::max(b.y1Mm, r.y1Mm)};
    const double m = 0.08 * std::max(b.widthMm(), b.heightMm()) + 0.2;
    m_view = {b.x0Mm - m, b.y0Mm - m, b.x1Mm + m, b.y1Mm + m};
    update();
}

ScanStageMap::Transform ScanStageMap::transform() const
{
    // Equal mm per pixel both ways: the view box is fitted and centred.
    Transform t;
    const double w = std::max(1, width()), h = std::max(1, height());
    t.scale = std::min(w / m_view.widthMm(), h / m_view.heightMm());
    const double usedW = m_view.widthMm() * t.scale, usedH = m_view.heightMm() * t.scale;
    t.originX = 0.5 * (w - usedW);
    t.originY = 0.5 * (h - usedH);
    return t;
}

QPointF ScanStageMap::toWidget(Point2 mm) const
{
    const Transform t = transform();
    return {t.originX + (mm.xMm - m_view.x0Mm) * t.scale, t.originY + (m_view.y1Mm - mm.yMm) * t.scale};
}

Point2 ScanStageMap::toStage(QPointF px) const
{
    const Transform t = transform();
    return {m_view.x0Mm + (px.x() - t.originX) / t.scale, m_view.y1Mm - (px.y() - t.originY) / t.scale};
}

Point2 ScanStageMap::clampToTravel(Point2 p) const
{
    return {std::clamp(p.xMm, m_travel.x0Mm, m_travel.x1Mm), std::clamp(p.yMm, m_travel.y0Mm, m_travel.y1Mm)};
}

void ScanStageMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), kOutside);
    const Transform t = transform();
    const QRectF travel(toWidget({m_travel.x0Mm, m_travel.y1Mm}), toWidget({m_travel.x1Mm, m_travel.y0Mm}));
    p.fillRect(travel, kStage);
    paintAxes(p, t);
    p.setPen(QPen(QColor(0x33, 0x3a, 0x45), 2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(travel);
    // Soft limits narrower than the travel: a dashed red line where the device stops.
    if (m_softLimits
        && (std::fabs(m_softLimits->x0Mm - m_travel.x0Mm) > 1e-6 || std::fabs(m_softLimits->x1Mm - m_travel.x1Mm) > 1e-6
            || std::fabs(m_softLimits->y0Mm - m_travel.y0Mm) > 1e-6 || std::fabs(m_softLimits->y1Mm - m_travel.y1Mm) > 1e-6)) {
        p.setPen(QPen(QColor(0xc6, 0x28, 0x28), 1.5, Qt::DashLine));
        p.drawRect(QRectF(toWidget({m_softLimits->x0Mm, m_softLimits->y1Mm}), toWidget({m_softLimits->x1Mm, m_softLimits->y0Mm})));
    }
    paintRegion(p);
    paintTiles(p, t);

    if (m_stage) {
        const QPointF c = toWidget(*m_stage);
        p.setPen(QPen(QColor(0xc6, 0x28, 0x28), 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(c, 7, 7);
        p.drawLine(c - QPointF(12, 0), c + QPointF(12, 0));
        p.drawLine(c - QPointF(0, 12), c + QPointF(0, 12));
    }
    // What is being drawn.
    p.setPen(QPen(kRegion, 1.5, Qt::DashLine));
    p.setBrush(QColor(kRegion.red(), kRegion.green(), kRegion.blue(), 30));
    if (m_dragFrom && m_dragTo)
        p.drawRect(QRectF(toWidget(*m_dragFrom), toWidget(*m_dragTo)).normalized());
    if (!m_polygon.empty()) {
        QPolygonF poly;
        for (const Point2& v : m_polygon)
            poly << toWidget(v);
        if (m_hover)
            poly << toWidget(clampToTravel(*m_hover));
        p.drawPolyline(poly);
        for (const Point2& v : m_polygon)
            p.drawEllipse(toWidget(v), 3, 3);
    }
}

void ScanStageMap::paintAxes(QPainter& p, const Transform& t)
{
    // Grid lines at a round step at least ~45 px apart, labelled along the travel's edges.
    const double step = niceStep(45.0 / t.scale);
    QFont f = font();
    f.setPointSizeF(std::max(7.0, f.pointSizeF() - 1.5));
    p.setFont(f);
    for (double x = std::ceil(m_travel.x0Mm / step) * step; x <= m_travel.x1Mm + 1e-9; x += step) {
        const QPointF a = toWidget({x, m_travel.y0Mm}), b = toWidget({x, m_travel.y1Mm});
        p.setPen(QPen(kGrid, 1));
        p.drawLine(a, b);
        p.setPen(QColor(0x6b, 0x72, 0x80));
        p.drawText(QRectF(a.x() - 30, a.y() + 2, 60, 14), Qt::AlignHCenter | Qt::AlignTop, QString::number(x, 'g', 6));
    }
    for (double y = std::ceil(m_travel.y0Mm / step) * step; y <= m_travel.y1Mm + 1e-9; y += step) {
        const QPointF a = toWidget({m_travel.x0Mm, y}), b = toWidget({m_travel.x1Mm, y});
        p.setPen(QPen(kGrid, 1));
        p.drawLine(a, b);
        p.setPen(QColor(0x6b, 0x72, 0x80));
        p.drawText(QRectF(a.x() - 64, a.y() - 7, 60, 14), Qt::AlignRight | Qt::AlignVCenter, QString::number(y, 'g', 6));
    }
    // Scale bar and axis names, bottom left.
    p.setPen(QPen(QColor(0x33, 0x3a, 0x45), 2));
    const double barPx = step * t.scale;
    const QPointF s(12, height() - 14);
    p.drawLine(s, s + QPointF(barPx, 0));
    p.drawText(QRectF(s.x(), s.y() - 18, barPx + 80, 16), Qt::AlignLeft, tr("%1 mm").arg(QString::number(step, 'g', 6)));
    p.drawText(QRectF(width() - 150, height() - 20, 144, 16), Qt::AlignRight, tr("X →   Y ↑"));
}

void ScanStageMap::paintRegion(QPainter& p)
{
    using motion::scan::RegionKind;
    p.setPen(QPen(kRegion, 2));
    p.setBrush(QColor(kRegion.red(), kRegion.green(), kRegion.blue(), 38));
    if (m_plan.region.kind == RegionKind::Polygon) {
        QPolygonF poly;
        for (const Point2& v : m_plan.region.vertices)
            poly << toWidget(v);
        p.drawPolygon(poly);
    } else {
        const Rect r = motion::scan::regionBounds(m_plan.region);
        p.drawRect(QRectF(toWidget({r.x0Mm, r.y1Mm}), toWidget({r.x1Mm, r.y0Mm})));
    }
}

void ScanStageMap::paintTiles(QPainter& p, const Transform& t)
{
    if (m_layout.tiles.empty())
        return;
    const double wPx = m_layout.grid.fieldWidthMm * t.scale, hPx = m_layout.grid.fieldHeightMm * t.scale;
    const QRectF visible = rect();
    const bool outlines = wPx >= 3 && hPx >= 3;
    const bool numbers = wPx >= 24 && hPx >= 14;
    QFont f = font();
    f.setPointSizeF(std::clamp(std::min(wPx, 2.5 * hPx) / 5.0, 6.0, 10.0));
    p.setFont(f);
    for (const auto& tile : m_layout.tiles) {
        const Rect field = motion::scan::tileField(m_layout, tile);
        const QRectF r(toWidget({field.x0Mm, field.y1Mm}), toWidget({field.x1Mm, field.y0Mm}));
        if (!r.intersects(visible))
            continue;
        const auto k = static_cast<std::size_t>(tile.index);
        const bool taken = k < m_taken.size() && m_taken[k];
        QColor fill = tile.index == m_current ? kCurrent : (taken ? kTaken : QColor(0, 0, 0, 0));
        if (fill.alpha())
            fill.setAlpha(tile.index == m_current ? 140 : 90);
        p.setPen(outlines ? QPen(QColor(kTile.red(), kTile.green(), kTile.blue(), 150), 1) : Qt::NoPen);
        p.setBrush(fill.alpha() ? QBrush(fill) : (outlines ? Qt::NoBrush : QBrush(QColor(kTile.red(), kTile.green(), kTile.blue(), 25))));
        p.drawRect(r);
        if (numbers) {
            p.setPen(QColor(0x22, 0x2a, 0x35));
            p.drawText(r, Qt::AlignCenter, QString::number(tile.index + 1));
        }
    }
    // The path: the stage's straight moves, overtravel points marked with a small cross.
    QPolygonF path;
    for (const auto& w : m_layout.path)
        path << toWidget(w.target);
    p.setPen(QPen(QColor(0x1a, 0x23, 0x33, 170), std::clamp(wPx / 40.0, 1.0, 2.0)));
    p.setBrush(Qt::NoBrush);
    p.drawPolyline(path);
    for (const auto& w : m_layout.path)
        if (w.tile < 0) {
            const QPointF c = toWidget(w.target);
            p.drawLine(c + QPointF(-3, -3), c + QPointF(3, 3));
            p.drawLine(c + QPointF(-3, 3), c + QPointF(3, -3));
        }
    // Where it begins and ends.
    const QPointF first = toWidget(m_layout.tiles.front().centre);
    const QPointF last = toWidget(m_layout.tiles.back().centre);
    p.setPen(Qt::NoPen);
    p.setBrush(kTaken.darker(130));
    p.drawEllipse(first, 5, 5);
    p.setBrush(QColor(0xc6, 0x28, 0x28));
    p.drawRect(QRectF(last - QPointF(4, 4), QSizeF(8, 8)));
}

void ScanStageMap::mousePressEvent(QMouseEvent* e)
{
    if (e->button() == Qt::RightButton || e->button() == Qt::MiddleButton) {
        m_panFrom = e->position();
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (e->button() != Qt::LeftButton || !m_drawingEnabled)
        return;
    const Point2 at = clampToTravel(toStage(e->position()));
    if (m_mode == DrawMode::Rectangle) {
        m_dragFrom = at;
        m_dragTo = at;
    } else {
        m_polygon.push_back(at);
    }
    update();
}

void ScanStageMap::mouseMoveEvent(QMouseEvent* e)
{
    if (m_panFrom) {
        const QPointF d = e->position() - *m_panFrom;
        m_panFrom = e->position();
        const double s = transform().scale;
        m_view = {m_view.x0Mm - d.x() / s, m_view.y0Mm + d.y() / s, m_view.x1Mm - d.x() / s, m_view.y1Mm + d.y() / s};
        update();
        return;
    }
    m_hover = toStage(e->position());
    emit pointerMoved(m_hover);
    if (m_dragFrom)
        m_dragTo = clampToTravel(*m_hover);
    update();
}

void ScanStageMap::mouseReleaseEvent(QMouseEvent* e)
{
    if (m_panFrom && (e->button() == Qt::RightButton || e->button() == Qt::MiddleButton)) {
        m_panFrom.reset();
        setCursor(m_drawingEnabled ? Qt::CrossCursor : Qt::ArrowCursor);
        return;
    }
    if (e->button() != Qt::LeftButton || !m_dragFrom)
        return;
    const Rect r = motion::scan::rectFromCorners(*m_dragFrom, clampToTravel(toStage(e->position())));
    m_dragFrom.reset();
    m_dragTo.reset();
    // A click without a drag draws nothing (it would be a zero-size region).
    const double minMm = 4.0 / transform().scale;
    if (r.widthMm() > minMm && r.heightMm() > minMm)
        emit rectangleDrawn(r);
    update();
}

void ScanStageMap::mouseDoubleClickEvent(QMouseEvent* e)
{
    if (e->button() != Qt::LeftButton || m_mode != DrawMode::Polygon || !m_drawingEnabled)
        return;
    // The double-click's first press already added this corner; a second one is a duplicate.
    if (m_polygon.size() >= 2) {
        const Point2 a = m_polygon[m_polygon.size() - 1], b = m_polygon[m_polygon.size() - 2];
        if (std::hypot(a.xMm - b.xMm, a.yMm - b.yMm) * transform().scale < 4)
            m_polygon.pop_back();
    }
    if (m_polygon.size() >= 3)
        emit polygonDrawn(m_polygon);
    m_polygon.clear();
    update();
}

void ScanStageMap::keyPressEvent(QKeyEvent* e)
{
    // Esc is the E-stop everywhere: it is never taken here.
    if (e->key() == Qt::Key_Backspace && !m_polygon.empty()) {
        m_polygon.pop_back();
        update();
        return;
    }
    if ((e->key() == Qt::Key_Return || e->key() == Qt::Key_Enter) && m_polygon.size() >= 3) {
        emit polygonDrawn(m_polygon);
        m_polygon.clear();
        update();
        return;
    }
    QWidget::keyPressEvent(e);
}

void ScanStageMap::wheelEvent(QWheelEvent* e)
{
    const double notches = e->angleDelta().y() / 120.0;
    if (notches != 0)
        zoomAt(e->position(), std::pow(1.25, -notches));
    e->accept();
}

void ScanStageMap::zoomAt(QPointF px, double factor)
{
    const Point2 c = toStage(px);
    const double span = std::max(m_view.widthMm(), m_view.heightMm()) * factor;
    if (span < 0.05 || span > 4 * std::max(m_travel.widthMm(), m_travel.heightMm()))
        return;
    m_view = {c.xMm - (c.xMm - m_view.x0Mm) * factor, c.yMm - (c.yMm - m_view.y0Mm) * factor,
              c.xMm + (m_view.x1Mm - c.xMm) * factor, c.yMm + (m_view.y1Mm - c.yMm) * factor};
    update();
}

void ScanStageMap::leaveEvent(QEvent*)
{
    m_hover.reset();
    emit pointerMoved(std::nullopt);
    update();
}

} // namespace ui
