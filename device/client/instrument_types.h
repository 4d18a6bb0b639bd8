#pragma once
// What a client knows about its instrument, in the axes' own units (mm, µL).
#include "device/protocol/messages.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace dev {

enum class LinkState { Disconnected, Connecting, Identified, Ready, Lost };
QString linkStateName(LinkState s);

struct AxisDescriptor {
    QChar letter;
    proto::AxisUnit unit = proto::AxisUnit::Millimetre;
    double travelMin = 0, travelMax = 0;  ///< axis units
    double maxSpeed = 0;                  ///< axis units per second
    double resolution = 0;                ///< one count of the measuring system
    /// Wire units (nm or nL) per axis unit.
    double wireScale() const { return unit == proto::AxisUnit::Microlitre ? 1e3 : 1e6; }
    QString unitName() const;             ///< "mm" or "µL"
};

struct DeviceIdentity {
    proto::DeviceKind kind = proto::DeviceKind::Analyzer;
    int protocolVersion = 0;
    std::uint32_t capabilities = 0;
    QString model, firmware;
    QVector<AxisDescriptor> axes;
    std::uint32_t linkBaud = 0;
    std::uint32_t maxTelemetryRateHz = 0;
    int jogWatchdogMs = 0;
    int axisIndex(QChar letter) const;
    QString kindName() const;
};

struct AxisReadout {
    double commanded = 0;  ///< axis units
    double measured = 0;   ///< encoder or grating
    bool homed = false, moving = false, homing = false, jogging = false;
    bool homeSwitch = false, limitSwitch = false, fault = false;
};

struct InstrumentStatus {
    bool estop = false, fault = false;
    quint64 deviceTimeUs = 0;
    QVector<AxisReadout> axes;
    bool anyMoving() const;
};

struct SoftLimits {
    double min = 0, max = 0;  ///< axis units
};

struct DeviceEvent {
    proto::EventKind kind = proto::EventKind::MotionDone;
    int axis = -1;            ///< −1: the whole instrument
    double position = 0;      ///< axis units; for an instrument-wide event the number as sent (path events: the segment index)
    quint64 deviceTimeUs = 0;
    QString text;
    QDateTime hostTime;
};

/// Why a request did not succeed.
struct RequestError {
    enum class Kind { Device, Timeout, LinkDown, Invalid };
    Kind kind = Kind::Device;
    proto::ErrorCode code = proto::ErrorCode::BadPayload;  ///< for Kind::Device
    int axis = -1;
    double value = 0;         ///< axis units where an axis is named, else as sent
    QString message;          ///< whole sentence for a person
};

} // namespace dev

Q_DECLARE_METATYPE(dev::LinkState)
Q_DECLARE_METATYPE(dev::InstrumentStatus)
Q_DECLARE_METATYPE(dev::DeviceEvent)
Q_DECLARE_METATYPE(dev::RequestError)
