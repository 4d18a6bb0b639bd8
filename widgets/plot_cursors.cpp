#include "widgets/plot_cursors.h"

#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"

#include <QHeaderView>
#include <QMouseEvent>

#include <cmath>

namespace ui {
namespace {
const QColor kCursorColour[2] = {QColor(0xc2, 0x18, 0x5b), QColor(0x00, 0x89, 0x7b)};
constexpr int kGrabPx = 6;  ///< how close to a cursor line a press grabs it
} // namespace

PlotCursors::PlotCursors(PlotStack* stack) : QObject(stack), m_stack(stack)
{
    connect(m_stack, &PlotStack::layoutChanged, this, &PlotCursors::rebuild);
    m_stack->installEventFilter(this);
}

PlotCursors::~PlotCursors() = default;  // items belong to the plot

void PlotCursors::setVisible(bool on)
{
    if (on && !m_placed) {
        const QCPRange r = m_stack->timeRange();
        m_x[0] = r.lower + r.size() / 3;
        m_x[1] = r.lower + r.size() * 2 / 3;
        m_placed = true;
    }
    m_visible = on;
    rebuild();
    emit changed();
}

void PlotCursors::setPositions(double xA, double xB)
{
    m_x[0] = xA;
    m_x[1] = xB;
    m_placed = true;
    place();
    m_stack->replot(QCustomPlot::rpQueuedReplot);
    emit changed();
}

void PlotCursors::rebuild()
{
    for (auto& lines : m_lines) {
        for (QCPItemStraightLine* l : std::as_const(lines))
            m_stack->removeItem(l);
        lines.clear();
    }
    for (QCPItemText*& t : m_labels) {
        if (t)
            m_stack->removeItem(t);
        t = nullptr;
    }
    if (!m_visible)
        return;
    for (int c = 0; c < 2; ++c) {
        QPen pen(kCursorColour[c], 1.2, Qt::DashLine);
        for (int i = 0; i < m_stack->panelCount(); ++i) {
            PlotPanel* p = m_stack->panel(i);
            auto* line = new QCPItemStraightLine(m_stack);
            line->setPen(pen);
            line->setSelectable(false);
            line->setClipAxisRect(p->rect());
            for (QCPItemPosition* pos : {line->point1, line->point2})
                pos->setAxes(p->timeAxis(), p->leftAxis());
            m_lines[c] << line;
        }
        PlotPanel* top = m_stack->panel(0);
        auto* label = new QCPItemText(m_stack);
        label->setText(c == 0 ? tr("A") : tr("B"));
        label->setColor(Qt::white);
        label->setBrush(kCursorColour[c]);
        label->setPadding(QMargins(3, 1, 3, 1));
        label->setSelectable(false);
        label->setClipAxisRect(top->rect());
        label->position->setAxes(top->timeAxis(), top->leftAxis());
        label->position->setAxisRect(top->rect());
        label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->setPositionAlignment(Qt::AlignTop | Qt::AlignHCenter);
        m_labels[c] = label;
    }
    place();
}

void PlotCursors::place()
{
    for (int c = 0; c < 2; ++c) {
        for (QCPItemStraightLine* l : std::as_const(m_lines[c])) {
            l->point1->setCoords(m_x[c], 0);
            l->point2->setCoords(m_x[c], 1);
        }
        if (m_labels[c])
            m_labels[c]->position->setCoords(m_x[c], 0);
    }
}

int PlotCursors::cursorNear(const QPoint& pos) const
{
    const int i = m_stack->panelAt(pos);
    if (!m_visible || i < 0)
        return -1;
    const QCPAxis* axis = m_stack->panel(i)->timeAxis();
    int best = -1;
    double bestPx = kGrabPx + 1;
    for (int c = 0; c < 2; ++c) {
        const double d = std::abs(axis->coordToPixel(m_x[c]) - pos.x());
        if (d <= kGrabPx && d < bestPx) {
            best = c;
            bestPx = d;
        }
    }
    return best;
}

bool PlotCursors::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_stack || !m_visible)
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton)
            return false;
        m_drag = cursorNear(e->pos());
        if (m_drag < 0)
            return false;  // not on a cursor: the plot pans as usual
        m_stack->setCursor(Qt::SplitHCursor);
        return true;
    }
    case QEvent::MouseMove: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (m_drag < 0)
            return false;
        m_x[m_drag] = m_stack->panel(0)->timeAxis()->pixelToCoord(e->pos().x());
        place();
        m_stack->replot(QCustomPlot::rpQueuedReplot);
        emit changed();
        return true;
    }
    case QEvent::MouseButtonRelease:
        if (m_drag < 0)
            return false;
        m_drag = -1;
        m_stack->unsetCursor();
        return true;
    default:
        return false;
    }
}

QVector<CursorReading> PlotCursors::readings() const
{
    QVector<CursorReading> out;
    const PlotDataSource* source = m_stack->source();
    for (int i = 0; i < m_stack->panelCount(); ++i)
        for (const PlotPanel::Line& l : m_stack->panel(i)->lines()) {
            CursorReading r;
            r.panel = i;
            r.key = l.key;
            r.name = l.name;
            r.unit = l.unit;
            const double anchor = m_stack->anchorS(l.key.instrument);
            const dev::tele::ChannelStore* store = source ? source->store(l.key) : nullptr;
            if (store && !store->empty() && !std::isnan(anchor)) {
                r.a = store->nearest(anchor + m_x[0]);
                r.b = store->nearest(anchor + m_x[1]);
            }
            out << r;
        }
    return out;
}

CursorReadout::CursorReadout(PlotCursors* cursors, QWidget* parent) : QTableWidget(parent), m_cursors(cursors)
{
    setColumnCount(4);
    setHorizontalHeaderLabels({tr("Channel"), tr("A"), tr("B"), tr("Δ (B − A)")});
    horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int c = 1; c < 4; ++c)
        horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    verticalHeader()->setVisible(false);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::NoSelection);
    setFocusPolicy(Qt::NoFocus);
    connect(cursors, &PlotCursors::changed, this, &CursorReadout::refresh);
    refresh();
}

void CursorReadout::refresh()
{
    setVisible(m_cursors->isVisible());
    if (!m_cursors->isVisible())
        return;
    const auto rows = m_cursors->readings();
    setRowCount(rows.size() + 1);
    auto put = [this](int row, int col, const QString& text) {
        QTableWidgetItem* it = item(row, col);
        if (!it) {
            it = new QTableWidgetItem;
            if (col > 0)
                it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(row, col, it);
        }
        if (it->text() != text)
            it->setText(text);
    };
    auto num = [](double v) { return QString::number(v, 'g', 6); };
    put(0, 0, tr("Time (s)"));
    put(0, 1, QString::number(m_cursors->position(0), 'f', 4));
    put(0, 2, QString::number(m_cursors->position(1), 'f', 4));
    put(0, 3, QString::number(m_cursors->deltaT(), 'f', 4));
    for (int i = 0; i < rows.size(); ++i) {
        const CursorReading& r = rows[i];
        put(i + 1, 0, r.unit.isEmpty() ? r.name : tr("%1 (%2)").arg(r.name, r.unit));
        put(i + 1, 1, r.a ? num(r.a->value) : tr("—"));
        put(i + 1, 2, r.b ? num(r.b->value) : tr("—"));
        const auto d = r.deltaY();
        put(i + 1, 3, d ? num(*d) : tr("—"));
    }
}

} // namespace ui
