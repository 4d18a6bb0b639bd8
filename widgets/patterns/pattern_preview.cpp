#include "widgets/patterns/pattern_preview.h"

#include "motion/path/grid_walker.h"

#include <algorithm>
#include <cmath>

namespace ui {

using motion::path::Segment;
using motion::path::Vec2;

PatternPreview::PatternPreview(QWidget* parent) : QCustomPlot(parent)
{
    setObjectName(QStringLiteral("patternPreview"));
    setMinimumSize(260, 260);
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_travel = new QCPItemRect(this);
    m_travel->setPen(QPen(QColor(0x70, 0x70, 0x70), 1.5));
    m_soft = new QCPItemRect(this);
    m_soft->setPen(QPen(QColor(0xe0, 0x8a, 0x00), 1.5, Qt::DashLine));
    m_curve = new QCPCurve(xAxis, yAxis);
    m_curve->setName(tr("pattern"));
    m_curve->setPen(QPen(QColor(0x30, 0x30, 0x30), 1.5));
    m_walk = new QCPCurve(xAxis, yAxis);
    m_walk->setName(tr("point-by-point steps"));
    m_walk->setPen(QPen(QColor(0x2e, 0x7d, 0x32), 1));
    m_walk->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 3));
    m_commanded = new QCPCurve(xAxis, yAxis);
    m_commanded->setName(tr("commanded"));
    m_commanded->setPen(QPen(QColor(0x90, 0x90, 0x90), 1, Qt::DashLine));
    // The measured XY is what telemetry sampled: drawn as its samples, not joined. A line
    // through them is no path the machine took (10 Hz on a small circle cut chords 0.12 mm
    // inside it); at a fast rate the markers run together into the trace anyway.
    m_measured = new QCPCurve(xAxis, yAxis);
    m_measured->setName(tr("measured (samples)"));
    m_measured->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 2));
    m_measured->setLineStyle(QCPCurve::lsNone);
    m_measured->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(0x1f, 0x77, 0xb4), 4));
    m_start = addGraph();
    m_start->setName(tr("start"));
    m_start->setLineStyle(QCPGraph::lsNone);
    m_start->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssTriangle, QPen(QColor(0x2e, 0x7d, 0x32), 2), QColor(0x2e, 0x7d, 0x32), 11));
    m_machine = addGraph();
    m_machine->setName(tr("machine"));
    m_machine->setLineStyle(QCPGraph::lsNone);
    m_machine->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(0xd3, 0x2f, 0x2f), 8));
    for (QCPCurve* c : {m_walk, m_commanded, m_measured})
        c->setAntialiased(false);
    legend->setVisible(true);
    QFont lf = legend->font();
    lf.setPointSizeF(lf.pointSizeF() * 0.85);
    legend->setFont(lf);
    legend->setBrush(QColor(255, 255, 255, 210));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    xAxis->setLabel(tr("X (mm)"));
    yAxis->setLabel(tr("Y (mm)"));
    for (QCPAxis* a : {xAxis, yAxis})
        a->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
    connect(xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { keepScale(); });
    connect(yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] { keepScale(); });
}

void PatternPreview::keepScale()
{
    if (m_adjusting)
        return;
    m_adjusting = true;
    // Equal mm per pixel: a circle looks round and a to-scale picture stays to scale.
    yAxis->setScaleRatio(xAxis, 1.0);
    updateWalk();
    m_adjusting = false;
}

void PatternPreview::resizeEvent(QResizeEvent* event)
{
    QCustomPlot::resizeEvent(event);
    // The axis rect takes its new size only at the next layout: a banner or a window that
    // changed the plot's shape turned a circle into an ellipse until something else replotted.
    // Twice: new ranges give new tick labels, whose width moves the axis rect once more.
    for (int pass = 0; pass < 2; ++pass) {
        updateLayout();
        keepScale();
    }
    replot(QCustomPlot::rpQueuedReplot);
}

double PatternPreview::aspect() const
{
    const QRect r = axisRect()->rect();
    if (r.width() <= 0 || r.height() <= 0 || yAxis->range().size() <= 0)
        return 0;
    return (xAxis->range().size() / r.width()) / (yAxis->range().size() / r.height());
}

void PatternPreview::setLimits(const motion::path::Box& travel, const motion::path::Box& soft)
{
    m_travel->topLeft->setCoords(travel.minX, travel.maxY);
    m_travel->bottomRight->setCoords(travel.maxX, travel.minY);
    m_soft->topLeft->setCoords(soft.minX, soft.maxY);
    m_soft->bottomRight->setCoords(soft.maxX, soft.minY);
    replot(QCustomPlot::rpQueuedReplot);
}

void PatternPreview::setStepMm(double step)
{
    if (step > 0 && std::isfinite(step)) {
        m_stepMm = step;
        updateWalk();
        replot(QCustomPlot::rpQueuedReplot);
    }
}

void PatternPreview::setPath(const std::vector<Segment>& path)
{
    m_path = path;
    redrawPath();
    updateWalk();
    replot(QCustomPlot::rpQueuedReplot);
}

