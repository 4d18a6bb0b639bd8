#include "widgets/report/grid_map_painter.h"

#include <QLocale>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace ui::report {

namespace {

struct GridFrame {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;  ///< the nodes' extent, mm
    double pitchMm = 1;                     ///< the smaller pitch
};

GridFrame frameOf(const motion::metrology::GridMapResult& map)
{
    GridFrame f;
    if (map.nodes.empty())
        return f;
    f.x0 = f.x1 = map.nodes.front().xMm;
    f.y0 = f.y1 = map.nodes.front().yMm;
    double pitch = 1e9;
    for (const auto& n : map.nodes) {
        f.x0 = std::min(f.x0, n.xMm), f.x1 = std::max(f.x1, n.xMm);
        f.y0 = std::min(f.y0, n.yMm), f.y1 = std::max(f.y1, n.yMm);
    }
    for (std::size_t k = 1; k < map.nodes.size(); ++k) {
        const double dx = std::fabs(map.nodes[k].xMm - map.nodes[k - 1].xMm), dy = std::fabs(map.nodes[k].yMm - map.nodes[k - 1].yMm);
        if (dx > 1e-9)
            pitch = std::min(pitch, dx);
        if (dy > 1e-9)
            pitch = std::min(pitch, dy);
    }
    f.pitchMm = pitch < 1e9 ? pitch : 1;
    return f;
}

double lengthUm(const motion::metrology::GridMapNode& n, GridVectors kind)
{
    const QPointF v = gridVectorUm(n, kind);
    return std::hypot(v.x(), v.y());
}

} // namespace

QPointF gridVectorUm(const motion::metrology::GridMapNode& n, GridVectors kind)
{
    if (kind == GridVectors::Reversal)
        return n.bidirectional() ? QPointF(*n.reversalXUm, *n.reversalYUm) : QPointF();
    return {n.exUm, n.eyUm};
}

QColor gridErrorColour(double lengthUm, double maxUm)
{
    const double t = maxUm > 0 ? std::clamp(lengthUm / maxUm, 0.0, 1.0) : 0.0;
    // Light blue → yellow → red: small errors recede, large ones stand out.
    const QColor a(210, 230, 250), b(250, 220, 90), c(215, 50, 40);
    auto mix = [](const QColor& u, const QColor& v, double s) {
        return QColor::fromRgbF(static_cast<float>(u.redF() + (v.redF() - u.redF()) * s), static_cast<float>(u.greenF() + (v.greenF() - u.greenF()) * s),
                                static_cast<float>(u.blueF() + (v.blueF() - u.blueF()) * s));
    };
    return t < 0.5 ? mix(a, b, t * 2) : mix(b, c, (t - 0.5) * 2);
}

double gridLongestErrorUm(const std::vector<const motion::metrology::GridMapResult*>& maps, GridVectors kind)
{
    double longest = 0;
    for (const auto* m : maps)
        if (m)
            for (const auto& n : m->nodes)
                longest = std::max(longest, lengthUm(n, kind));
    return longest;
}

double gridMagnification(const std::vector<const motion::metrology::GridMapResult*>& maps, GridVectors kind)
{
    double pitch = 1e9;
    for (const auto* m : maps)
        if (m && !m->nodes.empty())
            pitch = std::min(pitch, frameOf(*m).pitchMm);
    const double longest = gridLongestErrorUm(maps, kind);
    if (longest <= 0 || pitch >= 1e9)
        return 1;
    // Half a pitch (mm) for the longest error (µm): mm of drawing per µm of error.
    return 0.5 * pitch / longest;
}

void drawGridMap(QPainter& p, const QRectF& rect, const motion::metrology::GridMapResult& map, double magnification, double colourMaxUm,
                 GridVectors kind)
{
    if (map.nodes.empty())
        return;
    const GridFrame f = frameOf(map);
    // One scale for X and Y, with half a pitch of room around the outer nodes.
    const double spanX = f.x1 - f.x0 + f.pitchMm, spanY = f.y1 - f.y0 + f.pitchMm;
    const double scale = std::min(rect.width() / spanX, rect.height() / spanY);
    const QPointF origin(rect.center().x() - (f.x0 + f.x1) / 2 * scale, rect.center().y() + (f.y0 + f.y1) / 2 * scale);
    auto at = [&](double xMm, double yMm) { return QPointF(origin.x() + xMm * scale, origin.y() - yMm * scale); };
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    // The colour map: a square of one pitch around each node.
    const double half = f.pitchMm / 2 * scale;
    p.setPen(Qt::NoPen);
    for (const auto& n : map.nodes) {
        p.setBrush(gridErrorColour(lengthUm(n, kind), colourMaxUm));
        const QPointF c = at(n.xMm, n.yMm);
        p.drawRect(QRectF(c.x() - half, c.y() - half, 2 * half, 2 * half));
    }
    // The nominal grid.
    p.setBrush(Qt::NoBrush);
    const double lineW = std::max(0.1, scale * f.pitchMm * 0.01);
    p.setPen(QPen(QColor(150, 150, 150), lineW * 0.6));
    for (const auto& n : map.nodes)
        p.drawEllipse(at(n.xMm, n.yMm), lineW, lineW);
    // The error vectors, magnified, with a head a fifth of their length.
    p.setPen(QPen(QColor(20, 20, 20), lineW, Qt::SolidLine, Qt::RoundCap));
    for (const auto& n : map.nodes) {
        const QPointF a = at(n.xMm, n.yMm);
        const QPointF e = gridVectorUm(n, kind);
        const QPointF b = at(n.xMm + e.x() * magnification, n.yMm + e.y() * magnification);
        const QPointF d = b - a;
        const double len = std::hypot(d.x(), d.y());
        if (len < 1e-9)
            continue;
        p.drawLine(a, b);
        const QPointF u = d / len, v(-u.y(), u.x());
        const double h = std::min(len * 0.3, half * 0.35);
        p.drawLine(b, b - u * h + v * h * 0.5);
        p.drawLine(b, b - u * h - v * h * 0.5);
    }
    p.restore();
}

void drawGridColourBar(QPainter& p, const QRectF& rect, double maxUm)
{
    p.save();
    const int steps = 40;
    const double w = rect.width() * 0.7;
    p.setPen(Qt::NoPen);
    for (int k = 0; k < steps; ++k) {
        p.setBrush(gridErrorColour(maxUm * (k + 0.5) / steps, maxUm));
        p.drawRect(QRectF(rect.left() + w * k / steps, rect.top(), w / steps + 0.01, rect.height()));
    }
    p.setPen(Qt::black);
    p.setBrush(Qt::NoBrush);
    const QRectF label(rect.left() + w + rect.height() * 0.5, rect.top() - rect.height(), rect.width() - w, rect.height() * 3);
    p.drawText(label, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0 … %1 µm").arg(QLocale().toString(maxUm, 'f', 2)));
    p.restore();
}

} // namespace ui::report
