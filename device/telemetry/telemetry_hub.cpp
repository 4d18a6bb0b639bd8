#include "device/telemetry/telemetry_hub.h"

#include "device/protocol/messages_tuning.h"

#include <QDir>
#include <QVarLengthArray>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace tele {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The recorder's consumer name: not a name a widget would pick.
const QString kRecordingConsumer = QStringLiteral("\x01recording");
/// Slack on top of kPauseWindows × window × rate: a whole batch always fits.
constexpr std::size_t kStoreHeadroom = 1024;
/// No store grows past this (64 MB of values): a 600 s window at 10 kHz needs 12 M.
constexpr std::size_t kMaxStoreSamples = std::size_t(16) << 20;
/// Attempts at a lower rate after the device refused one as over capacity.
constexpr int kMaxFallbacks = 4;

bool refLess(const proto::ChannelRef& a, const proto::ChannelRef& b)
{
    return a.axis != b.axis ? a.axis < b.axis : a.kind < b.kind;
}

QString kindWord(proto::ChannelKind k)
{
    switch (k) {
    case proto::ChannelKind::Commanded: return TelemetryHub::tr("commanded");
    case proto::ChannelKind::Measured: return TelemetryHub::tr("measured");
    case proto::ChannelKind::Velocity: return TelemetryHub::tr("velocity");
    case proto::ChannelKind::FollowingError: return TelemetryHub::tr("following error");
    case proto::ChannelKind::ControllerOutput: return TelemetryHub::tr("controller output");
    case proto::ChannelKind::Switches: return TelemetryHub::tr("switches");
    case proto::ChannelKind::ContourError: return TelemetryHub::tr("contour error");
    case proto::ChannelKind::ControllerU: return TelemetryHub::tr("controller output u");
    }
    return {};
}

/// A CSV cell: quoted when it holds a separator, quote or line break.
QByteArray csvCell(const QString& text)
{
    QByteArray b = text.toUtf8();
    if (b.contains(',') || b.contains('"') || b.contains('\n') || b.contains('\r')) {
        b.replace("\"", "\"\"");
        b = '"' + b + '"';
    }
    return b;
}

void appendNumber(QByteArray& out, double v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest text that reads back the same
    out.append(buf, static_cast<qsizetype>(r.ptr - buf));
}

/// Device microseconds as seconds with six decimals, exactly.
void appendTimeUs(QByteArray& out, std::uint64_t us)
{
    char buf[40];
    auto r = std::to_chars(buf, buf + sizeof buf, us / 1000000);
    *r.ptr++ = '.';
    const auto frac = static_cast<unsigned>(us % 1000000);
    for (unsigned d = 100000; d > 0; d /= 10)
        *r.ptr++ = static_cast<char>('0' + (frac / d) % 10);
    out.append(buf, static_cast<qsizetype>(r.ptr - buf));
}
} // namespace

size_t qHash(const ChannelKey& key, size_t seed) noexcept
{
    return ::qHash((static_cast<quint64>(static_cast<quint32>(key.instrument)) << 16) | (quint64(key.ref.axis) << 8)
                       | static_cast<quint64>(key.ref.kind),
                   seed);
}

struct TelemetryHub::Recording {
    QFile file;
    QVector<ChannelKey> columns;
    QByteArray buffer;
    quint64 rows = 0;
};

TelemetryHub::Instrument::Instrument() : latestS(kNaN), pausedAtS(kNaN) {}

TelemetryHub::TelemetryHub(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<tele::ChannelKey>();
    m_flushTimer.setInterval(kRecordFlushMs);
    connect(&m_flushTimer, &QTimer::timeout, this, &TelemetryHub::flushRecording);
}

TelemetryHub::~TelemetryHub()
{
    if (m_record) {
        flushRecording();
        m_record.reset();
    }
    for (auto& [index, in] : m_instruments)
        for (const auto& c : in.connections)
            disconnect(c);
}

TelemetryHub::Instrument* TelemetryHub::instrument(int index)
{
    const auto it = m_instruments.find(index);
    return it == m_instruments.end() ? nullptr : &it->second;
}

