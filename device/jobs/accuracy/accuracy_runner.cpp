// The accuracy runner's motion: stops, moves, settling on the device clock, readings.
// Preparing, the run log and the results are in accuracy_runner_files.cpp.
#include "device/jobs/accuracy/accuracy_runner.h"

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using motion::metrology::Direction;

namespace {
/// Wall-clock interval between status readings while settling: at time scale K the
/// device clock moves K times this much between them.
constexpr int kPollMs = 10;

const motion::metrology::SettleRule& settleOf(const dev::files::accuracy::AccuracyTest& t)
{
    if (const auto* a = std::get_if<motion::metrology::AxisTest>(&t))
        return a->settle;
    return std::get<motion::metrology::XyLineTest>(t).settle;
}
double feedOf(const dev::files::accuracy::AccuracyTest& t)
{
    if (const auto* a = std::get_if<motion::metrology::AxisTest>(&t))
        return a->feedMmS;
    return std::get<motion::metrology::XyLineTest>(t).feedMmS;
}
double dwellOf(const dev::files::accuracy::AccuracyTest& t)
{
    if (const auto* a = std::get_if<motion::metrology::AxisTest>(&t))
        return a->dwellS;
    return std::get<motion::metrology::XyLineTest>(t).dwellS;
}
} // namespace

AccuracyRunner::AccuracyRunner(dev::Instrument* instrument, QObject* parent) : QObject(parent), m_instrument(instrument)
{
    qRegisterMetaType<dev::jobs::AccuracyRunner::State>();
    m_poll.setSingleShot(true);
    connect(&m_poll, &QTimer::timeout, this, &AccuracyRunner::pollSettle);
    if (!instrument)
        return;
    m_connections << connect(instrument, &dev::Instrument::eventReceived, this, &AccuracyRunner::onEvent);
    m_connections << connect(instrument, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (isActive() && s != dev::LinkState::Ready)
            stopWith(motion::msg::make("accuracy.run.link_lost"), false);
    });
    m_connections << connect(instrument, &dev::Instrument::statusChanged, this, [this](const dev::InstrumentStatus& s) {
        const bool moving = m_phase == Phase::Overrun || m_phase == Phase::Approach || m_phase == Phase::Target;
        if (!isActive() || !moving || !m_moveAccepted || m_waitingAxes == 0)
            return;
        quint64 restUs = 0;
        if (!m_arrival.feed(s, &restUs))
            return;
        m_waitingAxes = 0;
        m_motionDoneUs = std::max<quint64>(m_motionDoneUs, restUs);
        onMoveDone();
    });
}

AccuracyRunner::~AccuracyRunner()
{
    for (const auto& c : m_connections)
        disconnect(c);
    if (m_source && isActive())
        m_source->cancel();
}

const char* AccuracyRunner::stateName(State s)
{
    switch (s) {
    case State::Idle: return "idle";
    case State::Running: return "running";
    case State::Pausing: return "pausing";
    case State::Paused: return "paused";
    case State::Stopped: return "stopped";
    case State::Finished: return "finished";
    }
    return "idle";
}

void AccuracyRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

quint8 AccuracyRunner::axisMask() const
{
    unsigned mask = 0;
    for (int a : m_axes)
        mask |= 1u << a;
    return static_cast<quint8>(mask);
}

QString AccuracyRunner::axisNames() const
{
    QString out;
    if (!m_instrument)
        return out;
    for (int a : m_axes)
        if (a >= 0 && a < m_instrument->identity().axes.size())
            out += m_instrument->identity().axes[a].letter;
    return out;
}

bool AccuracyRunner::start(motion::msg::Message* why)
{
    auto refuse = [&](motion::msg::Message m) {
        if (why)
            *why = m;
        emit problem(m);
        return false;
    };
    if (!m_prepared)
        return refuse(motion::msg::make("accuracy.run.not_prepared"));
    if (isActive())
        return refuse(motion::msg::make("accuracy.run.busy"));
    if (m_state == State::Finished || m_entries.size() >= m_stops.size())
        return refuse(motion::msg::make("accuracy.run.finished_already"));
    if (!m_instrument || !m_instrument->isReady())
        return refuse(motion::msg::make("accuracy.run.not_connected"));
    const dev::InstrumentStatus& st = m_instrument->status();
    if (st.estop)
        return refuse(motion::msg::make("accuracy.run.estop"));
    for (int a : m_axes)
        if (a >= st.axes.size() || !st.axes[a].homed)
            return refuse(motion::msg::make("accuracy.run.not_homed",
                                    {motion::msg::verbatim("axis", QString(m_instrument->identity().axes[a].letter).toStdString())}));
    ++m_generation;
    m_firstOfSession = true;
    m_haveSessionStart = false;
    m_timeBaseS = m_entries.empty() ? 0.0 : m_entries.back().timeS;
    m_sessionEstimateS = m_sessionActualS = 0;
    m_sessionFirst = static_cast<int>(m_entries.size());
    setState(State::Running);
    nextStop();
    return true;
}

