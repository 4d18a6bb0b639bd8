#include "device/sim/sim_tuning.h"

#include "device/sim/sim_machine.h"
#include "motion/control/gains.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dev::sim {

using motion::control::EndReason;
using motion::control::Experiment;

namespace {
std::string fmt(const char* f, double a, double b = 0, double c = 0)
{
    char buf[200];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}
std::string join(const std::vector<std::string>& v)
{
    std::string s;
    for (const auto& x : v)
        s += (s.empty() ? "" : "; ") + x;
    return s;
}
motion::control::DiscreteGains toDouble(const dev::proto::WireGains& g) { return {g.kp, g.ki, g.kd}; }
dev::proto::WireGains toWire(const PidGains& g)
{
    return {static_cast<float>(g.kp), static_cast<float>(g.ki), static_cast<float>(g.kd)};
}
constexpr double kNmPerMm = 1e6;
std::int32_t nm(double mm) { return static_cast<std::int32_t>(std::clamp(std::lround(mm * kNmPerMm), -2147483647L, 2147483647L)); }
} // namespace

SimTuning::SimTuning(SimMachine& machine) : m_m(machine)
{
    m_axes.resize(static_cast<std::size_t>(machine.axisCount()));
    for (auto& a : m_axes)
        a.gains = a.saved = a.previous = machine.config().gains;
}

void SimTuning::setAllGains(const PidGains& g)
{
    for (auto& a : m_axes)
        a.gains = a.previous = g;
}

bool SimTuning::testRunning(int axis) const
{
    return axis >= 0 && axis < static_cast<int>(m_axes.size()) && m_axes[static_cast<std::size_t>(axis)].test.has_value();
}

void SimTuning::hostHeard() { m_lastHeardS = m_m.timeS(); }

SimTuning::Result SimTuning::getGains(std::uint8_t axis, dev::proto::GainsReply& out) const
{
    if (axis >= m_m.axisCount())
        return m_m.error(dev::proto::ErrorCode::BadAxis, -1, axis, "axis index " + std::to_string(axis) + " does not exist");
    if (!m_m.config().closedLoop)
        return m_m.error(dev::proto::kErrNotClosedLoop, axis, 0,
                         std::string("axis ") + m_m.st(axis).plant->config().letter + " runs open loop: it has no PID gains");
    const Axis& a = m_axes[axis];
    out.axis = axis;
    out.controlPeriodUs = static_cast<std::uint32_t>(std::lround(m_m.config().controlPeriodS * 1e6));
    out.gains = toWire(a.gains);
    out.saved = toWire(a.saved);
    out.flags = a.test ? dev::proto::kGainsTestRunning : 0;
    const motion::control::GainLimits lim;
    out.limits = {static_cast<float>(lim.kpMax), static_cast<float>(lim.kiMax), static_cast<float>(lim.kdMax)};
    return std::nullopt;
}

SimTuning::Result SimTuning::setGains(const dev::proto::SetGainsRequest& r)
{
    dev::proto::GainsReply unused;
    if (auto e = getGains(r.axis, unused))
        return e;
    const char letter = m_m.st(r.axis).plant->config().letter;
    if (m_axes[r.axis].test)
        return m_m.error(dev::proto::kErrTestActive, r.axis, 0,
                         std::string("axis ") + letter + " is running a test: its gains change once the test has ended");
    const auto problems = motion::control::checkGains(toDouble(r.gains));
    if (!problems.empty()) {
        std::vector<std::string> msgs;
        for (const auto& p : problems)
            msgs.push_back(motion::control::wireText(p));
        dev::proto::ErrorReply e = m_m.error(dev::proto::kErrBadGains, -1, problems.front().index,
                                        std::string("axis ") + letter + " gains refused, the previous ones stay: " + join(msgs));
        e.axis = r.axis;
        return e;
    }
    // Eq. 2 is incremental: new gains only size the next increments, so the
    // switch at the next control period is bumpless.
    Axis& a = m_axes[r.axis];
    const PidGains wanted{r.gains.kp, r.gains.ki, r.gains.kd};
    if (!(wanted.kp == a.gains.kp && wanted.ki == a.gains.ki && wanted.kd == a.gains.kd))
        a.previous = a.gains;
    a.gains = wanted;
    if (r.flags & dev::proto::kSetGainsSave)
        a.saved = a.gains;
    m_m.raiseEvent(dev::proto::kEvGainsChanged, r.axis,
                   fmt("gains per control period: kp %.6g, ki %.6g, kd %.6g", a.gains.kp, a.gains.ki, a.gains.kd)
                       + ((r.flags & dev::proto::kSetGainsSave) ? " (kept as power-up gains)" : ""),
                   dev::proto::reason::kGainsSet, {a.gains.kp, a.gains.ki, a.gains.kd, (r.flags & dev::proto::kSetGainsSave) ? 1.0 : 0.0});
    return std::nullopt;
}

