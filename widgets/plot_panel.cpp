#include "widgets/plot_panel.h"
#include "widgets/plot_ticks.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace ui {
namespace {

/// Colours by instrument and axis, so a channel keeps its colour in every plot:
/// the stage's X/Y in blue/orange, the analyzer's X/Y/Z/P in green/red/purple/brown.
QColor colourFor(const dev::tele::ChannelKey& key)
{
    static const QColor stage[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e)};
    static const QColor analyzer[] = {QColor(0x2c, 0xa0, 0x2c), QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd),
                                      QColor(0x8c, 0x56, 0x4b)};
    if (key.ref.axis == dev::proto::kNoAxis)
        return QColor(0xe3, 0x77, 0xc2);
    if (key.instrument == 1)
        return stage[key.ref.axis % 2];
    return analyzer[key.ref.axis % 4];
}

Qt::PenStyle styleFor(dev::proto::ChannelKind kind)
{
    switch (kind) {
    case dev::proto::ChannelKind::Commanded: return Qt::DashLine;
    case dev::proto::ChannelKind::Velocity: return Qt::DotLine;
    case dev::proto::ChannelKind::ControllerOutput: return Qt::DashDotLine;
    case dev::proto::ChannelKind::Switches: return Qt::DashDotDotLine;
    default: return Qt::SolidLine;
    }
}

} // namespace

QPen PlotPanel::penFor(const dev::tele::ChannelKey& key)
{
    // One pixel wide: the raster engine draws such lines on its fast path; a wider
    // (or fractional) pen goes through the stroker and costs ten times as much.
    QPen pen(colourFor(key), 1.0);
    pen.setStyle(styleFor(key.ref.kind));
    return pen;
}

PlotPanel::PlotPanel(QCustomPlot* plot, QCPMarginGroup* margins, QObject* parent)
    : QObject(parent), m_plot(plot), m_rect(new QCPAxisRect(plot)), m_points(std::make_unique<QVector<QCPGraphData>>())
{
    m_rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    m_rect->setupFullAxesBox(false);
    m_rect->axis(QCPAxis::atTop)->setVisible(false);
    rightAxis()->setVisible(false);
    timeAxis()->setTickLabels(false);
    leftAxis()->setNumberFormat(QStringLiteral("gb"));
    rightAxis()->setNumberFormat(QStringLiteral("gb"));
    useDistinctTickLabels(leftAxis());
    useDistinctTickLabels(rightAxis());
    for (QCPAxis* a : {timeAxis(), leftAxis(), rightAxis()}) {
        a->grid()->setPen(QPen(QColor(0xe6, 0xe6, 0xe6), 0));  // solid: dotted pens cost a dash pattern per frame
        QFont f = a->labelFont();
        f.setPointSizeF(f.pointSizeF() * 0.9);
        a->setLabelFont(f);
    }
    rightAxis()->grid()->setVisible(false);
    m_rect->setRangeDrag(Qt::Horizontal | Qt::Vertical);
    m_rect->setRangeZoom(Qt::Horizontal);
    m_rect->setRangeDragAxes({timeAxis()}, {leftAxis(), rightAxis()});
    m_rect->setRangeZoomAxes({timeAxis()}, {leftAxis(), rightAxis()});

    // A legend per panel, one row across the top left, so each plot says what it shows.
    m_legend = new QCPLegend;
    m_rect->insetLayout()->addElement(m_legend, Qt::AlignTop | Qt::AlignLeft);
    m_legend->setLayer(QStringLiteral("legend"));
    m_legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_legend->setWrap(4);
    m_legend->setBrush(QColor(255, 255, 255, 210));
    m_legend->setBorderPen(QPen(QColor(0xbb, 0xbb, 0xbb)));
    QFont lf = m_legend->font();
    lf.setPointSizeF(lf.pointSizeF() * 0.85);
    m_legend->setFont(lf);
    m_legend->setIconSize(22, 10);
    m_legend->setRowSpacing(0);
    m_legend->setColumnSpacing(6);
    m_legend->setVisible(false);
}

PlotPanel::~PlotPanel()
{
    for (const Line& l : std::as_const(m_lines)) {
        l.graph->removeFromLegend(m_legend);
        m_plot->removeGraph(l.graph);
    }
}

