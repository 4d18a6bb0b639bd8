// The grid map runner's files: preparing (the test against the instrument, the run log
// continued or kept aside), the log's lines, the map and its results.
#include "device/jobs/accuracy/grid_map_runner.h"

#include "device/files/accuracy/csv_table.h"
#include "device/files/accuracy/grid/grid_map_result_file.h"
#include "device/files/accuracy/grid/grid_map_test_file.h"
#include "device/files/json.h"
#include "device/files/text_file.h"

#include <QDir>
#include <QFileInfo>

namespace dev::jobs {

namespace {

constexpr const char* kGridRunLogSchema = "benchpilot.grid-map-run-log";

void addGridProblem(motion::msg::Problems* problems, motion::msg::Message m)
{
    if (problems)
        problems->push_back(motion::msg::error("", std::move(m)));
}

/// The test as the log's header holds it: its start is the log's own line when found.
std::string fingerprintOf(const motion::metrology::GridMapTest& t)
{
    motion::metrology::GridMapTest f = t;
    f.stopOnFailure = false;  // going on or stopping may change between sessions
    return dev::files::accuracy::gridMapTestToJson(f);
}

/// What a grid run's log holds; badLine is the first line that is not a log line (0: none).
struct GridRunLog {
    int badLine = 0;
    std::string fingerprint;
    bool haveStart = false;
    double startX = 0, startY = 0;
    struct Line {
        int node = 0;
        bool reverse = false;
        GridNodeReading reading;
    };
    std::vector<Line> nodes;
};

/// Where a reading of `node` in its pass stands in planGridMap's order (-1: not in the plan).
int stopIndexOf(const motion::metrology::GridMapTest& t, int node, bool reverse)
{
    const int n = t.columns * t.rows;
    if (node < 0 || node >= n || (reverse && !t.bidirectional))
        return -1;
    return reverse ? 2 * n - 1 - node : node;
}

GridRunLog parseGridLog(const std::string& text)
{
    GridRunLog out;
    std::size_t at = 0;
    int lineNo = 0;
    while (at < text.size()) {
        const std::size_t nl = text.find('\n', at);
        const bool complete = nl != std::string::npos;
        const std::string line = text.substr(at, complete ? nl - at : std::string::npos);
        at = complete ? nl + 1 : text.size();
        ++lineNo;
        if (line.empty())
            continue;
        const auto parsed = dev::files::json::parse(line);
        if (!parsed || !parsed.value->isObject()) {
            if (!complete && lineNo > 1)
                break;  // a torn last line: the crash came mid-write
            out.badLine = lineNo;
            return out;
        }
        const auto& v = *parsed.value;
        if (lineNo == 1) {
            const auto* schema = v.find("schema");
            const auto* test = v.find("test");
            if (!schema || schema->asString() != kGridRunLogSchema || !test || !test->isString()) {
                out.badLine = 1;
                return out;
            }
            out.fingerprint = test->asString();
            continue;
        }
        if (const auto* x = v.find("start_x_mm"); x && x->isNumber()) {
            const auto* y = v.find("start_y_mm");
            out.haveStart = y && y->isNumber();
            out.startX = x->asNumber();
            out.startY = y ? y->asNumber() : 0;
            continue;
        }
        const auto* node = v.find("node");
        if (!node || !node->isNumber()) {
            out.badLine = lineNo;
            return out;
        }
        GridNodeReading n;
        const auto* mx = v.find("measured_x_mm");
        const auto* my = v.find("measured_y_mm");
        if (mx && my && mx->isNumber() && my->isNumber()) {
            n.read = true;
            n.measuredXMm = mx->asNumber();
            n.measuredYMm = my->asNumber();
        } else {
            const auto* f = v.find("failed");
            n.failure = f && f->isString() ? f->asString() : std::string("grid.run.node_failed");
            if (const auto* im = v.find("image"); im && im->isString())
                n.image = im->asString();
        }
        bool reverse = false;
        if (const auto* pass = v.find("pass")) {
            if (!pass->isString() || (pass->asString() != "reverse" && pass->asString() != "forward")) {
                out.badLine = lineNo;
                return out;
            }
            reverse = pass->asString() == "reverse";
        }
        out.nodes.push_back({static_cast<int>(node->asNumber()), reverse, n});
    }
    return out;
}

/// True when `folder` holds this test's log with its start found: the run continues
/// from there, wherever the stage stands now.
bool logHasStart(const QString& folder, const motion::metrology::GridMapTest& test)
{
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(QDir(folder).filePath(QStringLiteral("grid-map.run-log.jsonl")), &text, &error))
        return false;
    const GridRunLog read = parseGridLog(text);
    return read.badLine == 0 && read.haveStart && read.fingerprint == fingerprintOf(test);
}

} // namespace

