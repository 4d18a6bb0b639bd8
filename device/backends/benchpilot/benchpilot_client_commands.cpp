// BenchPilotClient, part 4 of 5: the commands a person gives: home, move, jog
// (steps and held velocity jogs with their refresh), stop, E-stop, reset, set
// zero and soft limits. Each checks its arguments before anything is sent.
#include "device/backends/benchpilot/benchpilot_client.h"

#include "device/protocol/messages_arch.h"

#include <algorithm>
#include <cmath>

namespace dev {
namespace {
std::int32_t toWire(double v, double scale) { return static_cast<std::int32_t>(std::llround(v * scale)); }
} // namespace

// ---- commands -------------------------------------------------------------------

static std::optional<RequestError> invalid(const motion::msg::Message& why)
{
    RequestError e;
    e.kind = RequestError::Kind::Invalid;
    e.message = why;
    return e;
}

void BenchPilotClient::home(quint8 axisMask, Callback done)
{
    send(dev::proto::MsgType::Home, dev::proto::encode(dev::proto::HomeRequest{axisMask}), wrap(std::move(done), "request.home"));
}

void BenchPilotClient::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    auto refuse = [&](const motion::msg::Message& why) {
        const auto e = invalid(why);
        emit requestFailed(*e);
        if (done)
            done(e);
    };
    if (targets.isEmpty())
        return refuse(motion::msg::make("request.move_no_axis"));
    dev::proto::MoveRequest m;
    m.relative = relative;
    QMap<int, double> byAxis;
    for (const auto& [axis, value] : targets) {
        if (axis < 0 || axis >= m_identity.axes.size())
            return refuse(motion::msg::make("request.move_no_such_axis", {motion::msg::integer("index", axis, motion::msg::Unit::None)}));
        if (!std::isfinite(value))
            return refuse(motion::msg::make("request.move_target_not_number", {motion::msg::verbatim("axis", QString(m_identity.axes[axis].letter).toStdString())}));
        if (byAxis.contains(axis))
            return refuse(motion::msg::make("request.move_axis_twice", {motion::msg::verbatim("axis", QString(m_identity.axes[axis].letter).toStdString())}));
        byAxis[axis] = value;
    }
    if (!std::isfinite(speed) || speed < 0)
        return refuse(motion::msg::make("request.move_bad_speed"));
    for (auto it = byAxis.cbegin(); it != byAxis.cend(); ++it) {
        m.axisMask = static_cast<std::uint8_t>(m.axisMask | (1u << it.key()));
        m.targets.push_back(toWire(it.value(), m_identity.axes[it.key()].wireScale()));
    }
    m.speed = static_cast<std::uint32_t>(std::llround(speed * m_identity.axes[byAxis.firstKey()].wireScale()));
    send(dev::proto::MsgType::Move, dev::proto::encode(m), wrap(std::move(done), "request.move"));
}

