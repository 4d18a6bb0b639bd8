// BenchPilotClient, part 5 of 5: the rest of dev::Instrument over protocol 1 — the
// capabilities HELLO's bits mean, why one is missing, a status reading on demand,
// the host-timed dwell, the trigger output it does not have, and its parts.
#include "device/backends/benchpilot/benchpilot_client.h"

#include "device/backends/benchpilot/protocol_compensation_client.h"
#include "device/backends/benchpilot/protocol_compensation_2d_client.h"
#include "device/backends/benchpilot/protocol_path_client.h"
#include "device/backends/benchpilot/protocol_tuning_client.h"
#include "device/protocol/messages_arch.h"
#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_tuning.h"

#include <QPointer>

#include <cmath>

namespace dev {

Capabilities BenchPilotClient::capabilities() const
{
    if (m_identity.axes.isEmpty())
        return {};
    // SET_ZERO and SET_LIMITS are part of every protocol 1 device.
    Capabilities c = Capability::SetZero | Capability::SoftLimits;
    const struct {
        std::uint32_t bits;
        Capability capability;
    } map[] = {
        {dev::proto::CapHoming, Capability::Homing},
        {dev::proto::CapEncoder, Capability::MeasuredPosition},
        {dev::proto::CapGrating, Capability::MeasuredPosition},
        {dev::proto::CapClosedLoopPid, Capability::ClosedLoop},
        {dev::proto::CapTelemetry, Capability::Telemetry},
        {dev::proto::CapJogVelocity, Capability::VelocityJog},
        {dev::proto::CapPathQueue, Capability::PathQueue},
        {dev::proto::CapPathZFollow, Capability::PathZFollow},
        {dev::proto::kCapArchMove, Capability::ArchedMove},
        {dev::proto::CapCoupledXyThenZ, Capability::CoupledXyThenZ},
        {dev::proto::CapGains, Capability::PidGains},
        {dev::proto::CapExperiments, Capability::TuningTests},
        {dev::proto::CapPump, Capability::Pump},
        {dev::proto::CapCompensation, Capability::Compensation},
    };
    for (const auto& m : map)
        if (hasProtocolCapability(m.bits))
            c |= m.capability;
    // The jog watchdog stops a velocity move the host no longer renews, and the path
    // queue holds when the host goes quiet (docs/protocol.md).
    if (hasProtocolCapability(dev::proto::CapJogVelocity) && m_identity.jogWatchdogMs > 0)
        c |= Capability::StopsOnHostLoss;
    if (m_identity.reportsMotionLimits())
        c |= Capability::MachineLimits;
    return c;
}

motion::msg::Message BenchPilotClient::missingReason(Capability c) const
{
    motion::msg::Message m = Instrument::missingReason(c);
    const char* because = nullptr;
    switch (c) {
    case Capability::PidGains:
    case Capability::TuningTests:
    case Capability::ClosedLoop:
        if (!hasProtocolCapability(dev::proto::CapClosedLoopPid))
            because = "capability.because.open_loop";  // steppers without a position loop: nothing to tune
        break;
    case Capability::MachineLimits:
        because = "capability.because.older_firmware";  // a protocol 1.0 device: HELLO without the limits block
        break;

    case Capability::TriggerOutput:
        because = "capability.because.not_in_protocol";
        break;
    default: break;
    }
    if (because)
        m.args.push_back(motion::msg::term("because", because));
    return m;
}

void BenchPilotClient::readStatus(StatusCallback done)
{
    const QPointer<BenchPilotClient> self(this);
    send(dev::proto::MsgType::Status, {}, [self, done = std::move(done)](const std::optional<RequestError>& e, const dev::proto::Bytes& p) {
        if (!self)
            return;
        if (!e)
            self->applyStatus(p);
        if (done)
            done(e, self->m_status);
    });
}

void BenchPilotClient::whenStill(Callback then)
{
    const QPointer<BenchPilotClient> self(this);
    readStatus([self, then = std::move(then)](const std::optional<RequestError>& e, const InstrumentStatus& st) {
        if (!self)
            return;
        if (e)
            return then(e);
        if (!st.anyMoving())
            return then(std::nullopt);
        QTimer::singleShot(kStatusPollMs, self, [self, then] { self->whenStill(then); });
    });
}

void BenchPilotClient::dwell(double seconds, Callback done)
{
    if (!std::isfinite(seconds) || seconds < 0) {
        refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.dwell_invalid", {motion::msg::real("seconds", seconds, motion::msg::Unit::S)}));
        return;
    }
    // Protocol 1 has no dwell of its own: the host waits for the motion to end, then the time.
    const QPointer<BenchPilotClient> self(this);
    whenStill([self, seconds, done](const std::optional<RequestError>& e) {
        if (e) {
            if (done)
                done(e);
            return;
        }
        QTimer::singleShot(static_cast<int>(std::lround(seconds * 1000)), self, [self, done] {
            if (!done)
                return;
            if (self->isReady())
                return done(std::nullopt);
            RequestError lost;
            lost.kind = RequestError::Kind::LinkDown;
            lost.message = motion::msg::make("request.dwell_link_down");
            done(lost);
        });
    });
}

void BenchPilotClient::pulseTrigger(double, Callback done)
{
    refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.no_trigger_output"));
}

PathClient* BenchPilotClient::paths() { return m_paths; }
TuningClient* BenchPilotClient::tuning() { return m_tuning; }
CompensationClient* BenchPilotClient::compensation() { return m_compensation; }
Compensation2dClient* BenchPilotClient::compensation2d() { return m_compensation2d; }

} // namespace dev