void AccuracyRunner::pause()
{
    if (m_state == State::Running)
        setState(State::Pausing);
}

void AccuracyRunner::abort()
{
    if (isActive())
        stopWith(motion::msg::make("accuracy.run.aborted"), true);
    else if (m_state == State::Paused)
        stopWith(motion::msg::make("accuracy.run.aborted"), false);
}

void AccuracyRunner::stopWith(const motion::msg::Message& why, bool stopAxes)
{
    ++m_generation;  // every callback in flight is now stale
    m_poll.stop();
    if (m_source)
        m_source->cancel();
    if (stopAxes && m_instrument && m_instrument->isReady())
        m_instrument->stop(axisMask());
    m_phase = Phase::None;
    m_waitingAxes = 0;
    setState(State::Stopped);
    emit problem(why);
}

void AccuracyRunner::nextStop()
{
    if (m_state == State::Pausing) {
        setState(State::Paused);
        return;
    }
    if (!isActive())
        return;
    const std::size_t k = m_entries.size();
    if (k >= m_stops.size()) {
        finish();
        return;
    }
    emit stopStarted(static_cast<int>(k));
    emit progress(static_cast<int>(k), totalReadings(), etaS());
    const PlannedStop& s = m_stops[k];
    if (s.overrunMm) {
        moveTo(*s.overrunMm, Phase::Overrun);
    } else if (m_firstOfSession) {
        // A resumed run does not know where the axis came from: go to where this stop's
        // final move starts, so it is approached from its own side.
        moveTo(s.approachFromMm, Phase::Approach);
    } else {
        moveTo(s.targetMm, Phase::Target);
    }
    m_firstOfSession = false;
}

void AccuracyRunner::moveTo(const std::vector<double>& positionsMm, Phase phase)
{
    m_phase = phase;
    m_waitingAxes = 0;
    m_moveAccepted = false;
    m_motionDoneUs = 0;
    QVector<QPair<int, double>> targets;
    std::vector<std::pair<int, double>> expected;
    for (std::size_t n = 0; n < m_axes.size() && n < positionsMm.size(); ++n) {
        targets.push_back({m_axes[n], positionsMm[n]});
        expected.emplace_back(m_axes[n], positionsMm[n]);
        m_waitingAxes |= 1u << m_axes[n];
    }
    m_arrival.expect(std::move(expected));
    const quint64 generation = m_generation;
    const QPointer<AccuracyRunner> self(this);
    m_instrument->move(targets, false, feedOf(m_test), [self, generation](const std::optional<dev::RequestError>& e) {
        if (self)
            self->onMoveAccepted(e, generation);
    });
}

void AccuracyRunner::onMoveAccepted(const std::optional<dev::RequestError>& error, quint64 generation)
{
    if (generation != m_generation || !isActive())
        return;
    if (error) {
        stopWith(motion::msg::make("accuracy.run.move_refused", {motion::msg::nested("detail", error->message)}), false);
        return;
    }
    m_moveAccepted = true;
    if (m_waitingAxes == 0)
        onMoveDone();  // the MotionDone events came before the reply
}

