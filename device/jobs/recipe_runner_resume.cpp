// RecipeRunner: continuing a run that stopped (resume) or that a crash left in
// its log (resumeFromLog), and the progress a screen shows.
#include "device/files/text_file.h"
#include "device/jobs/recipe_runner.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using dev::files::plates::OpState;

namespace {
constexpr double kPlungerToleranceUl = 0.05;  ///< a count of the pump's encoder
motion::msg::Arg resumeUl(std::string name, double v) { return motion::msg::real(std::move(name), v, motion::msg::Unit::Ul); }
} // namespace

motion::plates::StartState RecipeRunner::resumeStart(const QString& logPath, const dev::Instrument& client)
{
    motion::plates::StartState s;
    const auto& a = client.status().axes;
    const auto& id = client.identity();
    const int ix = id.axisIndex(QLatin1Char('X')), iy = id.axisIndex(QLatin1Char('Y')), iz = id.axisIndex(QLatin1Char('Z')),
              ip = id.axisIndex(QLatin1Char('P'));
    if (ix >= 0 && iy >= 0 && iz >= 0 && ip >= 0 && std::max({ix, iy, iz, ip}) < a.size())
        s = {a[ix].commanded, a[iy].commanded, a[iz].commanded, a[ip].commanded};
    std::string text;
    motion::msg::Message error;
    if (dev::files::readText(logPath, &text, &error))
        if (const auto p = dev::files::plates::readRunLog(text).startPumpUl)
            s.pumpUl = *p;
    return s;
}

RunProgress RecipeRunner::progress() const
{
    RunProgress p;
    p.opsTotal = static_cast<int>(m_plan.ops.size());
    double plannedClosed = 0, remaining = 0;
    for (std::size_t i = 0; i < m_plan.ops.size() && i < m_opStates.size(); ++i) {
        if (dev::files::plates::isClosed(m_opStates[i])) {
            ++p.opsDone;
            plannedClosed += m_plan.ops[i].durationS;
        } else {
            remaining += m_plan.ops[i].durationS;
        }
    }
    const bool running = m_state == RunState::Running || m_state == RunState::Pausing || m_state == RunState::Aborting;
    p.elapsedS = m_elapsedBeforeS + (running ? m_clock.elapsed() / 1000.0 : 0.0);
    p.deviceS = m_deviceBeforeS + (running ? static_cast<double>(m_deviceLastUs - std::min(m_deviceStartUs, m_deviceLastUs)) / 1e6 : 0.0);
    if (m_op >= 0 && m_op < p.opsTotal && m_state == RunState::Paused) {
        // Paused between two ops: the last one is done and the next has not begun.
        p.nextOp = m_op;
        p.nextLabel = m_plan.ops[static_cast<std::size_t>(m_op)].label();
    } else if (m_op >= 0 && m_op < p.opsTotal && m_state != RunState::Finished) {
        const motion::plates::PlanOp& op = m_plan.ops[static_cast<std::size_t>(m_op)];
        p.currentOp = m_op;
        p.currentWhere = op.where();
        p.currentLabel = op.label();
    }
    // The profiles' estimate, scaled by how this stretch of the run compares to
    // it (the link's turnaround, a slower machine), once there is enough to judge.
    double ratio = 1;
    const double sessionS = p.elapsedS - m_sessionStartS;
    if (m_plannedDoneS > 2.0 && sessionS > 0)
        ratio = std::clamp(sessionS / m_plannedDoneS, 0.5, 4.0);
    p.etaS = remaining * ratio;
    p.fraction = m_plan.totalTimeS > 0 ? plannedClosed / m_plan.totalTimeS : (p.opsTotal ? double(p.opsDone) / p.opsTotal : 0);
    return p;
}

bool RecipeRunner::decideInterrupted(int op, const InterruptedDecider& decide, bool* redo, motion::msg::Message* error)
{
    const motion::plates::PlanOp& plan = m_plan.ops[static_cast<std::size_t>(op)];
    InterruptedOp q;
    q.op = op;
    q.label = plan.label();
    q.plannedDeltaUl = plan.pumpNetUl;
    q.plungerNowUl = plungerNow();
    if (op == m_op && m_pumpLogged)
        q.pumpStartUl = m_pumpStartUl;
    else if (m_logState && static_cast<std::size_t>(op) < m_logState->ops.size())
        q.pumpStartUl = m_logState->ops[static_cast<std::size_t>(op)].pumpStartUl;
    if (q.pumpStartUl && std::abs(plan.pumpNetUl) > kPlungerToleranceUl) {
        const double end = *q.pumpStartUl + plan.pumpNetUl;
        if (std::abs(*q.plungerNowUl - end) <= kPlungerToleranceUl)
            q.evidence = motion::msg::make("recipe.evidence.moved_in_full", {resumeUl("plunger", end)});
        else if (std::abs(*q.plungerNowUl - *q.pumpStartUl) <= kPlungerToleranceUl)
            q.evidence = motion::msg::make("recipe.evidence.nothing_moved", {resumeUl("plunger", *q.pumpStartUl)});
        else
            q.evidence = motion::msg::make("recipe.evidence.part_moved", {resumeUl("plunger", *q.plungerNowUl), resumeUl("before", *q.pumpStartUl), resumeUl("after", end)});
    } else {
        q.evidence = motion::msg::make("recipe.evidence.cannot_tell", {motion::msg::term("step", std::string("recipe.step.") + motion::plates::stepTypeName(plan.type))});
    }
    if (!decide) {
        *error = motion::msg::make("recipe.run.interrupted_needs_decision", {motion::msg::nested("op", q.label), motion::msg::nested("evidence", q.evidence)});
        return false;
    }
    const InterruptedChoice c = decide(q);
    if (c == InterruptedChoice::Cancel) {
        *error = motion::msg::make("recipe.run.not_resumed_no_decision", {motion::msg::nested("op", q.label)});
        return false;
    }
    *redo = c == InterruptedChoice::Redo;
    return true;
}