const TelemetryHub::Instrument* TelemetryHub::instrument(int index) const
{
    const auto it = m_instruments.find(index);
    return it == m_instruments.end() ? nullptr : &it->second;
}

void TelemetryHub::addInstrument(int index, const QString& name, dev::InstrumentClient* client)
{
    if (Instrument* old = instrument(index))
        for (const auto& c : old->connections)
            disconnect(c);
    Instrument& in = m_instruments[index];
    in = Instrument{};
    in.name = name;
    in.client = client;
    if (client) {
        in.connections << connect(client, &dev::InstrumentClient::stateChanged, this,
                                  [this, index](dev::LinkState s) { onStateChanged(index, s); });
        in.connections << connect(client, &dev::InstrumentClient::telemetryReceived, this,
                                  [this, index](const proto::TelemetryBatch& b) { onBatch(index, b); });
        in.connections << connect(client, &QObject::destroyed, this, [this, index] {
            if (Instrument* i = instrument(index))
                i->subscribeInFlight = false;
        });
    }
    recomputeCollected();
    if (client && client->isReady())
        onStateChanged(index, dev::LinkState::Ready);
}

QVector<int> TelemetryHub::instruments() const
{
    QVector<int> out;
    for (const auto& [index, in] : m_instruments)
        out << index;
    return out;
}

QString TelemetryHub::instrumentName(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->name : QString();
}

// ---- channels -------------------------------------------------------------------

QVector<ChannelKey> TelemetryHub::availableChannels(int index) const
{
    QVector<ChannelKey> out;
    const Instrument* in = instrument(index);
    if (!in || !in->client)
        return out;
    const dev::DeviceIdentity& id = in->client->identity();
    const bool pid = id.capabilities & proto::CapClosedLoopPid;
    using K = proto::ChannelKind;
    for (int a = 0; a < id.axes.size(); ++a) {
        const auto axis = static_cast<std::uint8_t>(a);
        for (K k : {K::Commanded, K::Measured, K::Velocity, K::FollowingError, K::ControllerOutput, K::Switches}) {
            if (k == K::ControllerOutput && !pid)
                continue;
            out.push_back(ChannelKey{index, {axis, k}});
        }
        if (id.capabilities & proto::CapGains)  // tuning: the PID's own output
            out.push_back(ChannelKey{index, {axis, K::ControllerU}});
    }
    if (pid)
        out.push_back(ChannelKey{index, {proto::kNoAxis, K::ContourError}});
    return out;
}

QString TelemetryHub::channelName(const ChannelKey& key) const
{
    const Instrument* in = instrument(key.instrument);
    const QString who = in ? in->name : tr("Instrument %1").arg(key.instrument);
    if (key.ref.kind == proto::ChannelKind::ContourError)
        return tr("%1 %2").arg(who, kindWord(key.ref.kind));
    QString axis = QString::number(key.ref.axis);
    if (in && in->client && key.ref.axis < in->client->identity().axes.size())
        axis = in->client->identity().axes[key.ref.axis].letter;
    return tr("%1 %2 %3").arg(who, axis, kindWord(key.ref.kind));
}

QString TelemetryHub::channelUnit(const ChannelKey& key) const
{
    const Instrument* in = instrument(key.instrument);
    bool microlitre = false;
    if (in && in->client && key.ref.axis < in->client->identity().axes.size())
        microlitre = in->client->identity().axes[key.ref.axis].unit == proto::AxisUnit::Microlitre;
    switch (key.ref.kind) {
    case proto::ChannelKind::Commanded:
    case proto::ChannelKind::Measured: return microlitre ? QStringLiteral("µL") : QStringLiteral("mm");
    case proto::ChannelKind::Velocity: return microlitre ? QStringLiteral("µL/s") : QStringLiteral("mm/s");
    case proto::ChannelKind::FollowingError: return microlitre ? QStringLiteral("nL") : QStringLiteral("µm");
    case proto::ChannelKind::ControllerOutput: return QStringLiteral("steps/s");
    case proto::ChannelKind::Switches: return QString();
    case proto::ChannelKind::ContourError:
    case proto::ChannelKind::ControllerU: return QStringLiteral("µm");
    }
    return {};
}

