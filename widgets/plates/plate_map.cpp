#include "widgets/plates/plate_map.h"

#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
constexpr double kMarginPx = 28;  ///< room for the row letters and column numbers
constexpr double kDragPx = 4;     ///< a press that moves less is a click
}

PlateMap::PlateMap(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(true);
    setFocusPolicy(Qt::ClickFocus);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

QColor PlateMap::colorOf(WellState s)
{
    switch (s) {
    case WellState::Unused: return QColor(0xfa, 0xfa, 0xfa);
    case WellState::Planned: return QColor(0x90, 0xca, 0xf9);
    case WellState::Done: return QColor(0x66, 0xbb, 0x6a);
    case WellState::Current: return QColor(0xff, 0xa7, 0x26);
    case WellState::Error: return QColor(0xe5, 0x39, 0x35);
    }
    return Qt::white;
}

void PlateMap::setLabware(const motion::plates::Labware& labware, const QString& title)
{
    m_labware = labware;
    m_title = title;
    m_selection.clear();
    m_states.clear();
    m_volumes.clear();
    emit selectionChanged();
    update();
}

void PlateMap::setTitle(const QString& title)
{
    if (title == m_title)
        return;
    m_title = title;
    update();
}

void PlateMap::setTransform(const motion::plates::PlateTransform& t, bool calibrated)
{
    m_transform = t;
    m_calibrated = calibrated;
}

void PlateMap::setWellStates(const QMap<QString, WellState>& states)
{
    m_states = states;
    update();
}

void PlateMap::setVolumes(const QMap<QString, double>& volumesUl)
{
    m_volumes = volumesUl;
}

void PlateMap::setSelection(const std::set<motion::plates::WellId>& wells)
{
    std::set<motion::plates::WellId> valid;
    for (const auto& w : wells)
        if (m_labware.well(w))
            valid.insert(w);
    if (valid == m_selection)
        return;
    m_selection = std::move(valid);
    emit selectionChanged();
    update();
}

double PlateMap::scale() const
{
    if (m_labware.lengthMm <= 0 || m_labware.widthMm <= 0)
        return 1;
    return std::max(0.1, std::min((width() - 2 * kMarginPx) / m_labware.lengthMm, (height() - 2 * kMarginPx) / m_labware.widthMm));
}

QPointF PlateMap::origin() const
{
    const double s = scale();
    return {(width() - m_labware.lengthMm * s) / 2, (height() - m_labware.widthMm * s) / 2};
}

QPointF PlateMap::toWidget(double xMm, double yMm) const
{
    // Plate y grows toward the front, which is down on the screen: no flip.
    return origin() + QPointF(xMm, yMm) * scale();
}

QPointF PlateMap::toPlate(const QPointF& p) const { return (p - origin()) / scale(); }

QPointF PlateMap::wellCenter(const motion::plates::WellId& w) const
{
    const motion::plates::Well* well = m_labware.well(w);
    return well ? toWidget(well->xMm, well->yMm) : QPointF();
}

std::optional<motion::plates::WellId> PlateMap::wellAt(const QPointF& pos) const
{
    const QPointF mm = toPlate(pos);
    for (const motion::plates::Well& w : m_labware.wells) {
        const double dx = mm.x() - w.xMm, dy = mm.y() - w.yMm;
        const bool inside = w.shape == motion::plates::WellShape::Circular ? std::hypot(dx, dy) <= w.diameterMm / 2
                                                                     : std::abs(dx) <= w.sizeXMm / 2 && std::abs(dy) <= w.sizeYMm / 2;
        if (inside)
            return w.id;
    }
    return std::nullopt;
}

std::set<motion::plates::WellId> PlateMap::wellsIn(const QRectF& r) const
{
    // Every well the rectangle touches: a drag from inside one well to inside another
    // takes both and the block between, wherever in them the pointer was pressed and let go.
    std::set<motion::plates::WellId> out;
    const QRectF n(toPlate(r.normalized().topLeft()), toPlate(r.normalized().bottomRight()));
    for (const motion::plates::Well& w : m_labware.wells) {
        const double dx = std::max({n.left() - w.xMm, 0.0, w.xMm - n.right()});
        const double dy = std::max({n.top() - w.yMm, 0.0, w.yMm - n.bottom()});
        const bool touched = w.shape == motion::plates::WellShape::Circular ? std::hypot(dx, dy) <= w.diameterMm / 2
                                                                      : dx <= w.sizeXMm / 2 && dy <= w.sizeYMm / 2;
        if (touched)
            out.insert(w.id);
    }
    return out;
}

QString PlateMap::describeWell(const motion::plates::WellId& id) const
{
    const motion::plates::Well* w = m_labware.well(id);
    if (!w)
        return {};
    const QString name = QString::fromStdString(motion::plates::wellName(id));
    const motion::plates::PointMm m = m_transform.apply({w->xMm, w->yMm});
    QString text = tr("%1 · plate (%2, %3) mm · machine (%4, %5) mm%6")
                       .arg(name)
                       .arg(w->xMm, 0, 'f', 2)
                       .arg(w->yMm, 0, 'f', 2)
                       .arg(m.x, 0, 'f', 2)
                       .arg(m.y, 0, 'f', 2)
                       .arg(m_calibrated ? QString() : tr(" (nominal: slot not calibrated)"));
    const auto v = m_volumes.constFind(name);
    if (v != m_volumes.constEnd() && std::abs(*v) > 1e-9)
        text += *v > 0 ? tr(" · %1 µL dispensed").arg(*v, 0, 'g', 6) : tr(" · %1 µL aspirated").arg(-*v, 0, 'g', 6);
    else if (m_states.value(name, WellState::Unused) != WellState::Unused)
        text += tr(" · visited, no net volume");
    text += tr(" · holds %1 µL").arg(w->volumeUl, 0, 'g', 6);
    return text;
}

void PlateMap::setHover(const QString& text)
{
    if (text == m_hoverText)
        return;
    m_hoverText = text;
    emit hovered(text);
}

void PlateMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().window());
    if (m_labware.wells.empty()) {
        p.drawText(rect(), Qt::AlignCenter, tr("No plate"));
        return;
    }
    const double s = scale();
    const QRectF footprint(toWidget(0, 0), toWidget(m_labware.lengthMm, m_labware.widthMm));
    p.setPen(QPen(QColor(0x60, 0x60, 0x60), 1.5));
    p.setBrush(QColor(0xe8, 0xea, 0xed));
    p.drawRoundedRect(footprint, 3 * s, 3 * s);
    // Chamfered corner by H1 / A12 on real plates is not drawn: A1 is marked instead.
    QFont f = font();
    f.setPointSizeF(std::clamp(s * 2.4, 6.0, 11.0));
    p.setFont(f);
    p.setPen(QColor(0x44, 0x44, 0x44));
    for (int r = 0; r < m_labware.rows; ++r) {
        const motion::plates::Well* w = m_labware.well({r, 0});
        if (!w)
            continue;
        const QPointF c = toWidget(0, w->yMm);
        p.drawText(QRectF(c.x() - kMarginPx, c.y() - 10, kMarginPx - 4, 20), Qt::AlignRight | Qt::AlignVCenter,
                   QString::fromStdString(motion::plates::rowName(r)));
    }
    for (int c = 0; c < m_labware.columns; ++c) {
        const motion::plates::Well* w = m_labware.well({0, c});
        if (!w)
            continue;
        const QPointF at = toWidget(w->xMm, 0);
        p.drawText(QRectF(at.x() - 15, at.y() - kMarginPx, 30, kMarginPx - 3), Qt::AlignHCenter | Qt::AlignBottom, QString::number(c + 1));
    }
    for (const motion::plates::Well& w : m_labware.wells) {
        const QString name = QString::fromStdString(motion::plates::wellName(w.id));
        const WellState st = m_states.value(name, WellState::Unused);
        const bool selected = m_selection.count(w.id) > 0;
        p.setBrush(colorOf(st));
        p.setPen(selected ? QPen(QColor(0x1a, 0x23, 0x7e), std::max(2.0, s * 0.5)) : QPen(QColor(0x75, 0x75, 0x75), 1));
        const QPointF c = toWidget(w.xMm, w.yMm);
        if (w.shape == motion::plates::WellShape::Circular) {
            const double r = w.diameterMm / 2 * s;
            p.drawEllipse(c, r, r);
        } else {
            p.drawRect(QRectF(c.x() - w.sizeXMm / 2 * s, c.y() - w.sizeYMm / 2 * s, w.sizeXMm * s, w.sizeYMm * s));
        }
    }
    if (m_dragging && m_pressAt) {
        p.setPen(QPen(QColor(0x1a, 0x23, 0x7e), 1, Qt::DashLine));
        p.setBrush(QColor(0x1a, 0x23, 0x7e, 30));
        p.drawRect(QRectF(*m_pressAt, m_dragTo).normalized());
    }
    p.setPen(QColor(0x33, 0x33, 0x33));
    p.drawText(QRectF(footprint.left(), footprint.bottom() + 2, footprint.width(), kMarginPx - 4), Qt::AlignLeft | Qt::AlignTop,
               m_title + tr("  ·  %1 × %2 mm, drawn to scale").arg(m_labware.lengthMm).arg(m_labware.widthMm));
}

