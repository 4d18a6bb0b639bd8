#include "device/jobs/scan_runner.h"

#include "device/client/compensation_client.h"

#include "device/files/scan_exports.h"
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"
#include "device/jobs/machine_model.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QPointer>

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using motion::scan::Point2;

namespace {
constexpr unsigned kBothAxes = 0x3;

/// A commanded position this close to the move's target (mm) is the target: the setpoint
/// comes back in whole nanometres (docs/protocol.md, wire units), so it differs from the
/// target by rounding; 0.1 µm is above that and far below a step or a grating count.
constexpr double kScanAtTargetMm = 1e-4;
/// Readings at rest on the target, in a row, that stand for a lost MotionDone: the second
/// confirms the first was not a passing moment, at the cost of one status poll, and only on
/// a line that lost the event.
constexpr int kScanRestPollsForArrival = 2;
/// The run's own pace corrects the time left only once this many tiles of the session are
/// taken: fewer are mostly the lead-in and the first settle, not the run's rhythm.
constexpr int kScanPaceMinTiles = 3;
/// …and only over a stretch the estimate puts at least this long (s): a shorter one is
/// dominated by the device clock's granularity and one tile's settle.
constexpr double kScanPaceMinStretchS = 0.5;
/// The correction is held between these factors: a stage five times slower or faster than
/// planned is a fault to report, not a pace to extrapolate over the rest of the run.
constexpr double kScanPaceMinFactor = 0.2;
constexpr double kScanPaceMaxFactor = 5.0;

constexpr double kScanSecondsPerUs = 1e-6;
constexpr double kScanUmPerMm = 1e3;
constexpr double kScanMsPerS = 1e3;
} // namespace

ScanRunner::ScanRunner(dev::Instrument* client, QObject* parent) : QObject(parent), m_client(client)
{
    qRegisterMetaType<dev::jobs::ScanRunner::State>();
    m_exposure.setSingleShot(true);
    m_exposure.setTimerType(Qt::PreciseTimer);
    connect(&m_exposure, &QTimer::timeout, this, &ScanRunner::onExposureEnd);
    m_settleTimeout.setSingleShot(true);
    connect(&m_settleTimeout, &QTimer::timeout, this, [this] {
        if (m_phase != Phase::Settling)
            return;
        stopWith(motion::msg::make("scan.run.not_settled", {tileArg(m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile),
                                                     motion::msg::real("tolerance", m_plan.toleranceUm, motion::msg::Unit::Um),
                                                     motion::msg::real("timeout", m_plan.settleTimeoutS, motion::msg::Unit::S),
                                                     motion::msg::real("off_x", m_lastOffUm[0], motion::msg::Unit::Um),
                                                     motion::msg::real("off_y", m_lastOffUm[1], motion::msg::Unit::Um)}),
                 false);
    });
    m_clientConnections << connect(m_client, &dev::Instrument::eventReceived, this, &ScanRunner::onEvent);
    m_clientConnections << connect(m_client, &dev::Instrument::statusChanged, this, [this](const dev::InstrumentStatus& s) {
        if (m_phase == Phase::Moving)
            checkArrivedByStatus(s);
        if (m_phase != Phase::Settling || s.axes.size() < 2)
            return;
        checkSettled({s.axes[0].measured, s.axes[1].measured}, s.deviceTimeUs);
    });
    // The stage model is taken once per prepare and again only when the device reports
    // other limits, so preflight and the lead-in check what the device has now.
    const auto retakeStageModel = [this] {
        if (m_prepared)
            m_stageModel = stageModelOf(m_client->identity(), m_client->softLimits());
    };
    m_clientConnections << connect(m_client, &dev::Instrument::identified, this, retakeStageModel);
    m_clientConnections << connect(m_client, &dev::Instrument::limitsChanged, this, retakeStageModel);
    m_clientConnections << connect(m_client, &dev::Instrument::stateChanged, this, [this](dev::LinkState st) {
        if (st != dev::LinkState::Ready && isActive())
            stopWith(motion::msg::make("scan.run.link_lost", {tileArg(currentTile())}), false);
    });
}

ScanRunner::~ScanRunner()
{
    for (const auto& c : m_clientConnections)
        disconnect(c);
}

