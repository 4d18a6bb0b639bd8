#include "device/jobs/recipe_runner.h"

#include "device/files/text_file.h"

#include <QFileInfo>
#include <QPointer>

#include <algorithm>
#include <cmath>
#include <memory>

namespace dev::jobs {

using motion::plates::MachineMove;
using motion::plates::MoveKind;
using dev::files::plates::OpState;

namespace {
constexpr double kSameMm = 1e-6;

const char* moveTerm(MoveKind k)
{
    switch (k) {
    case MoveKind::Raise: return "recipe.move.raise";
    case MoveKind::Travel: return "recipe.move.travel";
    case MoveKind::Lower: return "recipe.move.lower";
    case MoveKind::Pump: return "recipe.move.pump";
    case MoveKind::Touch: return "recipe.move.touch";
    case MoveKind::Dwell: return "recipe.move.dwell";
    }
    return "recipe.move.travel";
}

motion::msg::Arg recipeMm(std::string name, double v) { return motion::msg::real(std::move(name), v, motion::msg::Unit::Mm); }
motion::msg::Arg recipeUl(std::string name, double v) { return motion::msg::real(std::move(name), v, motion::msg::Unit::Ul); }
} // namespace

bool runActive(RunState s) { return s == RunState::Running || s == RunState::Pausing || s == RunState::Aborting; }

const char* runStateTerm(RunState s)
{
    switch (s) {
    case RunState::Idle: return "recipe.state.idle";
    case RunState::Running: return "recipe.state.running";
    case RunState::Pausing: return "recipe.state.pausing";
    case RunState::Paused: return "recipe.state.paused";
    case RunState::Aborting: return "recipe.state.aborting";
    case RunState::Stopped: return "recipe.state.stopped";
    case RunState::Finished: return "recipe.state.finished";
    }
    return "recipe.state.idle";
}

motion::msg::Arg RecipeRunner::opArg(int op) const
{
    return motion::msg::nested("op", op >= 0 && op < static_cast<int>(m_plan.ops.size()) ? m_plan.ops[static_cast<std::size_t>(op)].label()
                                                                              : motion::msg::make("recipe.run.the_run"));
}

RecipeRunner::RecipeRunner(dev::Instrument* client, QObject* parent) : QObject(parent), m_client(client)
{
    qRegisterMetaType<dev::jobs::RunState>();
    m_moveTimer.setSingleShot(true);
    m_dwellTimer.setSingleShot(true);
    connect(&m_moveTimer, &QTimer::timeout, this, &RecipeRunner::onMoveTimeout);
    connect(&m_dwellTimer, &QTimer::timeout, this, [this] { checkDwell(false); });
    m_events = connect(client, &dev::Instrument::eventReceived, this, &RecipeRunner::onEvent);
    m_link = connect(client, &dev::Instrument::stateChanged, this, &RecipeRunner::onLinkState);
    // A MotionDone lost on a noisy line would leave the move to its watchdog (seconds per
    // move at 1 % of bytes damaged). The status is polled anyway: two readings after the
    // move's reply with the axes at rest on the target are the arrival. Events and replies
    // share one ordered stream, so a MotionDone that was not lost came before them.
    auto restReadings = std::make_shared<std::pair<int, int>>(-1, 0);  // move serial, readings at rest
    connect(client, &dev::Instrument::statusChanged, this, [this, restReadings](const dev::InstrumentStatus& st) {
        if (runActive(m_state) && st.deviceTimeUs > m_deviceLastUs)
            m_deviceLastUs = st.deviceTimeUs;
        if (m_budgetStartPending && m_replied) {
            m_moveSentUs = st.deviceTimeUs;
            m_budgetStartPending = false;
        }
        if (!runActive(m_state) || !m_inFlight || m_inFlight->kind == MoveKind::Dwell || !m_replied || m_waitMask == 0)
            return;
        if (restReadings->first != m_moveSerial)
            *restReadings = {m_moveSerial, 0};
        const MachineMove& m = *m_inFlight;
        auto at = [&](char c, double v) {
            const int i = axis(c);
            return i >= 0 && i < st.axes.size() && !st.axes[i].moving && std::abs(st.axes[i].commanded - v) < 1e-3;
        };
        bool there = false;
        if (m.kind == MoveKind::Raise || m.kind == MoveKind::Lower)
            there = at('Z', m.zMm);
        else if (m.kind == MoveKind::Pump)
            there = at('P', m_pumpUl + m.pumpDeltaUl);
        else if (m.archPump)
            there = at('X', m.xMm) && at('Y', m.yMm) && at('Z', m.leaveZMm) && at('P', m_pumpUl + m.pumpDeltaUl);
        else
            there = at('X', m.xMm) && at('Y', m.yMm) && (!m.withZ || at('Z', m.zMm));
        if (!there || st.anyMoving()) {
            restReadings->second = 0;
            return;
        }
        if (++restReadings->second < 2)
            return;
        emit message(motion::msg::make("recipe.run.motion_done_lost", {motion::msg::term("move", moveTerm(m.kind))}), false);
        m_waitMask = 0;
        moveArrived();
    });
}

RecipeRunner::~RecipeRunner()
{
    disconnect(m_events);
    disconnect(m_link);
}

int RecipeRunner::axis(char letter) const { return m_client->identity().axisIndex(QChar::fromLatin1(letter)); }

double RecipeRunner::plungerNow() const
{
    const int p = axis('P');
    return p >= 0 && p < m_client->status().axes.size() ? m_client->status().axes[p].commanded : 0.0;
}

bool RecipeRunner::setPlan(const motion::plates::RecipePlan& plan, const QString& recipeName, motion::msg::Message* error)
{
    if (runActive(m_state) || m_state == RunState::Paused) {
        *error = motion::msg::make("recipe.run.busy_changing");
        return false;
    }
    if (!plan.ok()) {
        for (const auto& p : plan.problems)
            if (p.isError()) {
                *error = motion::msg::make("recipe.run.does_not_validate", {motion::msg::verbatim("field", p.path), motion::msg::nested("cause", p.message)});
                break;
            }
        return false;
    }
    m_plan = plan;
    m_recipeName = recipeName;
    m_opStates.assign(plan.ops.size(), OpState::NotStarted);
    m_op = -1;
    m_log.close();
    setState(RunState::Idle);
    emit progressChanged();
    return true;
}

bool RecipeRunner::checkMachine(motion::msg::Message* error) const
{
    if (!m_client->isReady()) {
        *error = motion::msg::make("recipe.run.not_connected");
        return false;
    }
    const auto& id = m_client->identity();
    if (id.kind != dev::proto::DeviceKind::Analyzer || axis('X') < 0 || axis('Y') < 0 || axis('Z') < 0 || axis('P') < 0) {
        *error = motion::msg::make("recipe.run.not_an_analyzer", {motion::msg::term("instrument", dev::instrumentTerm(id.kind))});
        return false;
    }
    const auto& st = m_client->status();
    if (st.estop) {
        *error = motion::msg::make("recipe.run.estop_latched");
        return false;
    }
    for (char c : {'X', 'Y', 'Z', 'P'}) {
        const int i = axis(c);
        if (i >= st.axes.size() || !st.axes[i].homed) {
            *error = motion::msg::make("recipe.run.not_homed", {motion::msg::verbatim("axis", std::string(1, c))});
            return false;
        }
    }
    if (st.anyMoving()) {
        *error = motion::msg::make("recipe.run.still_moving");
        return false;
    }
    return true;
}

bool RecipeRunner::preflight(motion::msg::Message* error) const
{
    // Every target of the ops still to do against the device's soft limits, so a
    // run never stops half-way on a refusal it could have foreseen.
    const auto& limits = m_client->softLimits();
    const int ix = axis('X'), iy = axis('Y'), iz = axis('Z'), ip = axis('P');
    if (limits.size() <= std::max({ix, iy, iz, ip}))
        return true;  // not known yet: the device still refuses what is out of range
    auto outside = [&](int a, double v) { return v < limits[a].min - 1e-6 || v > limits[a].max + 1e-6; };

    double p = plungerNow(), pMin = p, pMax = p;
    for (std::size_t k = static_cast<std::size_t>(std::max(0, nextOpenOp(0))); k < m_plan.ops.size(); ++k) {
        const motion::plates::PlanOp& op = m_plan.ops[k];
        if (dev::files::plates::isClosed(m_opStates[k]))
            continue;
        const motion::msg::Arg what = motion::msg::nested("op", op.label());
        for (const MachineMove& m : op.moves) {
            if ((m.kind == MoveKind::Travel || m.kind == MoveKind::Touch) && (outside(ix, m.xMm) || outside(iy, m.yMm))) {
                *error = motion::msg::make("recipe.run.xy_beyond_limits", {what, recipeMm("x", m.xMm), recipeMm("y", m.yMm), recipeMm("x_min", limits[ix].min),
                                                                   recipeMm("x_max", limits[ix].max), recipeMm("y_min", limits[iy].min), recipeMm("y_max", limits[iy].max)});
                return false;
            }
            if ((m.kind == MoveKind::Raise || m.kind == MoveKind::Lower || m.withZ) && outside(iz, m.zMm)) {
                *error = motion::msg::make("recipe.run.z_beyond_limits", {what, recipeMm("z", m.zMm), recipeMm("min", limits[iz].min), recipeMm("max", limits[iz].max)});
                return false;
            }
            if (m.kind == MoveKind::Pump || m.archPump) {
                p += m.pumpDeltaUl;
                pMin = std::min(pMin, p);
                pMax = std::max(pMax, p);
            }
        }
    }
    if (outside(ip, pMin) || outside(ip, pMax)) {
        *error = motion::msg::make(pMax > limits[ip].max ? "recipe.run.plunger_beyond_limits_full" : "recipe.run.plunger_beyond_limits_empty",
                           {recipeUl("from", pMin), recipeUl("to", pMax), recipeUl("now", plungerNow()), recipeUl("min", limits[ip].min), recipeUl("max", limits[ip].max)});
        return false;
    }
    return true;
}

void RecipeRunner::setState(RunState s)
{
    if (s == m_state)
        return;
    if (runActive(m_state) && !runActive(s)) {
        m_elapsedBeforeS += m_clock.elapsed() / 1000.0;
        m_deviceBeforeS += static_cast<double>(m_deviceLastUs - std::min(m_deviceStartUs, m_deviceLastUs)) / 1e6;
    }
    if (!runActive(m_state) && runActive(s)) {
        m_clock.restart();
        m_deviceStartUs = m_deviceLastUs = m_client->status().deviceTimeUs;
    }
    m_state = s;
    emit stateChanged(s);
    emit progressChanged();
}

bool RecipeRunner::logLine(dev::files::json::Value line)
{
    if (m_log.write(std::move(line)))
        return true;
    const motion::msg::Message why = m_log.lastError();
    m_log.close();
    stopRun(motion::msg::make("recipe.run.log_failed", {motion::msg::nested("cause", why)}));
    return false;
}

int RecipeRunner::nextOpenOp(int from) const
{
    for (int i = std::max(0, from); i < static_cast<int>(m_opStates.size()); ++i)
        if (!dev::files::plates::isClosed(m_opStates[static_cast<std::size_t>(i)]))
            return i;
    return static_cast<int>(m_opStates.size());
}

bool RecipeRunner::start(const QString& logPath, motion::msg::Message* error)
{
    if (runActive(m_state) || m_state == RunState::Paused) {
        *error = motion::msg::make("recipe.run.already_running");
        return false;
    }
    if (m_plan.ops.empty()) {
        *error = motion::msg::make("recipe.run.no_recipe");
        return false;
    }
    m_opStates.assign(m_plan.ops.size(), OpState::NotStarted);
    if (!checkMachine(error) || !preflight(error))
        return false;
    if (!m_log.create(logPath, error))
        return false;
    dev::files::json::Value head = dev::files::json::schemaObject(dev::files::plates::kRunLogSchema, dev::files::plates::kRunLogVersion);
    head.set("event", "run");
    head.set("recipe", m_recipeName.toStdString());
    head.set("fingerprint", motion::plates::fingerprintHex(m_plan.fingerprint));
    head.set("ops", static_cast<int>(m_plan.ops.size()));
    head.set("p_ul", plungerNow());
    // The order each step's wells were planned in: the ops above follow it, and the
    // fingerprint (which covers each op's well) holds a resume to it.
    dev::files::json::Value orders = dev::files::json::Value::array();
    for (motion::plates::WellOrder o : m_plan.orders)
        orders.push(motion::plates::wellOrderName(o));
    head.set("orders", std::move(orders));
    if (!m_log.write(head)) {
        *error = m_log.lastError();
        m_log.close();
        return false;
    }
    m_elapsedBeforeS = 0;
    m_deviceBeforeS = 0;
    m_op = 0;
    m_move = 0;
    m_pumpLogged = false;
    m_knowXy = m_knowZ = false;
    m_deferredFrom = -1;
    m_pumpUl = plungerNow();
    emit message(motion::msg::make("recipe.run.started", {motion::msg::verbatim("recipe", m_recipeName.toStdString()),
                                                  motion::msg::integer("ops", static_cast<long long>(m_plan.ops.size())),
                                                  motion::msg::real("time", std::round(m_plan.totalTimeS), motion::msg::Unit::S),
                                                  motion::msg::verbatim("log", QFileInfo(logPath).fileName().toStdString())}),
                 false);
    beginRunning();
    return true;
}

void RecipeRunner::beginRunning(bool newSession)
{
    const auto& id = m_client->identity();
    m_runInstrument = (id.model + QLatin1Char(' ') + id.firmware).trimmed().toStdString();
    m_pauseAsked = false;
    if (newSession) {
        m_plannedDoneS = 0;
        m_sessionStartS = m_elapsedBeforeS;
    }
    setState(RunState::Running);
    QTimer::singleShot(0, this, &RecipeRunner::nextMove);
}

void RecipeRunner::pause()
{
    if (m_state != RunState::Running)
        return;
    m_pauseAsked = true;
    setState(RunState::Pausing);
}

void RecipeRunner::nextMove()
{
    if (m_state != RunState::Running && m_state != RunState::Pausing)
        return;
    if (m_inFlight)
        return;
    if (m_op >= static_cast<int>(m_plan.ops.size())) {
        dev::files::json::Value v = dev::files::json::Value::object();
        v.set("event", "finished");
        logLine(std::move(v));
        m_log.close();
        setState(RunState::Finished);
        emit message(motion::msg::make("recipe.run.finished", {motion::msg::verbatim("recipe", m_recipeName.toStdString()),
                                                       motion::msg::integer("ops", static_cast<long long>(m_plan.ops.size()))}),
                     false);
        emit finished(true);
        return;
    }
    const motion::plates::PlanOp& op = m_plan.ops[static_cast<std::size_t>(m_op)];
    if (m_move == 0 && m_opStates[static_cast<std::size_t>(m_op)] == OpState::NotStarted) {
        dev::files::json::Value v = dev::files::json::Value::object();
        v.set("event", "start");
        v.set("op", m_op);
        v.set("step", op.step);
        v.set("kind", motion::plates::stepTypeName(op.type));
        if (!op.plate.empty())
            v.set("plate", op.plate);
        if (!op.well.empty())
            v.set("well", op.well);
        if (!op.station.empty())
            v.set("station", op.station);
        v.set("volume_ul", op.volumeUl);
        if (!logLine(std::move(v)))
            return;
        m_opStates[static_cast<std::size_t>(m_op)] = OpState::Started;
        emit opStarted(m_op);
        emit progressChanged();
    }
    while (m_move < static_cast<int>(op.moves.size())) {
        const MachineMove& m = op.moves[static_cast<std::size_t>(m_move)];
        if (m.archPump && !canArchPump()) {
            archPumpApart();
            continue;
        }
        if (m.arch && !m_client->can(dev::Capability::ArchedMove)) {
            archAsLegs();
            continue;
        }
        // A raise the next op's arched move makes instead, unless the run halts after this op.
        const bool handOver = m.kind == MoveKind::Raise && m.deferred && m_state == RunState::Running && !m_pauseAsked
            && m_client->can(dev::Capability::ArchedMove) && nextOpenOp(m_op + 1) == m_op + 1;
        if (handOver) {
            m_deferredFrom = m_op;
            ++m_move;
            continue;
        }
        const bool skip = (m.kind == MoveKind::Raise && m_knowZ && m_z <= m.zMm + kSameMm)
            || (m.kind == MoveKind::Lower && m_knowZ && std::abs(m_z - m.zMm) < kSameMm)
            || ((m.kind == MoveKind::Travel || m.kind == MoveKind::Touch) && m_knowXy && std::abs(m_x - m.xMm) < kSameMm
                && std::abs(m_y - m.yMm) < kSameMm && (!m.withZ || (m_knowZ && std::abs(m_z - m.zMm) < kSameMm)) && !m.archPump)
            || (m.kind == MoveKind::Dwell && m.seconds <= 0);
        if (!skip) {
            sendMove(m.arch ? archAsSent(m) : m);
            return;
        }
        ++m_move;
    }
    finishOp();
}

void RecipeRunner::sendMove(const MachineMove& planned)
{
    MachineMove m = planned;
    if (m.kind == MoveKind::Raise && !m_knowZ) {
        // Where Z is has not been commanded by this run yet (a start, a resume):
        // a raise goes no lower than the status says the tip is. Should the
        // status be a poll behind, the tip still ends at or above the safe height.
        const int iz = axis('Z');
        if (iz >= 0 && iz < m_client->status().axes.size())
            m.zMm = std::min(m.zMm, m_client->status().axes[iz].commanded);
    }
    if (m.kind == MoveKind::Raise && !m_knowXy && m_op >= 0 && m_op < static_cast<int>(m_plan.ops.size())) {
        // Not knowing where the tip stands in XY either (a start, a resume), the first
        // raise goes to the op's safe height, which clears whatever it may cross first.
        m.zMm = std::min(m.zMm, m_plan.ops[static_cast<std::size_t>(m_op)].safeZMm);
    }
    if ((m.kind == MoveKind::Pump || m.archPump) && !m_pumpLogged) {
        dev::files::json::Value v = dev::files::json::Value::object();
        v.set("event", "pump");
        v.set("op", m_op);
        v.set("p_ul", m_pumpUl);
        if (!logLine(std::move(v)))
            return;
        m_pumpLogged = true;
        m_pumpStartUl = m_pumpUl;
        m_opStates[static_cast<std::size_t>(m_op)] = OpState::Interrupted;  // until "done"
    }
    m_inFlight = m;
    m_replied = false;
    m_budgetStartPending = false;
    const int serial = ++m_moveSerial;
    if (m.kind == MoveKind::Dwell) {
        checkDwell(true);
        return;
    }
    QVector<QPair<int, double>> targets, zTargets;
    bool relative = false;
    switch (m.kind) {
    case MoveKind::Raise:
    case MoveKind::Lower:
        targets = {{axis('Z'), m.zMm}};
        break;
    case MoveKind::Travel:
    case MoveKind::Touch:
        if (m.arch)
            break;
        targets = {{axis('X'), m.xMm}, {axis('Y'), m.yMm}};
        // Arched travel: Z in a request of its own, so it runs with XY (in one request
        // the analyzer runs Z after XY).
        if (m.withZ)
            zTargets = {{axis('Z'), m.zMm}};
        break;
    case MoveKind::Pump:
        targets = {{axis('P'), m.pumpDeltaUl}};
        relative = true;
        break;
    case MoveKind::Dwell:
        break;
    }
    m_waitMask = 0;
    if (m.arch)
        targets = {{axis('X'), m.xMm}, {axis('Y'), m.yMm}, {axis('Z'), m.zMm}};  // each ends with its MotionDone
    if (m.archPump)
        targets.push_back({axis('P'), m.pumpDeltaUl});
    for (const auto& t : targets + zTargets)
        m_waitMask = static_cast<quint8>(m_waitMask | (1u << t.first));
    m_repliesPending = zTargets.isEmpty() ? 1 : 2;
    m_moveSentUs = m_client->status().deviceTimeUs;
    m_moveTimer.start(kMoveCheckMs);
    // The client keeps the callback until the device answers, which may be after
    // this runner is gone (a window closed mid-run): it must not reach a dead runner.
    const QPointer<RecipeRunner> self(this);
    const auto answered = [this, self, serial](const std::optional<dev::RequestError>& err) {
        if (!self || serial != m_moveSerial || !m_inFlight)
            return;
        if (err && err->kind != dev::RequestError::Kind::Device && err->kind != dev::RequestError::Kind::Invalid) {
            stopRun(linkLostMessage());
            return;
        }
        if (err) {
            stopRun(motion::msg::make("recipe.run.move_refused", {opArg(m_op), motion::msg::nested("cause", err->message)}));
            return;
        }
        if (--m_repliesPending > 0)
            return;
        m_replied = true;
        // The budget runs from the device's yes: a request repeated through a noisy line
        // reaches the device late, and on a sped-up simulator each wall-clock retry costs
        // that many times more of the device's clock. The status in hand may be older still
        // (its polls are repeated too); the first one that comes after the answer was
        // taken after the move began, so its clock starts the budget.
        m_budgetStartPending = true;
        if (m_waitMask == 0)
            moveArrived();
    };
    if (m.arch) {
        m_deferredFrom = -1;
        m_client->archMove({m.xMm, m.yMm, m.clearZMm, m.zMm, m.departMm, m.approachMm, m.speed, m.zSpeed, m.archPump, m.pumpDeltaUl,
                            m.pumpSpeed, m.liquidZMm, m.leaveZMm},
                           answered);
        return;
    }
    m_client->move(targets, relative, m.speed, answered);
    if (!zTargets.isEmpty())
        m_client->move(zTargets, false, m.zSpeed, answered);
}

void RecipeRunner::moveArrived()
{
    m_moveTimer.stop();
    const MachineMove m = *m_inFlight;
    m_inFlight.reset();
    m_waitMask = 0;
    switch (m.kind) {
    case MoveKind::Raise:
    case MoveKind::Lower:
        m_z = m.zMm;
        m_knowZ = true;
        break;
    case MoveKind::Travel:
    case MoveKind::Touch:
        m_x = m.xMm;
        m_y = m.yMm;
        m_knowXy = true;
        if (m.withZ) {
            m_z = m.archPump ? m.leaveZMm : m.zMm;
            m_knowZ = true;
        }
        if (m.archPump)
            m_pumpUl += m.pumpDeltaUl;
        break;
    case MoveKind::Pump:
        m_pumpUl += m.pumpDeltaUl;
        break;
    case MoveKind::Dwell:
        break;
    }
    if (m_state == RunState::Aborting) {
        setState(RunState::Stopped);
        emit message(motion::msg::make("recipe.run.aborted_tip_up", {recipeMm("z", m_z)}), true);
        emit finished(false);
        return;
    }
    ++m_move;
    nextMove();
}

void RecipeRunner::finishOp()
{
    const motion::plates::PlanOp& op = m_plan.ops[static_cast<std::size_t>(m_op)];
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("event", "done");
    v.set("op", m_op);
    v.set("p_ul", m_pumpUl);
    if (!logLine(std::move(v)))
        return;
    m_opStates[static_cast<std::size_t>(m_op)] = OpState::Done;
    m_plannedDoneS += op.durationS;
    emit opFinished(m_op);
    m_op = nextOpenOp(m_op + 1);
    m_move = 0;
    m_pumpLogged = false;
    emit progressChanged();
    if (m_pauseAsked && m_op < static_cast<int>(m_plan.ops.size())) {
        setState(RunState::Paused);
        emit message(motion::msg::make("recipe.run.paused_after", {motion::msg::nested("op", op.label())}), false);
        return;
    }
    nextMove();
}

void RecipeRunner::onEvent(const dev::DeviceEvent& e)
{
    if (!runActive(m_state))
        return;
    // Events carry the device's clock to the microsecond (a status only as often as it is polled).
    if (e.deviceTimeUs > m_deviceLastUs)
        m_deviceLastUs = e.deviceTimeUs;
    using K = dev::proto::EventKind;
    if (e.kind == K::EStop) {
        stopRun(motion::msg::make("recipe.run.estop", {opArg(m_op)}));
        return;
    }
    if (e.kind == K::LostSteps || e.kind == K::Fault) {
        stopRun(motion::msg::make("recipe.run.fault", {motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e)}));
        return;
    }
    if (!m_inFlight || e.axis < 0 || !(m_waitMask & (1u << e.axis)))
        return;
    if (e.kind == K::MotionDone) {
        m_waitMask = static_cast<quint8>(m_waitMask & ~(1u << e.axis));
        if (m_waitMask == 0 && m_replied)
            moveArrived();
    } else if (e.kind == K::Stopped || e.kind == K::LimitHit || e.kind == K::JogExpired) {
        if (m_state == RunState::Aborting)
            return;
        stopRun(motion::msg::make("recipe.run.event_during", {motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e),
                                                      opArg(m_op)}));
    }
}

