#pragma once
// Jobs on a hostile line over REAL pseudo-terminals (docs/testing.md): benchpilot-sim (its
// journal on) ← bp-faultline (the loopback's fault model, seeded) ← benchpilot-cli
// (QSerialPort), one CLI process after another as an operator would run them: a run that
// stops on the bad line is resumed from its log, a CLI killed with SIGKILL is replaced by
// a new one that resumes. The invariants are judged on the simulator's own journal, which
// it writes when stopped (benchpilot-sim --journal), by the judges the in-process runs
// use (hostile_outcome.h).
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"
#include "device/sim/machine_config.h"
#include "hostile_outcome.h"
#include "motion/plans/scan/scan_plan.h"
#include "plates_run_support.h"
#include "pty_simulator.h"
#include "wait.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>

#include <csignal>
#include <functional>
#include <optional>

namespace hostile {

/// The three programs' line: a simulator with its journal, and bp-faultline in front.
class PtyLine {
public:
    /// `lineArgs`: more bp-faultline options (--delay-ms, --unplug-every …).
    bool start(const QString& instrument, double timeScale, double rate, std::uint64_t seed, const QStringList& lineArgs = {})
    {
        m_journal = m_dir.filePath(QStringLiteral("journal.jsonl"));
        if (!m_sim.start(instrument, timeScale, {QStringLiteral("--journal"), m_journal})) {
            m_error = m_sim.error();
            return false;
        }
        m_port = m_dir.filePath(QStringLiteral("ttyFaulty"));
        m_line.start(itest::binary("bp-faultline"), QStringList{QStringLiteral("--device"), m_sim.link(), QStringLiteral("--listen"), m_port,
                                                                 QStringLiteral("--seed"), QString::number(seed), QStringLiteral("--rate"),
                                                                 QString::number(rate), QStringLiteral("--delay-ms"), QStringLiteral("0..3"),
                                                                 QStringLiteral("--json")}
                                                        + lineArgs);
        if (!m_line.waitForStarted(10000) || !itest::waitFor([&] { return m_line.canReadLine() || m_line.state() != QProcess::Running; }, 10000)
            || !m_line.canReadLine()) {
            m_error = QStringLiteral("bp-faultline did not start: %1").arg(QString::fromUtf8(m_line.readAllStandardError()));
            return false;
        }
        m_line.readLine();
        return true;
    }
    ~PtyLine()
    {
        for (QProcess* p : {&m_line, &m_sim.process()})
            if (p->state() != QProcess::NotRunning) {
                p->kill();
                p->waitForFinished(5000);
            }
    }
    QString port() const { return m_port; }
    QString error() const { return m_error; }
    /// Whether the simulator and bp-faultline still run, and what they said on stderr last.
    std::string health()
    {
        auto one = [](const char* name, QProcess& p) {
            std::string s = std::string(name) + (p.state() == QProcess::Running ? "=running" : "=exited:" + std::to_string(p.exitCode()));
            const QByteArray err = p.readAllStandardError().trimmed();
            if (!err.isEmpty())
                s += ":" + err.right(120).replace('\n', ' ').replace(',', ';').toStdString();
            return s;
        };
        return one("sim", m_sim.process()) + ";" + one("line", m_line);
    }
    QString dir() const { return m_dir.path(); }
    /// Pulls the cable now (bp-faultline puts it back after its --unplug-ms).
    void unplug() { ::kill(static_cast<pid_t>(m_line.processId()), SIGUSR1); }
    /// The line goes silent both ways now, neither port noticing (for its --hang-ms).
    void hang() { ::kill(static_cast<pid_t>(m_line.processId()), SIGUSR2); }