void ScanRunner::refreshCompensation()
{
    m_compEnabled[0].reset();
    m_compEnabled[1].reset();
    if (!m_plan.compensation.enabled || !m_client)
        return;
    dev::CompensationClient* comp = m_client->compensation();
    if (!comp || !m_client->can(dev::Capability::Compensation))
        return;
    if (m_compWatched != comp) {
        m_compWatched = comp;
        connect(comp, &dev::CompensationClient::changed, this, [this](int axis, const QString&) {
            if (axis == 0 || axis == 1)
                refreshCompensation();
        });
    }
    const QPointer<ScanRunner> self(this);
    for (int axis = 0; axis < 2; ++axis)
        comp->read(axis, [self, axis](const std::optional<dev::RequestError>& e, const dev::AxisCompensation& c) {
            if (self && !e)
                self->m_compEnabled[axis] = c.model.has_value() && c.enabled;
        });
}

QString ScanRunner::logPath() const { return QDir(m_folder).filePath(QString::fromLatin1(dev::files::scan::kRunLogFile)); }

motion::msg::Arg ScanRunner::tileArg(int tile) const
{
    if (tile < 0 || tile >= totalTiles())
        return motion::msg::nested("tile", motion::msg::make("scan.run.the_start"));
    return motion::msg::nested("tile", motion::msg::make("scan.run.tile", {motion::msg::integer("tile", tile + 1, motion::msg::Unit::None), motion::msg::integer("total", totalTiles()),
                                                           motion::msg::verbatim("label", m_records[static_cast<std::size_t>(tile)].label)}));
}

const char* ScanRunner::stateTerm(State s)
{
    switch (s) {
    case State::Idle: return "scan.state.idle";
    case State::Running: return "scan.state.running";
    case State::Pausing: return "scan.state.pausing";
    case State::Paused: return "scan.state.paused";
    case State::Stopped: return "scan.state.stopped";
    case State::Finished: return "scan.state.finished";
    }
    return "scan.state.idle";
}

void ScanRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

bool ScanRunner::prepare(const motion::scan::ScanPlan& plan, const QString& folder, bool restart, motion::msg::Message* error, Refusal* why)
{
    Refusal unused;
    Refusal& reason = why ? *why : unused;
    reason = Refusal::Other;  // every early return below is "something else"
    if (isActive()) {
        *error = motion::msg::make("scan.run.busy_preparing");
        return false;
    }
    const auto problems = motion::scan::validate(plan);
    if (!problems.empty()) {
        *error = motion::msg::make("scan.run.plan_problem", {motion::msg::verbatim("field", problems.front().path), motion::msg::nested("cause", problems.front().message)});
        return false;
    }
    if (!QDir().mkpath(folder)) {
        *error = motion::msg::make("file.cannot_make_folder", {motion::msg::verbatim("folder", folder.toStdString())});
        return false;
    }
    m_log.close();
    m_prepared = false;
    m_plan = plan;
    m_folder = folder;
    m_layout = motion::scan::layoutScan(plan);
    m_records = dev::files::scan::plannedRecords(plan, m_layout);
    m_images.assign(m_layout.tiles.size(), {});
    m_finishWhenWritten = false;
    m_taken.assign(m_layout.tiles.size(), 0);
    m_takenCount = 0;
    m_phase = Phase::None;
    const std::uint64_t fingerprint = motion::scan::layoutFingerprint(plan, m_layout);

    bool fresh = true;
    if (QFileInfo::exists(logPath()) && !adoptRunLog(fingerprint, restart, &fresh, error, &reason))
        return false;
    if (fresh && !dev::files::writeAtomically(logPath(), dev::files::scan::runLogHeader(m_plan.name, fingerprint, totalTiles()), error))
        return false;
    m_stageModel = stageModelOf(m_client->identity(), m_client->softLimits());
    m_estimate = motion::scan::estimateScan(m_plan, m_layout, m_stageModel);
    addCameraTimeToEstimate();
    m_prepared = true;
    refreshCompensation();
    reason = Refusal::None;
    setState(m_takenCount == totalTiles() ? State::Finished : State::Idle);
    emit progress(m_takenCount, totalTiles(), etaS());
    return true;
}

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

