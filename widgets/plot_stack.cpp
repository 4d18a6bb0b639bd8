#include "widgets/plot_stack.h"

#include "widgets/plot_panel.h"

#include <QTimer>

#include <cmath>

namespace ui {

PlotStack::PlotStack(const PlotDataSource* source, QWidget* parent)
    : QCustomPlot(parent), m_source(source), m_anchorS{std::nan(""), std::nan("")}
{
    plotLayout()->clear();  // drop the default axis rect and legend: panels bring their own
    plotLayout()->setRowSpacing(2);
    m_margins = new QCPMarginGroup(this);
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setNoAntialiasingOnDrag(true);
    setPlottingHints(QCP::phCacheLabels);
    // One paint buffer instead of two: the overlay layer gets no buffer of its own,
    // which saves clearing and compositing a full-size ARGB image every frame.
    layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    setNotAntialiasedElements(QCP::aeAll);
    setProperty(kTimeTitleProperty, tr("Time (s, 0 = newest sample)"));
    addPanel();
}

PlotStack::~PlotStack()
{
    qDeleteAll(m_panels);  // graphs first, while their axes still exist
    m_panels.clear();
}

int PlotStack::panelAt(const QPoint& pos) const
{
    for (int i = 0; i < m_panels.size(); ++i)
        if (m_panels[i]->rect()->outerRect().contains(pos))
            return i;
    return -1;
}

PlotPanel* PlotStack::addPanel()
{
    auto* p = new PlotPanel(this, m_margins, this);
    const QCPRange range = m_panels.isEmpty() ? QCPRange(-10, 0) : timeRange();
    plotLayout()->addElement(m_panels.size(), 0, p->rect());
    m_panels << p;
    ++m_programmatic;
    p->timeAxis()->setRange(range);
    --m_programmatic;
    watchRanges(p);
    relabel();
    emit layoutChanged();
    return p;
}

bool PlotStack::removePanel(int index)
{
    if (index < 0 || index >= m_panels.size() || m_panels.size() == 1)
        return false;
    PlotPanel* p = m_panels.takeAt(index);
    QCPAxisRect* rect = p->rect();
    delete p;  // removes its graphs
    plotLayout()->remove(rect);
    plotLayout()->simplify();
    if (m_highlighted >= m_panels.size())
        m_highlighted = m_panels.size() - 1;
    relabel();
    emit layoutChanged();
    return true;
}

void PlotStack::watchRanges(PlotPanel* p)
{
    connect(p->timeAxis(), qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this, p](const QCPRange& r) {
        if (m_programmatic)
            return;
        ++m_programmatic;
        for (PlotPanel* other : std::as_const(m_panels))
            if (other != p)
                other->timeAxis()->setRange(r);
        --m_programmatic;
        emit userMovedTime();
    });
    for (QCPAxis* a : {p->leftAxis(), p->rightAxis()})
        connect(a, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
            if (!m_programmatic)
                emit userMovedValues();
        });
}

void PlotStack::relabel()
{
    m_layoutDirty = true;
    for (int i = 0; i < m_panels.size(); ++i) {
        m_panels[i]->setTimeLabelsVisible(i == m_panels.size() - 1, property(kTimeTitleProperty).toString());
        m_panels[i]->setHighlighted(i == m_highlighted && m_panels.size() > 1);
    }
}

void PlotStack::setTimeTitle(const QString& title)
{
    setProperty(kTimeTitleProperty, title);
    relabel();
}

void PlotStack::setHighlightedPanel(int index)
{
    m_highlighted = index;
    relabel();
}

bool PlotStack::addChannel(int panel, const dev::tele::ChannelKey& key)
{
    PlotPanel* p = m_panels.value(panel);
    if (!p || !m_source || !p->addChannel(key, m_source->channelName(key), m_source->channelUnit(key)))
        return false;
    m_layoutDirty = true;  // a right-hand axis may have appeared
    emit layoutChanged();
    return true;
}

bool PlotStack::removeChannel(int panel, const dev::tele::ChannelKey& key)
{
    PlotPanel* p = m_panels.value(panel);
    if (!p || !p->removeChannel(key))
        return false;
    m_layoutDirty = true;
    emit layoutChanged();
    return true;
}

QVector<dev::tele::ChannelKey> PlotStack::allChannels() const
{
    QVector<dev::tele::ChannelKey> out;
    for (const PlotPanel* p : m_panels)
        for (const auto& k : p->channels()) {
            bool seen = false;
            for (const auto& o : std::as_const(out))
                seen = seen || sameChannel(o, k);
            if (!seen)
                out << k;
        }
    return out;
}

void PlotStack::setAnchors(double analyzerS, double stageS)
{
    m_anchorS[0] = analyzerS;
    m_anchorS[1] = stageS;
}

void PlotStack::setTimeRange(double x0S, double x1S)
{
    ++m_programmatic;
    for (PlotPanel* p : std::as_const(m_panels))
        p->timeAxis()->setRange(x0S, x1S);
    --m_programmatic;
}

QCPRange PlotStack::timeRange() const { return m_panels.first()->timeAxis()->range(); }

int PlotStack::columns() const { return m_panels.first()->rect()->width(); }

void PlotStack::redraw()
{
    ++m_programmatic;
    // Lay out first (when something changed) so the columns asked of the stores match the pixels drawn.
    if (m_layoutDirty || columns() <= 1) {
        updateLayout();
        m_layoutDirty = false;
    }
    const int cols = columns();
    const QCPRange r = timeRange();
    for (PlotPanel* p : std::as_const(m_panels)) {
        if (m_source)
            p->refresh(*m_source, r.lower, r.upper, m_anchorS, cols);
        if (m_autoScale)
            p->autoScaleValues();
    }
    --m_programmatic;
    replot(QCustomPlot::rpQueuedRefresh);
    emit redrawn();
}

void PlotStack::wheelEvent(QWheelEvent* event)
{
    const int i = panelAt(event->position().toPoint());
    if (i >= 0)
        m_panels[i]->rect()->setRangeZoom(event->modifiers() & Qt::ControlModifier ? Qt::Vertical : Qt::Horizontal);
    QCustomPlot::wheelEvent(event);
}

void PlotStack::changeEvent(QEvent* event)
{
    QCustomPlot::changeEvent(event);
    if (event->type() != QEvent::LanguageChange)
        return;
    // The legends name channels in the words of the language they were added in: named again
    // once the window has given the instruments their new names (after this event).
    QTimer::singleShot(0, this, [this] {
        if (!m_source)
            return;
        for (PlotPanel* p : std::as_const(m_panels))
            p->rename(*m_source);
        replot(QCustomPlot::rpQueuedReplot);
    });
}

void PlotStack::resizeEvent(QResizeEvent* event)
{
    m_layoutDirty = true;
    QCustomPlot::resizeEvent(event);
}

void PlotStack::mousePressEvent(QMouseEvent* event)
{
    const int i = panelAt(event->pos());
    if (i >= 0)
        emit panelClicked(i);
    QCustomPlot::mousePressEvent(event);
}

} // namespace ui
