#pragma once
// One instrument as screens, runners and the CLI use it, whatever it speaks: the
// BenchPilot protocol (device/backends/benchpilot/) or GRBL 1.1 and grblHAL
// (device/backends/grbl/, docs/grbl.md). Nothing above device/backends/ names a backend's class:
// runners and widgets hold a dev::Instrument*, and only app/ and tests compose a
// backend with its transport.
//
// The contract every backend keeps:
//  - Requests are asynchronous and answered exactly once through their callback (nullopt =
//    accepted, or a RequestError; a refusal is also emitted as requestFailed). A reply to a
//    motion request means the motion was *accepted*; its end comes as an event
//    (MotionDone, HomeDone, Stopped, LimitHit, …) and in the status.
//  - Positions, speeds and limits are in axis units (mm, µL), axis numbers are indices into
//    identity().axes.
//  - A velocity jog stops by itself when it is not renewed: startJog() is renewed by the
//    backend until stopJog(); setJogVelocities() must be renewed by the caller within
//    jogRefreshMs(). If the host dies or the link goes, motion stops within
//    identity().jogWatchdogMs on a device that has Capability::StopsOnHostLoss; a device
//    without it (GRBL) is kept only a short, bounded distance ahead.
//  - status() is kept fresh by the backend (BenchPilot polls every 50 ms; GRBL polls `?`),
//    statusChanged follows each update; readStatus() asks for one reading now.
//  - Capabilities gate features; whyNot() says why one is unavailable, as a motion::msg::Message.
//  - paths(), tuning() and compensation() are parts a backend may not have (nullptr). A backend's parts
//    live as long as it does; an InstrumentProxy emits partsReplaced() when it switches to
//    another backend, after which the pointers fetched before are gone: fetch them when a
//    job starts, not once for ever.
#include "device/client/capabilities.h"
#include "device/client/instrument_types.h"

#include <QObject>

#include <functional>
#include <map>
#include <optional>

namespace dev {

class CompensationClient;
class Compensation2dClient;
class PathClient;
class TuningClient;

class Instrument : public QObject {
    Q_OBJECT
public:
    using Callback = std::function<void(const std::optional<RequestError>&)>;
    using StatusCallback = std::function<void(const std::optional<RequestError>&, const InstrumentStatus&)>;
    using SubscribeCallback = std::function<void(const std::optional<RequestError>&, const dev::proto::SubscribeReply&)>;

    explicit Instrument(QObject* parent = nullptr);
    ~Instrument() override;

    // ---- the link ---------------------------------------------------------------------
    virtual void connectLink() = 0;
    virtual void disconnectLink() = 0;
    virtual LinkState state() const = 0;
    bool isReady() const { return state() == LinkState::Ready; }
    virtual LinkStats stats() const = 0;
    virtual QString linkDescription() const = 0;   ///< "/dev/ttyUSB0 at 115200 Bd", "simulated stage"

    // ---- identity, state, capabilities -------------------------------------------------
    virtual const DeviceIdentity& identity() const = 0;
    virtual const InstrumentStatus& status() const = 0;
    virtual const QVector<SoftLimits>& softLimits() const = 0;
    /// What the identified device can do (empty before identification).
    virtual Capabilities capabilities() const = 0;
    /// The device has `c` and the link is ready to use it.
    bool can(Capability c) const { return isReady() && capabilities().testFlag(c); }
    /// Why `c` cannot be used now; an empty Message when it can. Not connected comes
    /// first (capability.not_connected); then the backend's reason (capability.no_<key>).
    motion::msg::Message whyNot(Capability c) const;