Point2 ScanRunner::commanded(int pathIndex) const
{
    return motion::scan::commandedTarget(m_plan, m_layout.path[static_cast<std::size_t>(pathIndex)].target);
}

std::vector<motion::msg::Message> ScanRunner::preflight() const
{
    std::vector<motion::msg::Message> out;
    if (!m_prepared) {
        out.push_back(motion::msg::make("scan.run.not_prepared"));
        return out;
    }
    if (!m_client->isReady()) {
        out.push_back(motion::msg::make("scan.run.not_connected"));
        return out;
    }
    const auto& id = m_client->identity();
    if (id.kind != dev::proto::DeviceKind::Stage || id.axes.size() < 2) {
        out.push_back(motion::msg::make("scan.run.not_a_stage", {motion::msg::term("instrument", dev::instrumentTerm(id.kind))}));
        return out;
    }
    const auto& st = m_client->status();
    if (st.estop)
        out.push_back(motion::msg::make("scan.run.estop_latched"));
    if (st.axes.size() >= 2 && (!st.axes[0].homed || !st.axes[1].homed))
        out.push_back(motion::msg::make("scan.run.not_homed"));
    if (m_plan.compensation.enabled) {
        // The plan trusts the stage to move each target by its own correction.
        if (!m_client->can(dev::Capability::Compensation) || !m_client->compensation())
            out.push_back(motion::msg::make("scan.run.no_compensation_on_stage"));
        else
            for (int axis = 0; axis < 2; ++axis) {
                const motion::msg::Arg letter = motion::msg::verbatim("axis", axis == 0 ? "X" : "Y");
                if (!m_compEnabled[axis])
                    out.push_back(motion::msg::make("scan.run.compensation_being_read", {letter}));
                else if (!*m_compEnabled[axis])
                    out.push_back(motion::msg::make("scan.run.compensation_not_enabled", {letter}));
            }
    }
    // The whole plan against the device's travel and soft limits, before anything moves.
    for (const auto& p : motion::scan::validate(m_plan, m_stageModel))
        out.push_back(motion::msg::make("scan.run.plan_problem", {motion::msg::verbatim("field", p.path), motion::msg::nested("cause", p.message)}));
    return out;
}

int ScanRunner::waypointToResumeAt() const
{
    for (std::size_t k = 0; k < m_layout.path.size(); ++k) {
        const int tile = m_layout.path[k].tile;
        if (tile < 0 || m_taken[static_cast<std::size_t>(tile)])
            continue;
        // Come in through the tile's own overtravel point when it has one.
        if (k > 0 && m_layout.path[k - 1].tile < 0)
            return static_cast<int>(k - 1);
        return static_cast<int>(k);
    }
    return static_cast<int>(m_layout.path.size());
}

bool ScanRunner::start(motion::msg::Message* error)
{
    if (isActive()) {
        *error = motion::msg::make("scan.run.already_running");
        return false;
    }
    const std::vector<motion::msg::Message> blockers = preflight();
    if (!blockers.empty()) {
        *error = blockers.front();
        return false;
    }
    if (m_camera && !m_camera->begin(m_plan, m_folder.toStdString(), error))
        return false;
    if (!openLog(error))
        return false;
    m_pathIndex = waypointToResumeAt();
    m_extraApproach.reset();
    // Where the stage was left is unknown after a stop: a unidirectional plan comes
    // in to its next tile from the overtravel point whether or not the path has one there.
    if (m_plan.approach.unidirectional && m_pathIndex < static_cast<int>(m_layout.path.size())
        && m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile >= 0) {
        const Point2 over = motion::scan::overtravelPoint(m_layout, m_plan, m_layout.path[static_cast<std::size_t>(m_pathIndex)].target);
        m_extraApproach = motion::scan::commandedTarget(m_plan, over);
        if (!m_stageModel.travel.contains(*m_extraApproach))
            m_extraApproach.reset();  // at the edge of travel: the direct move is the best there is
    }
    m_sessionFirstTaken = m_takenCount;
    m_sessionFirstTile = -1;
    // The estimate starts at the first tile; this session starts wherever the stage
    // stands, so the move there counts towards the time left.
    const auto& st = m_client->status();
    const Point2 from = st.axes.size() >= 2 ? Point2{st.axes[0].commanded, st.axes[1].commanded} : Point2{};
    const Point2 firstTarget = m_extraApproach ? *m_extraApproach
                                               : (m_pathIndex < static_cast<int>(m_layout.path.size()) ? commanded(m_pathIndex) : from);
    m_leadInS = motion::scan::moveTimeS(from, firstTarget, m_plan.speedMmS, m_stageModel);
    if (m_extraApproach && m_pathIndex < static_cast<int>(m_layout.path.size()))
        m_leadInS += motion::scan::moveTimeS(*m_extraApproach, commanded(m_pathIndex), m_plan.speedMmS, m_stageModel);
    setState(State::Running);
    nextWaypoint();
    return true;
}