void BenchPilotClient::archMove(const ArchMove& a, Callback done)
{
    const int ix = m_identity.axisIndex(QLatin1Char('X')), iy = m_identity.axisIndex(QLatin1Char('Y')),
              iz = m_identity.axisIndex(QLatin1Char('Z'));
    if (!capabilities().testFlag(Capability::ArchedMove) || ix < 0 || iy < 0 || iz < 0)
        return refuse(done, RequestError::Kind::Invalid, whyNot(Capability::ArchedMove));
    for (double v : {a.xMm, a.yMm, a.clearZMm, a.zMm, a.departMm, a.approachMm})
        if (!std::isfinite(v))
            return refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.move_target_not_number", {motion::msg::verbatim("axis", "Z")}));
    if (!std::isfinite(a.xySpeed) || a.xySpeed < 0 || !std::isfinite(a.zSpeed) || a.zSpeed < 0)
        return refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.move_bad_speed"));
    const double s = m_identity.axes[ix].wireScale();  // nm per mm, like Y's and Z's
    dev::proto::ArchMoveRequest m;
    m.xySpeed = static_cast<std::uint32_t>(std::llround(a.xySpeed * s));
    m.zSpeed = static_cast<std::uint32_t>(std::llround(a.zSpeed * m_identity.axes[iz].wireScale()));
    m.x = toWire(a.xMm, s);
    m.y = toWire(a.yMm, m_identity.axes[iy].wireScale());
    m.clearZ = toWire(a.clearZMm, m_identity.axes[iz].wireScale());
    m.z = toWire(a.zMm, m_identity.axes[iz].wireScale());
    // The radii are a safety margin: rounded down, never wider than asked.
    m.departRadius = static_cast<std::uint32_t>(std::max(0.0, std::floor(a.departMm * s)));
    m.approachRadius = static_cast<std::uint32_t>(std::max(0.0, std::floor(a.approachMm * s)));
    if (a.pump) {
        const int ip = m_identity.axisIndex(QLatin1Char('P'));
        if (ip < 0 || !(m_identity.protocolCapabilities & dev::proto::kCapArchPump))
            return refuse(done, RequestError::Kind::Invalid, whyNot(Capability::ArchedMove));
        for (double v : {a.pumpUl, a.liquidZMm, a.leaveZMm})
            if (!std::isfinite(v))
                return refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.move_target_not_number", {motion::msg::verbatim("axis", "P")}));
        if (!std::isfinite(a.pumpSpeed) || a.pumpSpeed < 0)
            return refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.move_bad_speed"));
        dev::proto::ArchPump p;
        p.delta = toWire(a.pumpUl, m_identity.axes[ip].wireScale());
        p.speed = static_cast<std::uint32_t>(std::llround(a.pumpSpeed * m_identity.axes[ip].wireScale()));
        // The liquid height rounded toward the bottom (a larger Z): never higher than asked.
        p.liquidZ = static_cast<std::int32_t>(std::ceil(a.liquidZMm * m_identity.axes[iz].wireScale()));
        p.leaveZ = toWire(a.leaveZMm, m_identity.axes[iz].wireScale());
        m.pump = p;
    }
    send(dev::proto::MsgType::ArchMove, dev::proto::encode(m), wrap(std::move(done), "request.move"));
}

void BenchPilotClient::jogStep(int axis, double delta, double speed, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(delta) || !std::isfinite(speed) || speed < 0) {
        const auto e = invalid(motion::msg::make("request.jog_step_invalid"));
        emit requestFailed(*e);
        if (done)
            done(e);
        return;
    }
    const double k = m_identity.axes[axis].wireScale();
    dev::proto::JogStepRequest r;
    r.axis = static_cast<std::uint8_t>(axis);
    r.delta = toWire(delta, k);
    r.speed = static_cast<std::uint32_t>(std::llround(speed * k));
    send(dev::proto::MsgType::JogStep, dev::proto::encode(r), wrap(std::move(done), "request.jog_step"));
}

void BenchPilotClient::startJog(int axis, double velocity)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(velocity))
        return;
    m_jogs[axis] = velocity;
    refreshJogs();
    if (!m_jogTimer.isActive())
        m_jogTimer.start();
}

void BenchPilotClient::stopJog(int axis)
{
    if (!m_jogs.contains(axis))
        return;
    m_jogs.remove(axis);
    if (m_jogs.isEmpty())
        m_jogTimer.stop();
    if (axis < 0 || axis >= m_identity.axes.size())
        return;
    dev::proto::JogVelocityRequest r;
    r.axisMask = static_cast<std::uint8_t>(1u << axis);
    r.velocities = {0};
    send(dev::proto::MsgType::JogVelocity, dev::proto::encode(r), wrap({}, "request.jog"));
}

void BenchPilotClient::stopAllJogs()
{
    const auto axes = m_jogs.keys();
    for (int a : axes)
        stopJog(a);
}