double TelemetryHub::unitFactor(const ChannelKey& key) const
{
    // toAxisUnits() gives mm (µL); errors are a thousand times smaller than travel.
    switch (key.ref.kind) {
    case proto::ChannelKind::FollowingError:
    case proto::ChannelKind::ContourError:
    case proto::ChannelKind::ControllerU: return 1000.0;
    default: return 1.0;
    }
}

// ---- wants and subscriptions ---------------------------------------------------------

void TelemetryHub::setWanted(const QString& consumer, const QVector<ChannelKey>& channels, int rateHz)
{
    if (consumer.isEmpty())
        return;
    if (channels.isEmpty()) {
        m_wants.remove(consumer);
    } else {
        Want w;
        w.channels = channels;
        w.rateHz = rateHz > 0 ? rateHz : kDefaultRateHz;
        m_wants.insert(consumer, w);
    }
    recomputeCollected();
    scheduleApply();
}

int TelemetryHub::subscribedRateHz(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->subscribedRateHz : 0;
}

void TelemetryHub::recomputeCollected()
{
    for (auto& [index, in] : m_instruments) {
        QVector<proto::ChannelRef> refs;
        auto add = [&refs, idx = index](const QVector<ChannelKey>& keys) {
            for (const auto& k : keys)
                if (k.instrument == idx && std::find(refs.begin(), refs.end(), k.ref) == refs.end())
                    refs.push_back(k.ref);
        };
        for (auto it = m_wants.cbegin(); it != m_wants.cend(); ++it)
            add(it->channels);
        if (m_record)
            add(m_record->columns);
        std::sort(refs.begin(), refs.end(), refLess);
        in.collected = refs;
    }
}

void TelemetryHub::unionFor(int index, QVector<proto::ChannelRef>& channels, int& rateHz) const
{
    const Instrument* in = instrument(index);
    channels.clear();
    rateHz = 0;
    if (!in)
        return;
    const QVector<ChannelKey> available = availableChannels(index);
    for (const auto& ref : in->collected)
        if (available.contains(ChannelKey{index, ref}))
            channels.push_back(ref);
    for (auto it = m_wants.cbegin(); it != m_wants.cend(); ++it) {
        if (it.key() == kRecordingConsumer)
            continue;
        for (const auto& k : it->channels)
            if (k.instrument == index) {
                rateHz = std::max(rateHz, it->rateHz);
                break;
            }
    }
    if (channels.isEmpty())
        rateHz = 0;
    else if (rateHz == 0)
        rateHz = kDefaultRateHz;  // only the recorder wants this instrument
}

void TelemetryHub::scheduleApply()
{
    if (m_applyScheduled)
        return;
    m_applyScheduled = true;
    QMetaObject::invokeMethod(this, &TelemetryHub::applyWants, Qt::QueuedConnection);
}

void TelemetryHub::applyWants()
{
    m_applyScheduled = false;
    for (auto& [index, in] : m_instruments) {
        dropUnwantedStores(index);
        if (!in.client || !in.client->isReady())
            continue;  // applied when the client becomes Ready
        if (in.subscribeInFlight) {
            in.reapplyAfterReply = true;
            continue;
        }
        QVector<proto::ChannelRef> channels;
        int rateHz = 0;
        unionFor(index, channels, rateHz);
        if (channels == in.desired && rateHz == in.desiredRateHz)
            continue;
        in.desired = channels;
        in.desiredRateHz = rateHz;
        int ask = rateHz;
        Limit limit = Limit::None;
        const auto clock = static_cast<int>(in.client->identity().maxTelemetryRateHz);
        if (clock > 0 && ask > clock) {
            ask = clock;
            limit = Limit::SampleClock;
        }
        subscribe(index, channels, ask, rateHz, 0, limit, clock);
    }
}