void RecipeRunner::onMoveTimeout()
{
    if (!m_inFlight || m_inFlight->kind == MoveKind::Dwell)
        return;
    // The budget is counted on the device's clock (the status carries it), so a
    // simulator running slower or faster than the wall clock is judged by its own time.
    const double budgetUs = (m_inFlight->durationS * kMoveTimeFactor + kMoveGraceMs / 1000.0) * 1e6;
    // Unanswered, the move is the client's to settle: it repeats the request until the
    // device answers, or fails it (and the run stops for the link) when the device is silent.
    if (m_client->isReady() && (!m_replied || m_budgetStartPending)) {
        m_moveTimer.start(kMoveCheckMs);
        return;
    }
    if (m_client->isReady() && static_cast<double>(m_client->status().deviceTimeUs - std::min(m_moveSentUs, m_client->status().deviceTimeUs)) < budgetUs) {
        m_moveTimer.start(kMoveCheckMs);
        return;
    }
    // A MotionDone can be lost on a noisy link (events are not retransmitted):
    // the status, polled anyway, says whether the move arrived.
    const auto& st = m_client->status();
    const MachineMove& m = *m_inFlight;
    bool arrived = m_replied && m_client->isReady() && !st.anyMoving();
    auto at = [&](char c, double v) {
        const int i = axis(c);
        return i >= 0 && i < st.axes.size() && std::abs(st.axes[i].commanded - v) < 1e-3;
    };
    if (m.kind == MoveKind::Raise || m.kind == MoveKind::Lower)
        arrived = arrived && at('Z', m.zMm);
    else if (m.kind == MoveKind::Pump)
        arrived = arrived && at('P', m_pumpUl + m.pumpDeltaUl);
    else if (m.archPump)
        arrived = arrived && at('X', m.xMm) && at('Y', m.yMm) && at('Z', m.leaveZMm) && at('P', m_pumpUl + m.pumpDeltaUl);
    else
        arrived = arrived && at('X', m.xMm) && at('Y', m.yMm) && (!m.withZ || at('Z', m.zMm));
    if (arrived) {
        emit message(motion::msg::make("recipe.run.motion_done_lost", {motion::msg::term("move", moveTerm(m.kind))}), false);
        moveArrived();
        return;
    }
    // What the device last said goes in the log beside the stop: a timeout on a line that
    // works is rare enough that whoever reads the log needs the evidence, not a guess.
    dev::files::json::Value seen = dev::files::json::Value::object();
    seen.set("replied", m_replied);
    seen.set("ready", m_client->isReady());
    seen.set("device_s_since_answer", static_cast<double>(st.deviceTimeUs - std::min(m_moveSentUs, st.deviceTimeUs)) / 1e6);
    seen.set("budget_s", budgetUs / 1e6);
    dev::files::json::Value axes = dev::files::json::Value::object();
    for (int i = 0; i < st.axes.size() && i < m_client->identity().axes.size(); ++i) {
        dev::files::json::Value a = dev::files::json::Value::object();
        a.set("commanded", st.axes[i].commanded);
        a.set("measured", st.axes[i].measured);
        a.set("moving", st.axes[i].moving);
        axes.set(QString(m_client->identity().axes[i].letter).toStdString(), std::move(a));
    }
    seen.set("axes", std::move(axes));
    dev::files::json::Value want = dev::files::json::Value::object();
    if (m.kind == MoveKind::Raise || m.kind == MoveKind::Lower)
        want.set("Z", m.zMm);
    else if (m.kind == MoveKind::Pump)
        want.set("P", m_pumpUl + m.pumpDeltaUl);
    else {
        want.set("X", m.xMm);
        want.set("Y", m.yMm);
        if (m.withZ)
            want.set("Z", m.archPump ? m.leaveZMm : m.zMm);
        if (m.archPump)
            want.set("P", m_pumpUl + m.pumpDeltaUl);
    }
    seen.set("expected", std::move(want));
    stopRun(motion::msg::make("recipe.run.move_timeout", {motion::msg::term("move", moveTerm(m.kind)), opArg(m_op)}), std::move(seen));
}

