#pragma once
// The Calibration screen (docs/accuracy.md): define or open an accuracy test (an ISO 230-2 axis
// test, seed 000's linked XY line or an ISO 230-4 circle), pick where the readings
// come from (the instrument's readback, a gauge on a serial port, a person at a dial
// indicator, or an interferometer's capture imported afterwards), and run it with
// progress, time left, pause and abort; the deviations plotted reading by reading;
// the ISO figures with pass/fail and the ISO-style plot; the compensation fit with its
// order table and residuals, uploaded to, enabled and disabled on the instrument; the
// same test before and after compensation side by side; the circle's polar plot. Every
// finished run leaves its readings CSV, result JSON and PDF report in its folder.
#include "device/client/instrument.h"
#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/jobs/accuracy/accuracy_runner.h"  // complete for the signals' runner pointers (moc)
#include "device/jobs/accuracy/circle_runner.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTableWidget;

namespace dev {
class Transport;
}
namespace dev::jobs {
class ReadingSource;
class ManualSource;
struct StopContext;
} // namespace dev::jobs

namespace ui {

class CameraSession;
class AccuracyTestForm;
class DeviationPlot;
class FitPanel;
class GridMapPanel;
class PolarPlot;

class CalibrationScreen : public QWidget {
    Q_OBJECT
public:
    enum class FileAction { OpenTest, SaveTest, Folder, SaveCompensation, OpenSequence, OpenCapture };
    using FileChooser = std::function<QString(FileAction action, const QString& title, const QString& filter)>;
    using Confirm = std::function<bool(const QString& question)>;
    /// The transport of a gauge on `port` for instrument `index` reading `axis` (the app
    /// opens serial ports; "sim" is the in-process simulator's gauge), owned by `owner`.
    /// nullptr with `error` set when there is none.
    using GaugeFactory = std::function<dev::Transport*(int index, const QString& port, int axis, QObject* owner, QString* error)>;
    /// Runs expected to take longer than this (device seconds) ask first.
    static constexpr double kConfirmLongerThanS = 120;

    CalibrationScreen(QVector<dev::Instrument*> instruments, const QStringList& names, QWidget* parent = nullptr);
    ~CalibrationScreen() override;
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    void setGaugeFactory(GaugeFactory factory) { m_gaugeFactory = std::move(factory); }
    /// The GUI's camera, for the "camera reading a glass scale" source.
    void setCameraSession(CameraSession* session);

    void setInstrument(int index);
    int instrument() const { return m_current; }
    AccuracyTestForm* form() const { return m_form; }
    FitPanel* fitPanel() const { return m_fit; }
    DeviationPlot* livePlot() const { return m_live; }
    PolarPlot* polarPlot() const { return m_polar; }
    QTabWidget* tabs() const { return m_tabs; }
    /// The grid map by camera, its own tab.
    GridMapPanel* gridMapPanel() const { return m_gridMap; }
    dev::jobs::AccuracyRunner* runner() const { return m_runner.get(); }
    dev::jobs::CircleRunner* circleRunner() const { return m_circle.get(); }
    /// "readback", "gauge", "manual", "interferometer".
    void setSource(const QString& kind, const QString& port = {});
    QString outputFolder() const;
    void setOutputFolder(const QString& folder);

    bool openTest(const QString& path);
    bool saveTest(const QString& path);
    /// Runs (or resumes) the test; false (with a problem signal) when it cannot start.
    bool run();
    void pause();
    void abort();
    /// An interferometer's CSV export matched to the run's target sequence and evaluated
    /// against the axis test on screen; false (with a problem signal, nothing written)
    /// when they do not match.
    bool importCapture(const QString& sequencePath, const QString& capturePath);
    /// What a person typed at a manual stop; false (nothing taken) when it is not a reading.
    bool enterManual(const QString& text);

    /// The latest finished axis test and the one before it (for before/after).
    const std::optional<dev::files::accuracy::AccuracyResult>& latest() const { return m_latest; }
    const std::optional<dev::files::accuracy::AccuracyResult>& previous() const { return m_previous; }
    QString stateText() const;
    QString figuresText() const;  ///< the results table as text (for tests and the clipboard)

