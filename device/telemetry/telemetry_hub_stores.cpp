// TelemetryHub: the per-channel rolling stores. Sizing them for the window and
// rate, trimming, pause (freeze without losing what was frozen), and ingesting
// telemetry batches into them with the sample-counter bookkeeping (lost,
// received, held back).
#include "device/telemetry/telemetry_hub.h"
#include "device/telemetry/telemetry_hub_detail.h"

#include <algorithm>
#include <cmath>

namespace dev::tele {
namespace {
/// Slack on top of kPauseWindows × window × rate: a whole batch always fits.
constexpr std::size_t kStoreHeadroom = 1024;
/// No store grows past this (64 MB of values): a 600 s window at 10 kHz needs 12 M.
constexpr std::size_t kMaxStoreSamples = std::size_t(16) << 20;
} // namespace

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

ChannelStore* TelemetryHub::storeFor(Instrument& in, const dev::proto::ChannelRef& ref, double periodS)
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

void TelemetryHub::onBatch(int index, const dev::proto::TelemetryBatch& batch)
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
    const double deviceT0 = static_cast<double>(batch.firstSampleTimeUs) * 1e-6;
    const double period = static_cast<double>(batch.periodUs) * 1e-6;
    double t0 = deviceT0 + in.offsetS;
    if (!std::isnan(in.latestS) && t0 < in.latestS - period) {
        // Older than what we have: the device restarted its clock (power cycle). Its
        // time line goes on after the gap the host saw, so what the stores and the
        // history hold stays where it was and the new samples follow it (a gap shows).
        const double gapS = in.sinceBatch.isValid() ? static_cast<double>(in.sinceBatch.elapsed()) * 1e-3 : 0.0;
        in.offsetS = in.latestS + std::max({period, gapS, 1e-6}) - deviceT0;
        t0 = deviceT0 + in.offsetS;
        emit problem(motion::msg::make("telemetry.clock_restarted", {motion::msg::verbatim("instrument", in.name.toStdString())}));
    }
    in.sinceBatch.start();
    const double tLast = t0 + static_cast<double>(n - 1) * period;
    if (std::isnan(in.latestS) || tLast > in.latestS)
        in.latestS = tLast;
    if (m_paused && std::isnan(in.pausedAtS))
        in.pausedAtS = in.latestS;  // paused before any data: freeze on the first batch
    trim(in);

    dev::Instrument* client = in.client;
    std::size_t heldBack = 0;
    m_scratch.resize(n);
    for (std::size_t c = 0; c < nc; ++c) {
        const dev::proto::ChannelRef ref = batch.channels[c];
        const bool live = std::find(in.collected.begin(), in.collected.end(), ref) != in.collected.end();
        const bool keep = recordsKind(ref.kind);
        if (!live && !keep)
            continue;
        const double factor = unitFactor(ChannelKey{index, ref});
        const std::int32_t* v = batch.values.data() + c;
        if (client)
            for (std::size_t k = 0; k < n; ++k)
                m_scratch[k] = static_cast<float>(client->toAxisUnits(ref, v[k * nc]) * factor);
        else
            for (std::size_t k = 0; k < n; ++k)
                m_scratch[k] = static_cast<float>(v[k * nc] * factor);
        if (keep)  // the history is never frozen: a pause is a view, not a stop
            m_history->record(index, ref, batch.firstSampleIndex, t0, period, m_scratch.data(), n);
        if (!live)
            continue;
        ChannelStore* s = storeFor(in, ref, period);
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

} // namespace dev::tele
