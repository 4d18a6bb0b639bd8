#pragma once
// The BenchPilot backend's tuning: GET_GAINS / SET_GAINS, STEP_TEST / RELAY_TEST,
// GET_CAPTURE in chunks and the realtime TEST_ABORT (docs/protocol.md, "Tuning"), all
// through BenchPilotClient::request. Reached as BenchPilotClient::tuning().
#include "device/client/tuning_client.h"

#include <QPointer>

#include <memory>

namespace dev {

class BenchPilotClient;

class ProtocolTuningClient : public TuningClient {
    Q_OBJECT
public:
    explicit ProtocolTuningClient(BenchPilotClient* client, QObject* parent = nullptr);

    /// The device has gains (capability 8) / runs tests (capability 9).
    bool hasGains() const override;
    bool hasTests() const override;
    QVector<int> tunableAxes() const override;
    void getGains(int axis, GainsDone done) override;
    void setGains(int axis, const motion::control::DiscreteGains& gains, bool keepForPowerUp, Callback done = {}) override;
    void startStepTest(const StepTestParams& p, Callback done = {}) override;
    void startRelayTest(const RelayTestParams& p, Callback done = {}) override;
    void abortTests(quint8 axisMask = 0, Callback done = {}) override;
    /// Fetched in chunks of 80 samples.
    void fetchCapture(int axis, CaptureDone done, Progress progress = {}) override;

private:
    void fetchChunk(int axis, std::shared_ptr<TestCapture> into, quint32 first, CaptureDone done, Progress progress);
    /// A request whose reply has no payload.
    void send(dev::proto::MsgType type, const dev::proto::Bytes& payload, Callback done, const std::string& what);
    double scale(int axis) const;

    QPointer<BenchPilotClient> m_client;
};

} // namespace dev
