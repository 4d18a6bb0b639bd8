#pragma once
// One stable dev::Instrument in front of whichever backend the present connection
// needs. The application holds an InstrumentProxy per instrument for its whole
// lifetime and gives screens, runners and the telemetry hub that one pointer; when a
// connection turns out to need another backend (a port that answers with a GRBL
// banner instead of a BenchPilot HELLO), the session hands the proxy the new backend
// and nobody above has to reconnect a signal.
//
// Why a forwarding proxy rather than one object that swaps its protocol inside: each
// backend stays a plain, testable dev::Instrument with no knowledge of the others, and
// adding a backend touches only its folder and the place that picks it (app/).
//
// How it forwards:
//  - every call goes to the current backend; with none, the proxy is Disconnected, has
//    an empty identity and refuses requests (RequestError::LinkDown) at once;
//  - every signal of the current backend is re-emitted as the proxy's own; the old
//    backend's connections are cut when it is replaced, so a late signal from it never
//    reaches the screens;
//  - paths() and tuning() are the current backend's parts. Replacing the backend emits
//    partsReplaced() (and stateChanged / identified for the new one): whoever keeps a
//    part fetches it again, which is why runners fetch paths() when a job starts.
#include "device/client/instrument.h"

#include <QPointer>

namespace dev {

class InstrumentProxy final : public Instrument {
    Q_OBJECT
public:
    explicit InstrumentProxy(QObject* parent = nullptr);
    ~InstrumentProxy() override;

    /// Makes `backend` the current one and takes it (the proxy becomes its parent). The
    /// previous backend is disconnected from the proxy and deleted later, after anything
    /// on the stack that still uses it has returned. nullptr: no backend.
    void setBackend(Instrument* backend);
    Instrument* backend() const { return m_backend; }

    void connectLink() override;
    void disconnectLink() override;
    LinkState state() const override;
    LinkStats stats() const override;
    QString linkDescription() const override;
    const DeviceIdentity& identity() const override;
    const InstrumentStatus& status() const override;
    const QVector<SoftLimits>& softLimits() const override;
    Capabilities capabilities() const override;
    void home(quint8 axisMask, Callback done = {}) override;
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) override;
    void jogStep(int axis, double delta, double speed = 0, Callback done = {}) override;
    void startJog(int axis, double velocity) override;
    void stopJog(int axis) override;
    void stopAllJogs() override;
    bool isJogging(int axis) const override;
    void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) override;
    int jogRefreshMs() const override;
    void stop(quint8 axisMask = 0, Callback done = {}) override;
    void estop(Callback done = {}) override;
    void reset(Callback done = {}) override;
    void setZero(quint8 axisMask, Callback done = {}) override;
    void unlock(Callback done = {}) override;
    void archMove(const ArchMove& move, Callback done = {}) override;
    void setSoftLimits(int axis, double min, double max, Callback done = {}) override;
    void readStatus(StatusCallback done) override;
    void dwell(double seconds, Callback done) override;
    void pulseTrigger(double widthS, Callback done = {}) override;
    void subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done = {}) override;
    const QVector<dev::proto::ChannelRef>& subscribedChannels() const override;
    int subscribedRateHz() const override;
    double toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const override;
    PathClient* paths() override;
    TuningClient* tuning() override;
    CompensationClient* compensation() override;
    Compensation2dClient* compensation2d() override;

protected:
    motion::msg::Message missingReason(Capability c) const override;

private:
    /// Refuses a request for want of a backend; true when there is none.
    bool noBackend(const Callback& done);

    QPointer<Instrument> m_backend;
    QList<QMetaObject::Connection> m_forwards;
    // What the proxy shows with no backend.
    DeviceIdentity m_noIdentity;
    InstrumentStatus m_noStatus;
    QVector<SoftLimits> m_noLimits;
    QVector<dev::proto::ChannelRef> m_noChannels;
};

} // namespace dev
