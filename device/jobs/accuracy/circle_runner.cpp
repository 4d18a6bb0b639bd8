#include "device/jobs/accuracy/circle_runner.h"
#include "device/jobs/accuracy/reading_source.h"

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using motion::metrology::Rotation;
using motion::path::Segment;
using motion::path::SegmentKind;
using motion::path::Vec2;

namespace {
constexpr double kPi = 3.141592653589793;
double wrap(double a)
{
    while (a > kPi)
        a -= 2 * kPi;
    while (a <= -kPi)
        a += 2 * kPi;
    return a;
}
} // namespace

CircleRunner::CircleRunner(dev::Instrument* instrument, QObject* parent) : QObject(parent), m_instrument(instrument)
{
    qRegisterMetaType<dev::jobs::CircleRunner::State>();
    m_poll.setSingleShot(true);
    connect(&m_poll, &QTimer::timeout, this, &CircleRunner::poll);
    if (!instrument)
        return;
    m_connections << connect(instrument, &dev::Instrument::eventReceived, this, [this](const dev::DeviceEvent& e) {
        if (!isActive())
            return;
        if (e.kind == dev::proto::EventKind::EStop) {
            stopWith(motion::msg::make("accuracy.run.estop"));
            return;
        }
        if (m_phase != Phase::ToStart || (e.axis != m_axisX && e.axis != m_axisY))
            return;
        if (e.kind == dev::proto::EventKind::MotionDone) {
            m_waitingAxes &= ~(1u << e.axis);
            if (m_waitingAxes == 0 && m_moveAccepted)
                nextRun();
        } else if (e.kind == dev::proto::EventKind::Stopped || e.kind == dev::proto::EventKind::LimitHit || e.kind == dev::proto::EventKind::Fault) {
            stopWith(motion::msg::make("accuracy.run.axis_stopped", {motion::msg::verbatim("axis", e.axis == m_axisX ? "X" : "Y"),
                                                             motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e)}));
        }
    });
    m_connections << connect(instrument, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (isActive() && s != dev::LinkState::Ready)
            stopWith(motion::msg::make("accuracy.run.link_lost"));
    });
    m_connections << connect(instrument, &dev::Instrument::statusChanged, this, [this](const dev::InstrumentStatus& s) {
        if (!isActive() || m_phase != Phase::ToStart || !m_moveAccepted || m_waitingAxes == 0 || !m_arrival.feed(s))
            return;
        m_waitingAxes = 0;
        nextRun();
    });
}

CircleRunner::~CircleRunner()
{
    for (const auto& c : m_connections)
        disconnect(c);
    for (const auto& c : m_pathConnections)
        disconnect(c);
}

void CircleRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

bool CircleRunner::prepare(const motion::metrology::CircularTest& test, motion::msg::Problems* problems)
{
    if (problems)
        problems->clear();
    auto refuse = [&](motion::msg::Message m) {
        if (problems)
            problems->push_back({"", std::move(m)});
        return false;
    };
    if (isActive())
        return refuse(motion::msg::make("accuracy.run.busy"));
    m_prepared = false;
    if (!m_instrument || !m_instrument->isReady())
        return refuse(motion::msg::make("accuracy.run.not_connected"));
    if (!m_instrument->can(dev::Capability::PathQueue))
        return refuse(m_instrument->whyNot(dev::Capability::PathQueue));
    const auto& id = m_instrument->identity();
    if (test.axes.size() != 2)
        return refuse(motion::msg::make("accuracy.circle.axes_invalid", {motion::msg::verbatim("axes", test.axes)}));
    const int ax = id.axisIndex(QChar::fromLatin1(test.axes[0])), ay = id.axisIndex(QChar::fromLatin1(test.axes[1]));
    if (ax < 0 || ay < 0 || test.axes != "XY")
        return refuse(motion::msg::make("accuracy.run.no_such_axis", {motion::msg::verbatim("axis", test.axes)}));
    motion::metrology::XyLimits lim;
    auto limitsOf = [&](int i) {
        motion::metrology::AxisLimits l;
        if (i < m_instrument->softLimits().size()) {
            l.minMm = m_instrument->softLimits()[i].min;
            l.maxMm = m_instrument->softLimits()[i].max;
        }
        return l;
    };
    lim.x = limitsOf(ax);
    lim.y = limitsOf(ay);
    const double vmax = std::min(id.axes[ax].maxSpeed, id.axes[ay].maxSpeed);
    if (vmax > 0)
        lim.maxFeedMmS = vmax;
    const auto found = motion::metrology::validate(test, lim);
    if (problems)
        problems->insert(problems->end(), found.begin(), found.end());
    if (motion::msg::hasErrors(found))
        return false;
    m_test = test;
    m_axisX = ax;
    m_axisY = ay;
    m_rotations.clear();
    if (test.counterClockwise)
        m_rotations.push_back(Rotation::Ccw);
    if (test.clockwise)
        m_rotations.push_back(Rotation::Cw);
    m_runs.clear();
    m_current = {};
    m_prepared = true;
    setState(State::Idle);
    return true;
}

