#include "gated_instrument.h"

#include <QTimer>

#include <algorithm>

namespace app {

GatedInstrument::GatedInstrument(dev::Instrument* inner, std::function<QString()> blockedBy, std::function<void()> ask, QObject* parent)
    : dev::Instrument(parent), m_inner(inner), m_blockedBy(std::move(blockedBy)), m_ask(std::move(ask))
{
    connect(inner, &Instrument::stateChanged, this, &Instrument::stateChanged);
    connect(inner, &Instrument::identified, this, &Instrument::identified);
    connect(inner, &Instrument::statusChanged, this, &Instrument::statusChanged);
    connect(inner, &Instrument::limitsChanged, this, &Instrument::limitsChanged);
    connect(inner, &Instrument::eventReceived, this, &Instrument::eventReceived);
    connect(inner, &Instrument::telemetryReceived, this, &Instrument::telemetryReceived);
    connect(inner, &Instrument::linkError, this, &Instrument::linkError);
    connect(inner, &Instrument::requestFailed, this, &Instrument::requestFailed);
    connect(inner, &Instrument::samplesLost, this, &Instrument::samplesLost);
    connect(inner, &Instrument::partsReplaced, this, &Instrument::partsReplaced);
    connect(inner, &Instrument::noted, this, &Instrument::noted);
}

bool GatedInstrument::allowed(const Callback& done)
{
    const QString holder = m_blockedBy ? m_blockedBy() : QString();
    if (holder.isEmpty())
        return true;
    refuse(done, dev::RequestError::Kind::Invalid, motion::msg::make("request.bench_held", {motion::msg::verbatim("holder", holder.toStdString())}));
    // Asked once per refusal burst, from the event loop (never from inside a runner's call).
    if (m_ask && !m_askPending) {
        m_askPending = true;
        QTimer::singleShot(0, this, [this] {
            m_askPending = false;
            m_ask();
        });
    }
    return false;
}

void GatedInstrument::home(quint8 axisMask, Callback done)
{
    if (allowed(done))
        m_inner->home(axisMask, std::move(done));
}

void GatedInstrument::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    if (allowed(done))
        m_inner->move(targets, relative, speed, std::move(done));
}

void GatedInstrument::archMove(const ArchMove& move, Callback done)
{
    if (allowed(done))
        m_inner->archMove(move, std::move(done));
}

void GatedInstrument::jogStep(int axis, double delta, double speed, Callback done)
{
    if (allowed(done))
        m_inner->jogStep(axis, delta, speed, std::move(done));
}

void GatedInstrument::startJog(int axis, double velocity)
{
    if (allowed({}))
        m_inner->startJog(axis, velocity);
}

void GatedInstrument::setJogVelocities(const std::map<int, double>& velocities, Callback done)
{
    // Letting go (every velocity 0) is a stop: never gated.
    const bool stopping = std::all_of(velocities.begin(), velocities.end(), [](const auto& v) { return v.second == 0; });
    if (stopping || allowed(done))
        m_inner->setJogVelocities(velocities, std::move(done));
}

void GatedInstrument::setZero(quint8 axisMask, Callback done)
{
    if (allowed(done))
        m_inner->setZero(axisMask, std::move(done));
}

void GatedInstrument::unlock(Callback done)
{
    if (allowed(done))
        m_inner->unlock(std::move(done));
}

void GatedInstrument::setSoftLimits(int axis, double min, double max, Callback done)
{
    if (allowed(done))
        m_inner->setSoftLimits(axis, min, max, std::move(done));
}

void GatedInstrument::pulseTrigger(double widthS, Callback done)
{
    if (allowed(done))
        m_inner->pulseTrigger(widthS, std::move(done));
}

} // namespace app
