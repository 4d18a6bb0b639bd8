#pragma once
// ISO 230-2's plot of an axis test: the deviation of every reading against its
// target, ↑ and ↓ in their own colours, with each direction's mean and its ±2s band,
// so the reversal (the gap between the two means) and the spread are seen at once.
// While a run goes on the same plot fills reading by reading. Optionally a second set
// of means ("before") in grey, for the before/after view.
#include "motion/metrology/linear/iso230_2.h"

#include <qcustomplot.h>

#include <optional>

namespace ui {

class DeviationPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit DeviationPlot(QWidget* parent = nullptr);
    /// The readings so far and their evaluation (a partial one while running).
    void setData(const std::vector<motion::metrology::Reading>& readings, const motion::metrology::Evaluation& evaluation);
    /// Means of an earlier run drawn behind (empty: none).
    void setBefore(const std::optional<motion::metrology::Evaluation>& before);
    void clearAll();
    /// Before and during a run: the target axis spans the test's targets, so the plot shows
    /// where the readings are to come and does not rescale as each arrives (empty: the
    /// axis follows the data). Clears what is plotted.
    void showTargets(const std::vector<double>& targetsMm);
    void retranslateUi();

protected:
    void changeEvent(QEvent* event) override;

private:
    QCPGraph *m_upMean, *m_upHi, *m_upLo, *m_downMean, *m_downHi, *m_downLo, *m_upDots, *m_downDots, *m_before;
    std::optional<std::pair<double, double>> m_frame;  ///< the test's first and last target, mm
};

} // namespace ui