void ScanRunner::pause()
{
    if (m_state == State::Running)
        setState(State::Pausing);
}

void ScanRunner::abort()
{
    if (!isActive())
        return;
    stopWith(motion::msg::make("scan.run.aborted", {tileArg(currentTile())}), true);
}

int ScanRunner::currentTile() const
{
    if (m_pathIndex < 0 || m_pathIndex >= static_cast<int>(m_layout.path.size()))
        return -1;
    // An overtravel point belongs to the tile after it.
    for (std::size_t k = static_cast<std::size_t>(m_pathIndex); k < m_layout.path.size(); ++k)
        if (m_layout.path[k].tile >= 0)
            return m_layout.path[k].tile;
    return -1;
}

double ScanRunner::etaS() const
{
    if (m_layout.tiles.empty())
        return 0;
    int lastTaken = -1;
    for (int t = totalTiles() - 1; t >= 0; --t)
        if (m_taken[static_cast<std::size_t>(t)]) {
            lastTaken = t;
            break;
        }
    double remaining = m_estimate.totalS - (lastTaken >= 0 ? m_estimate.tileDoneS[static_cast<std::size_t>(lastTaken)] : 0.0);
    if (isActive() && m_takenCount == m_sessionFirstTaken)
        remaining += m_leadInS;  // still on the way to the first tile of this session
    // Once a few tiles of this session are taken, the run's own pace corrects the
    // estimate: trigger to trigger on the device's clock against the estimate for
    // the same stretch. The exposures at both ends cancel out, and neither a busy
    // host nor a simulator on a sped-up or stepped clock skews it.
    if (isActive() && m_sessionFirstTile >= 0 && lastTaken > m_sessionFirstTile && m_takenCount - m_sessionFirstTaken >= kScanPaceMinTiles) {
        const auto first = static_cast<std::size_t>(m_sessionFirstTile), last = static_cast<std::size_t>(lastTaken);
        const double estimated = m_estimate.tileDoneS[last] - m_estimate.tileDoneS[first];
        const quint64 fromUs = m_records[first].deviceTimeUs, toUs = m_records[last].deviceTimeUs;
        if (estimated > kScanPaceMinStretchS && toUs > fromUs)
            return remaining * std::clamp(static_cast<double>(toUs - fromUs) * kScanSecondsPerUs / estimated, kScanPaceMinFactor,
                                           kScanPaceMaxFactor);
    }
    return remaining;
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

void ScanRunner::nextWaypoint()
{
    if (m_state == State::Pausing) {
        m_phase = Phase::None;
        setState(State::Paused);
        return;
    }
    if (m_state != State::Running)
        return;
    // A resumed run may have holes (tiles whose images were taken again): tiles already
    // taken are passed over, with the overtravel points that lead to them.
    while (m_pathIndex < static_cast<int>(m_layout.path.size())) {
        const int tile = currentTile();
        if (tile < 0 || !m_taken[static_cast<std::size_t>(tile)])
            break;
        while (m_pathIndex < static_cast<int>(m_layout.path.size()) && m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile != tile)
            ++m_pathIndex;
        ++m_pathIndex;
    }
    if (m_pathIndex >= static_cast<int>(m_layout.path.size())) {
        m_phase = Phase::None;
        if (m_camera && m_camera->pendingWrites() > 0) {
            m_finishWhenWritten = true;  // the last images are still being written
            return;
        }
        finishRun();
        return;
    }
    m_onExtra = m_extraApproach.has_value();
    const Point2 target = m_onExtra ? *m_extraApproach : commanded(m_pathIndex);
    m_phase = Phase::Moving;
    m_waitingAxes = kBothAxes;
    m_motionDoneUs = 0;
    m_moveTarget = target;
    m_moveAccepted = false;
    m_restPolls = 0;
    // Listening for MotionDone starts before the request goes out: a move of zero
    // length reports done at once.
    // The client keeps a callback until the device answers, which may be after this
    // object is gone (a window closed, a run dropped): it must not reach a dead one.
    const QPointer<ScanRunner> self(this);
    m_client->move({{0, target.xMm}, {1, target.yMm}}, false, m_plan.speedMmS, [self](const std::optional<dev::RequestError>& e) {
        if (self)
            self->onMoveAccepted(e);
    });
}

void ScanRunner::finishRun()
{
    m_finishWhenWritten = false;
    m_log.close();
    QStringList written;
    motion::msg::Message error;
    if (!writeExports(&written, &error))
        emit problem(motion::msg::make("scan.run.exports_failed", {motion::msg::nested("cause", error)}));
    setState(State::Finished);
    emit progress(m_takenCount, totalTiles(), 0);
    emit finished(written);
}

void ScanRunner::onMoveAccepted(const std::optional<dev::RequestError>& error)
{
    if (m_phase != Phase::Moving)
        return;
    if (!error) {
        m_moveAccepted = true;
        return;
    }
    // A move lost with the link is the link's story, whichever signal comes first.
    if (error->kind == dev::RequestError::Kind::LinkDown || error->kind == dev::RequestError::Kind::Timeout || !m_client->isReady())
        stopWith(motion::msg::make("scan.run.link_lost_cause", {tileArg(currentTile()), motion::msg::nested("cause", error->message)}), false);
    else
        stopWith(motion::msg::make("scan.run.move_refused", {tileArg(currentTile()), motion::msg::nested("cause", error->message)}), false);
}

void ScanRunner::onEvent(const dev::DeviceEvent& e)
{
    if (m_phase == Phase::None)
        return;
    using dev::proto::EventKind;
    switch (e.kind) {
    case EventKind::MotionDone:
        if (m_phase != Phase::Moving || e.axis < 0 || e.axis > 1)
            return;
        m_waitingAxes &= ~(1u << e.axis);
        m_motionDoneUs = std::max<quint64>(m_motionDoneUs, e.deviceTimeUs);
        if (m_waitingAxes)
            return;
        onMoveArrived();
        return;
    case EventKind::EStop:
        stopWith(motion::msg::make("scan.run.estop", {tileArg(currentTile())}), false);
        return;
    case EventKind::Stopped:
    case EventKind::LimitHit:
    case EventKind::Fault:
    case EventKind::LostSteps:
        if (e.axis <= 1)
            stopWith(motion::msg::make("scan.run.stage_event", {motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e),
                                                        tileArg(currentTile())}),
                     false);
        return;
    default:
        return;
    }
}

