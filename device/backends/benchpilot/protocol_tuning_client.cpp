#include "device/backends/benchpilot/protocol_tuning_client.h"

#include "device/backends/benchpilot/benchpilot_client.h"

#include "device/protocol/messages_tuning.h"

#include <cmath>
#include <memory>

namespace dev {
namespace {
using motion::control::DiscreteGains;

dev::proto::WireGains toWire(const DiscreteGains& g)
{
    return {static_cast<float>(g.kp), static_cast<float>(g.ki), static_cast<float>(g.kd)};
}
DiscreteGains fromWire(const dev::proto::WireGains& g) { return {g.kp, g.ki, g.kd}; }

std::uint32_t toU32(double v)
{
    if (!(v > 0))
        return 0;
    return v >= 4294967295.0 ? 4294967295u : static_cast<std::uint32_t>(std::llround(v));
}

dev::proto::WireEnvelope toWire(const motion::control::Envelope& e, double scale)
{
    return {toU32(e.maxExcursion * scale), toU32(e.maxFollowingError * scale), toU32(e.maxDurationS * 1000)};
}

RequestError tuningInvalid(const motion::msg::Message& why)
{
    RequestError e;
    e.kind = RequestError::Kind::Invalid;
    e.message = why;
    return e;
}
} // namespace

ProtocolTuningClient::ProtocolTuningClient(BenchPilotClient* client, QObject* parent) : TuningClient(client, parent), m_client(client)
{
    connect(client, &BenchPilotClient::eventReceived, this, [this](const DeviceEvent& e) {
        if (e.kind == dev::proto::kEvTestEnded || e.kind == dev::proto::kEvTestTripped || e.kind == dev::proto::kEvTestAborted)
            emit testEnded(e.axis, e.kind, e.text);
        else if (e.kind == dev::proto::kEvGainsChanged)
            emit gainsChanged(e.axis, e.text);
    });
}

bool ProtocolTuningClient::hasGains() const { return m_client && m_client->hasProtocolCapability(dev::proto::CapGains); }
bool ProtocolTuningClient::hasTests() const { return m_client && m_client->hasProtocolCapability(dev::proto::CapExperiments); }

QVector<int> ProtocolTuningClient::tunableAxes() const
{
    QVector<int> out;
    if (!hasGains() || !m_client->hasProtocolCapability(dev::proto::CapClosedLoopPid))
        return out;
    for (int i = 0; i < m_client->identity().axes.size(); ++i)
        out.push_back(i);
    return out;
}

double ProtocolTuningClient::scale(int axis) const
{
    const auto& axes = m_client->identity().axes;
    return axis >= 0 && axis < axes.size() ? axes[axis].wireScale() : 1e6;
}

void ProtocolTuningClient::getGains(int axis, GainsDone done)
{
    m_client->request(
        dev::proto::kGetGains, dev::proto::encode(dev::proto::AxisRequest{static_cast<std::uint8_t>(axis)}),
        [done](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            AxisGains g;
            if (e)
                return done(e, g);
            const auto r = dev::proto::decodeGainsReply(payload);
            if (!r)
                return done(tuningInvalid(motion::msg::make("request.gains_unreadable")), g);
            g.axis = r->axis;
            g.controlPeriodS = r->controlPeriodUs * 1e-6;
            g.gains = fromWire(r->gains);
            g.saved = fromWire(r->saved);
            g.limits = fromWire(r->limits);
            g.testRunning = r->flags & dev::proto::kGainsTestRunning;
            done(std::nullopt, g);
        },
        "request.get_gains");
}

void ProtocolTuningClient::setGains(int axis, const DiscreteGains& gains, bool keep, Callback done)
{
    dev::proto::SetGainsRequest r{static_cast<std::uint8_t>(axis), static_cast<std::uint8_t>(keep ? dev::proto::kSetGainsSave : 0), toWire(gains)};
    send(dev::proto::kSetGains, dev::proto::encode(r), std::move(done), "request.set_gains");
}

void ProtocolTuningClient::startStepTest(const StepTestParams& p, Callback done)
{
    const double k = scale(p.axis);
    dev::proto::StepTestRequest r;
    r.axis = static_cast<std::uint8_t>(p.axis);
    const double step = std::llround(p.stepMm * k);
    if (!std::isfinite(p.stepMm) || std::abs(step) > 2147483647.0) {
        if (done)
            done(tuningInvalid(motion::msg::make("request.step_size_invalid", {motion::msg::real("step", p.stepMm, motion::msg::Unit::Mm)})));
        return;
    }
    r.step = static_cast<std::int32_t>(step);
    r.settleBand = toU32(p.settleBandMm * k);
    r.settleHoldMs = static_cast<std::uint16_t>(std::min(65535.0, std::max(0.0, std::round(p.settleHoldS * 1000))));
    r.runMs = toU32(p.runS * 1000);
    r.envelope = toWire(p.envelope, k);
    if (p.trialGains)
        r.trialGains = toWire(*p.trialGains);
    send(dev::proto::kStepTest, dev::proto::encode(r), std::move(done), "request.step_test");
}

void ProtocolTuningClient::startRelayTest(const RelayTestParams& p, Callback done)
{
    const double k = scale(p.axis);
    dev::proto::RelayTestRequest r;
    r.axis = static_cast<std::uint8_t>(p.axis);
    r.amplitude = toU32(p.amplitudeMm * k);
    r.hysteresis = toU32(p.hysteresisMm * k);
    r.forcedPeriodUs = toU32(p.forcedPeriodS * 1e6);
    r.cycles = static_cast<std::uint16_t>(std::clamp(p.cycles, 0, 65535));
    r.envelope = toWire(p.envelope, k);
    send(dev::proto::kRelayTest, dev::proto::encode(r), std::move(done), "request.relay_test");
}

void ProtocolTuningClient::abortTests(quint8 axisMask, Callback done)
{
    send(dev::proto::kTestAbort, dev::proto::encode(dev::proto::AbortRequest{axisMask}), std::move(done), "request.abort_test");
}

void ProtocolTuningClient::send(dev::proto::MsgType type, const dev::proto::Bytes& payload, Callback done, const std::string& what)
{
    m_client->request(
        type, payload,
        [done](const std::optional<RequestError>& e, const dev::proto::Bytes&) {
            if (done)
                done(e);
        },
        what);
}

void ProtocolTuningClient::fetchCapture(int axis, CaptureDone done, Progress progress)
{
    auto into = std::make_shared<TestCapture>();
    into->axis = axis;
    fetchChunk(axis, into, 0, std::move(done), std::move(progress));
}

void ProtocolTuningClient::fetchChunk(int axis, std::shared_ptr<TestCapture> into, quint32 first, CaptureDone done, Progress progress)
{
    const dev::proto::CaptureRequest q{static_cast<std::uint8_t>(axis), first, dev::proto::kMaxCaptureSamplesPerReply};
    QPointer<ProtocolTuningClient> self(this);
    m_client->request(
        dev::proto::kGetCapture, dev::proto::encode(q),
        [self, axis, into, first, done, progress](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            if (!self)
                return;
            if (e)
                return done(e, *into);
            const auto c = dev::proto::decodeCaptureReply(payload);
            if (!c)
                return done(tuningInvalid(motion::msg::make("request.capture_unreadable")), *into);
            if (first > 0 && c->testId != into->testId)
                return done(tuningInvalid(motion::msg::make("request.capture_replaced")), *into);
            const double k = self->scale(axis);
            auto& r = into->record;
            if (first == 0) {
                into->kind = c->kind;
                into->testId = c->testId;
                into->gains = fromWire(c->gains);
                r.periodS = c->periodUs * 1e-6;
                r.startPosition = c->startPosition / k;
                r.startOutput = 0;
                r.reason = static_cast<motion::control::EndReason>(c->reason);
                const bool duration = r.reason == motion::control::EndReason::Duration;
                r.tripValue = duration ? c->tripValue / 1000.0 : c->tripValue / k;
                r.tripLimit = duration ? c->tripLimit / 1000.0 : c->tripLimit / k;
                r.setpoint.reserve(c->total);
                r.measured.reserve(c->total);
                r.output.reserve(c->total);
            }
            for (const auto& s : c->samples)
                r.append(s.setpoint / k, s.measured / k, s.output / k);
            const quint32 next = first + static_cast<quint32>(c->samples.size());
            if (progress)
                progress(static_cast<int>(next), static_cast<int>(c->total));
            if (next >= c->total || c->samples.empty())
                return done(std::nullopt, *into);
            self->fetchChunk(axis, into, next, done, progress);
        },
        "request.read_capture");
}

} // namespace dev