void TelemetryHub::subscribe(int index, const QVector<proto::ChannelRef>& channels, int rateHz, int wantedHz, int attempt,
                             Limit limit, int statedHz)
{
    Instrument* in = instrument(index);
    if (!in || !in->client)
        return;
    in->subscribeInFlight = true;
    QPointer<TelemetryHub> self(this);
    in->client->subscribe(channels, rateHz, [self, index, channels, rateHz, wantedHz, attempt, limit, statedHz](
                                                const std::optional<dev::RequestError>& err, const proto::SubscribeReply& reply) {
        if (!self)
            return;
        Instrument* i = self->instrument(index);
        if (!i)
            return;
        i->subscribeInFlight = false;
        auto reapply = [&] {
            if (i->reapplyAfterReply) {
                i->reapplyAfterReply = false;
                self->scheduleApply();
            }
        };
        if (err) {
            const bool overCapacity = err->kind == dev::RequestError::Kind::Device
                && (err->code == proto::ErrorCode::OverCapacity || err->code == proto::ErrorCode::OutOfRange);
            const int stated = static_cast<int>(err->value);
            if (overCapacity && stated > 0 && attempt < kMaxFallbacks && i->client) {
                // The device states the fastest rate it carries, floored to whole Hz.
                // Its sample clock divides into whole ticks and serves a request with
                // the next rate not faster than asked: asking for the floored number
                // itself would get one tick slower (588 Hz = 10 kHz / 17 is stated;
                // asking 588 gets 10 kHz / 18 = 556 Hz). So first ask for just above
                // the tick rate that was meant (589 Hz), and if that is refused, the
                // stated number as it is, then lower.
                const auto clock = static_cast<int>(i->client->identity().maxTelemetryRateHz);
                int next = stated;
                if (attempt == 0 && clock >= stated) {
                    const int ticks = clock / stated;
                    next = (clock + ticks - 1) / ticks;
                }
                if (next >= rateHz)
                    next = attempt == 0 ? stated : rateHz - 1;
                next = std::max(1, std::min(next, rateHz - 1));
                self->subscribe(index, channels, next, wantedHz, attempt + 1,
                                err->code == proto::ErrorCode::OverCapacity ? Limit::Link : Limit::SampleClock, stated);
                return;
            }
            if (err->kind != dev::RequestError::Kind::LinkDown)
                emit self->problem(tr("%1 telemetry not subscribed: %2").arg(i->name, err->message));
            // Left as is until the wants change or the link comes back.
            reapply();
            return;
        }
        i->subscribed = reply.rateHz ? channels : QVector<proto::ChannelRef>{};
        i->subscribedRateHz = static_cast<int>(reply.rateHz);
        i->haveSampleIndex = false;  // a new subscription restarts the device's sample counter
        QString note;
        const int got = static_cast<int>(reply.rateHz);
        if (got > 0 && got < wantedHz) {
            if (limit == Limit::Link)
                note = tr("rate limited to %1 Hz by the %2-baud link (it carries at most %3 Hz with %4 channels)")
                           .arg(got)
                           .arg(i->client ? i->client->identity().linkBaud : 0)
                           .arg(statedHz)
                           .arg(channels.size());
            else if (limit == Limit::SampleClock)
                note = tr("rate limited to %1 Hz by the device's %2 Hz sample clock").arg(got).arg(statedHz);
        }
        if (got > 0 && note.isEmpty() && got != wantedHz)
            note = tr("the device streams at %1 Hz, the nearest its sample clock makes").arg(got);
        emit self->subscriptionChanged(index, got, note);
        reapply();
    });
}

void TelemetryHub::onStateChanged(int index, dev::LinkState state)
{
    Instrument* in = instrument(index);
    if (!in)
        return;
    in->haveSampleIndex = false;
    in->desired.clear();
    in->desiredRateHz = -1;  // the device forgot: apply again on Ready
    const bool wasStreaming = in->subscribedRateHz > 0;
    in->subscribed.clear();
    in->subscribedRateHz = 0;
    if (state == dev::LinkState::Ready)
        scheduleApply();
    else if (wasStreaming)
        emit subscriptionChanged(index, 0, dev::linkStateName(state));
}

