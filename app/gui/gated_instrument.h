#pragma once
// The instrument as the operator's screens hold it while the scripting API may be in
// control: the session's proxy, with every motion request first asking the gate.
// When a script holds the control lease (docs/api.md, "Control") the operator's jog,
// move, home, zero and run do not interleave with the script: the request is refused
// with a reason, and the window asks whether to take control back (the operator then
// does it again). Stop, E-stop and reset are never gated; reading never is.
//
// Why a decorator in app/: the screens keep their dev::Instrument*, device/ learns
// nothing of the API, and the API server uses the ungated proxy itself.
#include "device/client/instrument.h"

#include <QPointer>

#include <functional>

namespace app {

class GatedInstrument final : public dev::Instrument {
    Q_OBJECT
public:
    /// `blockedBy()` names who holds control ("" when the operator may go ahead);
    /// `ask()` is called (on the next event-loop turn) when a request was refused for it.
    GatedInstrument(dev::Instrument* inner, std::function<QString()> blockedBy, std::function<void()> ask, QObject* parent = nullptr);

    dev::Instrument* inner() const { return m_inner; }

    void connectLink() override { m_inner->connectLink(); }
    void disconnectLink() override { m_inner->disconnectLink(); }
    dev::LinkState state() const override { return m_inner->state(); }
    dev::LinkStats stats() const override { return m_inner->stats(); }
    QString linkDescription() const override { return m_inner->linkDescription(); }
    const dev::DeviceIdentity& identity() const override { return m_inner->identity(); }
    const dev::InstrumentStatus& status() const override { return m_inner->status(); }
    const QVector<dev::SoftLimits>& softLimits() const override { return m_inner->softLimits(); }
    dev::Capabilities capabilities() const override { return m_inner->capabilities(); }
    void home(quint8 axisMask, Callback done = {}) override;
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) override;
    void archMove(const ArchMove& move, Callback done = {}) override;
    void jogStep(int axis, double delta, double speed = 0, Callback done = {}) override;
    void startJog(int axis, double velocity) override;
    void stopJog(int axis) override { m_inner->stopJog(axis); }
    void stopAllJogs() override { m_inner->stopAllJogs(); }
    bool isJogging(int axis) const override { return m_inner->isJogging(axis); }
    void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) override;
    int jogRefreshMs() const override { return m_inner->jogRefreshMs(); }
    void stop(quint8 axisMask = 0, Callback done = {}) override { m_inner->stop(axisMask, std::move(done)); }
    void estop(Callback done = {}) override { m_inner->estop(std::move(done)); }
    void reset(Callback done = {}) override { m_inner->reset(std::move(done)); }
    void setZero(quint8 axisMask, Callback done = {}) override;
    void unlock(Callback done = {}) override;
    void setSoftLimits(int axis, double min, double max, Callback done = {}) override;
    void readStatus(StatusCallback done) override { m_inner->readStatus(std::move(done)); }
    void dwell(double seconds, Callback done) override { m_inner->dwell(seconds, std::move(done)); }
    void pulseTrigger(double widthS, Callback done = {}) override;
    void subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done = {}) override
    {
        m_inner->subscribe(channels, rateHz, std::move(done));
    }
    const QVector<dev::proto::ChannelRef>& subscribedChannels() const override { return m_inner->subscribedChannels(); }
    int subscribedRateHz() const override { return m_inner->subscribedRateHz(); }
    double toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const override { return m_inner->toAxisUnits(channel, value); }
    dev::PathClient* paths() override { return m_inner->paths(); }
    dev::TuningClient* tuning() override { return m_inner->tuning(); }
    dev::CompensationClient* compensation() override { return m_inner->compensation(); }
    dev::Compensation2dClient* compensation2d() override { return m_inner->compensation2d(); }

protected:
    motion::msg::Message missingReason(dev::Capability c) const override { return m_inner->whyNot(c); }

private:
    /// True when the request may go to the instrument; otherwise refuses it and asks.
    bool allowed(const Callback& done);

    QPointer<dev::Instrument> m_inner;
    std::function<QString()> m_blockedBy;
    std::function<void()> m_ask;
    bool m_askPending = false;
};

} // namespace app
