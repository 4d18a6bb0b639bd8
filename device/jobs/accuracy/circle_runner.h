#pragma once
// Runs an ISO 230-4 circular test (what a ballbar measures) on two axes of an
// instrument with a path queue: for each direction asked, a straight move to the
// start of the lead-in arc, then one queued path of the lead-in arc, the full
// revolution in quarter arcs and the lead-out arc at the test's feed, while status
// readings sample the measured X and Y. The samples of the evaluated revolution (by
// their angle about the centre, unwrapped from the start) are kept, at most
// samples_per_revolution of them, one per angular bin, and evaluated with
// motion/metrology (G per direction, G(b), H). Pause waits for the revolution in
// progress to end; abort clears the path and stops the axes.
//
// The samples come from status readings rather than a telemetry subscription, so
// the screens' own subscription is left alone; at 5 ms between readings a
// revolution of a few seconds gives hundreds.
#include "device/client/instrument.h"
#include "device/client/path_client.h"
#include "device/jobs/arrival_by_status.h"
#include "motion/metrology/contour/circular_test.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>
#include <vector>

namespace dev::jobs {

class CircleRunner : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Running, Pausing, Paused, Stopped, Finished };

    explicit CircleRunner(dev::Instrument* instrument, QObject* parent = nullptr);
    ~CircleRunner() override;

    /// Checks the test against the instrument: X and Y, the soft limits, the feed, a path
    /// queue (Capability::PathQueue, with its reason when missing).
    bool prepare(const motion::metrology::CircularTest& test, motion::msg::Problems* problems);
    /// Starts, or after a pause or stop runs the directions not yet done.
    bool start(motion::msg::Message* why = nullptr);
    void pause();
    void abort();

    State state() const { return m_state; }
    bool isActive() const { return m_state == State::Running || m_state == State::Pausing; }
    const motion::metrology::CircularTest& test() const { return m_test; }
    /// The directions in the order they run, and the samples of those done.
    const std::vector<motion::metrology::Rotation>& rotations() const { return m_rotations; }
    const std::vector<motion::metrology::CircularRun>& runs() const { return m_runs; }
    /// The samples of the revolution in progress (for a live plot).
    const motion::metrology::CircularRun& current() const { return m_current; }
    motion::metrology::CircularEvaluation evaluation() const;
    /// Device seconds left.
    double etaS() const;

    /// A measured position from the device's telemetry (feedCircleBatch): samples on the
    /// device's clock, so a loaded host or a sped-up simulator leaves no gaps. While they
    /// come, status readings only watch for the end of the path; without them (no
    /// subscription, the link shed the channels) the runner samples status readings.
    void addSample(double xMm, double yMm);
    int axisX() const { return m_axisX; }
    int axisY() const { return m_axisY; }

    static constexpr int kSamplePollMs = 5;
    /// Status polls while telemetry samples come: only the end of the path is watched.
    static constexpr int kEndPollMs = 20;
    /// Telemetry older than this (wall time) no longer counts as coming: status samples again.
    static constexpr int kTelemetryStaleMs = 150;

signals:
    void stateChanged(dev::jobs::CircleRunner::State state);
    /// `fraction`: of the whole test.
    void progress(double fraction, double etaS);
    void sampled(double xMm, double yMm);
    void runDone(int index);
    void problem(const motion::msg::Message& message);
    void finished();

private:
    enum class Phase { None, ToStart, Path };

    void setState(State s);
    void beginDirection();
    void nextRun();
    void onPathAppended(const std::optional<dev::RequestError>& e, quint64 generation);
    void poll();
    void takeSample(double xMm, double yMm);
    bool telemetryComing() const;
    void endRun();
    void stopWith(const motion::msg::Message& why);
    std::vector<motion::path::Segment> pathFor(motion::metrology::Rotation r) const;
    motion::path::Vec2 pointAt(double angleRad) const;
    double revolutionS() const;

    QPointer<dev::Instrument> m_instrument;
    QPointer<dev::PathClient> m_paths;
    motion::metrology::CircularTest m_test;
    std::vector<motion::metrology::Rotation> m_rotations;
    std::vector<motion::metrology::CircularRun> m_runs;
    motion::metrology::CircularRun m_current;
    int m_axisX = 0, m_axisY = 1;
    bool m_prepared = false;
    State m_state = State::Idle;
    Phase m_phase = Phase::None;
    quint64 m_generation = 0;
    unsigned m_waitingAxes = 0;
    bool m_moveAccepted = false;
    bool m_pathDone = false;
    // Angle bookkeeping of the run in progress (radians, in the run's own direction).
    double m_travelledRad = 0;
    double m_lastAngleRad = 0;
    bool m_haveAngle = false;
    std::vector<char> m_binTaken;
    QTimer m_poll;
    QElapsedTimer m_sinceTelemetry;  ///< wall time since the last telemetry sample (invalid: none yet)
    ArrivalByStatus m_arrival;  ///< a lost MotionDone made good by the status
    QList<QMetaObject::Connection> m_connections;
    QList<QMetaObject::Connection> m_pathConnections;
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::CircleRunner::State)
