#pragma once
// Private to the TelemetryHub's own .cpp files (the hub is split by
// responsibility: telemetry_hub.cpp, _subscription, _stores, _recording): what
// more than one of them needs. Nothing outside device/telemetry includes this.
#include "device/telemetry/telemetry_hub.h"

#include <limits>

namespace tele {
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The recorder's consumer name: not a name a widget would pick.
inline const QString kRecordingConsumer = QStringLiteral("\x01recording");

struct TelemetryHub::Recording {
    QFile file;
    QVector<ChannelKey> columns;
    QByteArray buffer;
    quint64 rows = 0;
};

} // namespace tele
