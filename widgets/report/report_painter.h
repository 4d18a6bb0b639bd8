#pragma once
// Drawing on an A4 page in millimetres for the accuracy report: text blocks, tables
// and line plots with axes, so the report's pages read like a lab's. Qt Gui only.
#include <QColor>
#include <QPainter>
#include <QPointF>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace ui::report {

/// A painter whose unit is the millimetre, with a cursor that moves down the page.
class Page {
public:
    static constexpr double kWidthMm = 210, kHeightMm = 297, kMarginMm = 18;

    explicit Page(QPainter& p);
    QPainter& painter() { return m_p; }
    double y() const { return m_y; }
    void setY(double y) { m_y = y; }
    double contentWidth() const { return kWidthMm - 2 * kMarginMm; }
    double left() const { return kMarginMm; }
    /// Space left above the bottom margin.
    double room() const { return kHeightMm - kMarginMm - m_y; }

    void title(const QString& text);
    void heading(const QString& text);
    /// Wrapped text; the cursor moves below it.
    void paragraph(const QString& text, double pointSize = 9, bool bold = false, QColor color = Qt::black);
    /// Rows of cells, the first row as the header; column widths as shares of the width.
    void table(const std::vector<QStringList>& rows, const std::vector<double>& shares, double pointSize = 8,
               const std::function<QColor(int row, int column)>& colorOf = {});
    void gap(double mm) { m_y += mm; }
    void footer(const QString& text, int pageNumber);

private:
    QFont font(double pointSize, bool bold) const;

    QPainter& m_p;
    double m_y = kMarginMm;
};

/// A line plot in a rectangle of the page: series of points with a colour and a style.
struct Series {
    QString name;
    std::vector<QPointF> points;   ///< data units
    QColor color = Qt::black;
    Qt::PenStyle style = Qt::SolidLine;
    bool markers = false;          ///< dots instead of (or besides) a line
    bool line = true;
};

struct PlotSpec {
    QString xLabel, yLabel;
    std::vector<Series> series;
    std::optional<double> yZero;   ///< draw a horizontal reference at this value
};

/// Draws the plot with its axes, ticks (1-2-5 steps), labels and legend in `rectMm`.
void drawPlot(QPainter& p, const QRectF& rectMm, const PlotSpec& spec);

/// A font of `pointSize` real points on a painter that draws in millimetres.
QFont pageFont(const QPainter& p, double pointSize, bool bold);

/// A "nice" tick step (1, 2 or 5 × 10^k) for a span and about `count` ticks.
double niceStep(double span, int count);

} // namespace ui::report
