#pragma once
// The Patterns screen: a pattern's parameters, its preview to scale (with the point-by-point
// steps when zoomed in) and estimated time; Run / Pause / Abort on the chosen instrument with
// progress and ETA; while it runs, commanded and measured XY over the preview and the contour
// error against the distance along the path; the summary (max, RMS, time); the run exported as
// CSV; patterns saved and loaded as files. A run that starts far from the machine asks first.
//
// Telemetry comes from the shared hub: the screen wants X and Y, commanded and measured, of the
// running instrument while a run goes, and hands every new sample to the runner.
#include "device/client/instrument.h"
#include "device/client/path_client.h"
#include "device/jobs/pattern_runner.h"
#include "motion/path/sample_density.h"
#include "motion/plans/pattern.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace dev::tele {
class TelemetryHub;
}

namespace ui {

class ContourPlot;
class NumberField;
class PatternForm;
class PatternPreview;

struct PatternInstrument {
    QString name;
    dev::Instrument* client = nullptr;  ///< its paths() run the patterns
    dev::jobs::PatternRunner* runner = nullptr;
    int hubIndex = 0;  ///< the instrument's index in the telemetry hub
};

class PatternScreen : public QWidget {
    Q_OBJECT
public:
    using Confirm = std::function<bool(const QString& question)>;
    /// Asks for a file; empty = cancelled. `save`: a file to write, else one to read.
    using FileChooser = std::function<QString(const QString& title, const QString& filter, bool save)>;
    static constexpr double kFarMoveShare = 0.25;  ///< an approach longer than this share of the travel asks first
    static constexpr int kTelemetryHz = 250;

    PatternScreen(QVector<PatternInstrument> instruments, dev::tele::TelemetryHub* hub, QWidget* parent = nullptr);
    /// The run's figures as the screen words them: the contour error, how many samples it
    /// rests on and at what rate, and a warning when they are too few for the figure
    /// (motion/path/sample_density.h).
    static QString runSummaryText(const dev::jobs::PatternRunSummary& summary, const motion::path::SampleDensity& density);
    /// How densely a runner's samples cover its path.
    static motion::path::SampleDensity densityOf(const dev::jobs::PatternRunner& runner);
    ~PatternScreen() override;
    void setConfirm(Confirm c) { m_confirm = std::move(c); }
    /// Asked before the long approach instead of Confirm (app/ offers "don't ask again this
    /// session" there); unset: Confirm asks.
    void setConfirmLongMove(Confirm c) { m_confirmLongMove = std::move(c); }
    void setFileChooser(FileChooser c) { m_chooser = std::move(c); }

    void setInstrument(int index);
    int instrument() const { return m_current; }
    motion::plans::Pattern pattern() const;
    void setPattern(const motion::plans::Pattern& p);
    /// The segments the preview shows (the plan of the form's pattern).
    const std::vector<motion::path::Segment>& plannedPath() const { return m_path; }

    // Actions (the buttons call these).
    bool run();
    void pauseOrResume();
    void abort();
    bool exportRun(const QString& path, QString* error);
    bool savePattern(const QString& path, QString* error);
    bool loadPattern(const QString& path, QString* error);

    PatternForm* form() const { return m_form; }
    PatternPreview* preview() const { return m_preview; }
    ContourPlot* contour() const { return m_contour; }
    dev::jobs::PatternRunner* runner() const;
    QString statusText() const;
    QString summaryText() const;

signals:
    void problem(const QString& message);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    const PatternInstrument& cur() const { return m_instruments[m_current]; }
    void replan();
    void refreshLimits();
    void updateButtons();
    void onRunnerState(dev::jobs::PatternRunner::State s);
    void showRunning();
    void onProgress(std::size_t done, std::size_t total);
    void onData(int hubIndex);
    void wantTelemetry(bool want);
    bool confirm(const QString& q) const { return !m_confirm || m_confirm(q); }

    QVector<PatternInstrument> m_instruments;
    QPointer<dev::tele::TelemetryHub> m_hub;
    int m_current = 0;
    int m_runOn = -1;              ///< instrument the last run was started on
    Confirm m_confirm;
    Confirm m_confirmLongMove;
    FileChooser m_chooser;
    std::vector<motion::path::Segment> m_path;
    double m_lastSampleS = -1;
    QTimer m_replan, m_redraw;
    QComboBox* m_instrumentBox;
    PatternForm* m_form;
    PatternPreview* m_preview;
    ContourPlot* m_contour;
    NumberField* m_step;
    QLabel* m_estimate;
    QLabel* m_status;
    QLabel* m_summary;
    QProgressBar* m_progress;
    QPushButton* m_run;
    QPushButton* m_pause;
    QPushButton* m_abort;
    QPushButton* m_export;
    QPushButton* m_load;
    QList<QMetaObject::Connection> m_runnerConnections;
};

} // namespace ui