    /// Stops both programs; the device's journal (with where the machine was left in
    /// `endCommanded`) and the line's counts. false when either said nothing.
    bool finish(Journal* journal, std::vector<double>* endCommanded, Outcome* o)
    {
        m_line.terminate();
        m_line.waitForFinished(10000);
        const QJsonObject counts = itest::lastJson(QString::fromUtf8(m_line.readAllStandardOutput()));
        o->damagedBytes = static_cast<qint64>(counts.value(QStringLiteral("damaged_bytes")).toDouble());
        m_sim.process().terminate();
        m_sim.process().waitForFinished(10000);
        QFile f(m_journal);
        if (counts.isEmpty() || !f.open(QIODevice::ReadOnly)) {
            m_error = QStringLiteral("no journal or no counts: %1").arg(QString::fromUtf8(m_sim.process().readAllStandardError()));
            return false;
        }
        while (!f.atEnd()) {
            const QJsonObject line = QJsonDocument::fromJson(f.readLine()).object();
            std::vector<double> commanded;
            for (const auto v : line.value(QStringLiteral("commanded")).toArray())
                commanded.push_back(v.toDouble());
            if (line.value(QStringLiteral("end")).toBool()) {
                *endCommanded = commanded;
                o->crcErrors = static_cast<quint64>(line.value(QStringLiteral("crc_errors")).toDouble());
                o->duplicatesAnswered = static_cast<quint64>(line.value(QStringLiteral("duplicates_answered")).toDouble());
                continue;
            }
            dev::sim::Firmware::JournalEntry e;
            e.timeS = line.value(QStringLiteral("t")).toDouble();
            e.type = static_cast<std::uint8_t>(line.value(QStringLiteral("type")).toInt());
            e.seq = static_cast<std::uint16_t>(line.value(QStringLiteral("seq")).toInt());
            const QByteArray payload = QByteArray::fromHex(line.value(QStringLiteral("payload")).toString().toLatin1());
            e.payload.assign(payload.begin(), payload.end());
            e.commanded = commanded;
            journal->push_back(std::move(e));
        }
        return !endCommanded->empty();
    }

private:
    QTemporaryDir m_dir;
    itest::PtySimulator m_sim;
    QProcess m_line;
    QString m_port, m_journal, m_error;
};

/// One CLI run to its end.
inline itest::ProgramRun cliRun(const QString& port, const QStringList& args, int timeoutMs = 120000)
{
    return itest::runProgram(itest::binary("benchpilot-cli"), QStringList{QStringLiteral("--port"), port} + args, timeoutMs);
}

/// The last line of what a CLI said on stderr: why it stopped, for the campaign's line.
inline std::string lastLine(const QString& text)
{
    const QStringList lines = text.trimmed().split(QLatin1Char('\n'));
    return lines.isEmpty() ? std::string() : lines.back().toStdString();
}

inline void noteStop(Outcome& o, const char* what, const itest::ProgramRun& r, PtyLine* line = nullptr)
{
    ++o.stops;
    // Why, by message id where the CLI said one (--json problem events), else its last words.
    std::string said = lastLine(r.err);
    for (const QString& l : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject obj = QJsonDocument::fromJson(l.toUtf8()).object();
        if (obj.value(QStringLiteral("event")).toString() == QLatin1String("problem"))
            said = obj.value(QStringLiteral("text")).toObject().value(QStringLiteral("id")).toString().toStdString();
    }
    for (char& c : said)
        c = c == ' ' || c == ',' ? '_' : c;
    o.why += (o.why.empty() ? "" : ",") + std::string(what) + ":" + std::to_string(r.exitCode) + (said.empty() ? "" : ":" + said.substr(said.size() > 90 ? said.size() - 90 : 0));
    // A CLI that hung for its minute, or a line that answered nothing at all: which end was
    // still there, once a run. A few runs a campaign end so (the line carries nothing after
    // the first stop, at 0.3 % as at 1 %) and nothing else says why.
    if (line && (!r.finished || r.err.contains(QStringLiteral("neither to a GRBL"))) && o.why.find("health(") == std::string::npos)
        o.why += ":health(" + line->health() + ")";
}

/// What the run log's last stop says the device reported (recipe.run.move_timeout writes
/// it), compacted for the outcome line; empty when the stop carries none.
inline std::string stopEvidence(const QString& logPath)
{
    QFile f(logPath);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    const QJsonObject last = QJsonDocument::fromJson(lines.isEmpty() ? QByteArray() : lines.back()).object();
    if (!last.contains(QStringLiteral("device")))
        return {};
    std::string s = QJsonDocument(last.value(QStringLiteral("device")).toObject()).toJson(QJsonDocument::Compact).toStdString();
    for (char& c : s)
        c = c == ' ' || c == ',' ? ';' : c;
    return ":" + s;
}

/// Homes through the bad line, retrying as an operator would (a failed home is a stop).
/// A home refused because the axes are still homing (the CLI before lost its link while
/// the device went on) is waited out, as an operator watching the stage would: retried at
/// 400 ms, five such refusals had ended a campaign's setup before the homing did.
inline bool ptyHome(PtyLine& line, Outcome& o)
{
    for (int i = 0; i < 10; ++i) {
        const auto r = cliRun(line.port(), {QStringLiteral("home")}, 60000);
        if (r.exitCode == 0)
            return true;
        noteStop(o, "home", r, &line);
        itest::spin(r.err.contains(QLatin1String("still moving or homing")) ? 3000 : 400);
    }
    return false;
}

/// How the runs ended, after a first run that may have been killed.
inline void endOutcome(Outcome& o, bool finished, const char* failure)
{
    if (o.end != "killed" || !finished)
        o.end = finished ? "finished" : (o.end == "killed" ? "killed-not-finished" : "stopped");
    else
        o.end = "killed+resumed";
    if (!finished)
        o.fail(failure);
}

/// How a first CLI process is cut: killed (SIGKILL) or the cable pulled, after `after`
/// wells or tiles are in its log; `after` < 0: not cut.
struct Cut {
    enum Kind { None, Kill, Unplug } kind = None;
    int after = -1;
};

/// Starts the first CLI process and cuts it as `cut` says once `progress()` reaches
/// `cut.after`; returns its run, or a run whose exitCode is -1 when it was killed.
inline itest::ProgramRun firstRun(PtyLine& line, const QStringList& args, const Cut& cut, const std::function<int()>& progress, Outcome& o)
{
    QProcess p;
    p.start(itest::binary("benchpilot-cli"), QStringList{QStringLiteral("--port"), line.port()} + args);
    itest::ProgramRun r;
    if (!p.waitForStarted(10000))
        return r;
    if (cut.kind != Cut::None) {
        itest::waitFor([&] { return progress() >= cut.after || p.state() == QProcess::NotRunning; }, 120000);
        if (p.state() == QProcess::Running) {
            if (cut.kind == Cut::Kill) {
                p.kill();  // SIGKILL: no chance to write anything more
                o.end = "killed";
            } else {
                line.unplug();
            }
        }
    }
    return itest::collectRun(p, p.waitForFinished(180000));
}

// ---- recipe through real ptys: every well once, never twice; the plunger accounted for ----

inline Outcome ptyRecipe(double rate, std::uint64_t seed, const std::string& wells, int wellCount, const Cut& cut, double volumeUl = 10)
{
    Outcome o{cut.kind == Cut::Kill ? "recipe-pty-kill" : "recipe-pty", rate, seed};
    o.hostStats = false;
    PtyLine line;
    if (!line.start(QStringLiteral("analyzer"), platestest::kRunTimeScale, rate, seed)) {
        o.end = "no-line";
        o.fail(line.error().toStdString());
        return o;
    }
    const QDir dir(line.dir());
    const QString recipe = dir.filePath(QStringLiteral("sampling.recipe.json"));
    const QString log = dir.filePath(QStringLiteral("run.jsonl"));
    {
        QFile f(recipe);
        const QString text = QStringLiteral(R"({"schema": "benchpilot.recipe", "version": 1, "name": "hostile",
            "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
            "steps": [{"type": "aspirate", "plate": "samples", "wells": "%1", "volume_ul": %2, "speed_ul_s": 100}]})")
                                 .arg(QString::fromStdString(wells))
                                 .arg(volumeUl);
        if (!f.open(QIODevice::WriteOnly) || f.write(text.toUtf8()) < 0) {
            o.fail("cannot write the recipe");
            return o;
        }
    }
    bool finished = false;
    if (ptyHome(line, o)) {
        const QStringList common{QStringLiteral("--json"), QStringLiteral("--calibration"), QStringLiteral("none")};
        auto isFinished = [](const itest::ProgramRun& r) {
            return r.exitCode == 0 && itest::lastJson(r.out).value(QStringLiteral("event")).toString() == QLatin1String("finished");
        };
        itest::ProgramRun r = firstRun(line, QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--log"), log} + common,
                                       cut, [&] { return static_cast<int>(platestest::countLog(log).dones.size()); }, o);
        finished = isFinished(r);
        QString decision;  // the operator's word for a well cut mid-aspirate, read from the CLI's evidence
        for (int round = 0; round < 12 && !finished; ++round) {
            noteStop(o, "run", r, &line);
            o.why += stopEvidence(log);
            itest::spin(400);  // as an operator would: a pulled cable is back after bp-faultline's 300 ms
            QStringList args{QStringLiteral("recipe"), QStringLiteral("run"), recipe};
            args << (QFileInfo::exists(log) ? QStringLiteral("--resume") : QStringLiteral("--log")) << log;
            if (!decision.isEmpty())
                args << QStringLiteral("--interrupted=") + decision;
            r = cliRun(line.port(), args + common);
            finished = isFinished(r);
            decision.clear();
            if (r.err.contains(QStringLiteral("not resumed: say --interrupted"))) {
                decision = r.err.contains(QStringLiteral("moved in full")) ? QStringLiteral("skip") : QStringLiteral("redo");
                o.why += ",asked:" + decision.toStdString();
            }
            if (!finished && round == 11)
                o.why += ",last:" + lastLine(r.err);
        }
    }
    endOutcome(o, finished, "the run did not finish");

