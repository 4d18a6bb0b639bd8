#pragma once
// Runs an ISO 230-2 axis test or seed 000's linked XY test on an instrument (docs/accuracy.md):
// for each stop of the run it moves (over the overrun point where the standard
// linear cycle has one), waits for the device's MotionDone, dwells and waits for the
// readback to settle on the device's clock, asks the reading source for the reading
// and appends it to the run log before going on. Pause waits for the reading in
// progress; abort stops the axes at once. A run that stopped for any reason (abort,
// E-stop, a refused move, a lost link, a gauge that answered garbage, a crash)
// continues from its run log at the next reading, approaching that stop from its own
// side, and never reads a stop twice. When the last stop is read the readings are
// evaluated (motion/metrology) and written as readings CSV and result JSON beside the
// log; an interferometer's run writes its target sequence for the import instead.
//
// Like the scan runner it needs nothing but moves, events and status readings, so it
// runs on any dev::Instrument. Everything it has to tell a person is a motion::msg::Message
// (ids accuracy.run.*, docs/accuracy.md).
#include "device/client/instrument.h"
#include "device/files/accuracy/accuracy_run_log.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/files/accuracy/interferometer_csv.h"
#include "device/jobs/accuracy/reading_source.h"
#include "device/jobs/arrival_by_status.h"
#include "motion/metrology/contour/xy_line_test.h"
#include "motion/metrology/linear/iso230_2.h"

#include <QFile>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>
#include <vector>

namespace dev::jobs {

/// One stop as the runner visits it.
struct PlannedStop {
    int cycle = 1;
    motion::metrology::Direction direction = motion::metrology::Direction::Up;
    int targetIndex = 0;                          ///< into the test's targets (points of an XY test)
    std::vector<double> targetMm;                 ///< per axis read (X; or X and Y)
    std::optional<std::vector<double>> overrunMm; ///< go here first
    std::vector<double> approachFromMm;           ///< where the final move starts (for a resumed run)
};

class AccuracyRunner : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Running, Pausing, Paused, Stopped, Finished };

    explicit AccuracyRunner(dev::Instrument* instrument, QObject* parent = nullptr);
    ~AccuracyRunner() override;

    /// An axis or XY-line test (circular tests: CircleRunner) with the source of its
    /// readings (not owned; it must outlive the run) and the folder for the run log and
    /// the results. The test is checked against the instrument (its axes, soft limits and
    /// speed) and the source against the test. A run log in the folder of the same test
    /// and source is continued; another's is refused unless `restart`, which keeps it
    /// aside under another name. Problems: paths of the test's fields, or "" for the run.
    bool prepare(const dev::files::accuracy::AccuracyTest& test, ReadingSource* source, const QString& folder, bool restart,
                 motion::msg::Problems* problems);
    /// Starts, or continues after a pause or a stop, at the first stop not yet read.
    /// Refused (why) when not prepared, not connected, an axis not homed, E-stop.
    bool start(motion::msg::Message* why = nullptr);
    void pause();
    void abort();

    State state() const { return m_state; }
    bool isActive() const { return m_state == State::Running || m_state == State::Pausing; }
    bool isXy() const { return m_xy; }
    QString axisNames() const;                    ///< "X", or "XY"
    const std::vector<PlannedStop>& stops() const { return m_stops; }
    const std::vector<dev::files::accuracy::RunLogEntry>& entries() const { return m_entries; }
    int readingsTaken() const { return static_cast<int>(m_entries.size()); }
    int totalReadings() const { return static_cast<int>(m_stops.size()); }
    /// The stop being worked on, or −1.
    int currentStop() const { return isActive() ? static_cast<int>(m_entries.size()) : -1; }
    /// Device seconds left: the estimate of the stops not read, at this run's pace.
    double etaS() const;
    ReadingSource* source() const { return m_source; }
    const dev::files::accuracy::AccuracyTest& test() const { return m_test; }

    /// The axis test's readings so far (an interferometer's: none until the import).
    std::vector<motion::metrology::Reading> readings() const;
    std::vector<motion::metrology::XyReading> xyReadings() const;
    /// ISO 230-2 of the readings so far: a run in progress is evaluated with unequal
    /// cycles allowed, for the live plot.
    motion::metrology::Evaluation evaluation() const;
    motion::metrology::XyEvaluation xyEvaluation() const;
    /// The run's stops with the times they were read, as the interferometer import needs them.
    std::vector<dev::files::accuracy::SequenceStop> sequence() const;

    QString folder() const { return m_folder; }
    QString logPath() const;
    /// "<folder>/<name>": the results are <base>.readings.csv, .accuracy-result.json,
    /// .targets.csv (XY: -x, -y and -contour readings and results).
    QString basePath() const;
    /// Files written when the run finished.
    const QStringList& results() const { return m_results; }

    static const char* stateName(State s);