void PlateMap::mousePressEvent(QMouseEvent* e)
{
    if (e->button() != Qt::LeftButton)
        return;
    m_pressAt = e->position();
    m_dragTo = e->position();
    m_dragging = false;
    m_dragBase = (e->modifiers() & Qt::ControlModifier) ? m_selection : std::set<motion::plates::WellId>{};
}

void PlateMap::mouseMoveEvent(QMouseEvent* e)
{
    const auto w = wellAt(e->position());
    setHover(w ? describeWell(*w) : QString());
    if (w)
        QToolTip::showText(e->globalPosition().toPoint(), m_hoverText, this);
    else
        QToolTip::hideText();
    if (!m_pressAt || !(e->buttons() & Qt::LeftButton))
        return;
    m_dragTo = e->position();
    if (!m_dragging && (m_dragTo - *m_pressAt).manhattanLength() < kDragPx)
        return;
    m_dragging = true;
    selectDragged();
    update();
}

void PlateMap::selectDragged()
{
    std::set<motion::plates::WellId> sel = m_dragBase;
    for (const auto& id : wellsIn(QRectF(*m_pressAt, m_dragTo)))
        sel.insert(id);
    setSelection(sel);
}

void PlateMap::mouseReleaseEvent(QMouseEvent* e)
{
    if (e->button() != Qt::LeftButton || !m_pressAt)
        return;
    if (m_dragging && e->position() != m_dragTo) {
        // Where the button came up ends the drag, even when no move was reported there.
        m_dragTo = e->position();
        selectDragged();
    }
    if (!m_dragging) {
        const auto w = wellAt(e->position());
        std::set<motion::plates::WellId> sel = (e->modifiers() & Qt::ControlModifier) ? m_selection : std::set<motion::plates::WellId>{};
        if (w) {
            if (sel.count(*w))
                sel.erase(*w);
            else
                sel.insert(*w);
        }
        setSelection(sel);
    }
    m_pressAt.reset();
    m_dragging = false;
    update();
}

void PlateMap::leaveEvent(QEvent*) { setHover(QString()); }

} // namespace ui
