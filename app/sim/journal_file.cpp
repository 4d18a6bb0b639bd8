#include "journal_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace app::sim {

bool writeJournal(const dev::sim::Firmware& firmware, const QString& path, QString* error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        *error = f.errorString();
        return false;
    }
    for (const auto& e : firmware.journal()) {
        QJsonArray commanded;
        for (double c : e.commanded)
            commanded.append(c);
        const QJsonObject line{{QStringLiteral("t"), e.timeS},
                               {QStringLiteral("type"), e.type},
                               {QStringLiteral("seq"), e.seq},
                               {QStringLiteral("payload"), QString::fromLatin1(QByteArray(reinterpret_cast<const char*>(e.payload.data()),
                                                                                          static_cast<qsizetype>(e.payload.size()))
                                                                                   .toHex())},
                               {QStringLiteral("commanded"), commanded}};
        f.write(QJsonDocument(line).toJson(QJsonDocument::Compact));
        f.write("\n");
    }
    // Where the machine was left: the plunger's account is closed against it.
    QJsonArray end;
    for (int i = 0; i < firmware.machine().axisCount(); ++i)
        end.append(firmware.machine().commandedLogical(i));
    f.write(QJsonDocument(QJsonObject{{QStringLiteral("end"), true},
                                      {QStringLiteral("commanded"), end},
                                      {QStringLiteral("crc_errors"), static_cast<qint64>(firmware.decoderStats().crcErrors)},
                                      {QStringLiteral("duplicates_answered"), static_cast<qint64>(firmware.duplicateRequests())}}).toJson(QJsonDocument::Compact));
    f.write("\n");
    if (!f.commit()) {
        *error = f.errorString();
        return false;
    }
    return true;
}

} // namespace app::sim
