#include "subscriptions.h"

#include "api_client.h"
#include "api_server.h"
#include "command_methods.h"
#include "json_rpc.h"

#include "device/telemetry/telemetry_hub.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

constexpr int kSnapshotLogEntries = 100;
constexpr int kMaxTelemetryBacklog = 16;  ///< batches held per client; older ones are dropped

struct KindName {
    dev::proto::ChannelKind kind;
    const char* name;
};
constexpr KindName kKinds[] = {{dev::proto::ChannelKind::Commanded, "commanded"},
                               {dev::proto::ChannelKind::Measured, "measured"},
                               {dev::proto::ChannelKind::Velocity, "velocity"},
                               {dev::proto::ChannelKind::FollowingError, "following_error"},
                               {dev::proto::ChannelKind::ControllerOutput, "controller_output"},
                               {dev::proto::ChannelKind::Switches, "switches"},
                               {dev::proto::ChannelKind::ContourError, "contour_error"}};

} // namespace

struct Subscriptions::Source {
    Topic topic;
    int instrument = -1;
    QJsonObject value;
    quint64 seq = 0;
    quint64 deviceTimeUs = 0;
};

struct Subscriptions::Sub {
    int id = 0;
    quint64 clientId = 0;
    QPointer<ApiClient> client;
    Topic topic = Topic::Positions;
    int instrument = -1;
    double periodMs = 100;
    qint64 lastSentMs = -1;
    bool snapshotSent = false;
    quint64 sentSeq = 0;
    QJsonObject sentValue;
    quint64 coalescedTotal = 0, droppedTotal = 0;
    // log
    std::deque<QJsonObject> logBacklog;
    quint64 logSeq = 0;
    // telemetry
    std::vector<dev::proto::ChannelRef> channels;
    QStringList channelNames, units;
    std::vector<double> factors;
    int rateHz = 0;
    QString consumer;
    std::deque<QJsonObject> batches;
    std::deque<int> batchSamples;
    quint64 nextSample = 0;
    bool haveNextSample = false;
};

Subscriptions::Subscriptions(ApiServer& server, QObject* parent) : QObject(parent), m_server(server)
{
    m_clock.start();
    m_pump.setInterval(kPumpMs);
    m_pump.setTimerType(Qt::PreciseTimer);
    connect(&m_pump, &QTimer::timeout, this, &Subscriptions::pump);
    const auto& instruments = server.instruments();
    for (int i = 0; i < instruments.size(); ++i) {
        dev::Instrument* c = instruments[i].instrument;
        if (!c)
            continue;
        auto positions = [this, i, c] {
            const auto& id = c->identity();
            const auto& st = c->status();
            QJsonObject v;
            for (int a = 0; a < id.axes.size() && a < st.axes.size(); ++a)
                v.insert(QString(id.axes[a].letter),
                         QJsonObject{{QStringLiteral("commanded"), st.axes[a].commanded},
                                     {QStringLiteral("measured"), st.axes[a].measured},
                                     // µm on mm axes, nL on the pump (µL): as the plots show it
                                     {QStringLiteral("following_error"), std::round((st.axes[a].measured - st.axes[a].commanded) * 1e6) / 1e3}});
            sourceChanged(Topic::Positions, i, v, st.deviceTimeUs);
        };
        auto state = [this, i, c] {
            const auto& id = c->identity();
            const auto& st = c->status();
            Source& src = source(Topic::State, i);
            QJsonObject v{{QStringLiteral("link"), QString::fromLatin1(dev::linkStateKey(c->state()))}};
            if (c->isReady()) {
                QJsonObject homed, moving, homing, home, limit;
                for (int a = 0; a < id.axes.size() && a < st.axes.size(); ++a) {
                    const QString l(id.axes[a].letter);
                    homed.insert(l, st.axes[a].homed);
                    moving.insert(l, st.axes[a].moving);
                    homing.insert(l, st.axes[a].homing);
                    home.insert(l, st.axes[a].homeSwitch);
                    limit.insert(l, st.axes[a].limitSwitch);
                }
                v.insert(QStringLiteral("estop"), st.estop);
                v.insert(QStringLiteral("fault"), st.fault);
                v.insert(QStringLiteral("homed"), homed);
                v.insert(QStringLiteral("moving"), moving);
                v.insert(QStringLiteral("homing"), homing);
                v.insert(QStringLiteral("home_switch"), home);
                v.insert(QStringLiteral("limit_switch"), limit);
            }
            if (src.value.contains(QStringLiteral("last_problem")))
                v.insert(QStringLiteral("last_problem"), src.value.value(QStringLiteral("last_problem")));
            sourceChanged(Topic::State, i, v, st.deviceTimeUs);
        };
        connect(c, &dev::Instrument::statusChanged, this, [positions, state] {
            positions();
            state();
        });
        connect(c, &dev::Instrument::stateChanged, this, state);
        connect(c, &dev::Instrument::eventReceived, this, [this, i, c](const dev::DeviceEvent& e) {
            using K = dev::proto::EventKind;
            if (e.kind != K::LimitHit && e.kind != K::Fault && e.kind != K::EStop && e.kind != K::LostSteps && e.kind != K::JogExpired)
                return;
            Source& src = source(Topic::State, i);
            QJsonObject v = src.value;
            const auto& axes = c->identity().axes;
            QJsonObject problem{{QStringLiteral("kind"), eventKindKey(e.kind)},
                                {QStringLiteral("text"), e.text},
                                {QStringLiteral("device_time_us"), static_cast<qint64>(e.deviceTimeUs)}};
            if (e.axis >= 0 && e.axis < axes.size())
                problem.insert(QStringLiteral("axis"), QString(axes[e.axis].letter));
            v.insert(QStringLiteral("last_problem"), problem);
            sourceChanged(Topic::State, i, v, e.deviceTimeUs);
        });
        connect(c, &dev::Instrument::telemetryReceived, this, [this, i](const dev::proto::TelemetryBatch& b) { onTelemetry(i, b); });
        positions();
        state();
    }
    connect(&server.journal(), &EventJournal::added, this, &Subscriptions::onJournal);
    connect(&server.jobs(), &JobBoard::changed, this, [this] {
        QJsonObject v;
        for (const Job& j : m_server.jobs().all())
            v.insert(j.id, j.toJson());
        sourceChanged(Topic::Jobs, -1, v, 0);
    });
}

