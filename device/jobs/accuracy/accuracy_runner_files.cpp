// The accuracy runner's preparation, run log and results (the motion is in
// accuracy_runner.cpp).
#include "device/jobs/accuracy/accuracy_runner.h"

#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/interferometer_csv.h"
#include "device/files/accuracy/readings_csv.h"
#include "device/files/text_file.h"
#include "motion/metrology/linear/run_sequence.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

#include <cmath>

namespace dev::jobs {

using motion::metrology::AxisTest;
using motion::metrology::Direction;
using motion::msg::Problems;
using motion::metrology::XyLineTest;

namespace {

void add(Problems* out, motion::msg::Message m, std::string path = {})
{
    if (out)
        out->push_back({std::move(path), std::move(m)});
}

/// A file name from a test's name: letters, digits, '-' and '_' kept, the rest '-'.
QString safeName(const std::string& name, const QString& fallback)
{
    QString out;
    for (QChar c : QString::fromStdString(name).trimmed())
        out += (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_')) ? c : QLatin1Char('-');
    while (out.contains(QStringLiteral("--")))
        out.replace(QStringLiteral("--"), QStringLiteral("-"));
    return out.isEmpty() || out == QLatin1String("-") ? fallback : out.left(80);
}

motion::metrology::AxisLimits limitsOf(const dev::Instrument& inst, int axis)
{
    motion::metrology::AxisLimits l;
    if (axis < inst.softLimits().size()) {
        l.minMm = inst.softLimits()[axis].min;
        l.maxMm = inst.softLimits()[axis].max;
    }
    if (axis < inst.identity().axes.size() && inst.identity().axes[axis].maxSpeed > 0)
        l.maxFeedMmS = inst.identity().axes[axis].maxSpeed;
    return l;
}

} // namespace

bool AccuracyRunner::prepare(const dev::files::accuracy::AccuracyTest& test, ReadingSource* source, const QString& folder, bool restart,
                             Problems* problems)
{
    if (problems)
        problems->clear();
    if (isActive()) {
        add(problems, motion::msg::make("accuracy.run.busy"));
        return false;
    }
    m_prepared = false;
    if (!m_instrument || !m_instrument->isReady()) {
        add(problems, motion::msg::make("accuracy.run.not_connected"));
        return false;
    }
    const dev::DeviceIdentity& id = m_instrument->identity();
    auto axisOf = [&](const std::string& letter) {
        return letter.size() == 1 ? id.axisIndex(QChar::fromLatin1(letter[0])) : -1;
    };
    Problems found;
    std::vector<PlannedStop> stops;
    std::vector<int> axes;
    if (const auto* a = std::get_if<AxisTest>(&test)) {
        const int i = axisOf(a->axis);
        if (i < 0) {
            add(problems, motion::msg::make("accuracy.run.no_such_axis", {motion::msg::verbatim("axis", a->axis)}), "axis");
            return false;
        }
        axes = {i};
        found = motion::metrology::validate(*a, limitsOf(*m_instrument, i));
        if (!motion::msg::hasErrors(found))
            for (const auto& s : motion::metrology::runSequence(*a)) {
                PlannedStop p;
                p.cycle = s.cycle;
                p.direction = s.direction;
                p.targetIndex = static_cast<int>(s.targetIndex);
                p.targetMm = {s.targetMm};
                if (s.overrunMm)
                    p.overrunMm = std::vector<double>{*s.overrunMm};
                p.approachFromMm = {s.approachFromMm};
                stops.push_back(p);
            }
        m_xy = false;
    } else if (const auto* x = std::get_if<XyLineTest>(&test)) {
        const int ix = axisOf("X"), iy = axisOf("Y");
        if (ix < 0 || iy < 0) {
            add(problems, motion::msg::make("accuracy.run.no_such_axis", {motion::msg::verbatim("axis", ix < 0 ? "X" : "Y")}));
            return false;
        }
        axes = {ix, iy};
        motion::metrology::XyLimits lim;
        lim.x = limitsOf(*m_instrument, ix);
        lim.y = limitsOf(*m_instrument, iy);
        if (lim.x.maxFeedMmS && lim.y.maxFeedMmS)
            lim.maxFeedMmS = std::min(*lim.x.maxFeedMmS, *lim.y.maxFeedMmS);
        found = motion::metrology::validate(*x, lim);
        if (!motion::msg::hasErrors(found)) {
            std::vector<double> previous;
            for (const auto& s : motion::metrology::runSequence(*x)) {
                PlannedStop p;
                p.cycle = s.cycle;
                p.targetIndex = static_cast<int>(s.pointIndex);
                p.targetMm = {s.targetMm.xMm, s.targetMm.yMm};
                if (s.overrunMm) {
                    p.overrunMm = std::vector<double>{s.overrunMm->xMm, s.overrunMm->yMm};
                    previous = *p.overrunMm;
                }
                p.approachFromMm = previous.empty() ? p.targetMm : previous;
                previous = p.targetMm;
                stops.push_back(p);
            }
        }
        m_xy = true;
    } else {
        add(problems, motion::msg::make("accuracy.run.circle_elsewhere"));
        return false;
    }
    if (problems)
        problems->insert(problems->end(), found.begin(), found.end());
    if (motion::msg::hasErrors(found) || stops.empty())
        return false;
    if (!source) {
        add(problems, motion::msg::make("accuracy.run.no_source"));
        return false;
    }
    if (source->maxAxes() < static_cast<int>(axes.size())) {
        add(problems, motion::msg::make("accuracy.run.source_axes", {motion::msg::term("source", readingKindTerm(source->kind())),
                                                             motion::msg::integer("count", static_cast<long long>(axes.size())),
                                                             motion::msg::integer("max", source->maxAxes())}));
        return false;
    }
    if (!QDir().mkpath(folder)) {
        add(problems, motion::msg::make("accuracy.run.folder_failed", {motion::msg::verbatim("folder", folder.toStdString())}));
        return false;
    }
    m_test = test;
    m_axes = axes;
    m_stops = std::move(stops);
    m_source = source;
    m_folder = folder;
    m_results.clear();
    const std::string json = dev::files::accuracy::accuracyTestToJson(test);
    m_header = {};
    m_header.test = std::visit([](const auto& t) { return t.name; }, test);
    m_header.kind = m_xy ? "xy-line" : "axis";
    m_header.fingerprint = dev::files::accuracy::fingerprintOf(json + "\nsource=" + readingKindName(source->kind()));
    m_header.stops = static_cast<int>(m_stops.size());
    m_header.source = readingKindName(source->kind());
    if (!openLog(restart, problems))
        return false;
    m_prepared = true;
    setState(m_entries.empty() ? State::Idle : (m_entries.size() >= m_stops.size() ? State::Finished : State::Stopped));
    emit progress(readingsTaken(), totalReadings(), etaS());
    return true;
}

QString AccuracyRunner::logPath() const { return QDir(m_folder).filePath(QLatin1String(dev::files::accuracy::kRunLogFile)); }

QString AccuracyRunner::basePath() const
{
    QString fallback = QStringLiteral("accuracy-") + axisNames();
    return QDir(m_folder).filePath(safeName(m_header.test, fallback));
}

bool AccuracyRunner::openLog(bool restart, Problems* problems)
{
    m_log.close();
    m_entries.clear();
    const QString path = logPath();
    if (QFileInfo::exists(path)) {
        std::string text;
        motion::msg::Message error;
        if (!dev::files::readText(path, &text, &error)) {
            add(problems, motion::msg::make("accuracy.run.log_unreadable", {motion::msg::verbatim("file", path.toStdString()), motion::msg::integer("line", 0),
                                                                    motion::msg::nested("detail", error)}));
            return false;
        }
        const auto read = dev::files::accuracy::parseRunLog(text);
        const bool same = read.log && read.log->header.fingerprint == m_header.fingerprint && read.log->header.stops == m_header.stops;
        if (!same && !restart) {
            if (!read.log) {
                const auto& p = read.problems.list().front();
                add(problems, motion::msg::make("accuracy.run.log_unreadable", {motion::msg::verbatim("file", path.toStdString()),
                                                                        motion::msg::integer("line", p.line),
                                                                        motion::msg::nested("detail", p.message)}));
            } else {
                add(problems, motion::msg::make("accuracy.run.other_log", {motion::msg::verbatim("file", path.toStdString()),
                                                                   motion::msg::verbatim("test", read.log->header.test)}));
            }
            return false;
        }
        if (same) {
            m_entries = read.log->entries;
        } else {
            // Kept aside, never overwritten: the first free accuracy-run-N.jsonl.
            for (int n = 1;; ++n) {
                const QString aside = QDir(m_folder).filePath(QStringLiteral("accuracy-run-%1.jsonl").arg(n));
                if (QFileInfo::exists(aside))
                    continue;
                if (!QFile::rename(path, aside)) {
                    add(problems, motion::msg::make("accuracy.run.log_not_kept_aside", {motion::msg::verbatim("file", path.toStdString()),
                                                                                motion::msg::verbatim("aside", aside.toStdString())}));
                    return false;
                }
                break;
            }
        }
    }
    m_log.setFileName(path);
    const bool fresh = !QFileInfo::exists(path);
    if (!m_log.open(QIODevice::Append | QIODevice::WriteOnly)) {
        add(problems, motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", path.toStdString()),
                                                                  motion::msg::verbatim("detail", m_log.errorString().toStdString())}));
        return false;
    }
    if (fresh) {
        const std::string h = dev::files::accuracy::runLogHeader(m_header);
        if (m_log.write(h.data(), static_cast<qint64>(h.size())) != static_cast<qint64>(h.size()) || !m_log.flush()) {
            add(problems, motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", path.toStdString()),
                                                                      motion::msg::verbatim("detail", m_log.errorString().toStdString())}));
            return false;
        }
    } else if (!m_entries.empty()) {
        // A torn last line (a crash mid-write) was dropped by the parser; start the next
        // line on a line of its own.
        QFile check(path);
        if (check.open(QIODevice::ReadOnly) && check.size() > 0 && check.seek(check.size() - 1) && check.read(1) != "\n")
            m_log.write("\n");
    }
    return true;
}

