#include "widgets/camera/focus_plot.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace ui {

FocusPlot::FocusPlot(QWidget* parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void FocusPlot::add(double focus)
{
    m_values.push_back(focus);
    if (m_values.size() > kHistory)
        m_values.remove(0, m_values.size() - kHistory);
    update();
}

void FocusPlot::clear()
{
    m_values.clear();
    update();
}

void FocusPlot::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = QRectF(rect()).adjusted(1, 3, -1, -3);
    p.fillRect(rect(), palette().base());
    p.setPen(palette().mid().color());
    p.drawRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5));
    if (m_values.size() < 2)
        return;
    // Scaled to the history's own range: what matters is where the peak is, not its value.
    // A range under a tenth of the figure is noise, not focus: it is drawn as a tenth, centred.
    const auto [lo, hi] = std::minmax_element(m_values.begin(), m_values.end());
    const double least = std::max(0.1 * std::abs(*hi), 1e-12);
    double base = *lo, span = *hi - *lo;
    if (span < least) {
        base = (*lo + *hi) / 2 - least / 2;
        span = least;
    }
    auto at = [&](int i) {
        return QPointF(r.left() + r.width() * i / double(kHistory - 1), r.bottom() - r.height() * (m_values[i] - base) / span);
    };
    QPainterPath path(at(0));
    for (int i = 1; i < m_values.size(); ++i)
        path.lineTo(at(i));
    p.setPen(QPen(QColor(0x15, 0x65, 0xc0), 1.5));
    p.drawPath(path);
    // The best so far, so a person knows when to turn back.
    const int best = int(hi - m_values.begin());
    p.setBrush(QColor(0x2e, 0x7d, 0x32));
    p.setPen(Qt::NoPen);
    p.drawEllipse(at(best), 3, 3);
}

} // namespace ui
