#pragma once
// The work the soak keeps both instruments busy with, each on its own instrument at
// the same time, over and over until the soak says stop:
//   analyzer: a plate run (the example recipes in turn), the plunger emptied, a jog of
//             X and Y held and let go;
//   stage:    a scan (the example plan), a line, a joystick jog of X and Y, an arc, a
//             sine by chords (the example pattern), a held key jog of one axis.
// Every job runs through the runner the screens and the CLI use; a job that does not
// finish is counted with what it said.
#include "soak_rig.h"

#include "device/client/joystick_driver.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/recipe_runner.h"
#include "device/jobs/scan_runner.h"
#include "motion/plans/scan/scan_plan.h"

#include <QString>

#include <map>
#include <memory>
#include <random>

namespace soak {

struct JobCount {
    quint64 done = 0, failed = 0;
};

/// Jobs of both instruments by kind ("plate", "scan", "line", "arc", "sine", "jog"),
/// and why the first few failures failed.
struct Tally {
    std::map<std::string, JobCount> byKind;
    std::vector<std::string> failures;
    quint64 done() const;
    quint64 failed() const;
    quint64 patternUnderruns = 0;     ///< path queue ran dry while a pattern ran (the run still completes)
    double maxContourUm = 0;          ///< worst contour error of any pattern
    bool verbose = false;             ///< a line per job as it ends (--verbose)
    void pass(const std::string& kind);
    void fail(const std::string& kind, const std::string& why);
};

/// What both kinds of work share: the stop flag, timing in device seconds, a seeded generator.
class Work : public QObject {
    Q_OBJECT
public:
    Work(Station& station, Tally& tally, double timeScale, std::uint64_t seed);
    /// Starts the first job; the next begins when one ends.
    virtual void begin() = 0;
    /// No new job after the one under way; finished() once it has ended.
    void finishUp();
    bool idle() const { return m_idle; }

signals:
    void finished();

protected:
    /// The next job, or finished() when asked to stop.
    void next();
    virtual void startJob() = 0;
    /// Runs `f` after `deviceS` of device time (at the nominal time scale).
    void after(double deviceS, std::function<void()> f);
    /// A jog velocity toward the middle of the axis' travel: `share` of its maximum speed.
    double towardMiddle(int axis, double share) const;
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_rng); }

    Station& m_station;
    Tally& m_tally;
    double m_timeScale;
    std::mt19937_64 m_rng;
    int m_round = 0;
    bool m_stopping = false, m_idle = false;
};

class AnalyzerWork : public Work {
    Q_OBJECT
public:
    AnalyzerWork(Station& station, Tally& tally, double timeScale, std::uint64_t seed, QStringList recipes, QString tempDir);
    void begin() override { next(); }

private:
    void startJob() override;
    void startPlate();
    void plateEnded(bool completed);
    void emptyPlunger();
    void jog();

    QStringList m_recipes;
    QString m_tempDir;
    std::unique_ptr<dev::jobs::RecipeRunner> m_runner;
    std::string m_problems;  ///< what the plate run said went wrong
};

class StageWork : public Work {
    Q_OBJECT
public:
    StageWork(Station& station, Tally& tally, double timeScale, std::uint64_t seed, const motion::scan::ScanPlan& scan,
              const std::vector<motion::path::Segment>& sine, QString tempDir);
    void begin() override;

private:
    void startJob() override;
    void startScan();
    void scanEnded(bool ok, const std::string& why);
    void startPattern(const std::string& kind, std::vector<motion::path::Segment> path);
    void patternEnded(const std::string& kind, dev::jobs::PatternRunner::State s);
    void joystick();
    void keyJog();
    std::vector<motion::path::Segment> line();
    std::vector<motion::path::Segment> arc();

    motion::scan::ScanPlan m_scanPlan;
    std::vector<motion::path::Segment> m_sine;
    QString m_tempDir;
    std::unique_ptr<dev::jobs::ScanRunner> m_scan;
    QString m_scanFolder;
    std::unique_ptr<dev::jobs::PatternRunner> m_pattern;
    std::string m_problems;
    dev::JoystickDriver m_stick;
};

} // namespace soak