signals:
    void stateChanged(dev::jobs::AccuracyRunner::State state);
    void progress(int taken, int total, double etaS);
    /// The axes are on their way to (or settling at) a stop.
    void stopStarted(int stop);
    void readingTaken(int stop);
    /// Why the run stopped or would not start.
    void problem(const motion::msg::Message& message);
    /// Every stop read; `files` are the results written.
    void finished(const QStringList& files);

private:
    enum class Phase { None, Overrun, Approach, Target, Settling, Reading };

    void setState(State s);
    void nextStop();
    void moveTo(const std::vector<double>& positionsMm, Phase phase);
    void onMoveAccepted(const std::optional<dev::RequestError>& error, quint64 generation);
    void onEvent(const dev::DeviceEvent& e);
    void onMoveDone();
    void pollSettle();
    void onStatus(const dev::InstrumentStatus& s);
    void takeReading(bool settled);
    void onReading(const TakeResult& r, bool settled, quint64 deviceTimeUs);
    void stopWith(const motion::msg::Message& why, bool stopAxes);
    bool openLog(bool restart, motion::msg::Problems* problems);
    bool appendLog(const dev::files::accuracy::RunLogEntry& e);
    void finish();
    void writeResults();
    double estimateStopS(std::size_t k, bool fromHere) const;
    quint8 axisMask() const;

    QPointer<dev::Instrument> m_instrument;
    dev::files::accuracy::AccuracyTest m_test;
    bool m_xy = false;
    std::vector<int> m_axes;                  ///< instrument axis indices read
    std::vector<PlannedStop> m_stops;
    std::vector<dev::files::accuracy::RunLogEntry> m_entries;
    QPointer<ReadingSource> m_source;
    QString m_folder;
    QFile m_log;
    dev::files::accuracy::RunLogHeader m_header;
    bool m_prepared = false;
    QStringList m_results;

    State m_state = State::Idle;
    Phase m_phase = Phase::None;
    bool m_firstOfSession = true;             ///< the next stop is approached from its own side first
    quint64 m_generation = 0;                 ///< callbacks of an aborted step are ignored
    unsigned m_waitingAxes = 0;               ///< bit per axis still owing MotionDone
    bool m_moveAccepted = false;
    quint64 m_motionDoneUs = 0;
    // Settling on the device clock.
    quint64 m_settleStartUs = 0;
    quint64 m_stableSinceUs = 0;
    std::vector<double> m_stableMin, m_stableMax;
    bool m_haveSettleSample = false;
    QTimer m_poll;
    ArrivalByStatus m_arrival;  ///< a lost MotionDone made good by the status
    // Time: device seconds since the run began, across resumptions.
    double m_timeBaseS = 0;                   ///< the run's time when this session began
    quint64 m_sessionStartUs = 0;
    bool m_haveSessionStart = false;
    quint64 m_lastDeviceUs = 0;
    double m_sessionEstimateS = 0;            ///< estimates of the stops read this session
    double m_sessionActualS = 0;
    int m_sessionFirst = 0;
    QList<QMetaObject::Connection> m_connections;
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::AccuracyRunner::State)
