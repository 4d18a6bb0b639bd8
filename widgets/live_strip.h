#pragma once
// A small live plot for the Jog screen: position (commanded and measured) and
// following error of one axis over the last kWindowS seconds. It wants its
// channels from the telemetry hub only while it is shown, and redraws on a
// coalescing timer like the Plots screen.
#include "widgets/plot_source.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QComboBox;
class QLabel;

namespace ui {

class PlotStack;

class LiveStrip : public QWidget {
    Q_OBJECT
public:
    static constexpr double kWindowS = 10;
    static constexpr int kRateHz = 100;
    static constexpr int kFrameMs = 33;  ///< ≤ 30 frames per second is plenty for a strip

    explicit LiveStrip(QWidget* parent = nullptr);
    ~LiveStrip() override;

    void setTelemetry(dev::tele::TelemetryHub* hub, int instrument);
    /// Axis letters of the instrument, in axis order (the axis chooser).
    void setAxes(const QStringList& letters);
    void setAxis(int axis);
    int axis() const { return m_axis; }
    /// The channels the strip shows now: commanded, measured, following error.
    QVector<dev::tele::ChannelKey> channels() const;
    PlotStack* stack() const { return m_stack; }
    int framesDrawn() const { return m_frames; }

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void rebuildChannels();
    void updateWanted();
    void redraw();
    QString consumer() const;

    QPointer<dev::tele::TelemetryHub> m_hub;
    HubPlotSource m_source;
    int m_instrument = 0;
    int m_axis = 0;
    QComboBox* m_axisChooser;
    QLabel* m_note;
    PlotStack* m_stack;
    QTimer m_frame;
    int m_frames = 0;
};

} // namespace ui