    // The client's record agrees: every well closed exactly once.
    const platestest::LogCounts lc = platestest::countLog(log);
    int closedTwice = 0;
    for (int op = 0; op < wellCount; ++op)
        closedTwice += (lc.dones.count(op) ? lc.dones.at(op) : 0) + (lc.skips.count(op) ? lc.skips.at(op) : 0) > 1;
    if (closedTwice)
        o.fail(std::to_string(closedTwice) + " wells closed twice in the run log");

    Journal j;
    std::vector<double> end;
    if (!line.finish(&j, &end, &o)) {
        o.fail(line.error().toStdString());
        return o;
    }
    // The device's record. The plunger's account opens at the first MOVE (after homing).
    const dev::sim::MachineConfig machine = dev::sim::analyzerConfig();
    std::vector<double> wireScale;
    int ix = 0, iy = 1, ip = 3;
    for (std::size_t a = 0; a < machine.axes.size(); ++a) {
        wireScale.push_back(machine.axes[a].unit == dev::proto::AxisUnit::Microlitre ? 1e3 : 1e6);
        const char l = machine.axes[a].letter;
        if (l == 'X')
            ix = static_cast<int>(a);
        else if (l == 'Y')
            iy = static_cast<int>(a);
        else if (l == 'P')
            ip = static_cast<int>(a);
    }
    std::size_t from = 0;
    while (from < j.size() && j[from].type != static_cast<std::uint8_t>(dev::proto::MsgType::Move))
        ++from;
    const double p0 = from < j.size() ? j[from].commanded[static_cast<std::size_t>(ip)] : end[static_cast<std::size_t>(ip)];
    const PlungerTally t = plungerByWell(j, from, wireScale, ix, iy, ip);
    judgeWells(o, t, wellCount, volumeUl, 0, end[static_cast<std::size_t>(ip)] - p0);
    return o;
}