SimTuning::Result SimTuning::checkTestable(std::uint8_t axis, bool homedNeeded) const
{
    if (m_m.estopActive())
        return m_m.error(dev::proto::ErrorCode::EStopActive, -1, 0, "E-stop is active: send reset before a test");
    dev::proto::GainsReply unused;
    if (auto e = getGains(axis, unused))
        return e;
    const auto& s = m_m.st(axis);
    const char letter = s.plant->config().letter;
    if (m_axes[axis].test)
        return m_m.error(dev::proto::kErrTestActive, axis, 0, std::string("axis ") + letter + " is already running a test");
    if (homedNeeded && !s.homed)
        return m_m.error(dev::proto::ErrorCode::NotHomed, axis, 0,
                         std::string("axis ") + letter + " is not homed: a test's envelope is checked against the soft limits");
    if (s.mode != SimMachine::Mode::Idle || m_m.awaitingHoming(axis))
        return m_m.error(dev::proto::ErrorCode::Busy, axis, 0, std::string("axis ") + letter + " is still moving");
    return std::nullopt;
}

SimTuning::Result SimTuning::checkEnvelope(int axis, const dev::proto::WireEnvelope& e, double) const
{
    const char letter = m_m.st(axis).plant->config().letter;
    if (e.maxDurationMs > kMaxTestS * 1000)
        return m_m.error(dev::proto::ErrorCode::OutOfRange, -1, e.maxDurationMs,
                         fmt("a test may last at most %.0f s (max duration %.3f s asked)", kMaxTestS, e.maxDurationMs / 1000.0));
    const auto& s = m_m.st(axis);
    const double here = s.plant->reference(), excursion = e.maxExcursion / kNmPerMm;
    if (here - excursion < m_m.softMinMachine(axis) - 1e-9 || here + excursion > m_m.softMaxMachine(axis) + 1e-9) {
        const bool low = here - excursion < m_m.softMinMachine(axis) - 1e-9;
        const double lim = (low ? m_m.softMinMachine(axis) : m_m.softMaxMachine(axis)) - s.offset;
        return m_m.error(dev::proto::ErrorCode::SoftLimit, axis, lim,
                         std::string("axis ") + letter + ": the envelope ±" + fmt("%.4g mm", excursion) + " around "
                             + fmt("%.4f mm", here - s.offset) + " crosses the " + (low ? "lower" : "upper")
                             + fmt(" soft limit %.4f mm", lim));
    }
    return std::nullopt;
}

