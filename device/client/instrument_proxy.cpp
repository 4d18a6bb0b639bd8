#include "device/client/instrument_proxy.h"

namespace dev {

InstrumentProxy::InstrumentProxy(QObject* parent) : Instrument(parent) {}

InstrumentProxy::~InstrumentProxy()
{
    for (const auto& c : m_forwards)
        disconnect(c);
}

void InstrumentProxy::setBackend(Instrument* backend)
{
    if (backend == m_backend)
        return;
    const LinkState before = state();
    for (const auto& c : m_forwards)
        disconnect(c);
    m_forwards.clear();
    if (m_backend)
        m_backend->deleteLater();
    m_backend = backend;
    if (backend) {
        backend->setParent(this);
        m_forwards << connect(backend, &Instrument::stateChanged, this, &Instrument::stateChanged);
        m_forwards << connect(backend, &Instrument::identified, this, &Instrument::identified);
        m_forwards << connect(backend, &Instrument::statusChanged, this, &Instrument::statusChanged);
        m_forwards << connect(backend, &Instrument::limitsChanged, this, &Instrument::limitsChanged);
        m_forwards << connect(backend, &Instrument::eventReceived, this, &Instrument::eventReceived);
        m_forwards << connect(backend, &Instrument::telemetryReceived, this, &Instrument::telemetryReceived);
        m_forwards << connect(backend, &Instrument::linkError, this, &Instrument::linkError);
        m_forwards << connect(backend, &Instrument::requestFailed, this, &Instrument::requestFailed);
        m_forwards << connect(backend, &Instrument::samplesLost, this, &Instrument::samplesLost);
        m_forwards << connect(backend, &Instrument::noted, this, &Instrument::noted);
        m_forwards << connect(backend, &Instrument::partsReplaced, this, &Instrument::partsReplaced);
    }
    // Screens learn of the new backend the way they learn of any change on a link.
    emit partsReplaced();
    if (state() != before)
        emit stateChanged(state());
    if (backend && !backend->identity().axes.isEmpty()) {
        emit identified(identity());
        emit limitsChanged();
        emit statusChanged(status());
    }
}

bool InstrumentProxy::noBackend(const Callback& done)
{
    if (m_backend)
        return false;
    refuse(done, RequestError::Kind::LinkDown, motion::msg::make("request.instrument_not_connected"));
    return true;
}

void InstrumentProxy::connectLink()
{
    if (m_backend)
        m_backend->connectLink();
    else
        emit linkError(motion::msg::make("link.no_connection_chosen"));
}

void InstrumentProxy::disconnectLink()
{
    if (m_backend)
        m_backend->disconnectLink();
}

LinkState InstrumentProxy::state() const { return m_backend ? m_backend->state() : LinkState::Disconnected; }
LinkStats InstrumentProxy::stats() const { return m_backend ? m_backend->stats() : LinkStats{}; }
QString InstrumentProxy::linkDescription() const { return m_backend ? m_backend->linkDescription() : tr("no link"); }
const DeviceIdentity& InstrumentProxy::identity() const { return m_backend ? m_backend->identity() : m_noIdentity; }
const InstrumentStatus& InstrumentProxy::status() const { return m_backend ? m_backend->status() : m_noStatus; }
const QVector<SoftLimits>& InstrumentProxy::softLimits() const { return m_backend ? m_backend->softLimits() : m_noLimits; }
Capabilities InstrumentProxy::capabilities() const { return m_backend ? m_backend->capabilities() : Capabilities{}; }

motion::msg::Message InstrumentProxy::missingReason(Capability c) const
{
    // whyNot() has found the proxy ready, so the backend is, and its reason is its own.
    return m_backend ? m_backend->whyNot(c) : Instrument::missingReason(c);
}

void InstrumentProxy::home(quint8 axisMask, Callback done)
{
    if (!noBackend(done))
        m_backend->home(axisMask, std::move(done));
}

void InstrumentProxy::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    if (!noBackend(done))
        m_backend->move(targets, relative, speed, std::move(done));
}

