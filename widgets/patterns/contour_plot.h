#pragma once
// Contour (cross-track) error of a run against the distance along the path, in µm, with the
// largest one marked: where along a circle or a raster the machine strays is visible at once.
#include <qcustomplot.h>

namespace ui {

class ContourPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit ContourPlot(QWidget* parent = nullptr);
    /// One judged sample: where along the path (mm) and its error (mm, signed).
    void addSample(double pathMm, double errorMm);
    void clear();
    /// Sets the x range to the path's whole length so progress reads left to right.
    void setPathLength(double mm);
    /// Rescales y to the data and redraws (coalesce calls: at most a few times a second).
    void refresh();
    int samples() const { return m_graph->data()->size(); }

private:
    QCPGraph* m_graph;
    QCPGraph* m_worst;
    double m_worstAbsUm = -1;
};

} // namespace ui