SimTuning::Result SimTuning::stepTest(const dev::proto::StepTestRequest& r)
{
    if (auto e = checkTestable(r.axis, true))
        return e;
    const char letter = m_m.st(r.axis).plant->config().letter;
    const PidGains& op = m_axes[r.axis].gains;
    motion::control::StepSpec spec;
    spec.step = r.step / kNmPerMm;
    spec.gains = r.trialGains ? toDouble(*r.trialGains) : motion::control::DiscreteGains{op.kp, op.ki, op.kd};
    if (r.trialGains) {
        const auto problems = motion::control::checkGains(spec.gains);
        if (!problems.empty()) {
            std::vector<std::string> msgs;
            for (const auto& p : problems)
                msgs.push_back(motion::control::wireText(p));
            dev::proto::ErrorReply e = m_m.error(dev::proto::kErrBadGains, -1, problems.front().index,
                                            std::string("axis ") + letter + " trial gains refused: " + join(msgs));
            e.axis = r.axis;
            return e;
        }
    }
    spec.settleBand = r.settleBand / kNmPerMm;
    spec.settleHoldS = r.settleHoldMs / 1000.0;
    spec.runS = r.runMs / 1000.0;
    spec.envelope = {r.envelope.maxExcursion / kNmPerMm, r.envelope.maxFollowingError / kNmPerMm, r.envelope.maxDurationMs / 1000.0};
    const auto problems = motion::control::checkStepSpec(spec);
    if (!problems.empty())
        return m_m.error(dev::proto::ErrorCode::OutOfRange, r.axis, spec.step, std::string("axis ") + letter + " step test: " + join(problems));
    if (auto e = checkEnvelope(r.axis, r.envelope, spec.step))
        return e;
    const auto& s = m_m.st(r.axis);
    const double deadband = m_m.config().loop.deadbandCounts * s.plant->config().resolution + 1e-12;
    start(r.axis, Experiment::stepTest(spec, s.plant->reference(), 0, m_m.config().controlPeriodS, deadband), 1,
          toWire({spec.gains.kp, spec.gains.ki, spec.gains.kd}));
    // A host may send the operator's own set as the "trial": it is still the set the axis holds under.
    m_axes[r.axis].testUsesOperatorGains = !r.trialGains || *r.trialGains == toWire(op);
    return std::nullopt;
}

SimTuning::Result SimTuning::relayTest(const dev::proto::RelayTestRequest& r)
{
    if (auto e = checkTestable(r.axis, true))
        return e;
    const char letter = m_m.st(r.axis).plant->config().letter;
    motion::control::RelaySpec spec;
    spec.amplitude = r.amplitude / kNmPerMm;
    spec.hysteresis = r.hysteresis / kNmPerMm;
    spec.forcedPeriodS = r.forcedPeriodUs / 1e6;
    spec.cycles = r.cycles;
    spec.envelope = {r.envelope.maxExcursion / kNmPerMm, r.envelope.maxFollowingError / kNmPerMm, r.envelope.maxDurationMs / 1000.0};
    const auto problems = motion::control::checkRelaySpec(spec);
    if (!problems.empty())
        return m_m.error(dev::proto::ErrorCode::OutOfRange, r.axis, spec.amplitude, std::string("axis ") + letter + " relay test: " + join(problems));
    if (auto e = checkEnvelope(r.axis, r.envelope, 0))
        return e;
    start(r.axis, Experiment::relay(spec, m_m.st(r.axis).plant->reference(), 0, m_m.config().controlPeriodS), 2, {});
    return std::nullopt;
}

void SimTuning::start(int axis, Experiment x, std::uint8_t kind, const dev::proto::WireGains& gains)
{
    Axis& a = m_axes[static_cast<std::size_t>(axis)];
    auto& s = m_m.st(axis);
    s.mode = SimMachine::Mode::Tuning;
    s.lostReported = false;
    s.plant->setReference(x.setpoint(), 0);
    a.capture = Capture{};
    a.capture.kind = kind;
    a.capture.testId = m_nextTestId++;
    a.capture.periodS = m_m.config().controlPeriodS;
    a.capture.startPosition = nm(x.startPosition() - s.offset);
    a.capture.gains = gains;
    a.capture.samples.reserve(kCaptureCapacity);
    a.lastReason = EndReason::Running;
    a.tripValue = a.tripLimit = 0;
    a.lastU = 0;
    a.testUsesOperatorGains = false;
    a.test = std::move(x);
    m_lastHeardS = m_m.timeS();  // the request itself was a frame from the host
}

bool SimTuning::controlStep(int axis, int ticksPerPeriod)
{
    Axis& a = m_axes[static_cast<std::size_t>(axis)];
    if (!a.test)
        return false;
    auto& s = m_m.st(axis);
    if (s.mode != SimMachine::Mode::Tuning)
        a.test->abort(EndReason::Fault);  // a switch or a fault took the axis
    const double u = a.test->control(s.plant->reportedMeasured());
    s.plant->applyCorrection(u - a.lastU, ticksPerPeriod);
    s.plant->setReference(a.test->setpoint(), 0);
    a.lastU = u;
    record(axis);
    if (!a.test->running())
        end(axis);
    return true;
}

