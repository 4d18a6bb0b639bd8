#pragma once
// Live data for API clients (docs/api.md, "Subscriptions"):
//
//   subscribe {"topics": {"positions": {"instrument": "stage", "max_hz": 50}, "state": {}, "log": {}, …}}
//
// Topics: positions (commanded, measured and following error per axis), state (link,
// homed, E-stop, moving, switches, last problem), jobs (the job board: well, tile,
// segment, ETA), log (the event journal) and telemetry (encoder/grating samples in
// batches, at the device's rate when asked).
//
// Each topic of each subscription sends a full snapshot first, then only what changed,
// at most max_hz times a second. Every message carries the source's sequence number,
// the device time, how many source updates it folded in since the previous message
// (`coalesced`: the sequence gap minus one) and running totals of folded and dropped
// updates. Overflow policy: positions, state and jobs keep only the newest value per
// client (a slow client gets the latest, never a queue); log entries and telemetry
// batches that a client is too far behind to take are dropped and counted.
#include "device/protocol/messages.h"

#include <QElapsedTimer>
#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <map>
#include <memory>
#include <vector>

namespace app::api {

class ApiClient;
class ApiServer;
struct JournalEntry;
struct ParamProblem;

class Subscriptions : public QObject {
    Q_OBJECT
public:
    static constexpr double kMaxHz = 1000;
    static constexpr double kDefaultHz = 10;
    static constexpr int kPumpMs = 2;            ///< how often due updates go out
    static constexpr int kMaxLogBacklog = 500;   ///< log entries held per client; older ones are dropped

    explicit Subscriptions(ApiServer& server, QObject* parent = nullptr);
    ~Subscriptions() override;

    /// Adds a subscription for the client; the result names it and its topics, or the
    /// problem is set.
    QJsonObject subscribe(ApiClient* client, const QJsonObject& params, ParamProblem* problem);
    bool unsubscribe(quint64 clientId, int subscription);
    void clientGone(quint64 clientId);

    /// Totals for benches and tests: messages sent, and updates folded or dropped.
    struct Counts {
        quint64 sent = 0, coalesced = 0, dropped = 0;
    };
    Counts counts(quint64 clientId) const;

private:
    enum class Topic { Positions, State, Jobs, Log, Telemetry };
    struct Sub;
    struct Source;

    Source& source(Topic topic, int instrument);
    void sourceChanged(Topic topic, int instrument, const QJsonObject& value, quint64 deviceTimeUs);
    void onJournal(const JournalEntry& entry);
    void onTelemetry(int instrument, const dev::proto::TelemetryBatch& batch);
    void pump();
    void send(Sub& s, bool snapshot);

    ApiServer& m_server;
    std::map<std::pair<int, int>, std::unique_ptr<Source>> m_sources;  ///< (topic, instrument)
    std::vector<std::unique_ptr<Sub>> m_subs;
    int m_nextId = 1;
    QTimer m_pump;
    QElapsedTimer m_clock;
    std::map<quint64, Counts> m_counts;
};

} // namespace app::api
