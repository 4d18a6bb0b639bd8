#pragma once
// The XY view: the path of an instrument's X and Y axes over a time range,
// commanded against measured (grating or encoder), at equal scale on both axes.
// Cost follows the screen: at most two points per pixel of the view's width are
// taken from the stores, evenly spread over the range.
#include "widgets/plot_source.h"

#include <qcustomplot.h>

namespace ui {

class XyView : public QCustomPlot {
    Q_OBJECT
public:
    explicit XyView(const PlotDataSource* source, QWidget* parent = nullptr);

    /// The instrument whose axes 0 (X) and 1 (Y) are drawn; the stage by default.
    void setInstrument(int instrument);
    int instrument() const { return m_instrument; }
    /// The four channels the view needs: X and Y, commanded and measured.
    QVector<dev::tele::ChannelKey> channels() const;

    /// Redraws the path over device times [anchorS + x0S, anchorS + x1S].
    void refresh(double anchorS, double x0S, double x1S);
    int commandedPoints() const;
    int measuredPoints() const;

private:
    /// Pairs X and Y samples of one kind by time; returns the number of points.
    int fill(QCPCurve* curve, dev::proto::ChannelKind kind, double t0S, double t1S, int maxPoints);

    const PlotDataSource* m_source;
    int m_instrument = 1;
    QCPCurve* m_commanded;
    QCPCurve* m_measured;
    QCPCurve* m_now;  ///< the newest measured position, a dot
    QVector<QCPCurveData> m_points;
};

} // namespace ui
