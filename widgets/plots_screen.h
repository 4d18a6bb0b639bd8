#pragma once
// The Plots screen: stacked live plots of both instruments' telemetry on one
// time axis, a channel picker, two cursors with their readout, the XY path of
// the stage, recording to CSV, export of the view (CSV, PNG, PDF) and of the
// recorded history (every instrument's positions and following errors, kept by the
// hub from connection on whether or not a plot shows them; plots draw it too, so a
// channel ticked after an incident shows what happened before).
//
// Data comes from the telemetry hub; the screen only says what it wants
// (setWanted) and reads the stores when it draws. It wants its channels while it
// is shown or paused (a paused view must keep its data), not while another screen
// is up: a 115 200-baud link carries about 2 500 values a second, and a hidden
// plot should not take them from the screen in front. Recording collects its own. Drawing is coalesced on a
// single-shot timer (at most one frame per kFrameMs, never per packet, none
// while hidden or paused).
#include "motion/message.h"
#include "widgets/plot_source.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <functional>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QSplitter;

namespace ui {

class ChannelPicker;
class CursorReadout;
class PlotCursors;
class PlotStack;
class XyView;

class PlotsScreen : public QWidget {
    Q_OBJECT
public:
    /// Asks for a file name to write; empty = cancelled. Supplied by the
    /// composition root (a dialog); without one, files go under Documents/BenchPilot.
    using FileChooser = std::function<QString(const QString& title, const QString& filter)>;
    static constexpr int kFrameMs = 16;  ///< ≤ 60 frames per second
    static constexpr int kDefaultRateHz = 200;
    static constexpr double kDefaultWindowS = 10;  ///< a live view; up to 10 min on request

    explicit PlotsScreen(dev::tele::TelemetryHub* hub, QWidget* parent = nullptr);
    ~PlotsScreen() override;
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }

    PlotStack* stack() const { return m_stack; }
    XyView* xyView() const { return m_xy; }
    PlotCursors* cursors() const { return m_cursors; }
    ChannelPicker* picker() const { return m_picker; }

    int plotCount() const;
    int addPlot();
    bool removePlot(int index);
    bool addChannel(int plot, const dev::tele::ChannelKey& key);
    bool removeChannel(int plot, const dev::tele::ChannelKey& key);

    void setWindowS(double seconds);
    double windowS() const;
    /// Freezes the view (the hub keeps collecting and recording); resume goes live again.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    void setRateHz(int rateHz);
    int rateHz() const;
    void setAutoScaleY(bool on);
    void setCursorsVisible(bool on);
    void setXyVisible(bool on);

    /// An empty path asks the file chooser. Results are told in message()/problem().
    bool exportCsv(const QString& path = {});
    bool exportPng(const QString& path = {});
    bool exportPdf(const QString& path = {});
    /// The recorded history (every instrument's positions and following errors, shown
    /// or not) of the last spanS seconds (≤ 0: all) as CSV; an empty path asks the chooser.
    bool exportHistory(double spanS, const QString& path = {});
    /// "last 4 min 12 s recorded": the longest history an instrument holds (empty without history).
    QString historyText() const;
    bool startRecording(const QString& path = {});
    void stopRecording();

    QString statusText() const;
    QString lastMessage() const { return m_lastMessage; }
    /// Whether the screen's message line shows its message as a problem (red).
    bool messageIsProblem() const { return m_messageProblem; }
    static constexpr int kNoteFadeMs = 8000;
    int framesDrawn() const { return m_frames; }

signals:
    void problem(const QString& message);
    void message(const QString& message);

protected:
    /// The status line is built from parts worded at different times: built anew.
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void buildToolbar(QHBoxLayout* bar);
    void scheduleRedraw();
    void redraw();
    void updateWanted();
    void refreshPicker();
    void applyDefaults(int instrument, const QVector<dev::tele::ChannelKey>& available);
    void showPlotInPicker(int index);
    void updateStatus();
    double liveAnchor(int instrument) const;
    QString chooseFile(const QString& title, const QString& filter, const QString& suffix);
    void tell(const QString& text, bool isProblem);

    QPointer<dev::tele::TelemetryHub> m_hub;  ///< may be destroyed before the screen
    HubPlotSource m_source;
    FileChooser m_chooser;
    PlotStack* m_stack;
    PlotCursors* m_cursors;
    CursorReadout* m_readout;
    ChannelPicker* m_picker;
    XyView* m_xy;
    QSplitter* m_split;
    QComboBox* m_window;
    QComboBox* m_rate;
    QPushButton* m_pause;
    QPushButton* m_autoY;
    QPushButton* m_cursorsButton;
    QPushButton* m_xyButton;
    QPushButton* m_addPlot;
    QPushButton* m_removePlot;
    QPushButton* m_record;
    QPushButton* m_exportCsv;
    QPushButton* m_exportPng;
    QPushButton* m_exportPdf;
    QPushButton* m_exportHistory;
    QLabel* m_status;
    QLabel* m_message;
    QTimer m_frame;        ///< single shot: the coalesced next frame
    QTimer m_statusTimer;  ///< status line, channel list: 4 Hz
    bool m_paused = false;
    bool m_defaultsApplied[2] = {false, false};
    QElapsedTimer m_arrival[2];  ///< host time of the last batch per instrument
    QHash<int, motion::msg::Message> m_notes;  ///< subscription notes per instrument (worded when shown)
    QHash<int, int> m_rates;      ///< streamed rate per instrument
    QString m_lastMessage;
    bool m_messageProblem = false;
    int m_frames = 0;
};

} // namespace ui