void ScanRunner::onMoveArrived()
{
    if (m_onExtra) {
        m_extraApproach.reset();
        m_onExtra = false;
        nextWaypoint();
        return;
    }
    if (m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile < 0) {
        ++m_pathIndex;  // an overtravel point: on to its tile
        nextWaypoint();
        return;
    }
    m_phase = Phase::Settling;
    m_lastOffUm[0] = m_lastOffUm[1] = NAN;
    m_settleTimeout.start(static_cast<int>(std::lround(m_plan.settleTimeoutS * kScanMsPerS)));
    requestStatus();
}

void ScanRunner::checkArrivedByStatus(const dev::InstrumentStatus& s)
{
    // Only readings that came after the move's reply count (the queue answers in order,
    // so they were taken after the move began); two in a row at rest on the target
    // are an arrival whose MotionDone the line lost.
    if (!m_moveAccepted || s.axes.size() < 2)
        return;
    const bool there = !s.axes[0].moving && !s.axes[1].moving && std::fabs(s.axes[0].commanded - m_moveTarget.xMm) < kScanAtTargetMm
        && std::fabs(s.axes[1].commanded - m_moveTarget.yMm) < kScanAtTargetMm;
    if (!there) {
        m_restPolls = 0;
        return;
    }
    if (m_restPolls++ == 0)
        m_motionDoneUs = std::max<quint64>(m_motionDoneUs, s.deviceTimeUs);
    if (m_restPolls < kScanRestPollsForArrival)
        return;
    m_waitingAxes = 0;
    onMoveArrived();
}