Subscriptions::~Subscriptions()
{
    for (auto& s : m_subs)
        if (!s->consumer.isEmpty() && m_server.hub())
            m_server.hub()->setWanted(s->consumer, {}, 0);
}

Subscriptions::Source& Subscriptions::source(Topic topic, int instrument)
{
    auto& slot = m_sources[{static_cast<int>(topic), instrument}];
    if (!slot) {
        slot = std::make_unique<Source>();
        slot->topic = topic;
        slot->instrument = instrument;
    }
    return *slot;
}

void Subscriptions::sourceChanged(Topic topic, int instrument, const QJsonObject& value, quint64 deviceTimeUs)
{
    Source& src = source(topic, instrument);
    if (deviceTimeUs)
        src.deviceTimeUs = deviceTimeUs;
    // A repeated value is not news: the sequence counts changes, so a gap is what was folded.
    if (value == src.value && src.seq > 0)
        return;
    src.value = value;
    ++src.seq;
    bool pending = false;
    for (auto& s : m_subs)
        if (s->topic == topic && s->instrument == instrument)
            pending = true;
    if (pending) {
        pump();
        if (!m_pump.isActive())
            m_pump.start();
    }
}

void Subscriptions::onJournal(const JournalEntry& entry)
{
    bool any = false;
    for (auto& s : m_subs) {
        if (s->topic != Topic::Log)
            continue;
        s->logBacklog.push_back(entry.toJson());
        s->logSeq = entry.seq;
        while (static_cast<int>(s->logBacklog.size()) > kMaxLogBacklog) {
            s->logBacklog.pop_front();
            ++s->droppedTotal;
            ++m_counts[s->clientId].dropped;
        }
        any = true;
    }
    if (any) {
        pump();
        if (!m_pump.isActive())
            m_pump.start();
    }
}