void AccuracyRunner::onEvent(const dev::DeviceEvent& e)
{
    if (!isActive())
        return;
    if (e.kind == dev::proto::EventKind::EStop) {
        stopWith(motion::msg::make("accuracy.run.estop"), false);
        return;
    }
    const bool ours = e.axis >= 0 && (axisMask() & (1u << e.axis));
    if (!ours || m_phase == Phase::None || m_phase == Phase::Settling || m_phase == Phase::Reading)
        return;
    if (e.kind == dev::proto::EventKind::MotionDone) {
        m_waitingAxes &= ~(1u << e.axis);
        m_motionDoneUs = std::max<quint64>(m_motionDoneUs, e.deviceTimeUs);
        if (m_waitingAxes == 0 && m_moveAccepted)
            onMoveDone();
        return;
    }
    if (e.kind == dev::proto::EventKind::Stopped || e.kind == dev::proto::EventKind::LimitHit || e.kind == dev::proto::EventKind::Fault
        || e.kind == dev::proto::EventKind::LostSteps) {
        const QString letter = e.axis < m_instrument->identity().axes.size() ? QString(m_instrument->identity().axes[e.axis].letter) : QString();
        stopWith(motion::msg::make("accuracy.run.axis_stopped", {motion::msg::verbatim("axis", letter.toStdString()),
                                                         motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e)}),
                 e.kind == dev::proto::EventKind::LostSteps);
    }
}

void AccuracyRunner::onMoveDone()
{
    const PlannedStop& s = m_stops[m_entries.size()];
    if (m_phase == Phase::Overrun || m_phase == Phase::Approach) {
        moveTo(s.targetMm, Phase::Target);
        return;
    }
    // At the target: dwell, then wait for the readback to settle, on the device clock.
    m_phase = Phase::Settling;
    m_settleStartUs = 0;
    m_haveSettleSample = false;
    pollSettle();
}

void AccuracyRunner::pollSettle()
{
    if (!isActive() || m_phase != Phase::Settling)
        return;
    const quint64 generation = m_generation;
    const QPointer<AccuracyRunner> self(this);
    m_instrument->readStatus([self, generation](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        if (e) {
            self->stopWith(motion::msg::make("accuracy.run.status_failed", {motion::msg::nested("detail", e->message)}), false);
            return;
        }
        self->onStatus(s);
    });
}

void AccuracyRunner::onStatus(const dev::InstrumentStatus& s)
{
    const quint64 now = s.deviceTimeUs;
    m_lastDeviceUs = now;
    if (!m_haveSessionStart) {
        m_sessionStartUs = now;
        m_haveSessionStart = true;
    }
    if (s.estop) {
        stopWith(motion::msg::make("accuracy.run.estop"), false);
        return;
    }
    const motion::metrology::SettleRule& rule = settleOf(m_test);
    const quint64 dwellEnd = m_motionDoneUs + static_cast<quint64>(std::llround(dwellOf(m_test) * 1e6));
    if (now < dwellEnd) {
        m_poll.start(kPollMs);
        return;
    }
    std::vector<double> values;
    for (int a : m_axes)
        values.push_back(a < s.axes.size() ? s.axes[a].measured : 0.0);
    if (!m_haveSettleSample) {
        m_haveSettleSample = true;
        m_settleStartUs = now;
        m_stableSinceUs = now;
        m_stableMin = m_stableMax = values;
    } else {
        bool within = true;
        for (std::size_t n = 0; n < values.size(); ++n) {
            const double lo = std::min(m_stableMin[n], values[n]), hi = std::max(m_stableMax[n], values[n]);
            if ((hi - lo) * 1e3 > rule.toleranceUm + 1e-9)
                within = false;
        }
        if (!within) {
            m_stableSinceUs = now;
            m_stableMin = m_stableMax = values;
        } else {
            for (std::size_t n = 0; n < values.size(); ++n) {
                m_stableMin[n] = std::min(m_stableMin[n], values[n]);
                m_stableMax[n] = std::max(m_stableMax[n], values[n]);
            }
        }
    }
    const bool settled = now - m_stableSinceUs >= static_cast<quint64>(std::llround(rule.windowS * 1e6));
    const bool timedOut = now - m_settleStartUs >= static_cast<quint64>(std::llround(rule.timeoutS * 1e6));
    if (settled || timedOut) {
        takeReading(settled);
        return;
    }
    m_poll.start(kPollMs);
}

