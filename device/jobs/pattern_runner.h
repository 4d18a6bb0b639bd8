#pragma once
// Runs a pattern on an instrument: checks it can (homed, inside the soft limits — the segment
// that is not is named — not too fast, no E-stop), moves to the pattern's start (XY, then Z on
// the analyzer), streams the segments into the device's path queue with flow control (each
// answer says how many slots are free; completed segments free more), pauses, resumes and
// aborts, and judges the measured XY it is fed against the geometric path (contour error).
//
// A lost link or a path the instrument ended (stop, E-stop, limit switch, a new connection)
// leaves the run Interrupted at the first segment not completed: the runner says so, and
// resume() continues from there once the instrument is back — on the path where the machine
// stopped, or after moving back to that segment's start if it was moved away meanwhile.
#include "device/client/instrument.h"
#include "device/client/path_client.h"
#include "motion/path/contour_tracker.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <optional>
#include <vector>

namespace dev::jobs {

struct PatternRunSample {
    double tS = 0;                     ///< device time since the path first started
    motion::path::Vec2 commanded, measured;
    double pathMm = 0;                 ///< where along the path the measured point is judged
    double contourMm = 0;              ///< signed contour error
    std::size_t segment = 0;
};

struct PatternRunSummary {
    std::size_t samples = 0;
    double maxContourMm = 0, rmsContourMm = 0, maxAtPathMm = 0;
    double durationS = 0;              ///< device time from the path's start to its end
    int underruns = 0;
    bool complete = false;             ///< every segment ran
};

class PatternRunner : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Approaching, Running, Paused, Done, Aborted, Interrupted, Failed };
    /// The state's term for people ("pattern.state.running"), worded by ui::words::term.
    static const char* stateTerm(State s);

    struct Options {
        double approachSpeedMmS = 0;   ///< 0: the instrument's default speed
        std::optional<double> zMm;     ///< analyzer: Z height to work at (reached after XY, seed 000)
    };
    /// Stored samples beyond this are thinned (every other one dropped); the summary counts all.
    static constexpr std::size_t kMaxStoredSamples = 1000000;
    /// A restart continues on the path from where the machine stands if it is this close to it.
    static constexpr double kOnPathMm = 0.005;

    /// Streams through the instrument's paths(), fetched again whenever the instrument's
    /// parts are replaced; an instrument without a path queue refuses every run.
    explicit PatternRunner(dev::Instrument* client, QObject* parent = nullptr);

    /// Everything that keeps this path from running now (pattern.run.*); empty when it can.
    std::vector<motion::msg::Message> preflight(const std::vector<motion::path::Segment>& path, const Options& options) const;
    /// How far the machine moves to reach the path's start (for a far-move confirmation).
    double approachDistanceMm(const std::vector<motion::path::Segment>& path) const;
    /// Estimated time of the path itself under the instrument's path limits.
    double estimatedS(const std::vector<motion::path::Segment>& path) const;

    /// Checks, then approaches and runs. False (and a message) if the checks fail.
    bool start(std::vector<motion::path::Segment> path, const Options& options);
    void pause();
    /// Goes on after a pause or a hold; after an interruption, continues from the first
    /// segment not completed.
    void resume();
    void abort();

    /// A telemetry sample (device time, host coordinates): judged while the path runs.
    void addSample(double deviceTimeS, motion::path::Vec2 commanded, motion::path::Vec2 measured);

    State state() const { return m_state; }
    bool busy() const { return m_state == State::Approaching || m_state == State::Running || m_state == State::Paused; }
    std::size_t totalSegments() const { return m_path.size(); }
    std::size_t segmentsDone() const { return m_done; }
    /// How far along the path the machine is: the last judged telemetry sample when there is
    /// one (segments are reported done only as the device finishes them, behind the machine).
    double pathDoneMm() const;
    /// The segment the machine is on (0-based), by the same measure.
    std::size_t currentSegment() const;
    double remainingS() const;          ///< estimate from the segments not done yet
    quint32 resumeIndex() const { return static_cast<quint32>(m_done); }
    const std::vector<motion::path::Segment>& path() const { return m_path; }
    const std::vector<PatternRunSample>& samples() const { return m_samples; }
    PatternRunSummary summary() const;
    const Options& options() const { return m_options; }

signals:
    void stateChanged(dev::jobs::PatternRunner::State state);
    void progress(std::size_t done, std::size_t total);
    /// A message for a banner, a log or stderr (pattern.run.*, worded by ui::words::text);
    /// `problem` when something went wrong.
    void message(const motion::msg::Message& text, bool problem);
    void finished(const dev::jobs::PatternRunSummary& summary);
    void sampleAdded(const dev::jobs::PatternRunSample& sample);

private:
    /// PATH_FINISHED, or a path status showing it done when the event was lost.
    void onPathFinished(quint64 deviceTimeUs);
    void setState(State s);
    void fail(const motion::msg::Message& why);
    void fail(const std::vector<motion::msg::Message>& why);
    void interrupt(const motion::msg::Message& why);
    void interrupt(const std::vector<motion::msg::Message>& why);
    void approach(motion::path::Vec2 to, bool withZ, std::function<void()> then);
    void onStatus();
    void beginAt(std::size_t index, std::optional<motion::path::Vec2> from);
    void pump();
    void onReply(const std::optional<dev::RequestError>& e, const dev::PathQueueState& s, std::size_t asked);
    void onLinkState(dev::LinkState s);
    void attachPaths();
    motion::path::Vec2 machineXy() const;

    QPointer<dev::Instrument> m_client;
    QPointer<dev::PathClient> m_paths;
    State m_state = State::Idle;
    std::vector<motion::path::Segment> m_path;
    std::vector<double> m_remainingS;   ///< estimated time from the start of segment k to the end
    Options m_options;
    std::optional<motion::path::ContourTracker> m_tracker;
    std::vector<PatternRunSample> m_samples;
    std::size_t m_thin = 1;             ///< keep every m_thin-th sample once the store filled up
    std::size_t m_seen = 0;
    std::optional<PatternRunSample> m_last;  ///< the newest judged sample of this run
    std::size_t m_sent = 0;             ///< segments queued on the device
    std::size_t m_done = 0;             ///< segments completed
    std::optional<motion::path::Vec2> m_firstFrom;  ///< the next append's first segment starts here (a restart)
    int m_free = 0;
    bool m_appendInFlight = false;
    bool m_pauseAsked = false, m_abortAsked = false;
    int m_underruns = 0;
    bool m_underrunSaid = false;
    double m_t0S = -1;                  ///< device time of the first PATH_STARTED
    double m_endS = -1;
    double m_lastSeenS = -1;            ///< latest device time seen while the path ran (the end of a stopped run)
    // Approach: waiting for the machine to be at rest at a point.
    std::function<void()> m_arrived;
    motion::path::Vec2 m_approachTo;
    int m_approachPolls = 0;
    QTimer m_poll;                      ///< status polls while the queue is full (events may be lost)
    QList<QMetaObject::Connection> m_connections;
    QList<QMetaObject::Connection> m_pathConnections;  ///< to m_paths' signals
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::PatternRunner::State)
Q_DECLARE_METATYPE(dev::jobs::PatternRunSummary)
