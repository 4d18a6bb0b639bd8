#pragma once
// The circular test's polar plot (ISO 230-4): each direction's path about its
// least-squares centre, the deviation from the least-squares circle magnified so a
// few micrometres show on a circle of centimetres, with the nominal circle dashed.
#include "motion/metrology/contour/circular_test.h"

#include <qcustomplot.h>

namespace ui {

class PolarPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit PolarPlot(QWidget* parent = nullptr);
    /// The runs evaluated; magnification 0 picks the automatic 1-2-5 one.
    void setEvaluation(const motion::metrology::CircularEvaluation& e, double nominalRadiusMm, double magnification = 0);
    /// Samples of a run in progress, drawn as measured (not magnified).
    void showLive(const std::vector<motion::metrology::XyPoint>& samplesMm, const motion::metrology::XyPoint& centreMm,
                  double nominalRadiusMm);
    void clearAll();
    double magnification() const { return m_magnification; }
    void retranslateUi();

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void keepRound();
    QCPCurve *m_nominal, *m_cw, *m_ccw, *m_live;
    QCPItemText* m_caption;
    double m_magnification = 0;
    double m_extent = 1;
};

} // namespace ui
