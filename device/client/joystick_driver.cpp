#include "device/client/joystick_driver.h"

#include <QPointer>

#include <algorithm>
#include <cmath>

namespace dev {

JoystickDriver::JoystickDriver(Instrument* client, QObject* parent) : QObject(parent), m_client(client)
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &JoystickDriver::onTimer);
    connect(client, &Instrument::stateChanged, this, [this](LinkState s) {
        // Lost mid-drag: the device's watchdog stops the axes; the stick must be let go first.
        if (s != LinkState::Ready && (active() || !m_sent.empty()))
            blockAll();
    });
    connect(client, &Instrument::statusChanged, this, [this](const InstrumentStatus& st) {
        if (st.estop && active())
            blockAll();
    });
}

JoystickDriver::~JoystickDriver()
{
    // A screen that goes away mid-drag must not leave the axes to the watchdog.
    if (m_client && active())
        stop();
}

bool JoystickDriver::active() const
{
    return std::any_of(m_wanted.begin(), m_wanted.end(), [](const auto& kv) { return kv.second != 0; });
}

void JoystickDriver::blockAll()
{
    m_wanted.clear();
    m_sent.clear();
    m_timer.stop();
    m_blocked = true;
    if (m_wasActive) {
        m_wasActive = false;
        emit activeChanged(false);
    }
}

void JoystickDriver::setVelocities(const std::map<int, double>& velocities)
{
    if (!m_client)
        return;
    ++m_wishes;
    const auto& axes = m_client->identity().axes;
    for (const auto& [axis, v] : velocities) {
        if (axis < 0 || axis >= axes.size() || !std::isfinite(v))
            continue;
        const double vmax = axes[axis].maxSpeed;
        m_wanted[axis] = std::clamp(v, -vmax, vmax);
    }
    if (m_blocked) {
        // Only a return to the centre re-arms the stick after a refusal or an E-stop.
        if (!active()) {
            m_blocked = false;
            m_wanted.clear();
        } else {
            m_wanted.clear();
        }
        return;
    }
    if (!m_client->isReady())
        return;
    const bool nowActive = active();
    if (nowActive != m_wasActive) {
        m_wasActive = nowActive;
        emit activeChanged(nowActive);
    }
    if (!differs()) {
        scheduleNext();
        return;
    }
    // A stop, or the first frame after a pause, goes at once; other changes once the last
    // frame is kMinIntervalMs old.
    const bool stopping = !nowActive;
    if (stopping || m_clock.elapsed() - m_lastSendMs >= kMinIntervalMs)
        sendNow();
    else
        scheduleNext();
}

void JoystickDriver::stop()
{
    std::map<int, double> zeros;
    for (const auto& [axis, v] : m_wanted)
        zeros[axis] = 0;
    for (const auto& [axis, v] : m_sent)
        zeros[axis] = 0;
    m_blocked = false;
    if (zeros.empty())
        return;
    setVelocities(zeros);
}

bool JoystickDriver::differs() const
{
    if (!m_client)
        return false;
    const auto& axes = m_client->identity().axes;
    for (const auto& [axis, v] : m_wanted) {
        const auto it = m_sent.find(axis);
        const double sent = it == m_sent.end() ? 0.0 : it->second;
        if (v == 0 && sent != 0)
            return true;  // any stop is a change
        if (std::fabs(v - sent) > kResolutionShare * axes[axis].maxSpeed)
            return true;
    }
    return false;
}

void JoystickDriver::scheduleNext()
{
    if (!active() && !differs()) {
        m_timer.stop();
        return;
    }
    const qint64 now = m_clock.elapsed();
    const qint64 due = differs() ? m_lastSendMs + kMinIntervalMs : m_lastSendMs + keepAliveMs();
    const int wait = static_cast<int>(std::max<qint64>(0, due - now));
    if (!m_timer.isActive() || m_timer.remainingTime() > wait)
        m_timer.start(wait);
}

void JoystickDriver::onTimer()
{
    if (!m_client || !m_client->isReady() || m_blocked)
        return;
    if (m_clock.elapsed() - m_lastSendMs < kMinIntervalMs) {
        scheduleNext();  // a frame went out meanwhile
        return;
    }
    if (active() || differs())
        sendNow();
}

int JoystickDriver::keepAliveMs() const { return m_client ? m_client->jogRefreshMs() : 50; }

void JoystickDriver::sendNow()
{
    if (!m_client)
        return;
    std::map<int, double> sending;
    for (const auto& [axis, v] : m_wanted) {
        const auto it = m_sent.find(axis);
        if (v == 0 && it == m_sent.end())
            continue;  // at rest and already told so
        sending[axis] = v;
    }
    if (sending.empty())
        return;
    for (const auto& [axis, v] : sending) {
        if (v == 0)
            m_sent.erase(axis);
        else
            m_sent[axis] = v;
    }
    // Axes at rest need not be wished for any more.
    for (auto it = m_wanted.begin(); it != m_wanted.end();)
        it = it->second == 0 ? m_wanted.erase(it) : std::next(it);
    m_lastSendMs = m_clock.elapsed();
    m_timer.stop();  // whatever was due is covered by this frame
    ++m_frames;
    const QPointer<JoystickDriver> self(this);  // the reply may come after the screen is gone
    m_client->setJogVelocities(sending, [this, self](const std::optional<RequestError>& e) {
        if (!self || !e || e->kind != RequestError::Kind::Device)
            return;
        // The instrument has reported the refusal (requestFailed); the stick stays dead
        // until it is back at the centre.
        blockAll();
    });
    scheduleNext();
}

} // namespace dev