void PatternPreview::redrawPath()
{
    QVector<QCPCurveData> pts;
    int k = 0;
    for (const Segment& s : m_path) {
        if (pts.isEmpty())
            pts.append(QCPCurveData(k++, s.start.x, s.start.y));
        if (s.isArc()) {
            // Chords of at most 1° (a 0.0004 % sagitta): smooth at any zoom that is not showing steps.
            const double len = motion::path::lengthMm(s);
            const int n = std::max(2, static_cast<int>(std::ceil(motion::path::sweepRad(s) * 180 / 3.14159265358979)));
            for (int i = 1; i <= n; ++i) {
                const Vec2 p = motion::path::pointAt(s, len * i / n);
                pts.append(QCPCurveData(k++, p.x, p.y));
            }
        } else {
            pts.append(QCPCurveData(k++, s.end.x, s.end.y));
        }
    }
    m_curve->data()->set(pts, true);
    m_start->data()->clear();
    if (!m_path.empty())
        m_start->addData(m_path.front().start.x, m_path.front().start.y);
}

void PatternPreview::updateWalk()
{
    QVector<QCPCurveData> pts;
    const double pxPerMm = axisRect()->width() / std::max(1e-12, xAxis->range().size());
    if (!m_path.empty() && m_stepMm * pxPerMm >= kStepPixels) {
        // The walk of every segment in view, on the grid whose origin is the path's start (where
        // the device's walk starts). Each segment starts at its own rounded start point, as on
        // the device, so segments out of view cost nothing.
        const Vec2 o = m_path.front().start;
        const QCPRange xr = xAxis->range(), yr = yAxis->range();
        auto g = [&](Vec2 p) { return motion::GridPoint{std::llround((p.x - o.x) / m_stepMm), std::llround((p.y - o.y) / m_stepMm)}; };
        int k = 0;
        for (const Segment& s : m_path) {
            const motion::path::Box b = motion::path::boundingBox(s);
            if (b.maxX < xr.lower || b.minX > xr.upper || b.maxY < yr.lower || b.minY > yr.upper)
                continue;
            std::optional<motion::path::GridWalker> w;
            if (s.isArc())
                w = motion::path::GridWalker::arc(g(s.start), g(s.end), g(s.center), s.ccw());
            if (!w)
                w = motion::path::GridWalker::line(g(s.start), g(s.end));
            auto add = [&](motion::GridPoint p) {
                const double x = o.x + static_cast<double>(p.x) * m_stepMm, y = o.y + static_cast<double>(p.y) * m_stepMm;
                if (x >= xr.lower && x <= xr.upper && y >= yr.lower && y <= yr.upper)
                    pts.append(QCPCurveData(k++, x, y));
                else if (!pts.isEmpty() && !std::isnan(pts.back().key))
                    pts.append(QCPCurveData(k++, qQNaN(), qQNaN()));  // a gap where the walk leaves the view
            };
            add(w->position());
            while (!w->done() && pts.size() < kMaxStepPoints) {
                w->step();
                add(w->position());
            }
            if (pts.size() >= kMaxStepPoints)
                break;
        }
    }
    m_walk->data()->set(pts, true);
    m_walk->setVisible(!pts.isEmpty());
    if (pts.isEmpty())
        m_walk->removeFromLegend();
    else
        m_walk->addToLegend();
}

void PatternPreview::fit()
{
    if (m_path.empty())
        return;
    motion::path::Box b = motion::path::boundingBox(m_path.front());
    for (const Segment& s : m_path) {
        const auto e = motion::path::boundingBox(s);
        b = {std::min(b.minX, e.minX), std::min(b.minY, e.minY), std::max(b.maxX, e.maxX), std::max(b.maxY, e.maxY)};
    }
    const double w = std::max(b.maxX - b.minX, 0.01), h = std::max(b.maxY - b.minY, 0.01);
    const double m = 0.12 * std::max(w, h);
    m_adjusting = true;
    xAxis->setRange(b.minX - m, b.maxX + m);
    yAxis->setRange(b.minY - m, b.maxY + m);
    updateLayout();
    // Grow whichever axis is short so mm per pixel is the same on both and all of it shows.
    const double px = axisRect()->width() / (b.maxX - b.minX + 2 * m), py = axisRect()->height() / (b.maxY - b.minY + 2 * m);
    if (px > py)
        xAxis->setRange(QCPRange((b.minX + b.maxX) / 2 - axisRect()->width() / py / 2, (b.minX + b.maxX) / 2 + axisRect()->width() / py / 2));
    else
        yAxis->setRange(QCPRange((b.minY + b.maxY) / 2 - axisRect()->height() / px / 2, (b.minY + b.maxY) / 2 + axisRect()->height() / px / 2));
    m_adjusting = false;
    updateWalk();
    replot(QCustomPlot::rpQueuedReplot);
}

void PatternPreview::addRunPoint(Vec2 commanded, Vec2 measured)
{
    m_commanded->addData(m_runPoints, commanded.x, commanded.y);
    m_measured->addData(m_runPoints, measured.x, measured.y);
    ++m_runPoints;
}

void PatternPreview::clearRun()
{
    m_commanded->data()->clear();
    m_measured->data()->clear();
    m_runPoints = 0;
    replot(QCustomPlot::rpQueuedReplot);
}

void PatternPreview::setMachinePosition(Vec2 p)
{
    m_machine->data()->clear();
    m_machine->addData(p.x, p.y);
}

void PatternPreview::clearMachinePosition()
{
    m_machine->data()->clear();
    replot(QCustomPlot::rpQueuedReplot);
}

int PatternPreview::pathPoints() const { return m_curve->data()->size(); }
int PatternPreview::walkPoints() const { return m_walk->data()->size(); }
int PatternPreview::runPoints() const { return m_runPoints; }

} // namespace ui
