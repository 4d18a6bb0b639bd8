#pragma once
// What any backend knows about its instrument, in the axes' own units (mm, µL).
// The vocabulary (device kinds, axis units, event kinds, motion profiles) is the
// BenchPilot protocol's, which every backend maps its device into.
#include "device/client/request_error.h"
#include "device/protocol/messages.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace dev {

enum class LinkState { Disconnected, Connecting, Identified, Ready, Lost };
/// The state's term for people ("link.state.ready"; ui::words::linkState words it).
const char* linkStateTerm(LinkState s);
/// The state as a stable key for JSON ("ready", "lost", …): never translated.
const char* linkStateKey(LinkState s);

struct AxisDescriptor {
    QChar letter;
    dev::proto::AxisUnit unit = dev::proto::AxisUnit::Millimetre;
    double travelMin = 0, travelMax = 0;  ///< axis units
    double maxSpeed = 0;                  ///< axis units per second: the planner's velocity limit
    double resolution = 0;                ///< one count of the measuring system
    // The planner's other limits, as the device reported them (HELLO's motion-limits
    // block, GRBL's $$); 0 where it did not (DeviceIdentity::motionProfile says whether
    // it reported any).
    double maxAccel = 0;                  ///< axis units per s²
    double maxJerk = 0;                   ///< axis units per s³; 0: not limited, or not reported
    double defaultSpeed = 0;              ///< axis units per second: a move without a speed runs at this
    double minAccelTimeS = 0;             ///< seed 000 S-curve: the shortest acceleration phase
    /// Wire units (nm or nL) per axis unit.
    double wireScale() const { return unit == dev::proto::AxisUnit::Microlitre ? 1e3 : 1e6; }
    QString unitName() const;             ///< "mm" or "µL"
};

struct DeviceIdentity {
    dev::proto::DeviceKind kind = dev::proto::DeviceKind::Analyzer;
    /// The firmware family and the protocol it speaks, as a person reads it:
    /// "BenchPilot protocol 1", "Grbl 1.1h", "grblHAL 1.1f".
    QString family;
    int protocolVersion = 0;
    /// The BenchPilot protocol's HELLO capability bits as sent (0 from other backends).
    /// What the host may do is Instrument::capabilities(), the same on every backend.
    std::uint32_t protocolCapabilities = 0;
    QString model, firmware;
    QVector<AxisDescriptor> axes;
    /// How the planner shapes a move; Unstated when the device gave no motion limits
    /// (a protocol 1.0 device): then the axes' maxAccel and friends are 0.
    dev::proto::MotionProfile motionProfile = dev::proto::MotionProfile::Unstated;
    std::uint32_t linkBaud = 0;
    std::uint32_t maxTelemetryRateHz = 0;
    int jogWatchdogMs = 0;                ///< a velocity jog not renewed is at rest this long after (0: the device has no watchdog)
    int axisIndex(QChar letter) const;
    /// "stage" or "analyzer": the key in JSON and logs, the same in every language.
    /// People read ui::words::term(dev::instrumentTerm(kind)).
    QString kindName() const;
    bool reportsMotionLimits() const { return motionProfile != dev::proto::MotionProfile::Unstated; }
};

struct AxisReadout {
    double commanded = 0;  ///< axis units
    double measured = 0;   ///< encoder or grating
    bool homed = false, moving = false, homing = false, jogging = false;
    bool homeSwitch = false, limitSwitch = false, fault = false;
};

struct InstrumentStatus {
    bool estop = false, fault = false;
    /// The device no longer trusts its position and refuses motion until it is homed, or
    /// unlocked on the operator's word (Instrument::unlock): GRBL's Alarm after a reset in
    /// motion, a hard limit or a power-up with homing enabled.
    bool positionLost = false;
    quint64 deviceTimeUs = 0;
    QVector<AxisReadout> axes;
    bool anyMoving() const;
};

struct SoftLimits {
    double min = 0, max = 0;  ///< axis units
};

struct DeviceEvent {
    dev::proto::EventKind kind = dev::proto::EventKind::MotionDone;
    int axis = -1;            ///< −1: the whole instrument
    double position = 0;      ///< axis units; for an instrument-wide event the number as sent (path events: the segment index)
    quint64 deviceTimeUs = 0;
    QString text;
    QDateTime hostTime;
    motion::msg::Message detail;      ///< structured form of `text` where the backend has one (GRBL: grbl.alarm{code})
    bool worded = false;      ///< `detail` says all the device said, even when empty (its reason was one this host knows)
};
/// The event's detail as a message argument called `name`: its worded form, or the
/// device's own text where the backend has none.
motion::msg::Arg eventDetail(const DeviceEvent& e, const char* name = "detail");

/// How the link has fared, for the status bar. A backend fills what applies to it
/// (a line protocol has no CRC errors; the counters it cannot know stay 0).
struct LinkStats {
    quint64 framesIn = 0, crcErrors = 0, malformed = 0, oversize = 0, droppedBytes = 0;
    quint64 retransmits = 0, timeouts = 0, lateReplies = 0;
    quint64 stalls = 0;  ///< timeout checks put off once because the host's event loop was held up
    quint64 telemetryBatches = 0, telemetrySamples = 0, lostSamples = 0;
};

} // namespace dev

Q_DECLARE_METATYPE(dev::LinkState)
Q_DECLARE_METATYPE(dev::InstrumentStatus)
Q_DECLARE_METATYPE(dev::DeviceEvent)