/// Writes the operator's decision about `op` and sets it up to be skipped or begun again.
bool RecipeRunner::preflightDecided(const std::vector<std::pair<int, bool>>& decisions, motion::msg::Message* error)
{
    // The plunger already stands after a skipped op's pump move (the analyzer
    // finished it): counting that move again made a dispense that was skipped
    // look like one more dispense than the syringe holds, and the resume was
    // refused. A redone op's move is still ahead.
    const std::vector<OpState> before = m_opStates;
    for (const auto& [op, redo] : decisions)
        m_opStates[static_cast<std::size_t>(op)] = redo ? OpState::NotStarted : OpState::Skipped;
    const bool ok = preflight(error);
    m_opStates = before;
    return ok;
}

bool RecipeRunner::applyDecision(int op, bool redo)
{
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("event", redo ? "redo" : "skip");
    v.set("op", op);
    v.set("p_ul", plungerNow());
    v.set("reason", redo ? "recipe.run.operator_redo" : "recipe.run.operator_skip");
    if (!m_log.write(v))
        return false;
    m_opStates[static_cast<std::size_t>(op)] = redo ? OpState::NotStarted : OpState::Skipped;
    emit message(motion::msg::make(redo ? "recipe.run.will_redo" : "recipe.run.counts_as_done", {opArg(op)}), false);
    return true;
}

bool RecipeRunner::checkResumedInstrument(motion::msg::Message* error)
{
    // A reconnect may find another instrument, or this one power-cycled: its plunger
    // then holds nothing the log says it should, and the next wells would get wrong volumes.
    const auto& id = m_client->identity();
    const std::string now = (id.model + QLatin1Char(' ') + id.firmware).trimmed().toStdString();
    if (!m_runInstrument.empty() && now != m_runInstrument) {
        *error = motion::msg::make("recipe.resume.other_instrument", {motion::msg::verbatim("was", m_runInstrument), motion::msg::verbatim("now", now)});
        return false;
    }
    const double plunger = plungerNow();
    // Mid-pump the plunger's place is the evidence the operator decides on (decideInterrupted).
    if (!m_pumpLogged && std::abs(plunger - m_pumpUl) > kPlungerToleranceUl) {
        *error = motion::msg::make("recipe.run.plunger_moved", {resumeUl("plunger", plunger), resumeUl("logged", m_pumpUl)});
        return false;
    }
    emit message(motion::msg::make("recipe.resume.found", {motion::msg::verbatim("instrument", now), resumeUl("plunger", plunger)}), false);
    return true;
}

bool RecipeRunner::resume(const InterruptedDecider& decide, motion::msg::Message* error)
{
    if (m_state == RunState::Paused) {
        if (!checkMachine(error) || !preflight(error))
            return false;
        m_knowXy = m_knowZ = false;
        m_deferredFrom = -1;
        beginRunning(false);  // the pace before the pause still holds: the ETA does not jump
        return true;
    }
    if (m_state != RunState::Stopped || m_op < 0 || m_op >= static_cast<int>(m_plan.ops.size())) {
        *error = motion::msg::make("recipe.run.nothing_to_resume");
        return false;
    }
    if (!m_log.isOpen()) {
        *error = motion::msg::make("recipe.run.log_closed");
        return false;
    }
    if (!checkMachine(error) || !checkResumedInstrument(error))
        return false;
    bool redo = true;
    if (m_pumpLogged && !decideInterrupted(m_op, decide, &redo, error))
        return false;
    if (!preflightDecided(m_pumpLogged ? std::vector<std::pair<int, bool>>{{m_op, redo}} : std::vector<std::pair<int, bool>>{}, error))
        return false;
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("event", "resume");
    if (!m_log.write(v)) {
        *error = m_log.lastError();
        return false;
    }
    if (m_pumpLogged) {
        if (!applyDecision(m_op, redo)) {
            *error = m_log.lastError();
            return false;
        }
    } else {
        m_opStates[static_cast<std::size_t>(m_op)] = OpState::NotStarted;  // nothing moved: begin it again
    }
    m_op = nextOpenOp(m_op);
    m_move = 0;
    m_pumpLogged = false;
    m_knowXy = m_knowZ = false;
    m_deferredFrom = -1;
    m_pumpUl = plungerNow();
    emit progressChanged();
    beginRunning();
    return true;
}

