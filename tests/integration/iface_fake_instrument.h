#pragma once
// A second, test-only backend of dev::Instrument: an XY stage that lives in memory and
// speaks no protocol at all. Moves arrive at once (the reply on the next turn of the event
// loop, MotionDone on the turn after), measured equals commanded, and the device clock
// advances by the time the move would take under the stated limits, so runners see a
// plausible device. Runners that work on it do not depend on the BenchPilot backend.
//
// Everything it was asked is recorded (moves, trigger pulses, jog velocities), and its
// identity — limits, capabilities — is the test's to choose.
#include "device/client/instrument.h"

#include <vector>

namespace itest {

class FakeInstrument : public dev::Instrument {
    Q_OBJECT
public:
    /// An XY stage, 100 × 100 mm, 20 mm/s, `accelMmS2` and `jerkMmS3` (0: not limited)
    /// reported as its planner's limits; `capabilities` is what it claims.
    explicit FakeInstrument(double accelMmS2 = 200, double jerkMmS3 = 4000,
                            dev::Capabilities capabilities = defaultCapabilities(), QObject* parent = nullptr);
    static dev::Capabilities defaultCapabilities();

    /// The identity before connectLink() (to state other limits, or none).
    dev::DeviceIdentity& identityToReport() { return m_identity; }

    void connectLink() override;
    void disconnectLink() override;
    dev::LinkState state() const override { return m_state; }
    dev::LinkStats stats() const override { return {}; }
    QString linkDescription() const override { return QStringLiteral("fake stage in memory"); }
    const dev::DeviceIdentity& identity() const override { return m_identity; }
    const dev::InstrumentStatus& status() const override { return m_status; }
    const QVector<dev::SoftLimits>& softLimits() const override { return m_limits; }
    dev::Capabilities capabilities() const override { return m_state == dev::LinkState::Disconnected ? dev::Capabilities{} : m_caps; }
    void home(quint8 axisMask, Callback done = {}) override;
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) override;
    void jogStep(int axis, double delta, double speed = 0, Callback done = {}) override;
    void startJog(int axis, double velocity) override { jogs.push_back({{axis, velocity}}); }
    void stopJog(int axis) override { jogs.push_back({{axis, 0.0}}); }
    void stopAllJogs() override {}
    bool isJogging(int) const override { return false; }
    void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) override;
    int jogRefreshMs() const override { return 100; }
    void stop(quint8 axisMask = 0, Callback done = {}) override;
    void estop(Callback done = {}) override;
    void reset(Callback done = {}) override;
    void setZero(quint8 axisMask, Callback done = {}) override;
    void setSoftLimits(int axis, double min, double max, Callback done = {}) override;
    void readStatus(StatusCallback done) override;
    void dwell(double seconds, Callback done) override;
    void pulseTrigger(double widthS, Callback done = {}) override;
    void subscribe(const QVector<dev::proto::ChannelRef>&, int, SubscribeCallback done = {}) override;
    const QVector<dev::proto::ChannelRef>& subscribedChannels() const override { return m_channels; }
    int subscribedRateHz() const override { return 0; }
    double toAxisUnits(const dev::proto::ChannelRef&, std::int32_t value) const override { return value / 1e6; }
    dev::PathClient* paths() override { return nullptr; }
    dev::TuningClient* tuning() override { return nullptr; }

    // What it was asked.
    std::vector<QVector<QPair<int, double>>> moves;
    std::vector<double> triggerWidthsS;
    std::vector<std::map<int, double>> jogs;

protected:
    motion::msg::Message missingReason(dev::Capability c) const override;

private:
    /// Answers on the next turn of the event loop, as a real link would.
    void later(std::function<void()> f);
    void arrive(const std::vector<int>& axes, double seconds, dev::proto::EventKind kind);

    dev::LinkState m_state = dev::LinkState::Disconnected;
    dev::DeviceIdentity m_identity;
    dev::InstrumentStatus m_status;
    QVector<dev::SoftLimits> m_limits;
    dev::Capabilities m_caps;
    QVector<dev::proto::ChannelRef> m_channels;
};

} // namespace itest
