// TelemetryHub: consumers' wants and the subscription that serves them. The
// union of what is wanted per instrument is subscribed at the highest wanted
// rate; a rate the device refuses as over capacity is retried lower, and the
// outcome is reported with a sentence saying what limited it.
#include "device/telemetry/telemetry_hub.h"
#include "device/telemetry/telemetry_hub_detail.h"

#include <algorithm>

namespace dev::tele {
namespace {
/// Attempts at a lower rate after the device refused one as over capacity.
constexpr int kMaxFallbacks = 4;

bool refLess(const dev::proto::ChannelRef& a, const dev::proto::ChannelRef& b)
{
    return a.axis != b.axis ? a.axis < b.axis : a.kind < b.kind;
}
} // namespace

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
        QVector<dev::proto::ChannelRef> refs;
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

void TelemetryHub::unionFor(int index, QVector<dev::proto::ChannelRef>& channels, int& rateHz) const
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
    // The history's channels ride along at whatever rate the others want; alone they
    // are streamed at the default rate (as the recording's are).
    for (const auto& k : available)
        if (recordsKind(k.ref.kind) && !channels.contains(k.ref))
            channels.push_back(k.ref);
    std::sort(channels.begin(), channels.end(), refLess);
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
        QVector<dev::proto::ChannelRef> channels;
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

void TelemetryHub::subscribe(int index, const QVector<dev::proto::ChannelRef>& channels, int rateHz, int wantedHz, int attempt,
                             Limit limit, int statedHz)
{
    Instrument* in = instrument(index);
    if (!in || !in->client)
        return;
    in->subscribeInFlight = true;
    QPointer<TelemetryHub> self(this);
    in->client->subscribe(channels, rateHz, [self, index, channels, rateHz, wantedHz, attempt, limit, statedHz](
                                                const std::optional<dev::RequestError>& err, const dev::proto::SubscribeReply& reply) {
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
                && (err->code == dev::proto::ErrorCode::OverCapacity || err->code == dev::proto::ErrorCode::OutOfRange);
            const int stated = static_cast<int>(err->value);
            if (err->kind == dev::RequestError::Kind::Device && err->code == dev::proto::ErrorCode::OverCapacity) {
                // History never costs a screen its rate: first leave out what only the
                // history wants (its channels get a gap until the wants change again).
                const QVector<dev::proto::ChannelRef> shed = self->historyOnly(index, channels);
                if (!shed.isEmpty() && shed.size() < channels.size()) {
                    QVector<dev::proto::ChannelRef> rest;
                    for (const auto& ref : channels)
                        if (!shed.contains(ref))
                            rest.push_back(ref);
                    self->subscribe(index, rest, rateHz, wantedHz, attempt, limit, statedHz);
                    return;
                }
            }
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
                                err->code == dev::proto::ErrorCode::OverCapacity ? Limit::Link : Limit::SampleClock, stated);
                return;
            }
            if (err->kind != dev::RequestError::Kind::LinkDown)
                emit self->problem(motion::msg::make("telemetry.not_subscribed", {motion::msg::verbatim("instrument", i->name.toStdString()), motion::msg::nested("cause", err->message)}));
            // Left as is until the wants change or the link comes back.
            reapply();
            return;
        }
        i->subscribed = reply.rateHz ? channels : QVector<dev::proto::ChannelRef>{};
        i->historyShed = !self->historyOnly(index, i->desired).isEmpty()
            && self->historyOnly(index, channels).size() < self->historyOnly(index, i->desired).size();
        i->subscribedRateHz = static_cast<int>(reply.rateHz);
        i->haveSampleIndex = false;  // a new subscription restarts the device's sample counter
        motion::msg::Message note;
        const int got = static_cast<int>(reply.rateHz);
        if (got > 0 && got < wantedHz) {
            if (limit == Limit::Link)
                note = motion::msg::make("telemetry.rate_link_limited",
                                 {motion::msg::integer("rate", got, motion::msg::Unit::Hz),
                                  motion::msg::integer("baud", i->client ? i->client->identity().linkBaud : 0, motion::msg::Unit::Baud),
                                  motion::msg::integer("max", statedHz, motion::msg::Unit::Hz), motion::msg::integer("channels", channels.size())});
            else if (limit == Limit::SampleClock)
                note = motion::msg::make("telemetry.rate_clock_limited", {motion::msg::integer("rate", got, motion::msg::Unit::Hz), motion::msg::integer("clock", statedHz, motion::msg::Unit::Hz)});
        }
        if (got > 0 && note.empty() && got != wantedHz)
            note = motion::msg::make("telemetry.rate_nearest", {motion::msg::integer("rate", got, motion::msg::Unit::Hz)});
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
        emit subscriptionChanged(index, 0, motion::msg::make("telemetry.link_state", {motion::msg::term("state", dev::linkStateTerm(state))}));
}

bool TelemetryHub::recordsKind(dev::proto::ChannelKind kind) const
{
    if (!m_history)
        return false;
    const auto& kinds = HistoryRecorder::recordedKinds();
    return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

QVector<dev::proto::ChannelRef> TelemetryHub::historyOnly(int index, const QVector<dev::proto::ChannelRef>& channels) const
{
    QVector<dev::proto::ChannelRef> out;
    const Instrument* in = instrument(index);
    for (const auto& ref : channels)
        if (recordsKind(ref.kind) && (!in || !in->collected.contains(ref)))
            out.push_back(ref);
    return out;
}

bool TelemetryHub::historyHeldBack(int index) const
{
    const Instrument* in = instrument(index);
    return in && in->historyShed && in->subscribedRateHz > 0;
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

} // namespace dev::tele