QCPAxis* PlotPanel::timeAxis() const { return m_rect->axis(QCPAxis::atBottom); }
QCPAxis* PlotPanel::leftAxis() const { return m_rect->axis(QCPAxis::atLeft); }
QCPAxis* PlotPanel::rightAxis() const { return m_rect->axis(QCPAxis::atRight); }

int PlotPanel::indexOf(const dev::tele::ChannelKey& key) const
{
    for (int i = 0; i < m_lines.size(); ++i)
        if (sameChannel(m_lines[i].key, key))
            return i;
    return -1;
}

QVector<dev::tele::ChannelKey> PlotPanel::channels() const
{
    QVector<dev::tele::ChannelKey> out;
    for (const Line& l : m_lines)
        out << l.key;
    return out;
}

QCPGraph* PlotPanel::graph(const dev::tele::ChannelKey& key) const
{
    const int i = indexOf(key);
    return i < 0 ? nullptr : m_lines[i].graph;
}

bool PlotPanel::addChannel(const dev::tele::ChannelKey& key, const QString& name, const QString& unit)
{
    if (hasChannel(key))
        return false;
    Line l;
    l.key = key;
    l.name = name;
    l.unit = unit;
    l.graph = m_plot->addGraph(timeAxis(), leftAxis());
    l.graph->setName(unit.isEmpty() ? name : QStringLiteral("%1 (%2)").arg(name, unit));
    l.graph->setAdaptiveSampling(false);  // the data is already at most two points per pixel column
    l.graph->setAntialiased(false);
    QPen pen = penFor(key);
    // Two lines of the same look in one plot (say measured position and velocity
    // of X on different axes) get told apart by a darker shade.
    for (const Line& other : std::as_const(m_lines))
        if (other.graph->pen().color() == pen.color() && other.graph->pen().style() == pen.style())
            pen.setColor(pen.color().darker(160));
    l.graph->setPen(pen);
    l.graph->removeFromLegend();
    l.graph->addToLegend(m_legend);
    m_lines << l;
    m_extent << std::make_pair(std::nan(""), std::nan(""));
    relayoutAxes();
    return true;
}

void PlotPanel::rename(const PlotDataSource& source)
{
    for (Line& l : m_lines) {
        l.name = source.channelName(l.key);
        l.graph->setName(l.unit.isEmpty() ? l.name : QStringLiteral("%1 (%2)").arg(l.name, l.unit));
    }
}

bool PlotPanel::removeChannel(const dev::tele::ChannelKey& key)
{
    const int i = indexOf(key);
    if (i < 0)
        return false;
    // removeGraph() only takes a graph out of the plot's own legend: this panel's legend
    // would keep an item pointing at the deleted graph and crash the next layout.
    m_lines[i].graph->removeFromLegend(m_legend);
    m_plot->removeGraph(m_lines[i].graph);
    m_lines.removeAt(i);
    m_extent.removeAt(i);
    relayoutAxes();
    return true;
}

void PlotPanel::relayoutAxes()
{
    // The first channel's unit goes on the left; the others share the right axis.
    const QString primary = m_lines.isEmpty() ? QString() : m_lines.first().unit;
    QStringList rightUnits;
    for (Line& l : m_lines) {
        const bool left = l.unit == primary;
        l.graph->setValueAxis(left ? leftAxis() : rightAxis());
        if (!left && !rightUnits.contains(l.unit))
            rightUnits << l.unit;
    }
    leftAxis()->setLabel(primary);
    rightAxis()->setLabel(rightUnits.join(QStringLiteral(", ")));
    rightAxis()->setVisible(!rightUnits.isEmpty());
    rightAxis()->setTickLabels(!rightUnits.isEmpty());
    m_legend->setVisible(!m_lines.isEmpty());
}

void PlotPanel::setTimeLabelsVisible(bool visible, const QString& title)
{
    timeAxis()->setTickLabels(visible);
    timeAxis()->setLabel(visible ? title : QString());
}

void PlotPanel::setHighlighted(bool on)
{
    // Only the chosen plot gets a fill: the others show the plot's own white background
    // and cost nothing to paint.
    m_rect->setBackground(on ? QBrush(QColor(0xf3, 0xf7, 0xff)) : QBrush(Qt::NoBrush));
}

