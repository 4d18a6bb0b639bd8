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
    dev::proto::ErrorCode code = dev::proto::ErrorCode::BadPayload;  ///< for Kind::Device
    int axis = -1;
    double value = 0;         ///< axis units where an axis is named, else as sent
    motion::msg::Message message;     ///< request.*, device.refused, link.*: worded by ui::words::text (docs/wording.md)
};

} // namespace dev

Q_DECLARE_METATYPE(dev::RequestError)
Q_DECLARE_METATYPE(motion::msg::Message)
