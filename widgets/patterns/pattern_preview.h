#pragma once
// A pattern drawn to scale (equal mm per pixel on X and Y) inside the instrument's travel and
// soft limits, with its start and direction; zoomed in far enough that one interpolation step
// spans a few pixels, the point-by-point walk (seed 002) the machine's reference takes is drawn
// over the true lines and arcs. While a run goes, the commanded and measured XY are laid over.
#include "motion/path/path_geometry.h"

#include <qcustomplot.h>

#include <vector>

namespace ui {

class PatternPreview : public QCustomPlot {
    Q_OBJECT
public:
    /// Zoomed in until a step spans this many pixels, the walk is drawn.
    static constexpr double kStepPixels = 3.0;
    /// At most this many walk points are drawn (only the ones in view are computed).
    static constexpr int kMaxStepPoints = 60000;

    explicit PatternPreview(QWidget* parent = nullptr);

    void setPath(const std::vector<motion::path::Segment>& path);
    void setLimits(const motion::path::Box& travel, const motion::path::Box& softLimits);
    /// Interpolation step (mm) of the walk drawn when zoomed in.
    void setStepMm(double step);
    double stepMm() const { return m_stepMm; }
    /// Fits the view to the pattern (and where the machine is).
    void fit();
    /// Overlays of a run; clearRun() removes them.
    void addRunPoint(motion::path::Vec2 commanded, motion::path::Vec2 measured);
    void clearRun();
    void setMachinePosition(motion::path::Vec2 p);
    /// No live link: no marker, rather than the last position read shown as the machine's.
    void clearMachinePosition();

    // For tests: what is drawn.
    int pathPoints() const;
    int walkPoints() const;
    int runPoints() const;
    const std::vector<motion::path::Segment>& path() const { return m_path; }
    /// mm per pixel across over mm per pixel up: 1 when a circle is drawn round.
    double aspect() const;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void redrawPath();
    void updateWalk();
    void keepScale();

    std::vector<motion::path::Segment> m_path;
    double m_stepMm = 0.0005;
    QCPCurve* m_curve;
    QCPCurve* m_walk;
    QCPCurve* m_commanded;
    QCPCurve* m_measured;
    QCPGraph* m_start;
    QCPGraph* m_machine;
    QCPItemRect* m_travel;
    QCPItemRect* m_soft;
    int m_runPoints = 0;
    bool m_adjusting = false;
};

} // namespace ui
