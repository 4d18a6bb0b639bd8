#pragma once
// Private to the TelemetryHub's own .cpp files (the hub is split by
// responsibility: telemetry_hub.cpp, _subscription, _stores, _recording): what
// more than one of them needs. Nothing outside device/telemetry includes this.
#include "device/telemetry/telemetry_hub.h"

#include <QByteArray>
#include <QString>

#include <charconv>
#include <limits>

namespace dev::tele {
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The recorder's consumer name: not a name a widget would pick.
inline const QString kRecordingConsumer = QStringLiteral("\x01recording");

/// A CSV cell: quoted when it holds a separator, quote or line break.
inline QByteArray csvCell(const QString& text)
{
    QByteArray b = text.toUtf8();
    if (b.contains(',') || b.contains('"') || b.contains('\n') || b.contains('\r')) {
        b.replace("\"", "\"\"");
        b = '"' + b + '"';
    }
    return b;
}

/// The shortest text that reads back as this value (a float's own digits, not a double's).
template <typename T>
void appendShortest(QByteArray& out, T v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, static_cast<qsizetype>(r.ptr - buf));
}

struct TelemetryHub::Recording {
    QFile file;
    QVector<ChannelKey> columns;
    QByteArray buffer;
    quint64 rows = 0;
};

} // namespace dev::tele
