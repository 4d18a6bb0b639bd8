#pragma once
// Telemetry of every instrument, gathered once for all who watch it: the Plots
// screen, the Jog screen's strip, a CSV recorder. Consumers say what they want
// (setWanted); the hub subscribes the union per instrument at the highest wanted
// rate the link carries, decodes batches into one ChannelStore per channel (a
// rolling window, oldest dropped), counts lost samples and streams recordings.
//
// Threading: everything on the thread the hub lives on (the GUI thread). Readers
// call store() when they draw and must not keep the pointer past the current
// event-loop turn: a store is replaced when its rate or the window changes and
// deleted when nobody wants its channel any more.
#include "device/client/instrument.h"
#include "device/telemetry/channel_store.h"
#include "device/telemetry/history_recorder.h"

#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVector>

#include <map>
#include <memory>

namespace dev::tele {

struct ChannelKey {
    int instrument = 0;  ///< the index given to addInstrument (by convention 0 analyzer, 1 stage)
    dev::proto::ChannelRef ref;
    bool operator==(const ChannelKey& o) const { return instrument == o.instrument && ref == o.ref; }
    bool operator!=(const ChannelKey& o) const { return !(*this == o); }
    /// Instrument, then axis, then kind: the order of availableChannels() and of CSV columns.
    bool operator<(const ChannelKey& o) const
    {
        if (instrument != o.instrument)
            return instrument < o.instrument;
        if (ref.axis != o.ref.axis)
            return ref.axis < o.ref.axis;
        return ref.kind < o.ref.kind;
    }
};
size_t qHash(const ChannelKey& key, size_t seed = 0) noexcept;

class TelemetryHub : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultRateHz = 100;      ///< for a consumer that asks for rate ≤ 0
    static constexpr double kMinWindowS = 1;
    static constexpr double kMaxWindowS = 600;
    static constexpr double kDefaultWindowS = 30;
    /// Stores hold this many windows of samples: one live window plus one for a pause (see setPaused).
    static constexpr double kPauseWindows = 2;

    explicit TelemetryHub(QObject* parent = nullptr);
    ~TelemetryHub() override;

    /// The hub owns the client's telemetry subscription from now on (replacing the
    /// client's default one when the client is, or becomes, Ready). Not owned.
    void addInstrument(int instrument, const QString& name, dev::Instrument* client);
    /// Its name in a new language (plots, CSV headers and messages use it from now on).
    void setInstrumentName(int instrument, const QString& name);
    QVector<int> instruments() const;
    QString instrumentName(int instrument) const;

    /// From the client's identity (empty until identified): per axis Commanded,
    /// Measured, Velocity, FollowingError, [ControllerOutput with CapClosedLoopPid],
    /// Switches; then ContourError (axis dev::proto::kNoAxis) with CapClosedLoopPid.
    QVector<ChannelKey> availableChannels(int instrument) const;
    QString channelName(const ChannelKey& key) const;  ///< "Stage X measured", "Stage contour error"
    /// Unit of the values in the store: positions in the axis unit (mm, µL),
    /// velocity per second (mm/s), following error in µm (nL on a µL axis),
    /// controller output in steps/s, contour error in µm, switches "" (bit0 home, bit1 limit).
    QString channelUnit(const ChannelKey& key) const;

    /// What one consumer wants; replaces its previous wish. Empty channels (or an
    /// empty consumer name) withdraws it. rateHz ≤ 0 means kDefaultRateHz.
    /// Applied on the next event-loop turn (several calls in one turn cost one
    /// SUBSCRIBE); subscriptionChanged() reports the outcome. An instrument nobody
    /// wants anything from has its telemetry switched off.
    void setWanted(const QString& consumer, const QVector<ChannelKey>& channels, int rateHz);
    /// The rate the device streams an instrument's telemetry at now (0: off).
    int subscribedRateHz(int instrument) const;

    /// nullptr if the channel is not collected (nobody wants it, or no batch yet).
    const ChannelStore* store(const ChannelKey& key) const;

    /// 1 s … 600 s (clamped). Stores hold kPauseWindows × window × rate samples;
    /// live, each batch trims them to [newest − window, newest].
    void setWindowS(double seconds);
    double windowS() const { return m_windowS; }