void Subscriptions::onTelemetry(int instrument, const dev::proto::TelemetryBatch& b)
{
    dev::Instrument* c = m_server.instruments().value(instrument).instrument;
    if (!c || b.sampleCount == 0)
        return;
    bool any = false;
    for (auto& s : m_subs) {
        if (s->topic != Topic::Telemetry || s->instrument != instrument)
            continue;
        std::vector<int> columns;
        for (const auto& ref : s->channels) {
            const auto it = std::find(b.channels.begin(), b.channels.end(), ref);
            columns.push_back(it == b.channels.end() ? -1 : static_cast<int>(it - b.channels.begin()));
        }
        // The stream may run faster than this client asked (another consumer wants more): every k-th sample.
        const double streamHz = b.periodUs > 0 ? 1e6 / b.periodUs : 0;
        const int step = s->rateHz > 0 && streamHz > s->rateHz ? std::max(1, static_cast<int>(std::floor(streamHz / s->rateHz + 1e-9))) : 1;
        QJsonArray samples;
        quint64 firstIndex = 0;
        bool haveFirst = false;
        for (int k = 0; k < b.sampleCount; ++k) {
            const quint64 index = b.firstSampleIndex + static_cast<quint64>(k);
            if (index % static_cast<quint64>(step) != 0)
                continue;
            if (!haveFirst) {
                firstIndex = index;
                haveFirst = true;
            }
            QJsonArray row;
            for (std::size_t ch = 0; ch < columns.size(); ++ch) {
                if (columns[ch] < 0) {
                    row.append(QJsonValue::Null);
                    continue;
                }
                const std::int32_t raw = b.values[static_cast<std::size_t>(k) * b.channels.size() + static_cast<std::size_t>(columns[ch])];
                row.append(c->toAxisUnits(s->channels[ch], raw) * s->factors[ch]);
            }
            samples.append(row);
        }
        if (samples.isEmpty())
            continue;
        const quint64 firstTimeUs = b.firstSampleTimeUs + (firstIndex - b.firstSampleIndex) * b.periodUs;
        s->batches.push_back(QJsonObject{{QStringLiteral("first_sample"), static_cast<qint64>(firstIndex)},
                                         {QStringLiteral("t0_us"), static_cast<qint64>(firstTimeUs)},
                                         {QStringLiteral("period_us"), static_cast<qint64>(b.periodUs) * step},
                                         {QStringLiteral("channels"), QJsonArray::fromStringList(s->channelNames)},
                                         {QStringLiteral("units"), QJsonArray::fromStringList(s->units)},
                                         {QStringLiteral("samples"), samples}});
        s->batchSamples.push_back(static_cast<int>(samples.size()));
        while (static_cast<int>(s->batches.size()) > kMaxTelemetryBacklog) {
            s->droppedTotal += static_cast<quint64>(s->batchSamples.front());
            m_counts[s->clientId].dropped += static_cast<quint64>(s->batchSamples.front());
            s->batches.pop_front();
            s->batchSamples.pop_front();
        }
        any = true;
    }
    if (any) {
        pump();
        if (!m_pump.isActive())
            m_pump.start();
    }
}

void Subscriptions::send(Sub& s, bool snapshot)
{
    static const char* kTopicNames[] = {"positions", "state", "jobs", "log", "telemetry"};
    QJsonObject params{{QStringLiteral("subscription"), s.id},
                       {QStringLiteral("topic"), QString::fromLatin1(kTopicNames[static_cast<int>(s.topic)])},
                       {QStringLiteral("snapshot"), snapshot}};
    if (s.instrument >= 0)
        params.insert(QStringLiteral("instrument"), m_server.instruments().value(s.instrument).key);
    QJsonObject data;
    quint64 seq = 0, deviceTime = 0, coalesced = 0;
    if (s.topic == Topic::Log) {
        QJsonArray entries;
        for (const auto& e : s.logBacklog)
            entries.append(e);
        data.insert(QStringLiteral("entries"), entries);
        seq = s.logSeq;
    } else if (s.topic == Topic::Telemetry) {
        data = s.batches.front();
        seq = static_cast<quint64>(data.value(QStringLiteral("first_sample")).toDouble());
        deviceTime = static_cast<quint64>(data.value(QStringLiteral("t0_us")).toDouble());
    } else {
        const Source& src = source(s.topic, s.instrument);
        if (snapshot) {
            data = src.value;
        } else {
            for (auto it = src.value.begin(); it != src.value.end(); ++it)
                if (s.sentValue.value(it.key()) != it.value())
                    data.insert(it.key(), it.value());
            for (auto it = s.sentValue.begin(); it != s.sentValue.end(); ++it)
                if (!src.value.contains(it.key()))
                    data.insert(it.key(), QJsonValue::Null);
        }
        seq = src.seq;
        deviceTime = src.deviceTimeUs;
        coalesced = snapshot || s.sentSeq == 0 ? 0 : src.seq - s.sentSeq - 1;
    }
    params.insert(QStringLiteral("seq"), static_cast<qint64>(seq));
    if (deviceTime)
        params.insert(QStringLiteral("device_time_us"), static_cast<qint64>(deviceTime));
    params.insert(QStringLiteral("coalesced"), static_cast<qint64>(coalesced));
    params.insert(QStringLiteral("coalesced_total"), static_cast<qint64>(s.coalescedTotal + coalesced));
    params.insert(QStringLiteral("dropped_total"), static_cast<qint64>(s.droppedTotal));
    params.insert(QStringLiteral("data"), data);
    if (!s.client || !s.client->send(notificationLine(QStringLiteral("subscription"), params), ApiClient::Priority::Update))
        return;  // behind: the value stays pending and the next message folds it in
    Counts& counts = m_counts[s.clientId];
    ++counts.sent;
    counts.coalesced += coalesced;
    s.coalescedTotal += coalesced;
    s.lastSentMs = m_clock.elapsed();
    s.snapshotSent = true;
    if (s.topic == Topic::Log) {
        s.logBacklog.clear();
    } else if (s.topic == Topic::Telemetry) {
        s.batches.pop_front();
        s.batchSamples.pop_front();
    } else {
        const Source& src = source(s.topic, s.instrument);
        s.sentSeq = src.seq;
        s.sentValue = src.value;
    }
}

