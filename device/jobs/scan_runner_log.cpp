// The scan runner's run log: continuing a folder's log (a torn last line dropped, tiles
// whose images are not whole taken again), setting another plan's log aside, appending
// a line per tile (scan_runner.h, docs/scan.md).
#include "device/jobs/scan_runner.h"

#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"

#include <QDateTime>
#include <QDir>

namespace dev::jobs {

bool ScanRunner::adoptRunLog(std::uint64_t fingerprint, bool restart, bool* fresh, motion::msg::Message* error, Refusal* why)
{
    std::string text;
    if (!dev::files::readText(logPath(), &text, error))
        return false;
    const auto log = dev::files::scan::parseRunLog(text);
    if (!log.log) {
        const motion::msg::Problem& first = log.problems.list().front();
        *error = motion::msg::make("scan.run.log_damaged", {motion::msg::verbatim("log", dev::files::scan::kRunLogFile),
                                                    motion::msg::integer("line", first.line, motion::msg::Unit::None),
                                                    motion::msg::nested("cause", first.message)});
        return false;
    }
    if (log.log->fingerprint == fingerprint && !restart) {
        *fresh = false;
        return continueFromLog(*log.log, fingerprint, error);
    }
    if (!restart) {
        *why = Refusal::OtherScansLog;
        *error = motion::msg::make("scan.run.other_scans_log", {motion::msg::integer("taken", static_cast<long long>(log.log->records.size())),
                                                        motion::msg::integer("tiles", log.log->tiles)});
        return false;
    }
    // Nothing is thrown away: the old log moves aside under its time.
    const QString aside = QDir(m_folder).filePath(
        QStringLiteral("scan-run.%1.jsonl").arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    if (!QFile::rename(logPath(), aside)) {
        *error = motion::msg::make("scan.run.cannot_move_log", {motion::msg::verbatim("file", aside.toStdString())});
        return false;
    }
    return true;
}

bool ScanRunner::continueFromLog(const dev::files::scan::RunLog& log, std::uint64_t fingerprint, motion::msg::Message* error)
{
    // The last line of a tile counts (a tile is logged once; a log edited by hand may not be).
    std::vector<int> lastLine(m_records.size(), -1);
    for (std::size_t i = 0; i < log.records.size(); ++i) {
        const auto k = static_cast<std::size_t>(log.records[i].target);
        if (k < m_records.size())
            lastLine[k] = static_cast<int>(i);
    }
    bool dropped = false;  // a line the log keeps no longer: its tile is taken again
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < log.records.size(); ++i) {
        const auto& r = log.records[i];
        const auto k = static_cast<std::size_t>(r.target);
        if (k >= m_records.size() || lastLine[k] != static_cast<int>(i)) {
            dropped = true;
            continue;
        }
        const dev::files::scan::TileImageRef image = i < log.images.size() ? log.images[i] : dev::files::scan::TileImageRef{};
        // With a camera, a tile is taken when its image is there, whole and the one logged.
        if (m_camera && !imageIntact(image)) {
            dropped = true;
            continue;
        }
        kept.push_back(i);
        m_records[k].measuredMm = r.measuredMm;
        m_records[k].deviceTimeUs = r.deviceTimeUs;
        m_records[k].settleS = r.settleS;
        m_images[k] = image;
        if (!m_taken[k]) {
            m_taken[k] = 1;
            ++m_takenCount;
        }
    }
    if (!log.tornTail && !dropped)
        return true;
    // A line torn by a crash would sit in front of the next one, and a tile taken again
    // must not be logged twice: write the log out again with the lines that stand
    // (atomically, so this cannot lose them either).
    std::string clean = dev::files::scan::runLogHeader(m_plan.name, fingerprint, totalTiles());
    for (std::size_t i : kept)
        clean += dev::files::scan::runLogLine(log.records[i], i < log.images.size() ? log.images[i] : dev::files::scan::TileImageRef{});
    return dev::files::writeAtomically(logPath(), clean, error);
}

bool ScanRunner::openLog(motion::msg::Message* error)
{
    if (m_log.isOpen())
        return true;
    m_log.setFileName(logPath());
    if (!m_log.open(QIODevice::WriteOnly | QIODevice::Append)) {
        *error = motion::msg::make("file.log.cannot_open", {motion::msg::verbatim("file", logPath().toStdString()), motion::msg::verbatim("detail", m_log.errorString().toStdString())});
        return false;
    }
    return true;
}

bool ScanRunner::appendLog(const std::string& line, motion::msg::Message* error)
{
    // One write and a flush per tile: a crash of the program loses nothing taken.
    if (m_log.write(line.data(), static_cast<qint64>(line.size())) != static_cast<qint64>(line.size()) || !m_log.flush()) {
        *error = motion::msg::make("file.log.cannot_write", {motion::msg::verbatim("file", logPath().toStdString()), motion::msg::verbatim("detail", m_log.errorString().toStdString())});
        return false;
    }
    return true;
}

} // namespace dev::jobs