    /// Pause freezes the view; collection and recording go on. Policy: while paused,
    /// nothing in [pausedAt − window, pausedAt] is trimmed, and new samples are
    /// stored while they fit (another whole window: a pause up to one window long
    /// loses nothing on the plots). Past that, new samples are not stored (counted
    /// in heldBackSamples(); a recording still gets them): what the user froze is
    /// never eroded. Resuming trims back to the live window.
    void setPaused(bool paused);
    bool paused() const { return m_paused; }
    /// Device time of the instrument's newest sample when the pause began (NaN if none yet).
    double pausedAtS(int instrument) const;
    /// Newest time seen from the instrument (NaN before the first batch), on its time
    /// line: the device clock, moved on past a gap when that clock starts again.
    double latestTimeS(int instrument) const;
    /// Samples (per sample time, all channels) the device sent that never arrived:
    /// gaps in the batches' sample counter, the same rule as the client's.
    quint64 lostSamples(int instrument) const;
    quint64 samplesReceived(int instrument) const;
    /// Samples not stored because a pause had filled the stores.
    quint64 heldBackSamples(int instrument) const;

    /// Streams the channels to a CSV file as batches arrive (see docs/telemetry.md):
    /// header `time_s,instrument,<name> [<unit>],…`; one row per device sample time
    /// of one instrument, cells of other instruments' channels empty. Buffered in
    /// memory at most kRecordFlushBytes or kRecordFlushMs. The channels are
    /// collected for as long as the recording runs (at the rate others want, or
    /// kDefaultRateHz). Returns false with a sentence in *error if the file cannot
    /// be written, nothing is to be recorded, or a recording already runs.
    bool startRecording(const QString& csvPath, const QVector<ChannelKey>& channels, motion::msg::Message* error);
    void stopRecording();
    bool recording() const { return m_record != nullptr; }
    QString recordingPath() const;
    quint64 recordedRows() const;
    static constexpr int kRecordFlushBytes = 64 * 1024;
    static constexpr int kRecordFlushMs = 500;

    // ---- history: the flight recorder (docs/telemetry.md "History") ----
    /// From now on every instrument, once identified, streams HistoryRecorder::recordedKinds()
    /// of every axis (at the rate others want, or kDefaultRateHz alone) and the hub keeps
    /// them within `budget` whether or not anyone wants them. Off until called: a hub in a
    /// test or a bench streams only what is wanted; the application turns it on.
    void enableHistory(const HistoryBudget& budget = {});
    bool historyEnabled() const { return m_history != nullptr; }
    /// nullptr without history; read-only (stores, span, memory).
    const HistoryRecorder* history() const { return m_history.get(); }
    /// nullptr before the channel's first recorded sample.
    const ChannelStore* historyStore(const ChannelKey& key) const;
    /// What a plot should draw: the live store while it covers the window (full rate),
    /// else the recorded history when that reaches further back (a channel just added,
    /// a screen opened after an incident); nullptr when neither has anything.
    const ChannelStore* viewStore(const ChannelKey& key) const;
    /// Every recorded channel of every instrument (instrument, axis, kind order).
    QVector<ChannelKey> historyChannels() const;
    /// Newest minus oldest recorded time of the instrument (0 when nothing is recorded).
    double historySpanS(int instrument) const;
    /// The link cannot carry the history's channels besides what the screens want: those
    /// the screens do not show are not recorded now (the rest is).
    bool historyHeldBack(int instrument) const;
    /// Writes every recorded channel's last spanS seconds (≤ 0: all) to a CSV file
    /// (atomically), the recording's format: `time_s,instrument,<name> [<unit>],…`, one
    /// row per kept sample time of one instrument; time_s is the instrument's time line.
    bool exportHistory(const QString& csvPath, double spanS, motion::msg::Message* error, quint64* rows = nullptr) const;

signals:
    /// New samples for the instrument: at most once per event-loop turn.
    void dataArrived(int instrument);
    /// The device now streams at rateHz (0: off). note says why the rate is lower
    /// than wanted, e.g. "rate limited to 588 Hz by the 115200-baud link (it carries
    /// at most 588 Hz with 4 channels)"; empty when the wanted rate was granted.
    void subscriptionChanged(int instrument, int rateHz, const motion::msg::Message& note);
    /// A sentence for the status bar or event log.
    void problem(const motion::msg::Message& message);

private:
    struct ChannelRefLess {
        bool operator()(const dev::proto::ChannelRef& a, const dev::proto::ChannelRef& b) const
        {
            return a.axis != b.axis ? a.axis < b.axis : a.kind < b.kind;
        }
    };
    struct Collected {
        std::unique_ptr<ChannelStore> store;
        double periodS = 0;  ///< sample period the store was sized for
    };
    struct Instrument {
        QString name;
        QPointer<dev::Instrument> client;
        QList<QMetaObject::Connection> connections;
        std::map<dev::proto::ChannelRef, Collected, ChannelRefLess> stores;
        /// Channels someone wants now (sorted); batches' other channels are ignored.
        QVector<dev::proto::ChannelRef> collected;
        // Subscription: what the device streams, what was last asked for.
        QVector<dev::proto::ChannelRef> subscribed;
        int subscribedRateHz = 0;
        QVector<dev::proto::ChannelRef> desired;  ///< the union last applied (sorted)
        int desiredRateHz = -1;              ///< -1: nothing applied since Ready
        bool subscribeInFlight = false;
        bool reapplyAfterReply = false;
        // Sample bookkeeping.
        double latestS;
        double pausedAtS;
        quint64 received = 0, lost = 0, heldBack = 0;
        std::uint32_t nextSampleIndex = 0;
        bool haveSampleIndex = false;
        bool dirty = false;
        /// Added to device times: 0 until the device's clock starts again, then what
        /// continues the instrument's time line after the gap (nothing recorded is dropped).
        double offsetS = 0;
        QElapsedTimer sinceBatch;  ///< host time since the last batch: the length of that gap
        /// The last subscription left the history-only channels out: the link could not carry them too.
        bool historyShed = false;
        Instrument();
    };
    struct Want {
        QVector<ChannelKey> channels;
        int rateHz = kDefaultRateHz;
    };
    struct Recording;

