#pragma once
// The event log as the API serves it (the `log` topic) and as the GUI shows the API's
// part of it: device events of every instrument, link changes and refusals, and every
// call that changed something with the name of the client that made it.
//
// Bounded: the newest kCapacity entries are kept, the oldest dropped first; each entry
// has a sequence number, so a reader that fell behind knows how many it missed.
#include "device/client/instrument_types.h"

#include <QDateTime>
#include <QJsonObject>
#include <QObject>
#include <QString>

#include <deque>

namespace dev {
class Instrument;
}

namespace app::api {

struct JournalEntry {
    quint64 seq = 0;
    QDateTime hostTime;
    quint64 deviceTimeUs = 0;  ///< 0 when the entry is not the device's
    QString source;            ///< "stage", "analyzer", "api"
    QString kind;              ///< "limit_hit", "link", "call", "control", …
    QString client;            ///< the API client it concerns; empty for the device's own
    QString text;              ///< a sentence for a person
    bool problem = false;
    QJsonObject toJson() const;
};

class EventJournal : public QObject {
    Q_OBJECT
public:
    static constexpr int kCapacity = 2000;

    explicit EventJournal(QObject* parent = nullptr);

    /// Records the instrument's events, link changes and refusals under `source`.
    void watch(const QString& source, dev::Instrument* instrument);
    void add(JournalEntry entry);
    const std::deque<JournalEntry>& entries() const { return m_entries; }
    quint64 lastSeq() const { return m_nextSeq - 1; }

signals:
    void added(const app::api::JournalEntry& entry);

private:
    std::deque<JournalEntry> m_entries;
    quint64 m_nextSeq = 1;
};

/// The event's kind as the log topic names it ("motion_done", "limit_hit", …).
QString eventKindKey(dev::proto::EventKind kind);

} // namespace app::api
