#pragma once
// Why a request to an instrument did not succeed: the device refused it, it timed
// out, the link went down, or the host found it invalid before sending. Every
// backend reports its failures in this one shape.
#include "device/protocol/messages.h"
#include "motion/message.h"

#include <QMetaType>
#include <QString>

namespace dev {

/// Why a request did not succeed.
struct RequestError {
    enum class Kind { Device, Timeout, LinkDown, Invalid };
    Kind kind = Kind::Device;
    proto::ErrorCode code = proto::ErrorCode::BadPayload;  ///< for Kind::Device
    int axis = -1;
    double value = 0;         ///< axis units where an axis is named, else as sent
    QString message;          ///< whole sentence for a person
    /// The same refusal as structured data, when the backend has it (a GRBL error:N names its
    /// code and the line it answers: grbl.error{code, line}); the app words it with
    /// words::text() and the CLI's JSON carries it. Empty from backends that give only `message`.
    msg::Message detail;
};

} // namespace dev

Q_DECLARE_METATYPE(dev::RequestError)
