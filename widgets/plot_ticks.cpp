#include "widgets/plot_ticks.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace ui {
namespace {

class DistinctTicker final : public QCPAxisTicker {
protected:
    double getTickStep(const QCPRange& range) override
    {
        m_stepSize = QCPAxisTicker::getTickStep(range);
        return m_stepSize;
    }

    QString getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision) override
    {
        if (!(m_stepSize > 0) || !std::isfinite(tick) || std::abs(tick) >= 1e7 || m_stepSize < 1e-9)
            return QCPAxisTicker::getTickLabel(tick, locale, formatChar, precision);
        // The fewest decimals that write the step exactly (0.25 needs two, 0.2 one), so
        // neighbouring labels differ and each says its own value.
        int decimals = 0;
        for (; decimals < 9; ++decimals) {
            const double scaled = m_stepSize * std::pow(10.0, decimals);
            if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled))
                break;
        }
        if (std::abs(tick) < m_stepSize * 1e-6)
            tick = 0;  // not "-0.000" for a tick at zero reached by rounding
        return locale.toString(tick, 'f', decimals);
    }

private:
    double m_stepSize = 0;
};

} // namespace

void useDistinctTickLabels(QCPAxis* axis) { axis->setTicker(QSharedPointer<QCPAxisTicker>(new DistinctTicker)); }

} // namespace ui