// ---- scan through real ptys: every tile once, each with a measured position ---------------

inline Outcome ptyScan(double rate, std::uint64_t seed, double sideMm, const Cut& cut)
{
    Outcome o{cut.kind == Cut::Kill ? "scan-pty-kill" : "scan-pty", rate, seed};
    o.hostStats = false;
    PtyLine line;
    if (!line.start(QStringLiteral("stage"), 10, rate, seed)) {
        o.end = "no-line";
        o.fail(line.error().toStdString());
        return o;
    }
    const QDir dir(line.dir());
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    const QString out = dir.filePath(QStringLiteral("out"));
    const double toleranceUm = motion::scan::ScanPlan().toleranceUm;  // `scan plan` leaves the default
    const auto made = itest::runProgram(itest::binary("benchpilot-cli"),
                                        {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"),
                                         QStringLiteral("40,60,%1,%2").arg(40 + sideMm).arg(60 + sideMm), QStringLiteral("--fov"), QStringLiteral("1,1"),
                                         QStringLiteral("--pixel-um"), QStringLiteral("0.5"), QStringLiteral("--exposure"), QStringLiteral("0.02")});
    QString error;
    if (made.exitCode != 0 || !dev::files::writeAtomically(plan, made.out.toStdString(), &error)) {
        o.fail("no plan: " + made.describe());
        return o;
    }
    const QString runLog = QDir(out).filePath(QLatin1String(dev::files::scan::kRunLogFile));
    auto logged = [&]() -> std::optional<dev::files::scan::RunLog> {
        std::string text;
        QString e;
        if (!dev::files::readText(runLog, &text, &e))
            return std::nullopt;
        return dev::files::scan::parseRunLog(text).log;
    };
    std::map<int, int> printed;  // tile → times a CLI said it took it
    auto count = [&](const itest::ProgramRun& r) {
        for (const QString& l : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
            const QJsonObject obj = QJsonDocument::fromJson(l.toUtf8()).object();
            if (obj.contains(QStringLiteral("tile")) && obj.contains(QStringLiteral("measured_mm")))
                ++printed[obj.value(QStringLiteral("tile")).toInt() - 1];
        }
    };
    bool finished = false;
    const QStringList args{QStringLiteral("--json"), QStringLiteral("scan"), QStringLiteral("run"), plan, QStringLiteral("--out"), out, QStringLiteral("--yes")};
    if (ptyHome(line, o)) {
        itest::ProgramRun r = firstRun(line, args, cut, [&] {
            const auto l = logged();
            return l ? static_cast<int>(l->records.size()) : 0;
        }, o);
        count(r);
        finished = r.exitCode == 0;
        for (int round = 0; round < 12 && !finished; ++round) {
            noteStop(o, "scan", r, &line);
            itest::spin(400);
            r = cliRun(line.port(), args);
            count(r);
            finished = r.exitCode == 0;
            if (!finished && round == 11)
                o.why += ",last:" + lastLine(r.err);
        }
    }
    endOutcome(o, finished, "the scan did not finish");
    const auto l = logged();
    std::map<int, int> taken;  // from the run log; a tile printed twice is taken twice too
    int tiles = 0;
    std::vector<motion::PositionRecord> records;
    if (l) {
        tiles = l->tiles;
        records = l->records;
        for (const auto& rec : records)
            ++taken[rec.target];
        for (const auto& [tile, n] : printed)
            taken[tile] = std::max(taken[tile], n);
    } else {
        o.fail("no run log");
    }
    Journal j;
    std::vector<double> end;
    if (!line.finish(&j, &end, &o)) {
        o.fail(line.error().toStdString());
        return o;
    }
    judgeTiles(o, records, tiles, taken, toleranceUm, xyMovesUm(j));
    return o;
}