void Subscriptions::pump()
{
    const qint64 now = m_clock.elapsed();
    bool pending = false;
    for (auto& sp : m_subs) {
        Sub& s = *sp;
        if (!s.client || !s.client->isOpen())
            continue;
        const bool due = s.lastSentMs < 0 || now - s.lastSentMs >= s.periodMs - 0.5;
        if (!s.snapshotSent) {
            if (s.client->canTakeUpdates() && s.topic != Topic::Telemetry)
                send(s, true);
            else if (s.topic == Topic::Telemetry)
                s.snapshotSent = true;  // telemetry has no state to snapshot: batches start now
            pending = pending || !s.snapshotSent;
            continue;
        }
        bool has = false;
        if (s.topic == Topic::Log)
            has = !s.logBacklog.empty();
        else if (s.topic == Topic::Telemetry)
            has = !s.batches.empty();
        else
            has = source(s.topic, s.instrument).seq > s.sentSeq;
        if (!has)
            continue;
        if (due && s.client->canTakeUpdates()) {
            send(s, false);
            // Telemetry batches go as fast as the client takes them.
            while (s.topic == Topic::Telemetry && !s.batches.empty() && s.client && s.client->canTakeUpdates())
                send(s, false);
        }
        if (s.topic == Topic::Log ? !s.logBacklog.empty() : s.topic == Topic::Telemetry ? !s.batches.empty()
                                                                                        : source(s.topic, s.instrument).seq > s.sentSeq)
            pending = true;
    }
    if (!pending)
        m_pump.stop();
}