void TelemetryHub::dropUnwantedStores(int index)
{
    Instrument* in = instrument(index);
    if (!in)
        return;
    for (auto it = in->stores.begin(); it != in->stores.end();) {
        if (std::find(in->collected.begin(), in->collected.end(), it->first) == in->collected.end())
            it = in->stores.erase(it);
        else
            ++it;
    }
}

// ---- stores ---------------------------------------------------------------------

std::size_t TelemetryHub::capacityFor(double periodS) const
{
    const double samples = std::ceil(kPauseWindows * m_windowS / periodS) + double(kStoreHeadroom);
    return samples >= double(kMaxStoreSamples) ? kMaxStoreSamples : static_cast<std::size_t>(samples);
}

void TelemetryHub::reallocate(Collected& c, std::size_t capacity)
{
    c.store = c.store ? std::make_unique<ChannelStore>(*c.store, capacity) : std::make_unique<ChannelStore>(capacity);
}

ChannelStore* TelemetryHub::storeFor(Instrument& in, const proto::ChannelRef& ref, double periodS)
{
    Collected& c = in.stores[ref];
    if (periodS > 0 && (!c.store || periodS < c.periodS))
        c.periodS = periodS;  // sized for the fastest rate seen: a slower stream fits too
    else if (c.periodS <= 0)
        c.periodS = 1.0 / kDefaultRateHz;
    const std::size_t need = capacityFor(c.periodS);
    if (!c.store || c.store->capacity() < need)
        reallocate(c, need);
    return c.store.get();
}

void TelemetryHub::resizeStores()
{
    for (auto& [index, in] : m_instruments) {
        trim(in);
        for (auto& [ref, c] : in.stores) {
            const std::size_t need = capacityFor(c.periodS);
            const std::size_t cap = c.store->capacity();
            // Shrinking keeps the newest samples: not while paused, when the frozen
            // range is the oldest part. Resuming shrinks.
            if (cap < need || (!m_paused && cap > 2 * need))
                reallocate(c, need);
        }
        in.dirty = true;
    }
    emitDirty();
}

void TelemetryHub::trim(Instrument& in)
{
    const bool frozen = m_paused && !std::isnan(in.pausedAtS);
    const double newest = frozen ? in.pausedAtS : in.latestS;
    if (std::isnan(newest))
        return;
    const double cutoff = newest - m_windowS;
    for (auto& [ref, c] : in.stores)
        c.store->trimBefore(cutoff);
}

const ChannelStore* TelemetryHub::store(const ChannelKey& key) const
{
    const Instrument* in = instrument(key.instrument);
    if (!in)
        return nullptr;
    const auto it = in->stores.find(key.ref);
    return it == in->stores.end() ? nullptr : it->second.store.get();
}

void TelemetryHub::setWindowS(double seconds)
{
    if (!std::isfinite(seconds))
        return;
    seconds = std::clamp(seconds, kMinWindowS, kMaxWindowS);
    if (seconds == m_windowS)
        return;
    m_windowS = seconds;
    resizeStores();
}

void TelemetryHub::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    for (auto& [index, in] : m_instruments)
        in.pausedAtS = paused ? in.latestS : kNaN;
    if (!paused)
        resizeStores();  // back to the live window; gives back memory a window change kept
}

double TelemetryHub::pausedAtS(int index) const
{
    const Instrument* in = instrument(index);
    return in && m_paused ? in->pausedAtS : kNaN;
}

double TelemetryHub::latestTimeS(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->latestS : kNaN;
}

quint64 TelemetryHub::lostSamples(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->lost : 0;
}

quint64 TelemetryHub::samplesReceived(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->received : 0;
}

quint64 TelemetryHub::heldBackSamples(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->heldBack : 0;
}

// ---- ingest ---------------------------------------------------------------------

