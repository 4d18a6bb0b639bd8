#include "device/backends/grbl/client/grbl_path_client.h"

#include "device/backends/grbl/client/grbl_client.h"
#include "device/backends/grbl/grbl_gcode.h"

#include <cmath>

namespace dev {

using motion::path::Segment;
using motion::path::Vec2;

namespace {

std::optional<RequestError> pathError(dev::proto::ErrorCode code, double value, motion::msg::Message message)
{
    RequestError e;
    e.kind = RequestError::Kind::Device;
    e.code = code;
    e.value = value;
    e.message = std::move(message);
    return e;
}

} // namespace

GrblPathClient::GrblPathClient(GrblClient* client, QObject* parent) : PathClient(parent), m_client(client)
{
    connect(client, &GrblClient::reportApplied, this, &GrblPathClient::onReport);
    connect(client, &GrblClient::controllerReset, this, &GrblPathClient::onReset);
    connect(client, &GrblClient::alarmRaised, this, &GrblPathClient::onAlarm);
    connect(client, &Instrument::stateChanged, this, [this](LinkState s) {
        if (s != LinkState::Ready && active())
            abortWith(dev::proto::PathReason::NewSession);
    });
}

bool GrblPathClient::available() const { return m_client && m_client->can(Capability::PathQueue); }

bool GrblPathClient::active() const
{
    using S = dev::proto::PathState;
    return m_state == S::Filling || m_state == S::Running || m_state == S::Starved || m_state == S::Holding || m_state == S::Held;
}

motion::path::PathLimits GrblPathClient::limits() const
{
    motion::path::PathLimits l;
    if (!m_client)
        return l;
    const auto& axes = m_client->machineLimits().axes;
    const int gx = m_client->grblIndexOf(0), gy = m_client->grblIndexOf(1);
    if (gx < 0 || gy < 0 || gx >= static_cast<int>(axes.size()) || gy >= static_cast<int>(axes.size()))
        return l;
    // GRBL limits each axis: along any XY direction at least the smaller of the two holds.
    l.accelMmS2 = std::min(axes[static_cast<std::size_t>(gx)].accelMmS2, axes[static_cast<std::size_t>(gy)].accelMmS2);
    l.maxSpeedMmS = std::min(axes[static_cast<std::size_t>(gx)].maxRateMmS, axes[static_cast<std::size_t>(gy)].maxRateMmS);
    l.junctionDeviationMm = m_client->machineLimits().junctionDeviationMm;
    return l;
}

void GrblPathClient::refreshLimits(Callback done)
{
    // Read with $$ at connection; GRBL's limits change only when its settings do.
    if (done)
        done(std::nullopt);
}

PathQueueState GrblPathClient::snapshot() const
{
    PathQueueState s;
    s.state = m_state;
    s.capacity = kCapacity;
    s.freeSlots = std::max(0, kCapacity - static_cast<int>(m_next - m_executing));
    s.nextIndex = m_next;
    s.executingIndex = m_executing;
    s.speedMmS = m_speedMmS;
    s.reason = m_reason;
    const auto l = limits();
    s.accelMmS2 = l.accelMmS2;
    s.junctionDeviationMm = l.junctionDeviationMm;
    return s;
}

void GrblPathClient::begin(quint32 firstIndex, Reply done)
{
    if (!available())
        return done(pathError(dev::proto::ErrorCode::PathState, 0, motion::msg::make("request.instrument_not_connected")), snapshot());
    if (active())
        return done(pathError(dev::proto::ErrorCode::PathState, m_next, motion::msg::make("grbl.path.already_running")), snapshot());
    m_state = dev::proto::PathState::Filling;
    m_reason = dev::proto::PathReason::None;
    m_segments.clear();
    m_first = m_next = m_executing = firstIndex;
    m_haveLast = false;
    m_linesOpen = 0;
    m_lastAckUs = 0;
    m_started = false;
    m_underrunSaid = false;
    m_holdAsked = m_clearAsked = false;
    done(std::nullopt, snapshot());
}

void GrblPathClient::append(quint32 firstIndex, const std::vector<Segment>& segments, bool start, bool last, Reply done)
{
    if (!active() || !m_client)
        return done(pathError(dev::proto::ErrorCode::PathState, m_next, motion::msg::make("grbl.path.not_begun")), snapshot());
    if (firstIndex != m_next)
        return done(pathError(dev::proto::ErrorCode::PathSequence, m_next,
                              motion::msg::make("grbl.path.out_of_sequence", {motion::msg::integer("expected", m_next, motion::msg::Unit::None),
                                                                      motion::msg::integer("sent", firstIndex, motion::msg::Unit::None)})),
                    snapshot());
    const int free = kCapacity - static_cast<int>(m_next - m_executing);
    if (static_cast<int>(segments.size()) > free)
        return done(pathError(dev::proto::ErrorCode::PathQueueFull, free, motion::msg::make("grbl.path.window_full", {motion::msg::integer("free", free)})), snapshot());
    // Paths need the instrument's X and Y on GRBL's X and Y (its XY plane, G17): capabilities()
    // says so, and available() is false otherwise.
    std::vector<std::string> lines;
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const Segment& s = segments[k];
        if (s.zMm)
            return done(pathError(dev::proto::ErrorCode::PathGeometry, firstIndex + k,
                                  motion::msg::make("grbl.path.z_in_path", {motion::msg::integer("segment", static_cast<long long>(firstIndex + k), motion::msg::Unit::None)})),
                        snapshot());
        const double feed = s.feedMmS * 60;
        const dev::grbl::GcodeLine l = s.isArc()
                                      ? dev::grbl::arcLine(s.ccw() ? dev::grbl::ArcDirection::CounterClockwise : dev::grbl::ArcDirection::Clockwise, s.end.x,
                                                      s.end.y, s.center.x - s.start.x, s.center.y - s.start.y, feed)
                                      : dev::grbl::moveLine(dev::grbl::Motion::Feed, false, {{'X', s.end.x}, {'Y', s.end.y}}, feed);
        if (!l.ok()) {
            motion::msg::Message problem = l.problem;  // grbl.gcode.*, with the segment it was for
            problem.args.push_back(motion::msg::integer("segment", static_cast<long long>(firstIndex + k), motion::msg::Unit::None));
            return done(pathError(dev::proto::ErrorCode::PathGeometry, firstIndex + k, std::move(problem)), snapshot());
        }
        lines.push_back(l.text);
    }
    const QPointer<GrblPathClient> self(this);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const quint32 index = firstIndex + static_cast<quint32>(k);
        ++m_linesOpen;
        const bool queued = m_client->sendLine(lines[k], [self, index](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self || !self->m_client)
                return;
            self->m_linesOpen = std::max(0, self->m_linesOpen - 1);
            self->m_lastAckUs = self->m_client->nowUs();
            if (!self->active())
                return;
            if (!a) {
                self->abortWith(dev::proto::PathReason::NewSession);
                return;
            }
            if (!a->ok) {
                // An error mid-job stops the job: what GRBL already holds is flushed, and the line is named.
                RequestError e = GrblClient::errorOf(a->errorCode, a->line, "request.path_segments");
                e.message.args.push_back(motion::msg::integer("segment", index, motion::msg::Unit::None));
                e.value = index;
                emit self->m_client->requestFailed(e);
                self->abortWith(dev::proto::PathReason::Stop, QStringLiteral("error:%1").arg(a->errorCode));
                self->m_client->holdThenFlush({});
                return;
            }
            if (!self->m_started) {
                self->m_started = true;
                emit self->started(self->m_first);
                emit self->startedAt(self->m_client->nowUs());
            }
        });
        if (!queued) {
            --m_linesOpen;
            abortWith(dev::proto::PathReason::NewSession);
            return done(pathError(dev::proto::ErrorCode::PathState, index, motion::msg::make("request.instrument_not_connected")), snapshot());
        }
        m_segments[index] = segments[k];
    }
    m_next = firstIndex + static_cast<quint32>(segments.size());
    if (last) {
        m_haveLast = true;
        m_lastIndex = m_next - 1;
    }
    m_underrunSaid = false;
    if (start && (m_state == dev::proto::PathState::Filling || m_state == dev::proto::PathState::Starved))
        m_state = dev::proto::PathState::Running;
    done(std::nullopt, snapshot());
}