QJsonObject Subscriptions::subscribe(ApiClient* client, const QJsonObject& params, ParamProblem* problem)
{
    auto fail = [problem](const QString& field, const QString& message) {
        *problem = {field, message};
        return QJsonObject{};
    };
    for (auto it = params.begin(); it != params.end(); ++it)
        if (it.key() != QLatin1String("topics"))
            return fail(it.key(), tr("unknown parameter (parameters: topics)"));
    const QJsonValue topicsValue = params.value(QStringLiteral("topics"));
    if (!topicsValue.isObject() || topicsValue.toObject().isEmpty())
        return fail(QStringLiteral("topics"),
                    tr("expected an object of topics, e.g. {\"positions\": {\"instrument\": \"stage\", \"max_hz\": 50}}"));
    const QJsonObject topics = topicsValue.toObject();
    static const std::pair<const char*, Topic> kTopics[] = {{"positions", Topic::Positions}, {"state", Topic::State},
                                                            {"jobs", Topic::Jobs},           {"log", Topic::Log},
                                                            {"telemetry", Topic::Telemetry}};
    std::vector<std::unique_ptr<Sub>> made;
    const int id = m_nextId;
    QJsonArray described;
    for (auto it = topics.begin(); it != topics.end(); ++it) {
        const QString field = QStringLiteral("topics.") + it.key();
        const auto t = std::find_if(std::begin(kTopics), std::end(kTopics), [&](const auto& p) { return it.key() == QLatin1String(p.first); });
        if (t == std::end(kTopics))
            return fail(field, tr("unknown topic (topics: positions, state, jobs, log, telemetry)"));
        if (!it.value().isObject())
            return fail(field, tr("expected an object of options (max_hz, instrument, …), {} for the defaults"));
        const QJsonObject o = it.value().toObject();
        const Topic topic = t->second;
        const bool perInstrument = topic == Topic::Positions || topic == Topic::State || topic == Topic::Telemetry;
        QStringList allowed{QStringLiteral("max_hz")};
        if (perInstrument)
            allowed << QStringLiteral("instrument");
        if (topic == Topic::Telemetry)
            allowed << QStringLiteral("channels") << QStringLiteral("rate_hz");
        for (auto k = o.begin(); k != o.end(); ++k)
            if (!allowed.contains(k.key()))
                return fail(field + QLatin1Char('.') + k.key(), tr("unknown option (options: %1)").arg(allowed.join(QStringLiteral(", "))));
        double hz = kDefaultHz;
        if (o.contains(QStringLiteral("max_hz"))) {
            const QJsonValue v = o.value(QStringLiteral("max_hz"));
            if (!v.isDouble() || !(v.toDouble() > 0) || v.toDouble() > kMaxHz)
                return fail(field + QStringLiteral(".max_hz"), tr("expected a number above 0 and at most %1").arg(kMaxHz));
            hz = v.toDouble();
        }
        QVector<int> instruments;
        if (perInstrument) {
            const QJsonValue v = o.value(QStringLiteral("instrument"));
            const auto& served = m_server.instruments();
            if (v.isUndefined()) {
                for (int i = 0; i < served.size(); ++i)
                    instruments << i;
            } else {
                int found = -1;
                for (int i = 0; i < served.size(); ++i)
                    if (v.isString() && served[i].key == v.toString())
                        found = i;
                if (found < 0) {
                    QStringList keys;
                    for (const auto& s : served)
                        keys << s.key;
                    return fail(field + QStringLiteral(".instrument"), tr("expected one of %1").arg(keys.join(QStringLiteral(", "))));
                }
                instruments << found;
            }
        } else {
            instruments << -1;
        }
        for (int instrument : instruments) {
            auto s = std::make_unique<Sub>();
            s->id = id;
            s->clientId = client->id();
            s->client = client;
            s->topic = topic;
            s->instrument = instrument;
            s->periodMs = 1000.0 / hz;
            QJsonObject d{{QStringLiteral("topic"), it.key()}, {QStringLiteral("max_hz"), hz}};
            if (instrument >= 0)
                d.insert(QStringLiteral("instrument"), m_server.instruments()[instrument].key);
            if (topic == Topic::Telemetry) {
                if (!m_server.hub())
                    return fail(field, tr("telemetry is not available here (no telemetry hub)"));
                dev::Instrument* c = m_server.instruments()[instrument].instrument;
                const auto& axes = c->identity().axes;
                QJsonArray names = o.value(QStringLiteral("channels")).toArray();
                if (!o.contains(QStringLiteral("channels")))
                    for (const auto& a : axes) {
                        names.append(QString(a.letter) + QStringLiteral(".measured"));
                        names.append(QString(a.letter) + QStringLiteral(".following_error"));
                    }
                if (!o.value(QStringLiteral("channels")).isUndefined() && (!o.value(QStringLiteral("channels")).isArray() || names.isEmpty()))
                    return fail(field + QStringLiteral(".channels"), tr("expected an array such as [\"X.measured\", \"X.following_error\"]"));
                QVector<dev::tele::ChannelKey> keys;
                const QVector<dev::tele::ChannelKey> available = m_server.hub()->availableChannels(m_server.instruments()[instrument].hubIndex);
                for (const QJsonValue& n : names) {
                    const QString name = n.toString();
                    dev::proto::ChannelRef ref;
                    bool ok = false;
                    const QString axisPart = name.section(QLatin1Char('.'), 0, 0), kindPart = name.section(QLatin1Char('.'), 1);
                    for (const auto& kn : kKinds) {
                        if (kn.kind == dev::proto::ChannelKind::ContourError && name == QLatin1String(kn.name)) {
                            ref = {dev::proto::kNoAxis, kn.kind};
                            ok = true;
                        } else if (kindPart == QLatin1String(kn.name) && axisPart.size() == 1) {
                            const int a = c->identity().axisIndex(axisPart[0]);
                            if (a >= 0) {
                                ref = {static_cast<std::uint8_t>(a), kn.kind};
                                ok = true;
                            }
                        }
                    }
                    const dev::tele::ChannelKey key{m_server.instruments()[instrument].hubIndex, ref};
                    if (!ok || !available.contains(key))
                        return fail(field + QStringLiteral(".channels"),
                                    tr("'%1' is not a channel of the %2 (AXIS.measured, AXIS.commanded, AXIS.velocity, "
                                       "AXIS.following_error, AXIS.controller_output, AXIS.switches, contour_error)")
                                        .arg(name, m_server.instruments()[instrument].key));
                    keys << key;
                    s->channels.push_back(ref);
                    s->channelNames << name;
                    const QString unit = m_server.hub()->channelUnit(key);
                    s->units << unit;
                    // The hub's units: following and contour error in µm (nL), from mm (µL).
                    s->factors.push_back(ref.kind == dev::proto::ChannelKind::FollowingError || ref.kind == dev::proto::ChannelKind::ContourError ? 1000.0 : 1.0);
                }
                int rate = dev::tele::TelemetryHub::kDefaultRateHz;
                if (o.contains(QStringLiteral("rate_hz"))) {
                    const QJsonValue v = o.value(QStringLiteral("rate_hz"));
                    if (!v.isDouble() || v.toDouble() < 1 || v.toDouble() > 100000)
                        return fail(field + QStringLiteral(".rate_hz"), tr("expected samples per second, 1 or more"));
                    rate = static_cast<int>(v.toDouble());
                }
                s->rateHz = rate;
                s->consumer = QStringLiteral("api telemetry %1/%2/%3").arg(client->id()).arg(id).arg(instrument);
                m_server.hub()->setWanted(s->consumer, keys, rate);
                d.insert(QStringLiteral("channels"), QJsonArray::fromStringList(s->channelNames));
                d.insert(QStringLiteral("units"), QJsonArray::fromStringList(s->units));
                d.insert(QStringLiteral("rate_hz"), rate);
            }
            described.append(d);
            made.push_back(std::move(s));
        }
    }
    ++m_nextId;
    for (auto& s : made) {
        if (s->topic == Topic::Log) {
            const auto& entries = m_server.journal().entries();
            const int skip = std::max(0, static_cast<int>(entries.size()) - kSnapshotLogEntries);
            for (std::size_t k = static_cast<std::size_t>(skip); k < entries.size(); ++k)
                s->logBacklog.push_back(entries[k].toJson());
            s->logSeq = m_server.journal().lastSeq();
        }
        m_subs.push_back(std::move(s));
    }
    // The snapshots go out right after the answer (the pump runs on the next turn).
    QTimer::singleShot(0, this, [this] {
        pump();
        if (!m_pump.isActive())
            m_pump.start();
    });
    return QJsonObject{{QStringLiteral("subscription"), id}, {QStringLiteral("topics"), described}};
}

bool Subscriptions::unsubscribe(quint64 clientId, int subscription)
{
    const auto before = m_subs.size();
    for (auto it = m_subs.begin(); it != m_subs.end();) {
        if ((*it)->clientId == clientId && (*it)->id == subscription) {
            if (!(*it)->consumer.isEmpty() && m_server.hub())
                m_server.hub()->setWanted((*it)->consumer, {}, 0);
            it = m_subs.erase(it);
        } else {
            ++it;
        }
    }
    return m_subs.size() != before;
}

void Subscriptions::clientGone(quint64 clientId)
{
    for (auto it = m_subs.begin(); it != m_subs.end();) {
        if ((*it)->clientId == clientId) {
            if (!(*it)->consumer.isEmpty() && m_server.hub())
                m_server.hub()->setWanted((*it)->consumer, {}, 0);
            it = m_subs.erase(it);
        } else {
            ++it;
        }
    }
    m_counts.erase(clientId);
}

Subscriptions::Counts Subscriptions::counts(quint64 clientId) const
{
    const auto it = m_counts.find(clientId);
    return it == m_counts.end() ? Counts{} : it->second;
}

} // namespace app::api