// ---- pattern through real ptys: the circle run whole through damaged bytes; cut by an
// unplug, the CLI ends saying how long it ran and the stage stops on the path -----------

inline Outcome ptyPattern(double rate, std::uint64_t seed, bool unplug)
{
    Outcome o{unplug ? "pattern-pty-unplug" : "pattern-pty", rate, seed};
    o.hostStats = false;
    PtyLine line;
    // --unplug-ms: the cable stays out long enough for the device's path silence to act.
    if (!line.start(QStringLiteral("stage"), 4, rate, seed, {QStringLiteral("--unplug-ms"), QStringLiteral("3000")})) {
        o.end = "no-line";
        o.fail(line.error().toStdString());
        return o;
    }
    constexpr double kCx = 50, kCy = 50, kR = 5;
    const QStringList args{QStringLiteral("--json"), QStringLiteral("pattern"), QStringLiteral("run"), QStringLiteral("--shape"),
                           QStringLiteral("circle"), QStringLiteral("--center"), QStringLiteral("%1,%2").arg(kCx).arg(kCy),
                           QStringLiteral("--radius"), QString::number(kR), QStringLiteral("--feed"), QStringLiteral("2")};
    QJsonObject result;
    bool finished = false;
    // At the circle's start first, so the cut below lands in the pattern, not on the way to it.
    bool atStart = false;
    if (ptyHome(line, o))
        for (int i = 0; i < 6 && !atStart; ++i) {
            const auto m = cliRun(line.port(), {QStringLiteral("move"), QStringLiteral("X=%1").arg(kCx + kR), QStringLiteral("Y=%1").arg(kCy)});
            atStart = m.exitCode == 0;
            if (!atStart)
                noteStop(o, "move", m, &line);
        }
    if (atStart) {
        QElapsedTimer since;
        since.start();
        // The circle is 31.4 mm at 2 mm/s: 15.7 s of device time, 3.9 s of wall time at 4x.
        // Unplugged 2 s after the CLI starts (its connect through 1 % damage takes up to a
        // second), the cut lands part-way round; the journal says whether it did.
        const Cut cut = unplug ? Cut{Cut::Unplug, 1} : Cut{};
        itest::ProgramRun r = firstRun(line, args, cut, [&] { return since.elapsed() > 2000 ? 1 : 0; }, o);
        result = itest::lastJson(r.out);
        finished = r.exitCode == 0 && result.value(QStringLiteral("complete")).toBool();
        if (!finished)
            noteStop(o, "pattern", r, &line);
        // Through damaged bytes alone a run stops only if the device fell silent: run it
        // again as an operator would (a pattern starts afresh), as often as the scan's loop.
        for (int round = 0; round < 6 && !finished && !unplug; ++round) {
            itest::spin(400);
            r = cliRun(line.port(), args);
            result = itest::lastJson(r.out);
            finished = r.exitCode == 0 && result.value(QStringLiteral("complete")).toBool();
            if (!finished)
                noteStop(o, "pattern", r, &line);
        }
    }
    Journal j;
    std::vector<double> end;
    if (!line.finish(&j, &end, &o)) {
        o.fail(line.error().toStdString());
        return o;
    }
    bool pathBegun = false;
    for (const auto& e : j)
        pathBegun = pathBegun || e.type == static_cast<std::uint8_t>(dev::proto::MsgType::PathBegin);
    if (unplug && !pathBegun && !finished) {
        o.end = "cut-before-the-run";  // nothing to judge: the cable went before the path did
        return o;
    }
    if (result.isEmpty()) {
        o.end = "no-result";
        o.fail("the CLI printed no result");
        return o;
    }
    // A run the host saw moving (a sample, a segment done) reports how long it ran. One cut
    // before the host heard the path start (its PATH_STARTED lost on the line, no status
    // yet) cannot know, and says 0.
    const double durationS = result.value(QStringLiteral("duration_s")).toDouble();
    const int samples = result.value(QStringLiteral("samples")).toInt(), segmentsDone = result.value(QStringLiteral("segments_done")).toInt();
    if ((samples > 0 || segmentsDone > 0) && !(durationS > 0))
        o.fail("duration_s 0 after " + std::to_string(samples) + " samples and " + std::to_string(segmentsDone) + " segments: a run that moved reports how long it ran");
    if (unplug)
        o.why += ",samples=" + std::to_string(samples) + ",duration_s=" + std::to_string(durationS);
    if (unplug) {
        o.end = finished ? "finished-before-the-cut" : "cut";
        if (finished)
            o.fail("the cut came after the end: nothing was tested");
    } else {
        o.end = finished ? "finished" : "stopped";
        if (!finished)
            o.fail("the pattern did not finish");
        else if (result.value(QStringLiteral("max_contour_um")).toDouble() > 5)
            o.fail("contour error " + std::to_string(result.value(QStringLiteral("max_contour_um")).toDouble()) + " um");
    }
    // The device's record: where it was left is on the circle (it never left the path,
    // and a cut stopped it on it), and at the circle's start after a whole run.
    if (end.size() < 2) {
        o.fail("the journal has no end position");
        return o;
    }
    const double offCircle = std::abs(std::hypot(end[0] - kCx, end[1] - kCy) - kR);
    if (offCircle > 0.01)
        o.fail("the stage stopped " + std::to_string(offCircle * 1e3) + " um off the circle");
    if (finished && !unplug && std::hypot(end[0] - (kCx + kR), end[1] - kCy) > 1e-3)
        o.fail("the stage does not stand at the path's end");
    return o;
}