QString GridMapRunner::logPath() const { return QDir(m_folder).filePath(QStringLiteral("grid-map.run-log.jsonl")); }
QString GridMapRunner::basePath() const { return QDir(m_folder).filePath(QStringLiteral("grid-map")); }

bool GridMapRunner::prepare(const motion::metrology::GridMapTest& test, ReadingSource* source, const QString& folder, bool restart,
                            motion::msg::Problems* problems)
{
    if (problems)
        problems->clear();
    if (isActive()) {
        addGridProblem(problems, motion::msg::make("accuracy.run.busy"));
        return false;
    }
    m_prepared = false;
    m_state = State::Idle;
    m_results.clear();
    m_haveStart = false;
    m_stops.clear();
    m_nodes.clear();
    if (!m_instrument) {
        addGridProblem(problems, motion::msg::make("accuracy.run.not_connected"));
        return false;
    }
    motion::msg::Problems found = motion::metrology::validate(test);
    m_axisX = m_instrument->identity().axisIndex(QLatin1Char('X'));
    m_axisY = m_instrument->identity().axisIndex(QLatin1Char('Y'));
    if (m_axisX < 0 || m_axisY < 0) {
        addGridProblem(problems, motion::msg::make("grid.run.needs_xy"));
        return false;
    }
    const auto& lim = m_instrument->softLimits();
    if (test.startXMm && test.startYMm && m_axisX < lim.size() && m_axisY < lim.size())
        for (auto& p : motion::metrology::validateTravel(test, *test.startXMm, *test.startYMm, lim[m_axisX].min, lim[m_axisX].max,
                                                         lim[m_axisY].min, lim[m_axisY].max))
            found.push_back(p);
    else if (!logHasStart(folder, test) && m_axisX < lim.size() && m_axisY < lim.size() && m_axisX < m_instrument->status().axes.size()
             && m_axisY < m_instrument->status().axes.size()) {
        // The start is the dot nearest where the stage stands, within half the plate's
        // pitch of it: a test that would leave the travel from there is refused now,
        // before anything is moved or written.
        const double h = 0.5 * test.platePitchMm;
        const double x = m_instrument->status().axes[m_axisX].measured, y = m_instrument->status().axes[m_axisY].measured;
        for (auto& p : motion::metrology::validateTravel(test, x - h, y - h, lim[m_axisX].min, lim[m_axisX].max, lim[m_axisY].min,
                                                         lim[m_axisY].max))
            found.push_back(p);
        for (auto& p : motion::metrology::validateTravel(test, x + h, y + h, lim[m_axisX].min, lim[m_axisX].max, lim[m_axisY].min,
                                                         lim[m_axisY].max))
            found.push_back(p);
    }
    if (!source)
        found.push_back(motion::msg::error("", motion::msg::make("accuracy.run.no_source")));
    else if (source->maxAxes() < 2)
        found.push_back(motion::msg::error("", motion::msg::make("grid.run.source_one_axis")));
    if (problems)
        *problems = found;
    if (motion::msg::hasErrors(found))
        return false;
    m_test = test;
    m_source = source;
    m_folder = folder;
    if (!QDir().mkpath(folder)) {
        addGridProblem(problems, motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", folder.toStdString()),
                                                                                     motion::msg::verbatim("detail", "")}));
        return false;
    }
    if (test.startXMm && test.startYMm) {
        m_haveStart = true;
        m_startXMm = *test.startXMm;
        m_startYMm = *test.startYMm;
    }
    if (!openLog(restart, problems))
        return false;
    if (m_haveStart && m_stops.empty()) {
        m_stops = motion::metrology::planGridMap(m_test, m_startXMm, m_startYMm);
        m_nodes.assign(m_stops.size(), {});
    }
    m_prepared = true;
    if (m_haveStart && nodesRead() == totalNodes())
        m_state = State::Finished;  // the results are on disk already
    return true;
}

