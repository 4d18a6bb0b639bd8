#include "motion/control/experiment.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace motion::control {

const char* endReasonName(EndReason r)
{
    switch (r) {
    case EndReason::Running: return "running";
    case EndReason::Settled: return "settled";
    case EndReason::Completed: return "completed";
    case EndReason::Excursion: return "max excursion crossed";
    case EndReason::FollowingError: return "max following error crossed";
    case EndReason::Duration: return "max duration reached";
    case EndReason::Stopped: return "stopped";
    case EndReason::EStop: return "E-stop";
    case EndReason::HostSilent: return "host went silent";
    case EndReason::Fault: return "fault";
    }
    return "unknown";
}

const char* endReasonTerm(EndReason r)
{
    switch (r) {
    case EndReason::Running: return "tuning.end.running";
    case EndReason::Settled: return "tuning.end.settled";
    case EndReason::Completed: return "tuning.end.completed";
    case EndReason::Excursion: return "tuning.end.excursion";
    case EndReason::FollowingError: return "tuning.end.following_error";
    case EndReason::Duration: return "tuning.end.duration";
    case EndReason::Stopped: return "tuning.end.stopped";
    case EndReason::EStop: return "tuning.end.estop";
    case EndReason::HostSilent: return "tuning.end.host_silent";
    case EndReason::Fault: return "tuning.end.fault";
    }
    return "tuning.end.unknown";
}

namespace {
bool positive(double v) { return std::isfinite(v) && v > 0; }
std::string fmt(const char* f, double v)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
void checkEnvelope(const Envelope& e, std::vector<std::string>& out)
{
    if (!positive(e.maxExcursion))
        out.push_back(fmt("envelope max excursion = %g must be above 0", e.maxExcursion));
    if (!positive(e.maxFollowingError))
        out.push_back(fmt("envelope max following error = %g must be above 0", e.maxFollowingError));
    if (!positive(e.maxDurationS))
        out.push_back(fmt("envelope max duration = %g s must be above 0", e.maxDurationS));
}
} // namespace

std::vector<std::string> checkStepSpec(const StepSpec& s)
{
    std::vector<std::string> out;
    if (!std::isfinite(s.step) || s.step == 0)
        out.push_back(fmt("step = %g must be a non-zero number", s.step));
    for (const auto& p : checkGains(s.gains, GainLimits{1e300, 1e300, 1e300}))
        out.push_back(wireText(p));
    if (!std::isfinite(s.settleBand) || s.settleBand < 0)
        out.push_back(fmt("settle band = %g must not be negative", s.settleBand));
    if (!std::isfinite(s.settleHoldS) || s.settleHoldS < 0)
        out.push_back(fmt("settle hold = %g s must not be negative", s.settleHoldS));
    if (!std::isfinite(s.runS) || s.runS < 0)
        out.push_back(fmt("run time = %g s must not be negative", s.runS));
    if (s.runS == 0 && s.settleBand == 0)
        out.push_back("a step test needs a settle band or a run time, or it only ends on the envelope");
    checkEnvelope(s.envelope, out);
    if (std::isfinite(s.step) && s.envelope.maxExcursion > 0 && std::abs(s.step) >= s.envelope.maxExcursion)
        out.push_back(fmt("envelope max excursion must be above the step size %g", std::abs(s.step)));
    if (std::isfinite(s.step) && s.envelope.maxFollowingError > 0 && std::abs(s.step) >= s.envelope.maxFollowingError)
        out.push_back(fmt("envelope max following error must be above the step size %g (the error is the step at the start)",
                          std::abs(s.step)));
    return out;
}

std::vector<std::string> checkRelaySpec(const RelaySpec& s)
{
    std::vector<std::string> out;
    if (!positive(s.amplitude))
        out.push_back(fmt("relay amplitude = %g must be above 0", s.amplitude));
    if (!std::isfinite(s.hysteresis) || s.hysteresis < 0)
        out.push_back(fmt("hysteresis = %g must not be negative", s.hysteresis));
    if (!std::isfinite(s.forcedPeriodS) || s.forcedPeriodS < 0)
        out.push_back(fmt("forced period = %g s must not be negative", s.forcedPeriodS));
    if (s.cycles < 1 || s.cycles > 10000)
        out.push_back(fmt("cycles = %g must be from 1 to 10000", s.cycles));
    checkEnvelope(s.envelope, out);
    return out;
}