void BenchPilotClient::refreshJogs()
{
    if (m_jogs.isEmpty() || m_state != LinkState::Ready)
        return;
    dev::proto::JogVelocityRequest r;
    for (int axis = 0; axis < m_identity.axes.size(); ++axis) {
        if (!m_jogs.contains(axis))
            continue;
        r.axisMask = static_cast<std::uint8_t>(r.axisMask | (1u << axis));
        r.velocities.push_back(toWire(m_jogs[axis], m_identity.axes[axis].wireScale()));
    }
    send(dev::proto::MsgType::JogVelocity, dev::proto::encode(r), [this, mask = r.axisMask](const auto& e, const auto&) {
        if (!e || e->kind != RequestError::Kind::Device)
            return;
        // A refused jog (busy, E-stop, too fast) ends the hold: say so once.
        for (int axis = 0; axis < 8; ++axis)
            if (mask & (1u << axis))
                m_jogs.remove(axis);
        if (m_jogs.isEmpty())
            m_jogTimer.stop();
        RequestError err = *e;
        err.message = motion::msg::make("request.refused", {motion::msg::term("action", "request.jog"), motion::msg::nested("cause", err.message)});
        emit requestFailed(err);
    });
}

void BenchPilotClient::setJogVelocities(const std::map<int, double>& velocities, Callback done)
{
    dev::proto::JogVelocityRequest r;
    for (const auto& [axis, v] : velocities) {  // ascending axes: the order the mask lists them in
        if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(v)) {
            refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.jog_invalid"));
            return;
        }
        r.axisMask = static_cast<std::uint8_t>(r.axisMask | (1u << axis));
        r.velocities.push_back(toWire(v, m_identity.axes[axis].wireScale()));
    }
    if (r.axisMask == 0) {
        if (done)
            done(std::nullopt);
        return;
    }
    send(dev::proto::MsgType::JogVelocity, dev::proto::encode(r), wrap(std::move(done), "request.jog"));
}

void BenchPilotClient::stop(quint8 axisMask, Callback done)
{
    for (int a = 0; a < 8; ++a)
        if (axisMask == 0 || (axisMask & (1u << a)))
            m_jogs.remove(a);
    if (m_jogs.isEmpty())
        m_jogTimer.stop();
    send(dev::proto::MsgType::Stop, dev::proto::encode(dev::proto::AxisMaskRequest{axisMask}), wrap(std::move(done), "request.stop"));
}

void BenchPilotClient::estop(Callback done)
{
    m_jogs.clear();
    m_jogTimer.stop();
    send(dev::proto::MsgType::EStop, {}, wrap(std::move(done), "request.estop"));
}

void BenchPilotClient::reset(Callback done)
{
    send(dev::proto::MsgType::Reset, {}, wrap(std::move(done), "request.reset"));
}

void BenchPilotClient::setZero(quint8 axisMask, Callback done)
{
    auto inner = wrap(std::move(done), "request.set_zero");
    send(dev::proto::MsgType::SetZero, dev::proto::encode(dev::proto::AxisMaskRequest{axisMask}), [this, inner](const auto& e, const auto& p) {
        if (!e)
            refreshLimits();
        inner(e, p);
    });
}

void BenchPilotClient::setSoftLimits(int axis, double min, double max, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(min) || !std::isfinite(max)) {
        const auto e = invalid(motion::msg::make("request.soft_limits_invalid"));
        emit requestFailed(*e);
        if (done)
            done(e);
        return;
    }
    const double k = m_identity.axes[axis].wireScale();
    dev::proto::SetLimitsRequest r;
    r.axis = static_cast<std::uint8_t>(axis);
    r.limits = {toWire(min, k), toWire(max, k)};
    auto inner = wrap(std::move(done), "request.soft_limits");
    send(dev::proto::MsgType::SetLimits, dev::proto::encode(r), [this, axis, min, max, inner](const auto& e, const auto& p) {
        if (!e && axis < m_limits.size()) {
            m_limits[axis] = {min, max};
            emit limitsChanged();
        }
        inner(e, p);
    });
}

} // namespace dev