bool AccuracyRunner::appendLog(const dev::files::accuracy::RunLogEntry& e)
{
    const std::string line = dev::files::accuracy::runLogLine(e);
    if (m_log.write(line.data(), static_cast<qint64>(line.size())) != static_cast<qint64>(line.size()) || !m_log.flush()) {
        stopWith(motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", logPath().toStdString()),
                                                             motion::msg::verbatim("detail", m_log.errorString().toStdString())}),
                 false);
        return false;
    }
    return true;
}

std::vector<motion::metrology::Reading> AccuracyRunner::readings() const
{
    std::vector<motion::metrology::Reading> out;
    if (m_xy)
        return out;
    for (const auto& e : m_entries)
        if (e.measuredMm && !e.measuredMm->empty() && !e.targetMm.empty())
            out.push_back({e.targetMm[0], e.direction, e.cycle, (*e.measuredMm)[0]});
    return out;
}

std::vector<motion::metrology::XyReading> AccuracyRunner::xyReadings() const
{
    std::vector<motion::metrology::XyReading> out;
    if (!m_xy)
        return out;
    for (const auto& e : m_entries)
        if (e.measuredMm && e.measuredMm->size() == 2 && static_cast<std::size_t>(e.stop) < m_stops.size())
            out.push_back({static_cast<std::size_t>(m_stops[static_cast<std::size_t>(e.stop)].targetIndex), e.cycle,
                           (*e.measuredMm)[0], (*e.measuredMm)[1]});
    return out;
}