bool RecipeRunner::resumeFromLog(const QString& logPath, const InterruptedDecider& decide, motion::msg::Message* error)
{
    if (m_state == RunState::Running || m_state == RunState::Pausing || m_state == RunState::Aborting || m_state == RunState::Paused) {
        *error = motion::msg::make("recipe.run.already_running");
        return false;
    }
    std::string text;
    if (!dev::files::readText(logPath, &text, error))
        return false;
    dev::files::plates::RunLogState st = dev::files::plates::readRunLog(text);
    const QString name = QFileInfo(logPath).fileName();
    const motion::msg::Arg logArg = motion::msg::verbatim("log", name.toStdString());
    if (!st.problems.empty()) {
        // The first problem says why; the log itself is left as it is for a person to read.
        const motion::msg::Problem& first = st.problems.list().front();
        *error = motion::msg::make("recipe.run.log_untrusted", {logArg, motion::msg::integer("line", first.line, motion::msg::Unit::None),
                                                        motion::msg::nested("cause", first.message)});
        return false;
    }
    if (st.fingerprint != motion::plates::fingerprintHex(m_plan.fingerprint) || st.opCount != static_cast<int>(m_plan.ops.size())) {
        *error = motion::msg::make("recipe.run.log_of_other_recipe", {logArg, motion::msg::integer("log_ops", st.opCount), motion::msg::verbatim("log_plan", st.fingerprint),
                                                              motion::msg::integer("ops", static_cast<long long>(m_plan.ops.size())),
                                                              motion::msg::verbatim("plan", motion::plates::fingerprintHex(m_plan.fingerprint))});
        return false;
    }
    if (st.finished) {
        *error = motion::msg::make("recipe.run.log_finished", {logArg});
        return false;
    }
    if (!checkMachine(error))
        return false;
    std::vector<int> interrupted;
    for (std::size_t i = 0; i < st.ops.size(); ++i)
        if (st.ops[i].state == OpState::Interrupted)
            interrupted.push_back(static_cast<int>(i));
    // With nothing interrupted, the plunger must be where the last completed op
    // left it; otherwise the syringe's content is not what the log says.
    if (interrupted.empty() && st.lastPumpUl && std::abs(*st.lastPumpUl - plungerNow()) > kPlungerToleranceUl) {
        *error = motion::msg::make("recipe.run.plunger_moved", {resumeUl("plunger", plungerNow()), resumeUl("logged", *st.lastPumpUl)});
        return false;
    }
    m_opStates.assign(m_plan.ops.size(), OpState::NotStarted);
    for (std::size_t i = 0; i < st.ops.size(); ++i)
        if (dev::files::plates::isClosed(st.ops[i].state))
            m_opStates[i] = st.ops[i].state;
    m_logState = std::move(st);
    std::vector<std::pair<int, bool>> decisions;
    for (int op : interrupted) {
        bool redo = true;
        if (!decideInterrupted(op, decide, &redo, error)) {
            m_logState.reset();
            return false;
        }
        decisions.push_back({op, redo});
    }
    m_logState.reset();
    if (!preflightDecided(decisions, error))
        return false;
    if (!m_log.append(logPath, error))
        return false;
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("event", "resume");
    if (!m_log.write(v)) {
        *error = m_log.lastError();
        return false;
    }
    for (const auto& [op, redo] : decisions)
        if (!applyDecision(op, redo)) {
            *error = m_log.lastError();
            return false;
        }
    const int started = std::count_if(m_opStates.begin(), m_opStates.end(), dev::files::plates::isClosed);
    m_elapsedBeforeS = 0;
    m_op = nextOpenOp(0);
    m_move = 0;
    m_pumpLogged = false;
    m_knowXy = m_knowZ = false;
    m_deferredFrom = -1;
    m_pumpUl = plungerNow();
    emit message(motion::msg::make("recipe.run.resuming", {motion::msg::verbatim("recipe", m_recipeName.toStdString()), logArg,
                                                   motion::msg::integer("done", started), motion::msg::integer("ops", static_cast<long long>(m_plan.ops.size())),
                                                   m_op < static_cast<int>(m_plan.ops.size()) ? opArg(m_op)
                                                                                              : motion::msg::nested("op", motion::msg::make("recipe.run.the_end"))}),
                 false);
    emit progressChanged();
    beginRunning();
    return true;
}

} // namespace dev::jobs
