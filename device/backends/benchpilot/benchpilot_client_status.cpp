// BenchPilotClient, part 3 of 5: what the client keeps up to date about the
// device: the status poll, the soft limits and the telemetry subscription, and
// the conversion of telemetry values to axis units.
#include "device/backends/benchpilot/benchpilot_client.h"

namespace dev {

void BenchPilotClient::applyStatus(const dev::proto::Bytes& payload)
{
    const auto s = dev::proto::decodeStatusReply(payload);
    if (!s || int(s->axes.size()) != m_identity.axes.size())
        return;
    m_status.estop = s->deviceFlags & dev::proto::DeviceEStop;
    m_status.fault = s->deviceFlags & dev::proto::DeviceFault;
    m_status.deviceTimeUs = s->deviceTimeUs;
    for (int i = 0; i < m_status.axes.size(); ++i) {
        const auto& a = s->axes[size_t(i)];
        const double k = m_identity.axes[i].wireScale();
        auto& r = m_status.axes[i];
        r.commanded = a.commanded / k;
        r.measured = a.measured / k;
        r.homed = a.flags & dev::proto::AxisHomed;
        r.moving = a.flags & dev::proto::AxisMoving;
        r.homing = a.flags & dev::proto::AxisHoming;
        r.jogging = a.flags & dev::proto::AxisJogging;
        r.homeSwitch = a.flags & dev::proto::AxisHomeSwitch;
        r.limitSwitch = a.flags & dev::proto::AxisLimitSwitch;
        r.fault = a.flags & dev::proto::AxisFault;
    }
    emit statusChanged(m_status);
}

void BenchPilotClient::refreshLimits(std::function<void()> then)
{
    send(dev::proto::MsgType::GetLimits, {}, [this, then](const auto& e, const auto& p) {
        if (!e)
            if (auto l = dev::proto::decodeLimitsReply(p)) {
                for (int i = 0; i < m_limits.size() && i < int(l->axes.size()); ++i) {
                    const double k = m_identity.axes[i].wireScale();
                    m_limits[i] = {l->axes[size_t(i)].min / k, l->axes[size_t(i)].max / k};
                }
                emit limitsChanged();
            }
        if (then)
            then();
    });
}

void BenchPilotClient::pollStatus()
{
    if (m_statusPending || m_state != LinkState::Ready)
        return;
    m_statusPending = true;
    send(dev::proto::MsgType::Status, {}, [this](const auto& e, const auto& p) {
        m_statusPending = false;
        if (!e)
            applyStatus(p);
    });
}

void BenchPilotClient::subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz,
                                 SubscribeCallback done)
{
    dev::proto::SubscribeRequest r;
    r.rateHz = static_cast<std::uint32_t>(std::max(0, rateHz));
    r.channels.assign(channels.begin(), channels.end());
    send(dev::proto::MsgType::Subscribe, dev::proto::encode(r), [this, channels, done](const auto& e, const auto& p) {
        dev::proto::SubscribeReply reply;
        if (!e) {
            if (auto d = dev::proto::decodeSubscribeReply(p))
                reply = *d;
            m_channels = reply.rateHz ? channels : QVector<dev::proto::ChannelRef>{};
            m_rateHz = static_cast<int>(reply.rateHz);
            m_haveSampleIndex = false;  // a new subscription restarts the device's sample counter
        } else if (!done) {
            // A caller with its own handler (the telemetry hub falls back to the
            // stated capacity) decides whether a person needs to hear about it.
            RequestError err = *e;
            err.message = motion::msg::make("request.telemetry_refused", {motion::msg::nested("cause", err.message)});
            emit requestFailed(err);
        }
        if (done)
            done(e, reply);
    });
}

double BenchPilotClient::toAxisUnits(const dev::proto::ChannelRef& c, std::int32_t value) const
{
    switch (c.kind) {
    case dev::proto::ChannelKind::Switches:
    case dev::proto::ChannelKind::ControllerOutput:
        return value;
    case dev::proto::ChannelKind::ContourError:
        return value / 1e6;
    default:
        if (c.axis < m_identity.axes.size())
            return value / m_identity.axes[c.axis].wireScale();
        return value;
    }
}

} // namespace dev