Experiment Experiment::stepTest(const StepSpec& spec, double y0, double u0, double periodS, double deadband)
{
    Experiment x;
    x.m_kind = Kind::Step;
    x.m_step = spec;
    x.m_periodS = periodS;
    x.m_deadband = deadband;
    x.m_y0 = y0;
    x.m_u0 = x.m_u = u0;
    x.m_setpoint = y0 + spec.step;
    x.m_pid = IncrementalPid(spec.gains);
    x.m_pid.reset(u0);
    return x;
}

Experiment Experiment::relay(const RelaySpec& spec, double y0, double u0, double periodS)
{
    Experiment x;
    x.m_kind = Kind::Relay;
    x.m_relay = spec;
    x.m_periodS = periodS;
    x.m_y0 = y0;
    x.m_u0 = x.m_u = u0;
    x.m_setpoint = y0;
    if (spec.forcedPeriodS > 0)
        x.m_forcedPeriods = std::max(2L, std::lround(spec.forcedPeriodS / periodS));
    return x;
}

void Experiment::abort(EndReason reason)
{
    if (m_reason == EndReason::Running)
        m_reason = reason;
}

bool Experiment::checkEnvelope(double y)
{
    const Envelope& env = m_kind == Kind::Step ? m_step.envelope : m_relay.envelope;
    auto trip = [&](EndReason r, double value, double limit) {
        m_reason = r;
        m_tripValue = value;
        m_tripLimit = limit;
        return true;
    };
    if (std::abs(y - m_y0) > env.maxExcursion)
        return trip(EndReason::Excursion, std::abs(y - m_y0), env.maxExcursion);
    if (std::abs(m_setpoint - y) > env.maxFollowingError)
        return trip(EndReason::FollowingError, std::abs(m_setpoint - y), env.maxFollowingError);
    if (elapsedS() > env.maxDurationS + 1e-9)
        return trip(EndReason::Duration, elapsedS(), env.maxDurationS);
    return false;
}

double Experiment::control(double y)
{
    if (m_reason != EndReason::Running || checkEnvelope(y))
        return m_u;
    ++m_k;
    if (m_kind == Kind::Step) {
        const double raw = m_setpoint - y;
        const double e = std::abs(raw) <= m_deadband ? 0.0 : raw;
        m_pid.step(e);
        m_u = m_pid.output();
        if (m_step.settleBand > 0) {
            // (A reading exactly on the band's edge is inside: positions are whole counts.)
            m_settledS = std::abs(raw) <= m_step.settleBand * (1 + 1e-9) + 1e-12 ? m_settledS + m_periodS : 0;
            if (m_settledS >= m_step.settleHoldS - 1e-12)
                m_reason = EndReason::Settled;
        }
        if (m_reason == EndReason::Running && m_step.runS > 0 && elapsedS() >= m_step.runS - 1e-12)
            m_reason = EndReason::Completed;
        return m_u;
    }
    const int before = m_state;
    if (m_forcedPeriods > 0) {
        // Square wave on a timer: up for the first half of each period.
        const long phase = (m_k - 1) % m_forcedPeriods;
        m_state = phase < m_forcedPeriods / 2 ? 1 : -1;
        if (phase == 0 && m_k > 1)
            ++m_cycles;
    } else {
        const double e = m_setpoint - y;
        if (m_state > 0 && e < -m_relay.hysteresis)
            m_state = -1;
        else if (m_state < 0 && e > m_relay.hysteresis)
            m_state = 1;
        if (before < 0 && m_state > 0)
            ++m_cycles;
    }
    m_u = m_u0 + m_state * m_relay.amplitude;
    if (m_cycles >= m_relay.cycles)
        m_reason = EndReason::Completed;
    return m_u;
}

} // namespace motion::control