void PlotPanel::refresh(const PlotDataSource& source, double x0S, double x1S, const double anchorS[2], int columns)
{
    for (int i = 0; i < m_lines.size(); ++i) {
        Line& l = m_lines[i];
        const dev::tele::ChannelStore* store = source.store(l.key);
        const int inst = std::clamp(l.key.instrument, 0, 1);
        m_extent[i] = {std::nan(""), std::nan("")};
        if (!store || store->empty() || std::isnan(anchorS[inst]) || columns <= 0 || !(x1S > x0S)) {
            l.graph->data()->clear();
            continue;
        }
        feed(l, *store, x0S, x1S, anchorS[inst], columns);
        // The extent of what is inside the range (not the edge samples), for auto-scale.
        double lo = std::nan(""), hi = std::nan("");
        for (const QCPGraphData& p : std::as_const(*m_points))
            if (p.key >= x0S && p.key <= x1S && !std::isnan(p.value)) {
                lo = std::isnan(lo) ? p.value : std::min(lo, p.value);
                hi = std::isnan(hi) ? p.value : std::max(hi, p.value);
            }
        m_extent[i] = {lo, hi};
    }
}

void PlotPanel::feed(Line& line, const dev::tele::ChannelStore& store, double x0S, double x1S, double anchorS, int columns)
{
    QVector<QCPGraphData>& pts = *m_points;
    pts.clear();
    const double t0 = anchorS + x0S, t1 = anchorS + x1S;
    const std::size_t lo = store.lowerBound(t0);
    const std::size_t hi = store.lowerBound(t1);
    // One sample either side of the range, so the line runs to the plot's edges.
    if (lo > 0) {
        const dev::tele::Sample s = store.at(lo - 1);
        pts.append(QCPGraphData(s.tS - anchorS, s.value));
    }
    if (hi - lo <= 2 * static_cast<std::size_t>(columns)) {
        for (std::size_t i = lo; i < hi; ++i) {
            const dev::tele::Sample s = store.at(i);
            pts.append(QCPGraphData(s.tS - anchorS, s.value));
        }
    } else {
        m_columns.resize(static_cast<std::size_t>(columns));
        store.decimate(t0, t1, columns, m_columns.data());
        const double width = (x1S - x0S) / columns;
        double last = pts.isEmpty() ? std::nan("") : pts.last().value;
        for (int c = 0; c < columns; ++c) {
            const dev::tele::MinMax& mm = m_columns[static_cast<std::size_t>(c)];
            if (mm.empty())
                continue;
            const double x = x0S + (c + 0.5) * width;
            if (mm.min == mm.max) {
                pts.append(QCPGraphData(x, mm.min));
                last = mm.min;
                continue;
            }
            // Draw the column's vertical stroke starting from the end nearer the
            // previous point, so a smooth signal does not zig-zag.
            const bool maxFirst = !std::isnan(last) && std::abs(last - mm.max) < std::abs(last - mm.min);
            pts.append(QCPGraphData(x, maxFirst ? mm.max : mm.min));
            pts.append(QCPGraphData(x, maxFirst ? mm.min : mm.max));
            last = maxFirst ? mm.min : mm.max;
        }
    }
    if (hi < store.size()) {
        const dev::tele::Sample s = store.at(hi);
        pts.append(QCPGraphData(s.tS - anchorS, s.value));
    }
    line.graph->data()->set(pts, true);
}

void PlotPanel::autoScaleValues()
{
    auto fit = [this](QCPAxis* axis) {
        double lo = std::nan(""), hi = std::nan("");
        for (int i = 0; i < m_lines.size(); ++i) {
            if (m_lines[i].graph->valueAxis() != axis || std::isnan(m_extent[i].first))
                continue;
            lo = std::isnan(lo) ? m_extent[i].first : std::min(lo, m_extent[i].first);
            hi = std::isnan(hi) ? m_extent[i].second : std::max(hi, m_extent[i].second);
        }
        if (std::isnan(lo))
            return;
        double span = hi - lo;
        if (!(span > 0))
            span = std::max(std::abs(hi) * 0.1, 1.0);  // a flat line sits in the middle of one unit
        const double mid = (hi + lo) / 2;
        axis->setRange(mid - span * 0.56, mid + span * 0.56);
    };
    fit(leftAxis());
    if (rightAxis()->visible())
        fit(rightAxis());
}

} // namespace ui