void TelemetryHub::onBatch(int index, const proto::TelemetryBatch& batch)
{
    Instrument* inp = instrument(index);
    if (!inp)
        return;
    Instrument& in = *inp;
    in.received += batch.sampleCount;
    // The counter runs on across batches of one subscription: a jump is samples lost.
    if (in.haveSampleIndex && batch.firstSampleIndex != in.nextSampleIndex) {
        const std::uint32_t gap = batch.firstSampleIndex - in.nextSampleIndex;
        if (gap < 0x80000000u)
            in.lost += gap;
    }
    in.haveSampleIndex = true;
    in.nextSampleIndex = batch.firstSampleIndex + batch.sampleCount;

    const std::size_t n = batch.sampleCount;
    const std::size_t nc = batch.channels.size();
    if (n == 0 || nc == 0 || batch.values.size() < n * nc || (n > 1 && batch.periodUs == 0))
        return;
    const double t0 = static_cast<double>(batch.firstSampleTimeUs) * 1e-6;
    const double period = static_cast<double>(batch.periodUs) * 1e-6;
    const double tLast = t0 + static_cast<double>(n - 1) * period;
    if (!std::isnan(in.latestS) && t0 < in.latestS - period) {
        // Older than what we have: the device restarted its clock (power cycle).
        for (auto& [ref, c] : in.stores)
            c.store->clear();
        in.latestS = kNaN;
        if (m_paused)
            in.pausedAtS = kNaN;
        emit problem(tr("%1: the device clock started again; its plots start afresh").arg(in.name));
    }
    if (std::isnan(in.latestS) || tLast > in.latestS)
        in.latestS = tLast;
    if (m_paused && std::isnan(in.pausedAtS))
        in.pausedAtS = in.latestS;  // paused before any data: freeze on the first batch
    trim(in);

    dev::InstrumentClient* client = in.client;
    std::size_t heldBack = 0;
    m_scratch.resize(n);
    for (std::size_t c = 0; c < nc; ++c) {
        const proto::ChannelRef ref = batch.channels[c];
        if (std::find(in.collected.begin(), in.collected.end(), ref) == in.collected.end())
            continue;
        ChannelStore* s = storeFor(in, ref, period);
        const double factor = unitFactor(ChannelKey{index, ref});
        const std::int32_t* v = batch.values.data() + c;
        if (client)
            for (std::size_t k = 0; k < n; ++k)
                m_scratch[k] = static_cast<float>(client->toAxisUnits(ref, v[k * nc]) * factor);
        else
            for (std::size_t k = 0; k < n; ++k)
                m_scratch[k] = static_cast<float>(v[k * nc] * factor);
        std::size_t take = n;
        if (m_paused) {
            // The frozen range is never overwritten: what does not fit waits outside.
            const std::size_t room = s->capacity() - s->size();
            if (take > room) {
                heldBack = std::max(heldBack, take - room);
                take = room;
            }
        }
        s->appendRun(t0, period, m_scratch.data(), take);
    }
    in.heldBack += heldBack;
    if (m_record)
        writeRecordRows(index, batch);
    in.dirty = true;
    emitDirty();
}

void TelemetryHub::emitDirty()
{
    if (m_emitScheduled)
        return;
    m_emitScheduled = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_emitScheduled = false;
            for (auto& [index, in] : m_instruments)
                if (in.dirty) {
                    in.dirty = false;
                    emit dataArrived(index);
                }
        },
        Qt::QueuedConnection);
}

// ---- recording ------------------------------------------------------------------