bool CircleRunner::start(motion::msg::Message* why)
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
    if (m_runs.size() >= m_rotations.size())
        return refuse(motion::msg::make("accuracy.run.finished_already"));
    if (!m_instrument || !m_instrument->isReady())
        return refuse(motion::msg::make("accuracy.run.not_connected"));
    const auto& st = m_instrument->status();
    if (st.estop)
        return refuse(motion::msg::make("accuracy.run.estop"));
    for (int a : {m_axisX, m_axisY})
        if (a >= st.axes.size() || !st.axes[a].homed)
            return refuse(motion::msg::make("accuracy.run.not_homed", {motion::msg::verbatim("axis", a == m_axisX ? "X" : "Y")}));
    m_paths = m_instrument->paths();  // fetched now: a backend switch replaces the part
    if (!m_paths)
        return refuse(m_instrument->whyNot(dev::Capability::PathQueue));
    for (const auto& c : m_pathConnections)
        disconnect(c);
    m_pathConnections.clear();
    m_pathConnections << connect(m_paths, &dev::PathClient::finished, this, [this](quint32, quint64) {
        if (isActive() && m_phase == Phase::Path)
            m_pathDone = true;  // the next status reading ends the run, so its last sample is in
    });
    m_pathConnections << connect(m_paths, &dev::PathClient::aborted, this, [this](quint32, const QString& reason) {
        if (isActive() && m_phase == Phase::Path)
            stopWith(motion::msg::make("accuracy.run.path_aborted", {motion::msg::verbatim("detail", reason.toStdString())}));
    });
    ++m_generation;
    setState(State::Running);
    beginDirection();
    return true;
}

void CircleRunner::beginDirection()
{
    // To the start of the lead-in arc of the next direction.
    const Rotation r = m_rotations[m_runs.size()];
    const double lead = m_test.leadArcDeg * kPi / 180;
    const Vec2 start = pointAt(r == Rotation::Ccw ? -lead : lead);
    m_phase = Phase::ToStart;
    m_waitingAxes = (1u << m_axisX) | (1u << m_axisY);
    m_moveAccepted = false;
    m_arrival.expect({{m_axisX, start.x}, {m_axisY, start.y}});
    const quint64 generation = m_generation;
    const QPointer<CircleRunner> self(this);
    m_instrument->move({{m_axisX, start.x}, {m_axisY, start.y}}, false, m_test.feedMmS,
                       [self, generation](const std::optional<dev::RequestError>& e) {
                           if (!self || generation != self->m_generation || !self->isActive())
                               return;
                           if (e) {
                               self->stopWith(motion::msg::make("accuracy.run.move_refused", {motion::msg::nested("detail", e->message)}));
                               return;
                           }
                           self->m_moveAccepted = true;
                           if (self->m_waitingAxes == 0)
                               self->nextRun();
                       });
    emit progress(static_cast<double>(m_runs.size()) / static_cast<double>(m_rotations.size()), etaS());
}

Vec2 CircleRunner::pointAt(double angleRad) const
{
    return {m_test.centreMm.xMm + m_test.radiusMm * std::cos(angleRad), m_test.centreMm.yMm + m_test.radiusMm * std::sin(angleRad)};
}

std::vector<Segment> CircleRunner::pathFor(Rotation r) const
{
    const double sign = r == Rotation::Ccw ? 1 : -1;
    const double lead = m_test.leadArcDeg * kPi / 180;
    std::vector<double> cuts{-lead};
    for (int q = 0; q <= 4; ++q)
        cuts.push_back(q * kPi / 2);
    cuts.push_back(2 * kPi + lead);
    std::vector<Segment> out;
    const Vec2 centre{m_test.centreMm.xMm, m_test.centreMm.yMm};
    for (std::size_t k = 1; k < cuts.size(); ++k) {
        if (cuts[k] - cuts[k - 1] < 1e-9)
            continue;  // no lead arc
        Segment s;
        s.kind = r == Rotation::Ccw ? SegmentKind::ArcCcw : SegmentKind::ArcCw;
        s.start = pointAt(sign * cuts[k - 1]);
        s.end = pointAt(sign * cuts[k]);
        s.center = centre;
        s.feedMmS = m_test.feedMmS;
        out.push_back(s);
    }
    return out;
}

void CircleRunner::nextRun()
{
    if (!isActive() || m_phase != Phase::ToStart)
        return;
    const Rotation r = m_rotations[m_runs.size()];
    m_current = {};
    m_current.rotation = r;
    m_travelledRad = 0;
    m_haveAngle = false;
    m_pathDone = false;
    m_binTaken.assign(static_cast<std::size_t>(std::max(8, m_test.samplesPerRevolution)), 0);
    m_phase = Phase::Path;
    const auto path = pathFor(r);
    const quint64 generation = m_generation;
    const QPointer<CircleRunner> self(this);
    m_paths->begin(0, [self, generation, path](const std::optional<dev::RequestError>& e, const dev::PathQueueState&) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        if (e) {
            self->stopWith(motion::msg::make("accuracy.run.move_refused", {motion::msg::nested("detail", e->message)}));
            return;
        }
        self->m_paths->append(0, path, true, true, [self, generation](const std::optional<dev::RequestError>& e2, const dev::PathQueueState&) {
            if (self)
                self->onPathAppended(e2, generation);
        });
    });
}