void ScanRunner::requestStatus()
{
    // An immediate reading rather than the next 50 ms poll: the tile is taken the
    // moment the grating says so. If it is not there yet, the polls that follow
    // (statusChanged) are checked until it is, or the settle timeout says why not.
    const QPointer<ScanRunner> self(this);
    m_client->readStatus([this, self](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || e || m_phase != Phase::Settling || s.axes.size() < 2)
            return;
        checkSettled({s.axes[0].measured, s.axes[1].measured}, s.deviceTimeUs);
    });
}

void ScanRunner::checkSettled(const std::vector<double>& measuredMm, quint64 deviceTimeUs)
{
    if (m_phase != Phase::Settling)
        return;
    const Point2 target = commanded(m_pathIndex);
    m_lastOffUm[0] = (measuredMm[0] - target.xMm) * kScanUmPerMm;
    m_lastOffUm[1] = (measuredMm[1] - target.yMm) * kScanUmPerMm;
    if (std::fabs(m_lastOffUm[0]) > m_plan.toleranceUm || std::fabs(m_lastOffUm[1]) > m_plan.toleranceUm)
        return;
    if (deviceTimeUs < m_motionDoneUs)
        return;  // a reading older than the move's end says nothing about the tile
    m_settleTimeout.stop();
    m_phase = Phase::Exposing;
    m_triggerMm = measuredMm;
    m_triggerUs = deviceTimeUs;
    const int tile = m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile;
    emit triggered(tile, deviceTimeUs);
    // A camera on the instrument's trigger output sees the output held for the exposure:
    // its rising edge starts an edge-triggered camera, its length times a level-triggered one.
    if (m_client->can(dev::Capability::TriggerOutput))
        m_client->pulseTrigger(m_plan.exposureS);
    if (m_camera) {
        takeWithCamera(tile);
        return;
    }
    m_exposure.start(static_cast<int>(std::lround(m_plan.exposureS * kScanMsPerS)));
}

void ScanRunner::onExposureEnd()
{
    if (m_phase != Phase::Exposing)
        return;
    const int tile = m_layout.path[static_cast<std::size_t>(m_pathIndex)].tile;
    motion::PositionRecord& r = m_records[static_cast<std::size_t>(tile)];
    r.measuredMm = m_triggerMm;
    r.deviceTimeUs = m_triggerUs;
    r.settleS = m_triggerUs > m_motionDoneUs ? static_cast<double>(m_triggerUs - m_motionDoneUs) * kScanSecondsPerUs : 0.0;
    motion::msg::Message error;
    if (!appendLog(dev::files::scan::runLogLine(r), &error)) {
        r.measuredMm.clear();
        stopWith(motion::msg::make("scan.run.log_failed", {motion::msg::nested("cause", error)}), false);
        return;
    }
    if (!m_taken[static_cast<std::size_t>(tile)]) {
        m_taken[static_cast<std::size_t>(tile)] = 1;
        ++m_takenCount;
    }
    if (m_sessionFirstTile < 0)
        m_sessionFirstTile = tile;
    m_phase = Phase::None;
    ++m_pathIndex;
    emit tileTaken(tile);
    emit progress(m_takenCount, totalTiles(), etaS());
    nextWaypoint();
}

void ScanRunner::stopWith(const motion::msg::Message& message, bool stopStage)
{
    m_exposure.stop();
    m_settleTimeout.stop();
    m_cameraTimeout.stop();
    m_finishWhenWritten = false;
    m_phase = Phase::None;
    m_extraApproach.reset();
    m_onExtra = false;
    if (stopStage && m_client->isReady())
        m_client->stop(0);
    setState(State::Stopped);
    emit problem(message);
    emit progress(m_takenCount, totalTiles(), etaS());
}

bool ScanRunner::writeExports(QStringList* written, motion::msg::Message* error) const
{
    if (!m_prepared) {
        *error = motion::msg::make("scan.run.not_prepared");
        return false;
    }
    return dev::files::scan::writeExports(m_folder, m_plan, m_layout, m_records, written, error);
}

} // namespace dev::jobs