bool TelemetryHub::startRecording(const QString& csvPath, const QVector<ChannelKey>& channels, QString* error)
{
    auto fail = [error](const QString& why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_record)
        return fail(tr("already recording to %1").arg(QDir::toNativeSeparators(m_record->file.fileName())));
    QVector<ChannelKey> columns;
    for (const auto& k : channels)
        if (instrument(k.instrument) && !columns.contains(k))
            columns.push_back(k);
    if (columns.isEmpty())
        return fail(tr("nothing to record: choose at least one channel of a connected instrument"));
    auto rec = std::make_unique<Recording>();
    rec->file.setFileName(csvPath);
    if (!rec->file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return fail(tr("cannot write %1: %2").arg(QDir::toNativeSeparators(csvPath), rec->file.errorString()));
    rec->columns = columns;
    rec->buffer.reserve(kRecordFlushBytes + 4096);
    QByteArray header = "time_s,instrument";
    for (const auto& k : columns) {
        const QString unit = channelUnit(k);
        header += ',' + csvCell(unit.isEmpty() ? channelName(k) : tr("%1 [%2]").arg(channelName(k), unit));
    }
    header += '\n';
    if (rec->file.write(header) != header.size() || !rec->file.flush())
        return fail(tr("cannot write %1: %2").arg(QDir::toNativeSeparators(csvPath), rec->file.errorString()));
    m_record = std::move(rec);
    m_flushTimer.start();
    recomputeCollected();
    Want w;
    w.channels = columns;
    w.rateHz = 0;  // does not raise anyone's rate; see unionFor()
    m_wants.insert(kRecordingConsumer, w);
    scheduleApply();
    return true;
}

void TelemetryHub::stopRecording()
{
    if (!m_record)
        return;
    flushRecording();
    if (m_record) {
        m_record->file.close();
        m_record.reset();
    }
    m_flushTimer.stop();
    m_wants.remove(kRecordingConsumer);
    recomputeCollected();
    scheduleApply();
}

QString TelemetryHub::recordingPath() const { return m_record ? m_record->file.fileName() : QString(); }
quint64 TelemetryHub::recordedRows() const { return m_record ? m_record->rows : 0; }

void TelemetryHub::writeRecordRows(int index, const proto::TelemetryBatch& batch)
{
    Recording& r = *m_record;
    const std::size_t nc = batch.channels.size();
    // Column → position of that channel in the batch (−1: not in it).
    QVarLengthArray<int, 32> pos(r.columns.size());
    bool any = false;
    for (int col = 0; col < r.columns.size(); ++col) {
        pos[col] = -1;
        if (r.columns[col].instrument != index)
            continue;
        for (std::size_t c = 0; c < nc; ++c)
            if (batch.channels[c] == r.columns[col].ref) {
                pos[col] = static_cast<int>(c);
                any = true;
            }
    }
    if (!any)
        return;
    const Instrument* in = instrument(index);
    const QByteArray who = csvCell(in ? in->name : QString::number(index));
    dev::InstrumentClient* client = in ? in->client.data() : nullptr;
    for (std::size_t k = 0; k < batch.sampleCount; ++k) {
        appendTimeUs(r.buffer, batch.firstSampleTimeUs + k * batch.periodUs);
        r.buffer += ',';
        r.buffer += who;
        for (int col = 0; col < r.columns.size(); ++col) {
            r.buffer += ',';
            if (pos[col] < 0)
                continue;
            const proto::ChannelRef ref = r.columns[col].ref;
            const std::int32_t raw = batch.values[k * nc + static_cast<std::size_t>(pos[col])];
            const double v = client ? client->toAxisUnits(ref, raw) : double(raw);
            appendNumber(r.buffer, v * unitFactor(r.columns[col]));
        }
        r.buffer += '\n';
        ++r.rows;
    }
    if (r.buffer.size() >= kRecordFlushBytes)
        flushRecording();
}

void TelemetryHub::flushRecording()
{
    if (!m_record || m_record->buffer.isEmpty())
        return;
    Recording& r = *m_record;
    const qint64 written = r.file.write(r.buffer);
    if (written != r.buffer.size() || !r.file.flush()) {
        failRecording(r.file.errorString());
        return;
    }
    r.buffer.resize(0);  // keeps its allocation (clear() would free it): no churn from one flush to the next
}

void TelemetryHub::failRecording(const QString& why)
{
    const QString path = QDir::toNativeSeparators(m_record->file.fileName());
    m_record->file.close();
    m_record.reset();
    m_flushTimer.stop();
    m_wants.remove(kRecordingConsumer);
    recomputeCollected();
    scheduleApply();
    emit problem(tr("recording to %1 stopped: %2").arg(path, why));
}

} // namespace tele