void CircleRunner::onPathAppended(const std::optional<dev::RequestError>& e, quint64 generation)
{
    if (generation != m_generation || !isActive())
        return;
    if (e) {
        stopWith(motion::msg::make("accuracy.run.move_refused", {motion::msg::nested("detail", e->message)}));
        return;
    }
    poll();
}

void CircleRunner::poll()
{
    if (!isActive() || m_phase != Phase::Path)
        return;
    const quint64 generation = m_generation;
    const QPointer<CircleRunner> self(this);
    m_instrument->readStatus([self, generation](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        if (e) {
            self->stopWith(motion::msg::make("accuracy.run.status_failed", {motion::msg::nested("detail", e->message)}));
            return;
        }
        const bool telemetry = self->telemetryComing();
        if (!telemetry && self->m_axisX < s.axes.size() && self->m_axisY < s.axes.size())
            self->takeSample(s.axes[self->m_axisX].measured, s.axes[self->m_axisY].measured);
        if (self->m_pathDone) {
            self->endRun();
            return;
        }
        self->m_poll.start(telemetry ? kEndPollMs : kSamplePollMs);
    });
}

void CircleRunner::addSample(double xMm, double yMm)
{
    if (!isActive() || m_phase != Phase::Path)
        return;
    m_sinceTelemetry.start();
    takeSample(xMm, yMm);
}

bool CircleRunner::telemetryComing() const
{
    return m_sinceTelemetry.isValid() && m_sinceTelemetry.elapsed() < kTelemetryStaleMs;
}

void CircleRunner::takeSample(double xMm, double yMm)
{
    const double angle = std::atan2(yMm - m_test.centreMm.yMm, xMm - m_test.centreMm.xMm);
    const double sign = m_current.rotation == Rotation::Ccw ? 1 : -1;
    if (!m_haveAngle) {
        // The run starts at −lead (ccw) or +lead (cw): travelled angle 0 there.
        const double lead = m_test.leadArcDeg * kPi / 180;
        m_travelledRad = sign * wrap(angle + sign * lead);
        m_haveAngle = true;
    } else {
        m_travelledRad += sign * wrap(angle - m_lastAngleRad);
    }
    m_lastAngleRad = angle;
    emit sampled(xMm, yMm);
    // The evaluated revolution: from the end of the lead-in arc, one turn.
    const double lead = m_test.leadArcDeg * kPi / 180;
    const double into = m_travelledRad - lead;
    if (into < 0 || into >= 2 * kPi)
        return;
    const auto bins = m_binTaken.size();
    const auto bin = std::min(bins - 1, static_cast<std::size_t>(into / (2 * kPi) * static_cast<double>(bins)));
    if (m_binTaken[bin])
        return;
    m_binTaken[bin] = 1;
    m_current.samplesMm.push_back({xMm, yMm});
    emit progress((static_cast<double>(m_runs.size()) + into / (2 * kPi)) / static_cast<double>(m_rotations.size()), etaS());
}

void CircleRunner::endRun()
{
    m_phase = Phase::None;
    m_runs.push_back(m_current);
    emit runDone(static_cast<int>(m_runs.size()) - 1);
    if (m_runs.size() >= m_rotations.size()) {
        setState(State::Finished);
        emit progress(1.0, 0);
        emit finished();
        return;
    }
    if (m_state == State::Pausing) {
        setState(State::Paused);
        return;
    }
    beginDirection();
}

void CircleRunner::pause()
{
    if (m_state == State::Running)
        setState(State::Pausing);
}

void CircleRunner::abort()
{
    if (!isActive() && m_state != State::Paused)
        return;
    const bool moving = isActive();
    stopWith(motion::msg::make("accuracy.run.aborted"));
    if (moving && m_instrument && m_instrument->isReady()) {
        if (m_paths)
            m_paths->clear();
        m_instrument->stop(static_cast<quint8>((1u << m_axisX) | (1u << m_axisY)));
    }
}

void CircleRunner::stopWith(const motion::msg::Message& why)
{
    ++m_generation;
    m_poll.stop();
    m_phase = Phase::None;
    m_current = {};
    setState(State::Stopped);
    emit problem(why);
}

motion::metrology::CircularEvaluation CircleRunner::evaluation() const { return motion::metrology::evaluate(m_test, m_runs); }

double CircleRunner::revolutionS() const
{
    const double lead = m_test.leadArcDeg * kPi / 180;
    return m_test.feedMmS > 0 ? (2 * kPi + 2 * lead) * m_test.radiusMm / m_test.feedMmS : 0;
}

double CircleRunner::etaS() const
{
    const double left = static_cast<double>(m_rotations.size() - std::min(m_rotations.size(), m_runs.size()));
    return left * (revolutionS() + 1.0);
}

} // namespace dev::jobs
