#include "soak_jobs.h"

#include "device/files/plates/deck_file.h"
#include "device/files/recipes/recipe_loader.h"
#include "device/jobs/machine_model.h"
#include "device/jobs/pattern_telemetry.h"
#include "motion/plans/pattern.h"

#include <QDir>
#include <QFile>
#include <QTimer>

#include <cmath>
#include <cstdio>

namespace soak {
namespace {
/// Failures kept word for word; the rest are only counted.
constexpr std::size_t kKeptFailures = 12;
/// A jog that moved its axes less than this did not run.
constexpr double kMovedMm = 0.05;

std::string ids(const std::vector<motion::msg::Message>& messages)
{
    std::string out;
    for (const auto& m : messages)
        out += (out.empty() ? "" : ", ") + motion::msg::debugString(m);
    return out;
}
} // namespace

quint64 Tally::done() const
{
    quint64 n = 0;
    for (const auto& [kind, c] : byKind)
        n += c.done;
    return n;
}

quint64 Tally::failed() const
{
    quint64 n = 0;
    for (const auto& [kind, c] : byKind)
        n += c.failed;
    return n;
}

void Tally::pass(const std::string& kind)
{
    ++byKind[kind].done;
    if (verbose)
        std::printf("  done: %s\n", kind.c_str());
}

void Tally::fail(const std::string& kind, const std::string& why)
{
    if (verbose)
        std::printf("  FAILED: %s: %s\n", kind.c_str(), why.c_str());
    ++byKind[kind].failed;
    if (failures.size() < kKeptFailures)
        failures.push_back(kind + ": " + why);
}

// ---- Work ------------------------------------------------------------------------------

Work::Work(Station& station, Tally& tally, double timeScale, std::uint64_t seed)
    : m_station(station), m_tally(tally), m_timeScale(timeScale), m_rng(seed)
{
}

void Work::finishUp()
{
    m_stopping = true;
}

void Work::next()
{
    if (m_stopping) {
        m_idle = true;
        emit finished();
        return;
    }
    if (m_station.client.state() != dev::LinkState::Ready) {
        // Nothing can run without the link; the soak reports the drop and ends.
        m_tally.fail("link", std::string(m_station.name) + " link not ready: no further jobs");
        m_idle = true;
        emit finished();
        return;
    }
    // Queued: a job's end never starts the next one inside the runner's own signal.
    QTimer::singleShot(0, this, [this] {
        if (m_tally.verbose)
            std::printf("  %s: job %d starts\n", m_station.name, m_round);
        startJob();
        ++m_round;
    });
}

void Work::after(double deviceS, std::function<void()> f)
{
    QTimer::singleShot(std::max(1, static_cast<int>(std::lround(deviceS * 1000 / m_timeScale))), this, std::move(f));
}

double Work::towardMiddle(int axis, double share) const
{
    const auto& a = m_station.client.identity().axes[axis];
    const double middle = (a.travelMin + a.travelMax) / 2;
    const double v = share * a.maxSpeed;
    return m_station.client.status().axes[axis].commanded < middle ? v : -v;
}

// ---- the analyzer ----------------------------------------------------------------------

AnalyzerWork::AnalyzerWork(Station& station, Tally& tally, double timeScale, std::uint64_t seed, QStringList recipes, QString tempDir)
    : Work(station, tally, timeScale, seed), m_recipes(std::move(recipes)), m_tempDir(std::move(tempDir))
{
}

void AnalyzerWork::startJob()
{
    if (m_round % 2 == 0)
        startPlate();
    else
        jog();
}

void AnalyzerWork::startPlate()
{
    dev::Instrument& c = m_station.client;
    const QString file = m_recipes[(m_round / 2) % m_recipes.size()];
    const dev::files::plates::LoadedRecipe l = dev::files::plates::loadRecipe(file, dev::files::plates::builtinDeck(), {});
    if (!l.ok()) {
        m_tally.fail("plate", file.toStdString() + " does not load");
        next();
        return;
    }
    // As `recipe run` plans it: from where the machine stands, with its own motion limits.
    motion::plates::StartState start;
    const auto& axes = c.status().axes;
    if (axes.size() >= 4)
        start = {axes[0].commanded, axes[1].commanded, axes[2].commanded, axes[3].commanded};
    motion::plates::PlanContext context = l.context;
    context.deck = dev::jobs::deckWithDeviceMotion(context.deck, c.identity());
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(l.recipe, context, start);
    m_runner = std::make_unique<dev::jobs::RecipeRunner>(&c);
    m_problems.clear();
    connect(m_runner.get(), &dev::jobs::RecipeRunner::message, this, [this](const motion::msg::Message& m, bool problem) {
        if (problem)
            m_problems += (m_problems.empty() ? "" : ", ") + motion::msg::debugString(m);
    });
    if (m_tally.verbose)
        connect(m_runner.get(), &dev::jobs::RecipeRunner::opFinished, this, [](int op) { std::printf("    plate op %d done\n", op); });
    connect(m_runner.get(), &dev::jobs::RecipeRunner::finished, this, [this](bool completed) {
        QTimer::singleShot(0, this, [this, completed] { plateEnded(completed); });
    });
    const QString log = QStringLiteral("%1/plate-%2.run.jsonl").arg(m_tempDir).arg(m_round);
    motion::msg::Message error;
    if (!m_runner->setPlan(plan, QString::fromStdString(l.recipe.name), &error) || !m_runner->start(log, &error)) {
        m_runner.reset();
        QFile::remove(log);
        m_tally.fail("plate", "refused: " + motion::msg::debugString(error));
        next();
    }
}

void AnalyzerWork::plateEnded(bool completed)
{
    if (!m_runner)
        return;
    const dev::jobs::RunProgress p = m_runner->progress();
    const QString log = m_runner->logPath();
    m_runner.reset();
    QFile::remove(log);  // the soak keeps no files: only its own figures may grow
    if (completed && p.opsDone == p.opsTotal)
        m_tally.pass("plate");
    else
        m_tally.fail("plate", "stopped after " + std::to_string(p.opsDone) + " of " + std::to_string(p.opsTotal) + " ops: " + m_problems);
    emptyPlunger();
}

void AnalyzerWork::emptyPlunger()
{
    // The next recipe is planned from here: a plunger left full would refuse it.
    whenStill(&m_station.client, this, [this](bool still) {
        const int p = m_station.axis('P');
        if (!still || p < 0) {
            m_tally.fail("plate", "not at rest after the run");
            next();
            return;
        }
        if (std::abs(m_station.client.status().axes[p].commanded) < 1e-9) {
            next();
            return;
        }
        m_station.client.move({{p, 0.0}}, false, 0, [this](const std::optional<dev::RequestError>& e) {
            if (e) {
                m_tally.fail("plate", "emptying the plunger refused: " + motion::msg::debugString(e->message));
                next();
                return;
            }
            whenStill(&m_station.client, this, [this](bool) { next(); });
        });
    });
}

void AnalyzerWork::jog()
{
    dev::Instrument& c = m_station.client;
    const int x = m_station.axis('X'), y = m_station.axis('Y');
    const double x0 = c.status().axes[x].commanded, y0 = c.status().axes[y].commanded;
    c.startJog(x, towardMiddle(x, 0.3));
    c.startJog(y, towardMiddle(y, 0.3));
    after(uniform(0.5, 1.5), [this, x, y, x0, y0] {
        m_station.client.stopAllJogs();
        whenStill(&m_station.client, this, [this, x, y, x0, y0](bool still) {
            const auto& a = m_station.client.status().axes;
            if (!still)
                m_tally.fail("jog", "analyzer not at rest after the jog");
            else if (std::abs(a[x].commanded - x0) < kMovedMm || std::abs(a[y].commanded - y0) < kMovedMm)
                m_tally.fail("jog", "analyzer jog did not move X and Y");
            else
                m_tally.pass("jog");
            next();
        });
    });
}

// ---- the stage -------------------------------------------------------------------------

StageWork::StageWork(Station& station, Tally& tally, double timeScale, std::uint64_t seed, const motion::scan::ScanPlan& scan,
                     const std::vector<motion::path::Segment>& sine, QString tempDir)
    : Work(station, tally, timeScale, seed), m_scanPlan(scan), m_sine(sine), m_tempDir(std::move(tempDir)), m_stick(&station.client)
{
}

void StageWork::begin()
{
    // The pattern runner times paths by the device's path limits: read them once, as the
    // Patterns screen does on connecting.
    m_station.client.paths()->refreshLimits([this](const auto&) { next(); });
}

void StageWork::startJob()
{
    switch (m_round % 6) {
    case 0: startScan(); break;
    case 1: startPattern("line", line()); break;
    case 2: joystick(); break;
    case 3: startPattern("arc", arc()); break;
    case 4: startPattern("sine", m_sine); break;
    default: keyJog(); break;
    }
}

void StageWork::startScan()
{
    // A new folder each time: one holding a finished log of the same tiles would be continued.
    m_scanFolder = QStringLiteral("%1/scan-%2").arg(m_tempDir).arg(m_round);
    QDir().mkpath(m_scanFolder);
    m_scan = std::make_unique<dev::jobs::ScanRunner>(&m_station.client);
    m_problems.clear();
    connect(m_scan.get(), &dev::jobs::ScanRunner::problem, this, [this](const motion::msg::Message& m) {
        m_problems += (m_problems.empty() ? "" : ", ") + motion::msg::debugString(m);
    });
    if (m_tally.verbose)
        connect(m_scan.get(), &dev::jobs::ScanRunner::tileTaken, this, [](int tile) { std::printf("    tile %d taken\n", tile); });
    connect(m_scan.get(), &dev::jobs::ScanRunner::finished, this, [this] {
        QTimer::singleShot(0, this, [this] { scanEnded(true, {}); });
    });
    connect(m_scan.get(), &dev::jobs::ScanRunner::stateChanged, this, [this](dev::jobs::ScanRunner::State s) {
        if (s == dev::jobs::ScanRunner::State::Stopped)
            QTimer::singleShot(0, this, [this] { scanEnded(false, m_problems); });
    });
    motion::msg::Message error;
    if (!m_scan->prepare(m_scanPlan, m_scanFolder, true, &error) || !m_scan->start(&error))
        QTimer::singleShot(0, this, [this, error] { scanEnded(false, "refused: " + motion::msg::debugString(error)); });
}

void StageWork::scanEnded(bool ok, const std::string& why)
{
    if (!m_scan)
        return;
    const int taken = m_scan->takenTiles(), total = m_scan->totalTiles();
    m_scan.reset();
    QDir(m_scanFolder).removeRecursively();
    if (ok && taken == total && total > 0)
        m_tally.pass("scan");
    else
        m_tally.fail("scan", std::to_string(taken) + " of " + std::to_string(total) + " tiles: " + why);
    whenStill(&m_station.client, this, [this](bool) { next(); });
}

void StageWork::startPattern(const std::string& kind, std::vector<motion::path::Segment> path)
{
    dev::Instrument& c = m_station.client;
    m_pattern = std::make_unique<dev::jobs::PatternRunner>(&c);
    m_problems.clear();
    // Fed as the CLI feeds it, from the batches the hub's subscription brings (the plots'
    // wish covers X and Y commanded and measured).
    connect(&c, &dev::Instrument::telemetryReceived, m_pattern.get(), [this](const dev::proto::TelemetryBatch& b) {
        dev::jobs::feedBatch(*m_pattern, m_station.client, b);
    });
    connect(m_pattern.get(), &dev::jobs::PatternRunner::message, this, [this](const motion::msg::Message& m, bool problem) {
        if (problem)
            m_problems += (m_problems.empty() ? "" : ", ") + motion::msg::debugString(m);
    });
    connect(m_pattern.get(), &dev::jobs::PatternRunner::stateChanged, this, [this, kind](dev::jobs::PatternRunner::State s) {
        using S = dev::jobs::PatternRunner::State;
        if (s == S::Done || s == S::Failed || s == S::Aborted || s == S::Interrupted)
            QTimer::singleShot(0, this, [this, kind, s] { patternEnded(kind, s); });
    });
    const std::string why = path.empty() ? std::string("no segments") : ids(m_pattern->preflight(path, {}));
    if (path.empty() || !m_pattern->start(std::move(path), {})) {
        m_pattern.reset();
        m_tally.fail(kind, "refused: " + why);
        next();
    }
}

void StageWork::patternEnded(const std::string& kind, dev::jobs::PatternRunner::State s)
{
    if (!m_pattern)
        return;
    const dev::jobs::PatternRunSummary summary = m_pattern->summary();
    m_pattern.reset();
    m_tally.patternUnderruns += static_cast<quint64>(summary.underruns);
    m_tally.maxContourUm = std::max(m_tally.maxContourUm, summary.maxContourMm * 1e3);
    if (s == dev::jobs::PatternRunner::State::Done && summary.complete)
        m_tally.pass(kind);
    else
        m_tally.fail(kind, std::string("ended ") + dev::jobs::PatternRunner::stateTerm(s) + ": " + m_problems);
    whenStill(&m_station.client, this, [this](bool) { next(); });
}

std::vector<motion::path::Segment> StageWork::line()
{
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Line;
    p.feedMmS = uniform(5, 15);
    p.line.startMm = {uniform(20, 40), uniform(20, 40)};
    p.line.endMm = {uniform(60, 80), uniform(60, 80)};
    return motion::plans::plan(p);
}

std::vector<motion::path::Segment> StageWork::arc()
{
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Arc;
    p.feedMmS = uniform(5, 15);
    p.arc.centerMm = {50, 50};
    p.arc.radiusMm = uniform(10, 30);
    p.arc.startDeg = uniform(0, 360);
    p.arc.sweepDeg = uniform(90, 300);
    p.arc.clockwise = uniform(0, 1) < 0.5;
    return motion::plans::plan(p);
}

void StageWork::joystick()
{
    const double x0 = m_station.client.status().axes[0].commanded, y0 = m_station.client.status().axes[1].commanded;
    m_stick.setVelocities({{0, towardMiddle(0, 0.3)}, {1, towardMiddle(1, 0.2)}});
    after(uniform(1, 3), [this, x0, y0] {
        m_stick.stop();
        whenStill(&m_station.client, this, [this, x0, y0](bool still) {
            const auto& a = m_station.client.status().axes;
            if (!still)
                m_tally.fail("jog", "stage not at rest after the joystick");
            else if (std::abs(a[0].commanded - x0) < kMovedMm || std::abs(a[1].commanded - y0) < kMovedMm)
                m_tally.fail("jog", "the joystick did not move X and Y");
            else
                m_tally.pass("jog");
            next();
        });
    });
}

void StageWork::keyJog()
{
    const int axis = uniform(0, 1) < 0.5 ? 0 : 1;
    const double from = m_station.client.status().axes[axis].commanded;
    m_station.client.startJog(axis, towardMiddle(axis, 0.5));
    after(uniform(0.5, 2), [this, axis, from] {
        m_station.client.stopJog(axis);
        whenStill(&m_station.client, this, [this, axis, from](bool still) {
            if (!still)
                m_tally.fail("jog", "stage not at rest after the key jog");
            else if (std::abs(m_station.client.status().axes[axis].commanded - from) < kMovedMm)
                m_tally.fail("jog", "the key jog did not move its axis");
            else
                m_tally.pass("jog");
            next();
        });
    });
}

} // namespace soak
