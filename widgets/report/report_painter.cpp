#include "widgets/report/report_painter.h"

#include <QFontMetricsF>

#include <algorithm>
#include <cmath>

namespace ui::report {

Page::Page(QPainter& p) : m_p(p) {}

QFont pageFont(const QPainter& p, double pointSize, bool bold)
{
    // The painter draws in millimetres (its world transform scales to the device), and
    // a font's point size is scaled by that transform too: undo it.
    const double s = p.worldTransform().m11() > 0 ? p.worldTransform().m11() : 1.0;
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPointSizeF(pointSize / s);
    f.setBold(bold);
    return f;
}

QFont Page::font(double pointSize, bool bold) const { return pageFont(m_p, pointSize, bold); }

void Page::title(const QString& text)
{
    paragraph(text, 15, true);
    m_y += 1;
}

void Page::heading(const QString& text)
{
    m_y += 3;
    paragraph(text, 11, true);
    m_y += 0.5;
}

void Page::paragraph(const QString& text, double pointSize, bool bold, QColor color)
{
    m_p.setFont(font(pointSize, bold));
    m_p.setPen(color);
    const QRectF box(left(), m_y, contentWidth(), 1000);
    const QRectF used = m_p.boundingRect(box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, text);
    m_p.drawText(box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, text);
    m_y += used.height() + 1;
}

void Page::table(const std::vector<QStringList>& rows, const std::vector<double>& shares, double pointSize,
                 const std::function<QColor(int, int)>& colorOf)
{
    if (rows.empty())
        return;
    const double rowH = pointSize * 0.3528 * 1.55;  // points to mm, with leading
    double total = 0;
    for (double s : shares)
        total += s;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        m_p.setFont(font(pointSize, r == 0));
        double x = left();
        if (r == 0) {
            m_p.setPen(Qt::NoPen);
            m_p.setBrush(QColor(235, 238, 242));
            m_p.drawRect(QRectF(left(), m_y, contentWidth(), rowH));
            m_p.setBrush(Qt::NoBrush);
        }
        for (int c = 0; c < rows[r].size() && c < static_cast<int>(shares.size()); ++c) {
            const double w = contentWidth() * shares[static_cast<std::size_t>(c)] / total;
            m_p.setPen(colorOf && r > 0 ? colorOf(static_cast<int>(r), c) : QColor(Qt::black));
            const auto align = c == 0 ? Qt::AlignLeft : Qt::AlignRight;
            m_p.drawText(QRectF(x + 1, m_y, w - 2, rowH), align | Qt::AlignVCenter, rows[r][c]);
            x += w;
        }
        m_y += rowH;
        m_p.setPen(QPen(QColor(200, 200, 200), 0.15));
        m_p.drawLine(QPointF(left(), m_y), QPointF(left() + contentWidth(), m_y));
    }
    m_y += 2;
}

void Page::footer(const QString& text, int pageNumber)
{
    m_p.setFont(font(7, false));
    m_p.setPen(QColor(110, 110, 110));
    const QRectF box(left(), kHeightMm - kMarginMm + 4, contentWidth(), 5);
    m_p.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, text);
    m_p.drawText(box, Qt::AlignRight | Qt::AlignVCenter, QString::number(pageNumber));
}

double niceStep(double span, int count)
{
    if (!(span > 0) || !std::isfinite(span))
        return 1;
    const double raw = span / std::max(1, count);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw)
            return m * mag;
    return 10 * mag;
}