    Instrument* instrument(int index);
    const Instrument* instrument(int index) const;
    void onStateChanged(int index, dev::LinkState state);
    void onBatch(int index, const dev::proto::TelemetryBatch& batch);
    void scheduleApply();
    void applyWants();
    /// Union of wanted channels of one instrument (sorted, only available ones) and the highest wanted rate.
    void unionFor(int index, QVector<dev::proto::ChannelRef>& channels, int& rateHz) const;
    void recomputeCollected();
    /// What held a subscription's rate below the wanted one.
    enum class Limit { None, Link, SampleClock };
    void subscribe(int index, const QVector<dev::proto::ChannelRef>& channels, int rateHz, int wantedHz, int attempt,
                   Limit limit, int statedHz);
    /// Channels only the history wants (not a consumer, not the recording), sorted.
    QVector<dev::proto::ChannelRef> historyOnly(int index, const QVector<dev::proto::ChannelRef>& channels) const;
    bool recordsKind(dev::proto::ChannelKind kind) const;
    void dropUnwantedStores(int index);
    std::size_t capacityFor(double periodS) const;
    ChannelStore* storeFor(Instrument& in, const dev::proto::ChannelRef& ref, double periodS);
    /// Replaces the store by one of `capacity` holding its newest samples.
    void reallocate(Collected& c, std::size_t capacity);
    void resizeStores();
    void trim(Instrument& in);
    double unitFactor(const ChannelKey& key) const;  ///< store unit per toAxisUnits() unit
    void writeRecordRows(int index, const dev::proto::TelemetryBatch& batch);
    void flushRecording();
    void failRecording(const QString& why);
    void emitDirty();

    std::map<int, Instrument> m_instruments;
    QHash<QString, Want> m_wants;
    double m_windowS = kDefaultWindowS;
    bool m_paused = false;
    bool m_applyScheduled = false;
    bool m_emitScheduled = false;
    std::vector<float> m_scratch;  ///< one batch of one channel in store units
    std::unique_ptr<Recording> m_record;
    std::unique_ptr<HistoryRecorder> m_history;
    QTimer m_flushTimer;
};

} // namespace dev::tele

Q_DECLARE_METATYPE(dev::tele::ChannelKey)