void SimTuning::record(int axis)
{
    Axis& a = m_axes[static_cast<std::size_t>(axis)];
    Capture& c = a.capture;
    if (++c.phase < c.stride)
        return;
    c.phase = 0;
    if (c.samples.size() >= kCaptureCapacity) {
        // Full: keep every other sample and record at half the rate from now on,
        // so the whole test stays in the buffer (stated in the capture's period).
        for (std::size_t i = 0; 2 * i < c.samples.size(); ++i)
            c.samples[i] = c.samples[2 * i];
        c.samples.resize((c.samples.size() + 1) / 2);
        c.stride *= 2;
        c.periodS *= 2;
    }
    const auto& s = m_m.st(axis);
    c.samples.push_back({nm(a.test->setpoint() - s.offset), nm(s.plant->reportedMeasured() - s.measuredOffset), nm(a.test->output())});
}

void SimTuning::end(int axis)
{
    Axis& a = m_axes[static_cast<std::size_t>(axis)];
    if (!a.test)
        return;
    const Experiment x = *a.test;
    a.test.reset();
    a.lastReason = x.reason();
    a.tripValue = x.tripValue();
    a.tripLimit = x.tripLimit();
    auto& s = m_m.st(axis);
    const char letter = s.plant->config().letter;
    const bool diverged = x.reason() == EndReason::Excursion || x.reason() == EndReason::FollowingError;
    const bool fallBack = diverged && a.testUsesOperatorGains
        && !(a.previous.kp == a.gains.kp && a.previous.ki == a.gains.ki && a.previous.kd == a.gains.kd);
    a.testUsesOperatorGains = false;
    if (fallBack) {
        // The operator's set is what diverged: hold under the one before it.
        std::swap(a.gains, a.previous);
        m_m.raiseEvent(dev::proto::kEvGainsChanged, axis,
                       fmt("gains per control period: kp %.6g, ki %.6g, kd %.6g", a.gains.kp, a.gains.ki, a.gains.kd)
                           + " (the set in force before the one that tripped the test)",
                       dev::proto::reason::kGainsFellBack, {a.gains.kp, a.gains.ki, a.gains.kd});
    }
    // Trial gains never replaced the operator's; the axis stops where it is
    // (or stays on the step it settled on) under them.
    if (x.reason() == EndReason::Settled)
        s.plant->resumeLoop(m_m.config().loop);
    else if (x.reason() != EndReason::EStop)  // (E-stop has frozen the motor where it is)
        s.plant->stopAtMeasured();
    if (s.mode == SimMachine::Mode::Tuning)
        s.mode = SimMachine::Mode::Idle;
    const char* what = x.kind() == Experiment::Kind::Step ? "step test" : "relay test";
    const double test = x.kind() == Experiment::Kind::Step ? dev::proto::reason::kStepTest : dev::proto::reason::kRelayTest;
    const std::string axisName = std::string("axis ") + letter + " " + what;
    const double t = x.elapsedS();
    const double at = s.plant->reportedMeasured() - s.measuredOffset;
    const std::string stoppedAt = fmt("; axis stopped at %.4f mm", at);
    namespace why = dev::proto::reason;
    switch (x.reason()) {
    case EndReason::Settled:
        m_m.raiseEvent(dev::proto::kEvTestEnded, axis, axisName + fmt(" settled after %.3f s", t), why::kSettled, {test, t});
        break;
    case EndReason::Completed:
        m_m.raiseEvent(dev::proto::kEvTestEnded, axis, axisName + fmt(" completed in %.3f s", t), why::kCompleted, {test, t});
        break;
    case EndReason::Excursion:
        m_m.raiseEvent(dev::proto::kEvTestTripped, axis,
                       axisName + fmt(" stopped: max excursion %.4f mm crossed (%.4f mm) after %.3f s", x.tripLimit(), x.tripValue(), t)
                           + stoppedAt,
                       why::kExcursion, {test, x.tripLimit(), x.tripValue(), t, at});
        break;
    case EndReason::FollowingError:
        m_m.raiseEvent(dev::proto::kEvTestTripped, axis,
                       axisName + fmt(" stopped: max following error %.4f mm crossed (%.4f mm) after %.3f s", x.tripLimit(), x.tripValue(), t)
                           + stoppedAt,
                       why::kFollowingError, {test, x.tripLimit(), x.tripValue(), t, at});
        break;
    case EndReason::Duration:
        m_m.raiseEvent(dev::proto::kEvTestTripped, axis, axisName + fmt(" stopped: max duration %.3f s reached", x.tripLimit()) + stoppedAt,
                       why::kDuration, {test, x.tripLimit(), at});
        break;
    case EndReason::Stopped:
        m_m.raiseEvent(dev::proto::kEvTestAborted, axis, axisName + " stopped on request", why::kOnRequest, {test});
        break;
    case EndReason::EStop: m_m.raiseEvent(dev::proto::kEvTestAborted, axis, axisName + " ended by E-stop", why::kByEStop, {test}); break;
    case EndReason::HostSilent:
        m_m.raiseEvent(dev::proto::kEvTestAborted, axis, axisName + fmt(" ended: no frame from the host for %.1f s; axis stopped", kHostSilenceS),
                       why::kHostSilent, {test, kHostSilenceS});
        break;
    case EndReason::Fault:
    case EndReason::Running: m_m.raiseEvent(dev::proto::kEvTestAborted, axis, axisName + " ended by a fault", why::kByFault, {test}); break;
    }
}