void GrblPathClient::queryStatus(Reply done) { done(std::nullopt, snapshot()); }

void GrblPathClient::hold(Callback done)
{
    if (active() && m_state != dev::proto::PathState::Held && m_client) {
        m_holdAsked = true;
        m_state = dev::proto::PathState::Holding;
        m_reason = dev::proto::PathReason::HostHold;
        m_client->sendRealtime(dev::grbl::rt::kFeedHold);
    }
    if (done)
        done(std::nullopt);
}

void GrblPathClient::resume(Callback done)
{
    if ((m_state == dev::proto::PathState::Holding || m_state == dev::proto::PathState::Held) && m_client) {
        m_client->sendRealtime(dev::grbl::rt::kCycleStart);
        m_state = dev::proto::PathState::Running;
        m_reason = dev::proto::PathReason::None;
        m_holdAsked = false;
    }
    if (done)
        done(std::nullopt);
}

void GrblPathClient::clear(Callback done)
{
    if (!active() || !m_client) {
        if (done)
            done(std::nullopt);
        return;
    }
    m_clearAsked = true;
    const QPointer<GrblPathClient> self(this);
    m_client->holdThenFlush([self, done](const std::optional<RequestError>& e) {
        if (self && self->active())
            self->abortWith(dev::proto::PathReason::Cleared);
        if (done)
            done(e);
    });
}