    /// A run of this screen is under way or paused part-way: the instrument is the operator's.
    bool busy() const;

signals:
    void problem(const QString& message);
    void notice(const QString& message);
    /// A runner made for a run, about to start on instrument `instrument` (0 analyzer,
    /// 1 stage); it lives until the next run or the screen goes (the API's job board).
    void accuracyRunStarting(dev::jobs::AccuracyRunner* runner, int instrument);
    void circleRunStarting(dev::jobs::CircleRunner* runner, int instrument);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    QWidget* buildLeft();
    QWidget* buildResults();
    QWidget* buildBeforeAfter();
    QWidget* buildCircle();
    dev::Instrument* cur() const;
    std::unique_ptr<dev::jobs::ReadingSource> makeSource(int axis, QString* error);
    bool runAxis();
    /// Runs `test` in its newest run folder (going on with a stopped run there), or in `into`.
    /// A finished run there shows its results and offers a new run beside it.
    bool startAxis(const dev::files::accuracy::AccuracyTest& test, const QString& into = {});
    bool runCircle();
    void onReading();
    void onAxisFinished();
    void onCircleFinished();
    void chooseAndImportCapture();
    void adoptAxisResult(const dev::files::accuracy::AccuracyResult& r, const motion::metrology::AxisTest& test,
                         const std::vector<motion::metrology::Reading>& readings, const QString& basePath, const motion::msg::Message& source);
    static QString fileProblemLines(const motion::msg::Problems& problems);
    void showResult();
    void showBeforeAfter();
    void onManualWanted(const dev::jobs::StopContext& stop);
    void updateRunUi();
    /// Between runs the live plot spans the axis test on screen (found in an Xvfb session:
    /// it showed 0 … 5 mm for a test of 10 … 90 mm until the first reading).
    void previewTargets();
    void saveCompensation();
    void writeReport();
    QString choose(FileAction action, const QString& title, const QString& filter);
    bool confirm(const QString& question);

    QVector<dev::Instrument*> m_instruments;
    QStringList m_names;
    int m_current = 0;
    int m_runOn = -1;
    std::unique_ptr<dev::jobs::AccuracyRunner> m_runner;
    std::unique_ptr<dev::jobs::CircleRunner> m_circle;
    std::unique_ptr<dev::jobs::ReadingSource> m_source;
    QPointer<dev::jobs::ManualSource> m_manual;
    std::optional<dev::files::accuracy::AccuracyResult> m_latest, m_previous;
    std::optional<motion::metrology::AxisTest> m_latestTest;
    std::vector<motion::metrology::Reading> m_latestReadings;
    QString m_latestBasePath;  ///< the latest axis run's files without their endings
    motion::msg::Message m_latestSource;  ///< how its readings were taken, for its report
    bool m_opening = false;    ///< a run waits for its source (a gauge's port) to open
    std::optional<motion::metrology::CircularEvaluation> m_circleResult;
    FileChooser m_chooser;
    Confirm m_confirm;
    GaugeFactory m_gaugeFactory;
    CameraSession* m_cameraSession = nullptr;
    GridMapPanel* m_gridMap = nullptr;
    motion::msg::Message m_lastProblem;

    QComboBox* m_instrumentBox;
    AccuracyTestForm* m_form;
    QLabel* m_formProblems;
    QPushButton *m_open, *m_save;
    QComboBox* m_sourceBox;
    QLineEdit* m_port;
    QLineEdit* m_folder;
    QPushButton* m_browse;
    QPushButton *m_runButton, *m_pauseButton, *m_abortButton, *m_importButton;
    QProgressBar* m_progress;
    QLabel* m_state;
    QWidget* m_manualRow;
    QLabel* m_manualPrompt;
    QLineEdit* m_manualValue;
    QPushButton* m_manualEnter;
    QTabWidget* m_tabs;
    DeviationPlot* m_live;
    PolarPlot* m_livePolar;
    QTableWidget* m_figures;
    DeviationPlot* m_resultPlot;
    QLabel* m_verdict;
    QPushButton *m_saveComp, *m_reportButton;
    FitPanel* m_fit;
    QTableWidget* m_beforeAfter;
    DeviationPlot* m_beforeAfterPlot;
    QLabel* m_beforeAfterNote;
    PolarPlot* m_polar;
    QTableWidget* m_circleFigures;
    QList<QPair<QLabel*, const char*>> m_worded;
};

} // namespace ui