void InstrumentProxy::archMove(const ArchMove& move, Callback done)
{
    if (!noBackend(done))
        m_backend->archMove(move, std::move(done));
}

void InstrumentProxy::jogStep(int axis, double delta, double speed, Callback done)
{
    if (!noBackend(done))
        m_backend->jogStep(axis, delta, speed, std::move(done));
}

void InstrumentProxy::startJog(int axis, double velocity)
{
    if (m_backend)
        m_backend->startJog(axis, velocity);
}

void InstrumentProxy::stopJog(int axis)
{
    if (m_backend)
        m_backend->stopJog(axis);
}

void InstrumentProxy::stopAllJogs()
{
    if (m_backend)
        m_backend->stopAllJogs();
}

bool InstrumentProxy::isJogging(int axis) const { return m_backend && m_backend->isJogging(axis); }

void InstrumentProxy::setJogVelocities(const std::map<int, double>& velocities, Callback done)
{
    if (!noBackend(done))
        m_backend->setJogVelocities(velocities, std::move(done));
}

// With no backend nothing moves; the BenchPilot pace keeps a caller's timer sensible meanwhile.
int InstrumentProxy::jogRefreshMs() const { return m_backend ? m_backend->jogRefreshMs() : 50; }

void InstrumentProxy::stop(quint8 axisMask, Callback done)
{
    if (!noBackend(done))
        m_backend->stop(axisMask, std::move(done));
}

void InstrumentProxy::estop(Callback done)
{
    if (!noBackend(done))
        m_backend->estop(std::move(done));
}

void InstrumentProxy::reset(Callback done)
{
    if (!noBackend(done))
        m_backend->reset(std::move(done));
}

void InstrumentProxy::setZero(quint8 axisMask, Callback done)
{
    if (!noBackend(done))
        m_backend->setZero(axisMask, std::move(done));
}

void InstrumentProxy::unlock(Callback done)
{
    if (!noBackend(done))
        m_backend->unlock(std::move(done));
}

void InstrumentProxy::setSoftLimits(int axis, double min, double max, Callback done)
{
    if (!noBackend(done))
        m_backend->setSoftLimits(axis, min, max, std::move(done));
}

void InstrumentProxy::readStatus(StatusCallback done)
{
    if (m_backend)
        return m_backend->readStatus(std::move(done));
    noBackend([this, done](const std::optional<RequestError>& e) {
        if (done)
            done(e, m_noStatus);
    });
}

void InstrumentProxy::dwell(double seconds, Callback done)
{
    if (!noBackend(done))
        m_backend->dwell(seconds, std::move(done));
}

void InstrumentProxy::pulseTrigger(double widthS, Callback done)
{
    if (!noBackend(done))
        m_backend->pulseTrigger(widthS, std::move(done));
}

void InstrumentProxy::subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done)
{
    if (m_backend)
        return m_backend->subscribe(channels, rateHz, std::move(done));
    noBackend([done](const std::optional<RequestError>& e) {
        if (done)
            done(e, {});
    });
}

const QVector<dev::proto::ChannelRef>& InstrumentProxy::subscribedChannels() const
{
    return m_backend ? m_backend->subscribedChannels() : m_noChannels;
}

int InstrumentProxy::subscribedRateHz() const { return m_backend ? m_backend->subscribedRateHz() : 0; }

double InstrumentProxy::toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const
{
    return m_backend ? m_backend->toAxisUnits(channel, value) : value;
}

PathClient* InstrumentProxy::paths() { return m_backend ? m_backend->paths() : nullptr; }
TuningClient* InstrumentProxy::tuning() { return m_backend ? m_backend->tuning() : nullptr; }
CompensationClient* InstrumentProxy::compensation() { return m_backend ? m_backend->compensation() : nullptr; }
Compensation2dClient* InstrumentProxy::compensation2d() { return m_backend ? m_backend->compensation2d() : nullptr; }

} // namespace dev