    // ---- motion -------------------------------------------------------------------------
    /// 0 = every axis, in the device's order (the analyzer lifts Z first).
    virtual void home(quint8 axisMask, Callback done = {}) = 0;
    /// Absolute or relative straight move of several axes (axis index → target in axis
    /// units). speed: axis units per second along the path, 0 = the device's default.
    virtual void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) = 0;
    /// Arched travel (Capability::ArchedMove; refused without it): Z up to `clearZMm`
    /// (unless above it already; Z counts down from home), X and Y to the target, Z down
    /// to `zMm`, blended by the device: XY starts while Z still rises as long as it is
    /// within `departMm` of its start when Z gets there, and Z starts down once XY is
    /// within `approachMm` of its target. Speeds in mm/s, 0 = the axes' default. X, Y and
    /// Z each end with MotionDone (Z once, at the bottom).
    /// With `pump` (the device's HELLO bit kCapArchPump; refused without it): the plunger
    /// moves `pumpUl` (relative, µL/s `pumpSpeed`, 0 = default) once the way down has
    /// passed `liquidZMm`, and Z then rises to `leaveZMm`, passing `liquidZMm` again no
    /// earlier than the plunger stops; P ends with MotionDone, Z at the top of that rise.
    struct ArchMove {
        double xMm = 0, yMm = 0, clearZMm = 0, zMm = 0, departMm = 0, approachMm = 0;
        double xySpeed = 0, zSpeed = 0;
        bool pump = false;
        double pumpUl = 0, pumpSpeed = 0, liquidZMm = 0, leaveZMm = 0;
    };
    virtual void archMove(const ArchMove& move, Callback done = {});
    virtual void jogStep(int axis, double delta, double speed = 0, Callback done = {}) = 0;
    /// Hold-to-jog of one axis (keys, buttons): the backend renews it until stopJog().
    virtual void startJog(int axis, double velocity) = 0;
    virtual void stopJog(int axis) = 0;
    virtual void stopAllJogs() = 0;
    virtual bool isJogging(int axis) const = 0;
    /// Several axes at once in one realtime request (the joystick): axis → axis units/s,
    /// 0 stops that axis now; axes not named keep what they had. The caller renews it
    /// within jogRefreshMs() or the device stops the axes by itself.
    virtual void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) = 0;
    virtual int jogRefreshMs() const = 0;
    virtual void stop(quint8 axisMask = 0, Callback done = {}) = 0;  ///< realtime; 0 = all axes
    virtual void estop(Callback done = {}) = 0;                       ///< realtime; latches until reset()
    virtual void reset(Callback done = {}) = 0;
    virtual void setZero(quint8 axisMask, Callback done = {}) = 0;
    /// Accepts the position the device believes it is at after it lost track of it
    /// (status().positionLost: GRBL's `$X` after an alarm), on the operator's word; the GUI
    /// and the CLI ask first. Refused by a device that never locks itself this way.
    virtual void unlock(Callback done = {});
    virtual void setSoftLimits(int axis, double min, double max, Callback done = {}) = 0;
    /// One status reading taken now (not the next poll), also applied to status().
    virtual void readStatus(StatusCallback done) = 0;
    /// Holds still for `seconds` once the motion already commanded has ended, then done().
    virtual void dwell(double seconds, Callback done) = 0;
    /// Pulses the trigger output (Capability::TriggerOutput) for `widthS`; refused with a
    /// reason on a device without one.
    virtual void pulseTrigger(double widthS, Callback done = {}) = 0;

    // ---- telemetry ----------------------------------------------------------------------
    /// Replaces the telemetry subscription; rate 0 stops it.
    virtual void subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done = {}) = 0;
    virtual const QVector<dev::proto::ChannelRef>& subscribedChannels() const = 0;
    virtual int subscribedRateHz() const = 0;
    /// Converts a telemetry value of a channel to axis units (mm, µL, per second, …).
    virtual double toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const = 0;

    // ---- parts a backend may not have ---------------------------------------------------
    virtual PathClient* paths() = 0;     ///< line/arc streaming; nullptr when the backend has none
    virtual TuningClient* tuning() = 0;  ///< PID gains and tests; nullptr when the backend has none
    /// Axis error compensation kept on the device; nullptr when the backend has none (the
    /// default, so a backend without it need not say so: Capability::Compensation does).
    virtual CompensationClient* compensation() { return nullptr; }
    /// An XY stage's 2D compensation table kept on the device; nullptr when the backend has none.
    virtual Compensation2dClient* compensation2d() { return nullptr; }

signals:
    void stateChanged(dev::LinkState state);
    void identified(const dev::DeviceIdentity& identity);
    void statusChanged(const dev::InstrumentStatus& status);
    void limitsChanged();
    void eventReceived(const dev::DeviceEvent& event);
    void telemetryReceived(const dev::proto::TelemetryBatch& batch);
    /// Something went wrong on the link or with a request; for a status bar or log.
    void linkError(const motion::msg::Message& message);
    void requestFailed(const dev::RequestError& error);
    void samplesLost(quint64 totalLost);
    /// Something worth a line in the event log that changes no state: a controller's own
    /// message ([MSG:…] on GRBL), a line the backend does not know (logged, never fatal).
    void noted(const motion::msg::Message& note);
    /// paths(), tuning() and compensation() now return other objects (see the contract above).
    void partsReplaced();

protected:
    /// The backend's reason that the identified device lacks `c` (whyNot() has already
    /// ruled out a link that is not ready). The default names the capability, the
    /// instrument and its family; a backend adds a `because` where it knows one.
    virtual motion::msg::Message missingReason(Capability c) const;
    /// For backends: a refusal of `what` before anything is sent (bad axis, a missing
    /// capability), reported like a device's refusal.
    void refuse(const Callback& done, RequestError::Kind kind, const motion::msg::Message& message);
};

/// The term that names an instrument kind in messages: "instrument.analyzer", "instrument.stage".
std::string instrumentTerm(dev::proto::DeviceKind kind);

} // namespace dev