SimTuning::Result SimTuning::abort(std::uint8_t mask, EndReason why)
{
    if (mask == 0)
        mask = 0xFF;
    for (int i = 0; i < static_cast<int>(m_axes.size()); ++i) {
        if (!(mask & (1u << i)) || !m_axes[static_cast<std::size_t>(i)].test)
            continue;
        m_axes[static_cast<std::size_t>(i)].test->abort(why);
        end(i);
    }
    return std::nullopt;
}

void SimTuning::tick()
{
    bool any = false;
    for (const auto& a : m_axes)
        any = any || a.test.has_value();
    if (any && m_m.timeS() - m_lastHeardS > kHostSilenceS)
        abort(0xFF, EndReason::HostSilent);
}

SimTuning::Result SimTuning::capture(const dev::proto::CaptureRequest& r, dev::proto::CaptureReply& out) const
{
    dev::proto::GainsReply unused;
    if (auto e = getGains(r.axis, unused))
        return e;
    const Axis& a = m_axes[r.axis];
    const Capture& c = a.capture;
    if (c.kind == 0 || r.first > c.samples.size())
        return m_m.error(dev::proto::kErrNoCapture, -1, static_cast<double>(c.samples.size()),
                         c.kind == 0 ? std::string("no test has run on this axis yet")
                                     : "sample " + std::to_string(r.first) + " is past the " + std::to_string(c.samples.size())
                                         + " captured");
    out.axis = r.axis;
    out.kind = c.kind;
    out.reason = static_cast<std::uint8_t>(a.test ? EndReason::Running : a.lastReason);
    out.testId = c.testId;
    out.periodUs = static_cast<std::uint32_t>(std::lround(c.periodS * 1e6));
    out.total = static_cast<std::uint32_t>(c.samples.size());
    out.startPosition = c.startPosition;
    const bool duration = a.lastReason == EndReason::Duration;
    const double scale = duration ? 1e3 : kNmPerMm;  // ms for the duration limit, nm otherwise
    out.tripValue = a.test ? 0 : static_cast<std::uint32_t>(std::lround(a.tripValue * scale));
    out.tripLimit = a.test ? 0 : static_cast<std::uint32_t>(std::lround(a.tripLimit * scale));
    out.gains = c.gains;
    out.first = r.first;
    const std::size_t n = std::min<std::size_t>({r.maxCount, dev::proto::kMaxCaptureSamplesPerReply, c.samples.size() - r.first});
    out.samples.assign(c.samples.begin() + static_cast<std::ptrdiff_t>(r.first),
                       c.samples.begin() + static_cast<std::ptrdiff_t>(r.first + n));
    return std::nullopt;
}

} // namespace dev::sim
