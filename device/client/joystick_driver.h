#pragma once
// Continuous velocity jog of several axes at once for a joystick (or keys acting as one): the
// wanted velocity of each axis goes to the device in one Instrument::setJogVelocities (on the
// BenchPilot protocol one JOG_VELOCITY: a mask, one velocity per axis), but only as often as it
// is worth it — a mouse drag asks hundreds of times a second:
//   - a change is sent at once if the last frame is kMinIntervalMs old, else when it is (the
//     latest wish wins; nothing queues up);
//   - a change smaller than kResolutionShare of the axis' maximum speed is not a change;
//   - holding still, the same velocities are re-sent every Instrument::jogRefreshMs() so the
//     device's jog watchdog (trip at 200 ms) keeps the motion alive — and stops it when
//     BenchPilot goes quiet;
//   - going to zero is sent at once (a stop never waits).
// Every frame is realtime (it overtakes queued requests). A refusal (E-stop, busy), a lost link
// or an E-stop seen in the status ends the hold: nothing is sent again until the stick is
// moved anew from the centre.
#include "device/client/instrument.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <map>

namespace dev {

class JoystickDriver : public QObject {
    Q_OBJECT
public:
    static constexpr int kMinIntervalMs = 20;                          ///< at most 50 frames a second while it changes
    static constexpr double kResolutionShare = 0.005;                  ///< 0.5 % of the axis' maximum speed

    explicit JoystickDriver(Instrument* instrument, QObject* parent = nullptr);
    ~JoystickDriver() override;

    /// Wanted velocities, axis index → axis units/s (axes not named keep what they had). Values
    /// are clamped to each axis' maximum speed.
    void setVelocities(const std::map<int, double>& velocities);
    /// Every axis to zero, now.
    void stop();
    /// Something is moving (or about to): a non-zero velocity is wanted.
    bool active() const;
    /// After a refusal, a lost link or an E-stop the driver ignores wishes until they return to zero.
    bool blocked() const { return m_blocked; }
    quint64 framesSent() const { return m_frames; }
    quint64 wishes() const { return m_wishes; }
    /// Holding still, the same velocities go out this often: the instrument's jog refresh.
    int keepAliveMs() const;

signals:
    void activeChanged(bool active);

private:
    void onTimer();
    void sendNow();
    bool differs() const;
    void scheduleNext();
    void blockAll();

    QPointer<Instrument> m_client;
    std::map<int, double> m_wanted;  ///< axis → velocity now wanted
    std::map<int, double> m_sent;    ///< axis → velocity last sent (non-zero ones, and zeros not yet sent)
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_lastSendMs = -1000000;
    quint64 m_frames = 0, m_wishes = 0;
    bool m_blocked = false;
    bool m_wasActive = false;
};

} // namespace dev