motion::metrology::Evaluation AccuracyRunner::evaluation() const
{
    motion::metrology::EvaluationOptions o;
    o.allowUnequalCycles = m_state != State::Finished;
    return motion::metrology::evaluate(readings(), o);
}

motion::metrology::XyEvaluation AccuracyRunner::xyEvaluation() const
{
    const auto* x = std::get_if<XyLineTest>(&m_test);
    if (!x)
        return {};
    return motion::metrology::evaluate(motion::metrology::pointsOf(*x), xyReadings());
}

std::vector<dev::files::accuracy::SequenceStop> AccuracyRunner::sequence() const
{
    std::vector<dev::files::accuracy::SequenceStop> out;
    for (const auto& e : m_entries) {
        dev::files::accuracy::SequenceStop s;
        s.index = e.stop + 1;
        s.targetMm = e.targetMm.empty() ? 0 : e.targetMm[0];
        s.direction = e.direction;
        s.cycle = e.cycle;
        s.timeS = e.timeS;
        s.settled = e.settled;
        out.push_back(s);
    }
    return out;
}

void AccuracyRunner::finish()
{
    m_phase = Phase::None;
    writeResults();
    setState(State::Finished);
    emit progress(readingsTaken(), totalReadings(), 0);
    emit finished(m_results);
}