void GrblPathClient::advanceTo(quint32 index)
{
    while (m_executing < index) {
        m_segments.erase(m_executing);
        emit segmentDone(m_executing);
        ++m_executing;
    }
}

void GrblPathClient::onReport(quint64 askedUs)
{
    if (!active() || !m_client)
        return;
    const auto& work = m_client->workPositionMm();
    const Vec2 p{m_client->instrumentValue(0, work), m_client->instrumentValue(1, work)};
    const dev::grbl::MachineState st = m_client->machineState();
    m_speedMmS = m_client->feedMmMin().value_or(0) / 60;
    // Which sent segment the machine is on: the first (from the one executing) that the position
    // lies inside. GRBL follows the G-code's geometry, so a position is on its segment.
    bool atEnd = false;
    for (quint32 j = m_executing; j < m_next; ++j) {
        const auto it = m_segments.find(j);
        if (it == m_segments.end())
            continue;
        const auto near = motion::path::nearestOn(it->second, p);
        const double len = motion::path::lengthMm(it->second);
        if (std::fabs(near.distanceMm) < kOnSegmentMm && near.alongMm < len - kOnSegmentMm) {
            advanceTo(j);
            break;
        }
        if (j + 1 == m_next && motion::path::norm(it->second.end - p) < kOnSegmentMm) {
            advanceTo(j);
            atEnd = true;
        }
    }
    const bool settled = m_linesOpen == 0 && askedUs > m_lastAckUs && st == dev::grbl::MachineState::Idle;
    if (m_state == dev::proto::PathState::Holding && st == dev::grbl::MachineState::Hold && m_client->status().axes.size() >= 2
        && !m_client->status().axes[0].moving && !m_client->status().axes[1].moving) {
        m_state = dev::proto::PathState::Held;
        emit held(m_executing, QString());
        return;
    }
    if (!settled || m_state == dev::proto::PathState::Holding || m_state == dev::proto::PathState::Held)
        return;
    if (m_haveLast && m_executing >= m_lastIndex && atEnd) {
        advanceTo(m_lastIndex);
        m_segments.clear();
        emit segmentDone(m_lastIndex);
        m_executing = m_lastIndex + 1;
        m_state = dev::proto::PathState::Done;
        emit finished(m_lastIndex, m_client->nowUs());
        return;
    }
    if (atEnd && !m_haveLast && !m_underrunSaid) {
        // GRBL plans to rest at the end of what it holds: it ran dry before the path's end.
        m_underrunSaid = true;
        m_state = dev::proto::PathState::Starved;
        emit underrun(m_next - 1);
    }
}

void GrblPathClient::onReset(bool expected)
{
    if (!active() || m_clearAsked)
        return;
    const bool estop = m_client && m_client->status().estop;
    abortWith(estop ? dev::proto::PathReason::EStop : expected ? dev::proto::PathReason::Stop : dev::proto::PathReason::NewSession);
}

void GrblPathClient::onAlarm(int code)
{
    if (!active())
        return;
    abortWith(code == dev::grbl::alarm::kHardLimit || code == dev::grbl::alarm::kSoftLimit ? dev::proto::PathReason::LimitSwitch : dev::proto::PathReason::Stop,
              QStringLiteral("ALARM:%1").arg(code));
}

void GrblPathClient::abortWith(dev::proto::PathReason reason, const QString& controllerSaid)
{
    if (!active())
        return;
    m_state = dev::proto::PathState::Aborted;
    m_reason = reason;
    m_segments.clear();
    emit aborted(m_executing, controllerSaid);
}

} // namespace dev