void RecipeRunner::onLinkState(dev::LinkState s)
{
    if (s == dev::LinkState::Ready && m_state == RunState::Stopped && m_op >= 0 && m_op < static_cast<int>(m_plan.ops.size())) {
        emit message(motion::msg::make("recipe.run.back", {opArg(m_op)}), false);
        return;
    }
    if (s != dev::LinkState::Ready && runActive(m_state))
        stopRun(linkLostMessage());
}

motion::msg::Message RecipeRunner::linkLostMessage() const
{
    return motion::msg::make("recipe.run.link_lost", {opArg(m_op)});
}

void RecipeRunner::stopRun(const motion::msg::Message& reason, dev::files::json::Value detail)
{
    m_moveTimer.stop();
    m_dwellTimer.stop();
    m_inFlight.reset();
    m_waitMask = 0;
    ++m_moveSerial;
    if (m_log.isOpen()) {
        dev::files::json::Value v = dev::files::json::Value::object();
        v.set("event", "stop");
        v.set("reason", reason.id);  // the id: a log is read in any language
        if (detail.isObject())
            v.set("device", std::move(detail));
        if (!m_log.write(v))
            m_log.close();
    }
    setState(RunState::Stopped);
    emit message(reason, true);
    emit finished(false);
}

void RecipeRunner::abort()
{
    if (m_state == RunState::Paused) {
        stopRun(motion::msg::make("recipe.run.aborted_while_paused"));
        return;
    }
    if (m_state != RunState::Running && m_state != RunState::Pausing)
        return;
    m_moveTimer.stop();
    m_dwellTimer.stop();
    m_inFlight.reset();
    m_waitMask = 0;
    const int serial = ++m_moveSerial;
    if (m_log.isOpen()) {
        dev::files::json::Value v = dev::files::json::Value::object();
        v.set("event", "stop");
        v.set("reason", "recipe.run.aborted");
        m_log.write(v);
    }
    setState(RunState::Aborting);
    // Stop at once; once everything is still, lift the tip out of the well.
    const QPointer<RecipeRunner> self(this);
    m_client->stop(0, [this, self, serial](const std::optional<dev::RequestError>&) {
        if (!self || serial != m_moveSerial || m_state != RunState::Aborting)
            return;
        auto fresh = std::make_shared<int>(0);
        auto conn = std::make_shared<QMetaObject::Connection>();
        *conn = connect(m_client, &dev::Instrument::statusChanged, this, [this, serial, fresh, conn](const dev::InstrumentStatus& st) {
            if (serial != m_moveSerial || m_state != RunState::Aborting) {
                disconnect(*conn);
                return;
            }
            if (++*fresh < 2 || st.anyMoving())
                return;
            disconnect(*conn);
            const int iz = axis('Z');
            const double safe = m_op >= 0 && m_op < static_cast<int>(m_plan.ops.size()) ? m_plan.ops[static_cast<std::size_t>(m_op)].safeZMm : 0.0;
            if (st.estop || iz < 0 || iz >= st.axes.size() || !st.axes[iz].homed) {
                setState(RunState::Stopped);
                emit message(motion::msg::make("recipe.run.aborted_tip_down"), true);
                emit finished(false);
                return;
            }
            m_z = st.axes[iz].commanded;
            m_knowZ = false;
            m_knowXy = false;
            m_deferredFrom = -1;
            if (m_z <= safe + kSameMm) {
                setState(RunState::Stopped);
                emit message(motion::msg::make("recipe.run.aborted_tip_up", {recipeMm("z", m_z)}), true);
                emit finished(false);
                return;
            }
            MachineMove up;
            up.kind = MoveKind::Raise;
            up.zMm = safe;
            up.durationS = 2;
            sendMove(up);
        });
    });
}

} // namespace dev::jobs