void drawPlot(QPainter& p, const QRectF& rect, const PlotSpec& spec)
{
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Series& s : spec.series)
        for (const QPointF& q : s.points) {
            if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
                continue;
            x0 = std::min(x0, q.x());
            x1 = std::max(x1, q.x());
            y0 = std::min(y0, q.y());
            y1 = std::max(y1, q.y());
        }
    if (spec.yZero) {
        y0 = std::min(y0, *spec.yZero);
        y1 = std::max(y1, *spec.yZero);
    }
    if (x0 > x1) {
        x0 = 0;
        x1 = 1;
        y0 = -1;
        y1 = 1;
    }
    if (x1 - x0 < 1e-12) {
        x0 -= 1;
        x1 += 1;
    }
    if (y1 - y0 < 1e-12) {
        y0 -= 1;
        y1 += 1;
    }
    const double xs = niceStep(x1 - x0, 6), ys = niceStep(y1 - y0, 6);
    x0 = std::floor(x0 / xs) * xs;
    x1 = std::ceil(x1 / xs) * xs;
    y0 = std::floor(y0 / ys) * ys;
    y1 = std::ceil(y1 / ys) * ys;

    p.setFont(pageFont(p, 6.5, false));
    const QRectF area(rect.left() + 14, rect.top() + 2, rect.width() - 16, rect.height() - 16);
    auto X = [&](double v) { return area.left() + (v - x0) / (x1 - x0) * area.width(); };
    auto Y = [&](double v) { return area.bottom() - (v - y0) / (y1 - y0) * area.height(); };
    // Grid and ticks.
    p.setPen(QPen(QColor(225, 225, 225), 0.12));
    for (double v = x0; v <= x1 + xs * 1e-6; v += xs)
        p.drawLine(QPointF(X(v), area.top()), QPointF(X(v), area.bottom()));
    for (double v = y0; v <= y1 + ys * 1e-6; v += ys)
        p.drawLine(QPointF(area.left(), Y(v)), QPointF(area.right(), Y(v)));
    p.setPen(QPen(Qt::black, 0.2));
    p.drawRect(area);
    for (double v = x0; v <= x1 + xs * 1e-6; v += xs)
        p.drawText(QRectF(X(v) - 10, area.bottom() + 0.5, 20, 4), Qt::AlignHCenter | Qt::AlignTop,
                   QString::number(std::abs(v) < xs * 1e-6 ? 0 : v, 'g', 6));
    for (double v = y0; v <= y1 + ys * 1e-6; v += ys)
        p.drawText(QRectF(rect.left(), Y(v) - 2, 13, 4), Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(std::abs(v) < ys * 1e-6 ? 0 : v, 'g', 6));
    p.drawText(QRectF(area.left(), area.bottom() + 5, area.width(), 4), Qt::AlignHCenter | Qt::AlignTop, spec.xLabel);
    p.save();
    p.translate(rect.left() + 1.5, area.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-area.height() / 2, -2, area.height(), 4), Qt::AlignCenter, spec.yLabel);
    p.restore();
    if (spec.yZero) {
        p.setPen(QPen(QColor(120, 120, 120), 0.2, Qt::DashLine));
        p.drawLine(QPointF(area.left(), Y(*spec.yZero)), QPointF(area.right(), Y(*spec.yZero)));
    }
    // Series, clipped to the plot area.
    p.save();
    p.setClipRect(area);
    for (const Series& s : spec.series) {
        if (s.line && s.points.size() > 1) {
            p.setPen(QPen(s.color, 0.35, s.style));
            for (std::size_t k = 1; k < s.points.size(); ++k)
                p.drawLine(QPointF(X(s.points[k - 1].x()), Y(s.points[k - 1].y())), QPointF(X(s.points[k].x()), Y(s.points[k].y())));
        }
        if (s.markers) {
            p.setPen(Qt::NoPen);
            p.setBrush(s.color);
            for (const QPointF& q : s.points)
                p.drawEllipse(QPointF(X(q.x()), Y(q.y())), 0.7, 0.7);
            p.setBrush(Qt::NoBrush);
        }
    }
    p.restore();
    // Legend, in the top left of the area.
    double ly = area.top() + 1;
    for (const Series& s : spec.series) {
        if (s.name.isEmpty())
            continue;
        p.setPen(QPen(s.color, 0.35, s.style));
        if (s.line)
            p.drawLine(QPointF(area.left() + 2, ly + 1.5), QPointF(area.left() + 7, ly + 1.5));
        if (s.markers) {
            p.setBrush(s.color);
            p.drawEllipse(QPointF(area.left() + 4.5, ly + 1.5), 0.45, 0.45);
            p.setBrush(Qt::NoBrush);
        }
        p.setPen(Qt::black);
        p.drawText(QRectF(area.left() + 8, ly, 60, 3), Qt::AlignLeft | Qt::AlignVCenter, s.name);
        ly += 3.2;
    }
}

} // namespace ui::report