bool GridMapRunner::openLog(bool restart, motion::msg::Problems* problems)
{
    m_log.close();
    const QString path = logPath();
    const std::string fingerprint = fingerprintOf(m_test);
    if (QFileInfo::exists(path)) {
        std::string text;
        motion::msg::Message error;
        if (!dev::files::readText(path, &text, &error)) {
            addGridProblem(problems, motion::msg::make("accuracy.run.log_unreadable", {motion::msg::verbatim("file", path.toStdString()),
                                                                                       motion::msg::integer("line", 0), motion::msg::nested("detail", error)}));
            return false;
        }
        const GridRunLog read = parseGridLog(text);
        const bool same = read.badLine == 0 && read.fingerprint == fingerprint;
        if (!same && !restart) {
            if (!read.badLine == 0)
                addGridProblem(problems, motion::msg::make("accuracy.run.log_unreadable", {motion::msg::verbatim("file", path.toStdString()),
                                                                                           motion::msg::integer("line", read.badLine),
                                                                                           motion::msg::nested("detail", motion::msg::make("grid.run.log_line"))}));
            else
                addGridProblem(problems, motion::msg::make("accuracy.run.other_log", {motion::msg::verbatim("file", path.toStdString()),
                                                                                      motion::msg::verbatim("test", m_test.name)}));
            return false;
        }
        if (same) {
            if (read.haveStart && !m_haveStart) {
                m_haveStart = true;
                m_startXMm = read.startX;
                m_startYMm = read.startY;
            }
            if (m_haveStart) {
                m_stops = motion::metrology::planGridMap(m_test, m_startXMm, m_startYMm);
                m_nodes.assign(m_stops.size(), {});
                for (const auto& line : read.nodes) {
                    const int k = stopIndexOf(m_test, line.node, line.reverse);
                    if (k >= 0 && k < totalNodes() && !m_nodes[static_cast<std::size_t>(k)].read)
                        m_nodes[static_cast<std::size_t>(k)] = line.reading;  // a later reading of a failed node wins
                }
            }
        } else {
            for (int n = 1;; ++n) {
                const QString aside = QDir(m_folder).filePath(QStringLiteral("grid-map.run-log-%1.jsonl").arg(n));
                if (QFileInfo::exists(aside))
                    continue;
                if (!QFile::rename(path, aside)) {
                    addGridProblem(problems, motion::msg::make("accuracy.run.log_not_kept_aside", {motion::msg::verbatim("file", path.toStdString()),
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
        addGridProblem(problems, motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", path.toStdString()),
                                                                                     motion::msg::verbatim("detail", m_log.errorString().toStdString())}));
        return false;
    }
    if (fresh) {
        dev::files::json::Value h = dev::files::json::schemaObject(kGridRunLogSchema, 1);
        h.set("test", dev::files::json::Value(fingerprint));
        const std::string line = dev::files::json::write(h, false) + "\n";
        if (m_log.write(line.data(), static_cast<qint64>(line.size())) != static_cast<qint64>(line.size()) || !m_log.flush()) {
            addGridProblem(problems, motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", path.toStdString()),
                                                                                         motion::msg::verbatim("detail", m_log.errorString().toStdString())}));
            return false;
        }
    } else {
        // A torn last line was dropped by the parser: the next starts on a line of its own.
        QFile check(path);
        if (check.open(QIODevice::ReadOnly) && check.size() > 0 && check.seek(check.size() - 1) && check.read(1) != "\n")
            m_log.write("\n");
    }
    return true;
}

bool GridMapRunner::appendLog(const std::string& line)
{
    if (m_log.write(line.data(), static_cast<qint64>(line.size())) != static_cast<qint64>(line.size()) || !m_log.flush()) {
        stopWith(motion::msg::make("accuracy.run.log_write_failed", {motion::msg::verbatim("file", logPath().toStdString()),
                                                                     motion::msg::verbatim("detail", m_log.errorString().toStdString())}),
                 false);
        return false;
    }
    return true;
}

motion::metrology::GridMapInput GridMapRunner::input() const
{
    motion::metrology::GridMapInput in;
    for (int i = 0; i < m_test.columns; ++i)
        in.xMm.push_back(m_startXMm + i * m_test.pitchXMm);
    for (int j = 0; j < m_test.rows; ++j)
        in.yMm.push_back(m_startYMm + j * m_test.pitchYMm);
    const std::size_t n = in.xMm.size() * in.yMm.size();
    in.exUm.assign(n, 0.0);
    in.eyUm.assign(n, 0.0);
    if (m_test.bidirectional) {
        in.reverseExUm.assign(n, 0.0);
        in.reverseEyUm.assign(n, 0.0);
    }
    for (std::size_t k = 0; k < m_stops.size() && k < m_nodes.size(); ++k) {
        const auto& s = m_stops[k];
        const auto& r = m_nodes[k];
        const auto node = static_cast<std::size_t>(s.node(m_test.columns));
        if (!r.read || node >= n)
            continue;
        (s.reverse ? in.reverseExUm : in.exUm)[node] = (r.measuredXMm - s.xMm) * 1e3;
        (s.reverse ? in.reverseEyUm : in.eyUm)[node] = (r.measuredYMm - s.yMm) * 1e3;
    }
    return in;
}

std::optional<motion::metrology::GridMapResult> GridMapRunner::result() const
{
    if (!m_haveStart || m_nodes.empty() || nodesRead() != totalNodes())
        return std::nullopt;
    return motion::metrology::analyseGridMap(input());
}

void GridMapRunner::finish()
{
    m_phase = Phase::None;
    writeResults();
    setState(State::Finished);
    emit progress(nodesRead() + nodesFailed(), totalNodes());
    if (nodesFailed() > 0)
        emit problem(motion::msg::make("grid.run.incomplete", {motion::msg::integer("failed", nodesFailed()),
                                                               motion::msg::integer("total", totalNodes())}));
    emit finished(m_results);
}

void GridMapRunner::writeResults()
{
    m_results.clear();
    const QString base = basePath();
    motion::msg::Message error;
    auto failed = [&](const QString& file) {
        emit problem(motion::msg::make("accuracy.run.results_failed", {motion::msg::verbatim("file", file.toStdString()), motion::msg::nested("detail", error)}));
    };
    using dev::files::accuracy::csvField;
    using dev::files::accuracy::csvNumber;
    // Every reading, taken or not: a failed one says why and where its image is.
    // The pass says from which side the node was approached: forward from −X −Y,
    // reverse from +X +Y.
    std::string csv = "node,pass,column,row,x_mm,y_mm,measured_x_mm,measured_y_mm,ex_um,ey_um,failure,image\n";
    for (std::size_t k = 0; k < m_stops.size() && k < m_nodes.size(); ++k) {
        const auto& s = m_stops[k];
        const auto& n = m_nodes[k];
        csv += std::to_string(s.node(m_test.columns) + 1) + "," + (s.reverse ? "reverse" : "forward") + "," + std::to_string(s.column + 1) + ","
               + std::to_string(s.row + 1) + "," + csvNumber(s.xMm) + "," + csvNumber(s.yMm) + ",";
        if (n.read)
            csv += csvNumber(n.measuredXMm) + "," + csvNumber(n.measuredYMm) + "," + csvNumber((n.measuredXMm - s.xMm) * 1e3) + ","
                   + csvNumber((n.measuredYMm - s.yMm) * 1e3) + ",,";
        else
            csv += ",,,," + csvField(n.failure) + "," + csvField(QFileInfo(QString::fromStdString(n.image)).fileName().toStdString());
        csv += "\n";
    }
    const QString csvPath = base + QStringLiteral(".readings.csv");
    if (dev::files::writeAtomically(csvPath, csv, &error))
        m_results << csvPath;
    else
        failed(csvPath);
    const auto map = result();
    if (!map)
        return;
    dev::files::accuracy::GridMapResultFile f;
    f.result = *map;
    f.source = m_test.name + (m_source ? std::string(" read by the ") + readingKindName(m_source->kind()) : std::string());
    const QString json = base + QStringLiteral(".grid-map-result.json");
    if (dev::files::accuracy::saveGridMapResultFile(json, f, &error))
        m_results << json;
    else
        failed(json);
}

} // namespace dev::jobs
