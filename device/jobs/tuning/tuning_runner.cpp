#include "device/jobs/tuning/tuning_runner.h"
#include "motion/numbers.h"

#include "motion/control/tuning/tuning_rules.h"

#include <QDateTime>

#include <cmath>

namespace dev {

using namespace motion::control;

namespace {
using motion::kPi;
motion::msg::Arg labelArg(const motion::msg::Message& label) { return motion::msg::nested("run", label); }
} // namespace

const char* stateTerm(TuningRunner::State s)
{
    switch (s) {
    case TuningRunner::State::Idle: return "tuning.state.idle";
    case TuningRunner::State::Running: return "tuning.state.running";
    case TuningRunner::State::Interrupted: return "tuning.state.interrupted";
    case TuningRunner::State::Done: return "tuning.state.done";
    case TuningRunner::State::Failed: return "tuning.state.failed";
    case TuningRunner::State::Aborted: return "tuning.state.aborted";
    }
    return "tuning.state.idle";
}

TuningRunner::TuningRunner(QObject* parent) : QObject(parent) { qRegisterMetaType<dev::TuningRunner::State>(); }

void TuningRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

DiscreteGains TuningRunner::ruleGains(const std::string& ruleId, double ku, double tuS, double periodS)
{
    const TuningRule* r = findRule(ruleId);
    return r ? toDiscrete(applyRule(*r, ku, tuS), periodS) : DiscreteGains{};
}

StepJudging TuningRunner::judging(const TuningTarget& target)
{
    StepJudging j;
    j.resolution = target.noiseFloor();
    if (target.unit() == QLatin1String("mm"))
        j.targetBand = 0.005;
    return j;
}

bool TuningRunner::startZn(TuningTarget* target, const ZnOptions& o)
{
    if (busy())
        return false;
    motion::msg::Message problem;
    if (!target || !target->ready())
        problem = motion::msg::make("tuning.run.target_not_ready");
    else if (!target->cannotTune().empty())
        problem = target->cannotTune();
    else if (!(o.envelope.maxExcursion > 0 && o.envelope.maxFollowingError > 0 && o.envelope.maxDurationS > 0))
        problem = motion::msg::make("tuning.run.envelope_not_positive");
    else if (o.method == TuningMethod::UltimateGain && !(std::abs(o.step) > 0 && std::abs(o.step) < o.trialShare * o.envelope.maxExcursion
                                                           && std::abs(o.step) < o.trialShare * o.envelope.maxFollowingError))
        problem = motion::msg::make("tuning.run.trial_step_invalid", {motion::msg::real("share", 100 * o.trialShare, motion::msg::Unit::Percent)});
    else if (o.method == TuningMethod::Relay && !(o.relayAmplitude > 0 && o.hysteresis >= 0))
        problem = motion::msg::make("tuning.run.relay_invalid");
    if (!problem.empty()) {
        emit finished(false, problem);
        return false;
    }
    m_target = target;
    m_options = o;
    m_stepOnly = false;
    m_verifying = false;
    m_abortRequested = false;
    m_sign = 1;
    m_runsDone = 0;
    m_runSeconds = 0;
    m_search.reset();
    m_relay.reset();
    m_result = TuningResult{};
    m_result.target = target->describe().toStdString();
    m_result.method = o.method == TuningMethod::Relay ? "relay" : "ultimate-gain";
    m_result.controlPeriodS = target->controlPeriodS();
    m_result.unit = target->unit().toStdString();
    m_result.envelope = o.envelope;
    m_swing = std::max(2 * target->noiseFloor(), 1e-6 * std::abs(o.step));
    if (o.method == TuningMethod::UltimateGain) {
        m_result.step = o.step;
        UltimateGainOptions uo;
        uo.startKp = o.startKp;
        uo.kpMax = o.kpMax;
        uo.growth = 1.6;
        uo.swing = m_swing;
        m_search.emplace(uo);
    } else {
        m_result.relayAmplitude = o.relayAmplitude;
        m_result.hysteresis = o.hysteresis;
        RelayAutotuneOptions ro;
        ro.amplitude = o.relayAmplitude;
        ro.hysteresis = o.hysteresis;
        ro.periodS = target->controlPeriodS();
        ro.relayCycles = o.relayCycles;
        ro.refine = o.refine;
        ro.input = target->inputModel();
        if (ro.input == InputModel::Sampled) {
            // A device: more cycles per forced run, so the quantised output averages out.
            ro.forcedCycles = 12;
            ro.skipCycles = 4;
        }
        m_relay.emplace(ro);
    }
    setState(State::Running);
    next();
    return true;
}

bool TuningRunner::startStepTest(TuningTarget* target, const StepSpec& spec, const motion::msg::Message& label)
{
    if (busy() || !target || !target->ready()) {
        emit finished(false, motion::msg::make(busy() ? "tuning.run.step_busy" : "tuning.run.step_not_ready"));
        return false;
    }
    // The firmware's own check, in its words (the reference device says the same).
    const auto problems = checkStepSpec(spec);
    if (!problems.empty()) {
        std::string joined;
        for (const auto& p : problems)
            joined += (joined.empty() ? "" : "; ") + p;
        emit finished(false, motion::msg::make("tuning.run.step_refused", {motion::msg::verbatim("detail", joined)}));
        return false;
    }
    m_target = target;
    m_stepOnly = true;
    m_verifying = false;
    m_abortRequested = false;
    m_runsDone = 0;
    m_runSeconds = 0;
    setState(State::Running);
    m_pending = [this, spec, label] {
        reportProgress(label);
        m_runClock.start();
        m_target->runStep(spec, false, 0, [this, label](const RunOutcome& out) { onRun(out, 3, label); });
    };
    m_pending();
    return true;
}

void TuningRunner::abort()
{
    if (m_state == State::Interrupted) {
        setState(State::Aborted);
        emit finished(false, motion::msg::make("tuning.run.aborted_while_interrupted"));
        return;
    }
    if (!busy())
        return;
    m_abortRequested = true;
    if (m_target)
        m_target->abort();
}

bool TuningRunner::resume()
{
    if (m_state != State::Interrupted || !m_pending || !m_target || !m_target->ready())
        return false;
    m_abortRequested = false;
    setState(State::Running);
    emit message(motion::msg::make("tuning.run.resumed"));
    m_pending();
    return true;
}

int TuningRunner::remainingRunsEstimate() const
{
    const int verify = m_options.verifyRule.empty() || m_verifying ? 0 : 1;
    if (m_stepOnly)
        return 1;
    if (m_verifying)
        return 1;
    if (m_search)
        return std::max(1, 10 - static_cast<int>(m_search->trials().size())) + verify;
    if (m_relay)
        return std::max(1, (m_options.refine ? 5 : 1) - m_runsDone) + verify;
    return 1;
}

void TuningRunner::reportProgress(const motion::msg::Message& what)
{
    const int left = remainingRunsEstimate();
    const double fraction = double(m_runsDone) / double(m_runsDone + left);
    if (m_runsDone > 0) {
        const double eta = m_runSeconds / m_runsDone * left;
        emit progress(fraction, motion::msg::make("tuning.progress.with_eta", {labelArg(what), motion::msg::real("eta", std::max(1L, std::lround(eta)), motion::msg::Unit::S)}));
        return;
    }
    emit progress(fraction, what);
}

void TuningRunner::next()
{
    if (m_search) {
        if (const auto kp = m_search->nextKp()) {
            runTrial(*kp);
            return;
        }
        concludeSearch();
        return;
    }
    if (m_relay) {
        if (const auto spec = m_relay->next()) {
            runRelay(*spec);
            return;
        }
        concludeSearch();
    }
}

void TuningRunner::runTrial(double kp)
{
    StepSpec s;
    const bool device = m_target->inputModel() == InputModel::Sampled;
    s.step = m_sign * m_options.step * m_search->stepScale();
    m_sign = device ? -m_sign : 1;  // a device walks back and forth, not away
    s.gains = {kp, 0, 0};
    s.settleBand = 0;
    s.runS = device ? m_options.trialS : m_options.envelope.maxDurationS;
    s.envelope = trialEnvelope(m_options.envelope, m_options.trialShare);
    s.envelope.maxDurationS = device ? m_options.trialS + 0.2 : m_options.envelope.maxDurationS * 1.01;
    const int n = static_cast<int>(m_search->trials().size()) + 1;
    const motion::msg::Message label = motion::msg::make("tuning.label.trial", {motion::msg::integer("trial", n, motion::msg::Unit::None), motion::msg::real("kp", kp)});
    const double swing = m_swing * m_search->stepScale();
    m_currentKp = kp;
    m_pending = [this, s, label, swing] {
        reportProgress(label);
        m_runClock.start();
        m_target->runStep(s, true, swing, [this, label](const RunOutcome& out) { onRun(out, 0, label); });
    };
    m_pending();
}

void TuningRunner::runRelay(const RelaySpec& spec0)
{
    RelaySpec s = spec0;
    s.envelope = trialEnvelope(m_options.envelope, m_options.trialShare);
    const bool forced = s.forcedPeriodS > 0;
    // Long enough for the cycles asked, with room to settle; the relay's own period is not known yet.
    s.envelope.maxDurationS = forced ? std::min(m_options.envelope.maxDurationS, s.forcedPeriodS * (s.cycles + 2) * 1.5 + 0.2)
                                     : m_options.envelope.maxDurationS;
    const motion::msg::Message label = forced ? motion::msg::make("tuning.label.forced_run", {motion::msg::real("period", s.forcedPeriodS, motion::msg::Unit::S)})
                                      : motion::msg::make("tuning.label.relay_run");
    const bool continueRun = forced;
    m_pending = [this, s, label, continueRun, forced] {
        reportProgress(label);
        m_runClock.start();
        m_target->runRelay(s, continueRun, [this, label, forced](const RunOutcome& out) { onRun(out, forced ? 2 : 1, label); });
    };
    m_pending();
}

bool TuningRunner::endedBadly(const Record& r, const motion::msg::Message& label)
{
    switch (r.reason) {
    case EndReason::EStop:
        fail(motion::msg::make("tuning.run.estop", {labelArg(label)}));
        return true;
    case EndReason::HostSilent:
        setState(State::Interrupted);
        emit message(motion::msg::make("tuning.run.host_silent", {labelArg(label)}));
        return true;
    case EndReason::Fault:
        fail(motion::msg::make("tuning.run.fault", {labelArg(label)}));
        return true;
    case EndReason::Stopped:
        if (m_abortRequested) {
            setState(State::Aborted);
            emit finished(false, motion::msg::make("tuning.run.aborted_during", {labelArg(label)}));
        } else {
            fail(motion::msg::make("tuning.run.stopped_elsewhere", {labelArg(label)}));
        }
        return true;
    default: return false;
    }
}

void TuningRunner::onRun(const RunOutcome& out, int kind, const motion::msg::Message& label)
{
    if (m_state != State::Running)
        return;
    m_runSeconds += m_runClock.isValid() ? m_runClock.elapsed() / 1000.0 : 0;
    if (!out.ok) {
        if (m_abortRequested) {
            setState(State::Aborted);
            emit finished(false, motion::msg::make("tuning.run.aborted_during", {labelArg(label)}));
        } else if (out.linkLost) {
            setState(State::Interrupted);
            emit message(motion::msg::make("tuning.run.interrupted", {labelArg(label), motion::msg::nested("cause", out.error)}));
        } else {
            fail(motion::msg::make("tuning.run.failed", {labelArg(label), motion::msg::nested("cause", out.error)}));
        }
        return;
    }
    ++m_runsDone;
    emit recordArrived(out.record, label, kind);
    if (endedBadly(out.record, label))
        return;
    if (m_stepOnly || m_verifying) {
        const StepVerdict verdict = judgeStep(out.record, judging(*m_target));
        emit stepTestDone(out.record, verdict, label);
        if (m_verifying) {
            TuningResult::Verification v;
            v.rule = m_options.verifyRule;
            v.gains = ruleGains(m_options.verifyRule, m_result.ku, m_result.tuS, m_result.controlPeriodS);
            v.metrics = verdict.metrics;
            v.limitCycle = verdict.limitCycle;
            v.settledInside5umS = std::isnan(verdict.insideTargetBandS) ? -1 : verdict.insideTargetBandS;
            v.outcome = endReasonName(out.record.reason);
            m_result.verification = v;
        }
        setState(State::Done);
        emit progress(1, motion::msg::make(m_verifying ? "tuning.progress.verified" : "tuning.progress.step_done"));
        const motion::msg::Arg reason = motion::msg::term("reason", endReasonTerm(out.record.reason));
        emit finished(true, m_verifying ? motion::msg::make("tuning.run.verified", {motion::msg::real("ku", m_result.ku), motion::msg::real("tu", m_result.tuS, motion::msg::Unit::S),
                                                                            motion::msg::term("rule", "tuning.rule." + m_options.verifyRule), reason})
                                        : motion::msg::make("tuning.run.step_done", {labelArg(label), reason}));
        return;
    }
    if (m_abortRequested) {
        setState(State::Aborted);
        emit finished(false, motion::msg::make("tuning.run.aborted_after", {labelArg(label)}));
        return;
    }
    if (m_search) {
        m_search->report(m_currentKp, out.record);
        const UltimateTrial& t = m_search->trials().back();
        if (t.inconclusive)
            emit message(motion::msg::make("tuning.run.repeat_half_step", {labelArg(label)}));
    } else if (m_relay) {
        m_relay->report(out.record);
    }
    next();
}

void TuningRunner::fail(const motion::msg::Message& why)
{
    setState(State::Failed);
    emit finished(false, why);
}

void TuningRunner::concludeSearch()
{
    m_result.runs = m_runsDone;
    m_result.createdUtc = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    if (m_search) {
        for (const auto& t : m_search->trials()) {
            TuningResult::Trial tr;
            tr.kp = t.kp;
            tr.ratio = t.oscillation.oscillating ? t.oscillation.ratio : 0;
            tr.periodS = t.oscillation.periodS;
            if (t.inconclusive)
                tr.outcome = "hit the envelope";
            else if (!t.oscillation.oscillating)
                tr.outcome = std::isinf(t.logRatio) && t.logRatio > 0 ? "grows" : "no oscillation";
            else if (t.sustained)
                tr.outcome = "sustained";
            else
                tr.outcome = t.oscillation.ratio < 1 ? "decays" : "grows";
            m_result.trials.push_back(tr);
        }
        if (!m_search->result()) {
            fail(motion::msg::make("tuning.run.ultimate_failed", {motion::msg::nested("cause", m_search->failure())}));
            return;
        }
        m_result.ku = m_search->result()->ku;
        m_result.tuS = m_search->result()->tuS;
    } else if (m_relay) {
        if (!m_relay->result()) {
            fail(motion::msg::make("tuning.run.relay_failed", {motion::msg::nested("cause", m_relay->failure())}));
            return;
        }
        const RelayResult& r = *m_relay->result();
        m_result.ku = r.ku;
        m_result.tuS = r.tuS;
        m_result.kuDescribing = r.kuDescribing;
        m_result.tuRelayS = r.tuRelayS;
        m_result.refined = r.refined;
        for (const auto& p : r.points)
            m_result.points.push_back({p.omegaRadS, p.gain(), p.phaseRad() * 180 / kPi});
        if (!m_relay->failure().empty())
            emit message(m_relay->failure());
    }
    emit ultimateFound(m_result.ku, m_result.tuS);
    if (m_options.verifyRule.empty() || !findRule(m_options.verifyRule)) {
        setState(State::Done);
        emit progress(1, motion::msg::make("tuning.progress.done"));
        emit finished(true, motion::msg::make("tuning.run.found", {motion::msg::real("ku", m_result.ku), motion::msg::real("tu", m_result.tuS, motion::msg::Unit::S)}));
        return;
    }
    runVerification();
}

void TuningRunner::runVerification()
{
    m_verifying = true;
    StepSpec s;
    s.step = m_sign * m_options.verifyStep;
    s.gains = ruleGains(m_options.verifyRule, m_result.ku, m_result.tuS, m_result.controlPeriodS);
    const bool device = m_target->inputModel() == InputModel::Sampled;
    if (device) {
        s.settleBand = m_options.settleBand;
        s.settleHoldS = 0.05;
        s.runS = std::min(1.0, 0.9 * m_options.envelope.maxDurationS);  // a completed test, not a tripped one, if it hunts
    } else {
        s.runS = std::min(m_options.envelope.maxDurationS * 0.99, 30 * m_result.tuS);  // the whole response, for its metrics
    }
    s.envelope = m_options.envelope;
    s.envelope.maxFollowingError = std::max(s.envelope.maxFollowingError, 1.5 * std::abs(s.step));
    const motion::msg::Message label = motion::msg::make("tuning.label.verification", {motion::msg::term("rule", "tuning.rule." + m_options.verifyRule)});
    m_pending = [this, s, label] {
        reportProgress(label);
        m_runClock.start();
        m_target->runStep(s, false, 0, [this, label](const RunOutcome& out) { onRun(out, 3, label); });
    };
    m_pending();
}

} // namespace dev