// ---- tuning through real ptys: a Ziegler–Nichols run cut by an unplug leaves the gains the axis had ----

/// The X gains `benchpilot-cli gains --json` reads, retried through the bad line; empty when
/// no read got through.
inline QJsonObject ptyGains(const QString& port, Outcome& o)
{
    for (int i = 0; i < 6; ++i) {
        const auto r = cliRun(port, {QStringLiteral("--json"), QStringLiteral("gains")}, 30000);
        if (r.exitCode == 0)
            return itest::lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject();
        noteStop(o, "gains", r);
        itest::spin(300);
    }
    return {};
}

inline Outcome ptyTuningCut(double rate, std::uint64_t seed)
{
    Outcome o{"tuning-pty-unplug", rate, seed};
    o.hostStats = false;
    PtyLine line;
    if (!line.start(QStringLiteral("stage"), 1, rate, seed, {QStringLiteral("--unplug-ms"), QStringLiteral("3000")})) {
        o.end = "no-line";
        o.fail(line.error().toStdString());
        return o;
    }
    QJsonObject before, after;
    bool moving = true;
    if (ptyHome(line, o)) {
        for (int i = 0; i < 6; ++i) {
            const auto m = cliRun(line.port(), {QStringLiteral("move"), QStringLiteral("X=50")});
            if (m.exitCode == 0)
                break;
            noteStop(o, "move", m, &line);
        }
        before = ptyGains(line.port(), o);
        QElapsedTimer since;
        since.start();
        // Ziegler–Nichols' trials run for several seconds at real time; the cable goes 2 s
        // after the CLI starts (its connect through 1 % damage takes up to a second).
        const itest::ProgramRun r = firstRun(line,
                                             {QStringLiteral("--json"), QStringLiteral("tune"), QStringLiteral("--method"),
                                              QStringLiteral("zn"), QStringLiteral("--axis"), QStringLiteral("X"),
                                              QStringLiteral("--max-duration"), QStringLiteral("60")},
                                             Cut{Cut::Unplug, 1}, [&] { return since.elapsed() > 2000 ? 1 : 0; }, o);
        o.end = r.exitCode == 0 ? "finished-before-the-cut" : "cut";
        if (r.exitCode != 0)
            noteStop(o, "tune", r, &line);
        itest::spin(3500);  // the cable back
        after = ptyGains(line.port(), o);
        for (int i = 0; i < 6; ++i) {
            const auto st = cliRun(line.port(), {QStringLiteral("--json"), QStringLiteral("status")}, 30000);
            if (st.exitCode != 0)
                continue;
            moving = itest::lastJson(st.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject()
                         .value(QStringLiteral("moving")).toBool(true);
            break;
        }
    }
    Journal j;
    std::vector<double> end;
    if (!line.finish(&j, &end, &o))
        o.fail(line.error().toStdString());
    if (before.isEmpty() || after.isEmpty()) {
        o.fail("the gains could not be read through the line");
        return o;
    }
    for (const char* k : {"Kp", "Ki", "Kd"})
        if (before.value(QLatin1String(k)).toDouble() != after.value(QLatin1String(k)).toDouble())
            o.fail(std::string("gain ") + k + " changed: " + std::to_string(before.value(QLatin1String(k)).toDouble()) + " -> "
                   + std::to_string(after.value(QLatin1String(k)).toDouble()));
    if (moving)
        o.fail("axis X still moving after the cut, or its status never read");
    if (o.end == "finished-before-the-cut")
        o.fail("the cut came after the end: nothing was tested");
    return o;
}

// ---- a held jog through real ptys: nothing moves longer than the watchdog allows after the
// line dies (pulled, or hung with neither port noticing) ------------------------------------

inline Outcome ptyJog(double rate, std::uint64_t seed)
{
    const bool unplug = seed % 2;
    Outcome o{unplug ? "jog-pty-unplug" : "jog-pty-hang", rate, seed};
    o.hostStats = false;
    PtyLine line;
    if (!line.start(QStringLiteral("stage"), 1, rate, seed,
                    {QStringLiteral("--unplug-ms"), QStringLiteral("3000"), QStringLiteral("--hang-ms"), QStringLiteral("3000")})) {
        o.end = "no-line";
        o.fail(line.error().toStdString());
        return o;
    }
    // 10 s at 4 mm/s on X, renewed by the CLI every 50 ms; the line dies 2 s in.
    QProcess p;
    p.start(itest::binary("benchpilot-cli"), {QStringLiteral("--port"), line.port(), QStringLiteral("jog"), QStringLiteral("X"),
                                              QStringLiteral("4"), QStringLiteral("10")});
    if (!p.waitForStarted(10000)) {
        o.fail("the CLI did not start");
        return o;
    }
    itest::spin(2000);
    if (unplug)
        line.unplug();
    else
        line.hang();
    o.end = unplug ? "unplugged" : "hung";
    const itest::ProgramRun r = itest::collectRun(p, p.waitForFinished(30000));
    if (r.exitCode != 0)
        noteStop(o, "jog", r, &line);
    itest::spin(1000);  // a CLI whose port vanished ends at once: give the device's watchdog its time
    Journal j;
    std::vector<double> end;
    if (!line.finish(&j, &end, &o)) {
        o.fail(line.error().toStdString());
        return o;
    }
    bool jogged = false;
    for (const auto& e : j)
        jogged = jogged || e.type == static_cast<std::uint8_t>(dev::proto::MsgType::JogVelocity);
    if (!jogged) {
        o.end = "cut-before-the-jog";  // the connect through the damage took the 2 s: nothing to judge
        return o;
    }
    judgeCoast(o, j, {0}, dev::proto::kJogWatchdogMs / 1000.0);
    return o;
}

} // namespace hostile