void AccuracyRunner::writeResults()
{
    m_results.clear();
    const QString base = basePath();
    motion::msg::Message error;
    auto failed = [&](const QString& file) {
        emit problem(motion::msg::make("accuracy.run.results_failed", {motion::msg::verbatim("file", file.toStdString()), motion::msg::nested("detail", error)}));
    };
    const QString created = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    const std::string reference = m_source ? readingKindName(m_source->kind()) : "";
    // The sequence with its times: what an interferometer's capture is imported against,
    // and a record of when each stop was read for the others.
    const QString targets = base + QStringLiteral(".targets.csv");
    if (!m_xy) {
        if (dev::files::accuracy::saveTargetSequence(targets, sequence(), &error))
            m_results << targets;
        else
            failed(targets);
    }
    if (m_source && m_source->kind() == ReadingKind::Interferometer)
        return;  // the readings come with the import
    auto writeAxis = [&](const QString& stem, const std::vector<motion::metrology::Reading>& readings,
                         const motion::metrology::Evaluation& evaluation, const std::string& axis,
                         const motion::metrology::AxisTolerances& tolerances) {
        const QString csv = stem + QStringLiteral(".readings.csv");
        if (dev::files::accuracy::saveReadingsCsv(csv, readings, &error))
            m_results << csv;
        else
            failed(csv);
        if (!evaluation.ok())
            return;
        dev::files::accuracy::AccuracyResult r;
        r.axis = axis;
        r.evaluation = evaluation;
        r.tolerances = tolerances;
        r.reference = reference;
        r.readingsFile = QFileInfo(csv).fileName().toStdString();
        r.createdUtc = created.toStdString();
        const QString json = stem + QStringLiteral(".accuracy-result.json");
        if (dev::files::accuracy::saveAccuracyResultFile(json, r, &error))
            m_results << json;
        else
            failed(json);
    };
    if (const auto* a = std::get_if<AxisTest>(&m_test)) {
        writeAxis(base, readings(), evaluation(), a->axis, a->tolerances);
        return;
    }
    const auto* x = std::get_if<XyLineTest>(&m_test);
    const motion::metrology::XyEvaluation e = xyEvaluation();
    const auto points = motion::metrology::pointsOf(*x);
    const auto xy = xyReadings();
    std::vector<motion::metrology::Reading> rx, ry, rc;
    for (std::size_t k = 0; k < xy.size(); ++k) {
        const auto& p = points[xy[k].pointIndex];
        rx.push_back({p.xMm, Direction::Up, xy[k].cycle, xy[k].xMm});
        ry.push_back({p.yMm, Direction::Up, xy[k].cycle, xy[k].yMm});
        const double along = std::hypot(p.xMm - points.front().xMm, p.yMm - points.front().yMm);
        if (k < e.contourMm.size())
            rc.push_back({along, Direction::Up, xy[k].cycle, along + e.contourMm[k]});
    }
    writeAxis(base + QStringLiteral("-x"), rx, e.x, "X", {});
    writeAxis(base + QStringLiteral("-y"), ry, e.y, "Y", {});
    writeAxis(base + QStringLiteral("-contour"), rc, e.contour, "C", x->contourTolerances);
}

} // namespace dev::jobs