void AccuracyRunner::takeReading(bool settled)
{
    m_phase = Phase::Reading;
    const std::size_t k = m_entries.size();
    const PlannedStop& s = m_stops[k];
    StopContext ctx;
    ctx.index = static_cast<int>(k);
    ctx.total = totalReadings();
    ctx.cycle = s.cycle;
    ctx.direction = s.direction;
    ctx.axes = m_axes;
    for (int a : m_axes)
        ctx.letters.push_back(m_instrument->identity().axes[a].letter);
    ctx.targetsMm = s.targetMm;
    ctx.deviceTimeUs = m_lastDeviceUs;
    ctx.runTimeS = m_timeBaseS + (m_lastDeviceUs - m_sessionStartUs) * 1e-6;
    const quint64 generation = m_generation;
    const quint64 at = m_lastDeviceUs;
    const QPointer<AccuracyRunner> self(this);
    m_source->take(ctx, [self, generation, settled, at](const TakeResult& r) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        self->onReading(r, settled, at);
    });
}

void AccuracyRunner::onReading(const TakeResult& r, bool settled, quint64 deviceTimeUs)
{
    if (!r.problem.empty()) {
        stopWith(r.problem, false);
        return;
    }
    const std::size_t k = m_entries.size();
    const PlannedStop& s = m_stops[k];
    dev::files::accuracy::RunLogEntry e;
    e.stop = static_cast<int>(k);
    e.cycle = s.cycle;
    e.direction = s.direction;
    e.targetMm = s.targetMm;
    if (!r.deferred) {
        if (r.valuesMm.size() != s.targetMm.size()) {
            stopWith(motion::msg::make("accuracy.run.reading_incomplete", {motion::msg::integer("count", static_cast<long long>(r.valuesMm.size())),
                                                                   motion::msg::integer("expected", static_cast<long long>(s.targetMm.size()))}),
                     false);
            return;
        }
        e.measuredMm = r.valuesMm;
    }
    e.settled = settled;
    e.deviceTimeUs = deviceTimeUs;
    e.timeS = m_timeBaseS + (deviceTimeUs - m_sessionStartUs) * 1e-6;
    if (!appendLog(e))
        return;  // appendLog stopped the run with its reason
    m_sessionEstimateS += estimateStopS(k, false);
    m_sessionActualS = e.timeS - m_timeBaseS;
    m_entries.push_back(std::move(e));
    m_phase = Phase::None;
    emit readingTaken(static_cast<int>(k));
    emit progress(readingsTaken(), totalReadings(), etaS());
    nextStop();
}

double AccuracyRunner::estimateStopS(std::size_t k, bool fromHere) const
{
    if (k >= m_stops.size())
        return 0;
    const PlannedStop& s = m_stops[k];
    double accel = 100;  // mm/s², a device that did not say
    double vmax = 1e9;
    if (m_instrument)
        for (int a : m_axes)
            if (a < m_instrument->identity().axes.size()) {
                const auto& d = m_instrument->identity().axes[a];
                if (d.maxAccel > 0)
                    accel = std::min(accel == 100 ? d.maxAccel : accel, d.maxAccel);
                if (d.maxSpeed > 0)
                    vmax = std::min(vmax, d.maxSpeed);
            }
    const double v = std::min(feedOf(m_test), vmax);
    auto moveS = [&](const std::vector<double>& from, const std::vector<double>& to) {
        double d2 = 0;
        for (std::size_t n = 0; n < from.size() && n < to.size(); ++n)
            d2 += (to[n] - from[n]) * (to[n] - from[n]);
        const double d = std::sqrt(d2);
        return d < 1e-9 ? 0.0 : d / v + v / accel;
    };
    double t = dwellOf(m_test) + settleOf(m_test).windowS + 0.05;
    const std::vector<double>& start = (fromHere || !s.overrunMm) ? s.approachFromMm : *s.overrunMm;
    if (s.overrunMm) {
        const std::vector<double>& prev = k > 0 ? m_stops[k - 1].targetMm : s.approachFromMm;
        t += moveS(prev, *s.overrunMm);
    }
    t += moveS(start, s.targetMm);
    return t;
}

double AccuracyRunner::etaS() const
{
    double left = 0;
    for (std::size_t k = m_entries.size(); k < m_stops.size(); ++k)
        left += estimateStopS(k, false);
    // This run's pace so far, once a few stops give it a meaning.
    const int done = readingsTaken() - m_sessionFirst;
    if (done >= 2 && m_sessionEstimateS > 0 && m_sessionActualS > 0)
        left *= std::clamp(m_sessionActualS / m_sessionEstimateS, 0.25, 4.0);
    return left;
}

} // namespace dev::jobs
