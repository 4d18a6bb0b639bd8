#pragma once
// The flight recorder of the telemetry hub (docs/telemetry.md, "History"): every connected
// instrument's positions and following errors, kept from connection on whether or
// not a screen shows them, so "what just happened?" can be answered and exported
// after the fact. The live stores follow what screens want; this does not.
//
// Budget (docs/telemetry.md, "History"): each recorded channel is one ChannelStore
// (a ring of float values, times as periodic runs, min/max pyramid) of
//     capacity = seconds × rateHz  samples    (default 300 s × 100 Hz = 30 000)
// fixed when the channel is first seen. A stream faster than rateHz is kept at
// every k-th sample, k = ⌈stream rate / rateHz⌉ (picked on the device's sample
// counter, so runs stay periodic and one run costs 32 bytes, not one per sample):
// the ring then always spans at least `seconds`. When full the oldest sample is
// overwritten. A gap in the stream (reconnect, telemetry off) starts a new run,
// so plots show it as a gap; nothing before it is dropped.
//
// Plain C++ over the protocol's types (no Qt): the hub converts wire units and
// keeps the time line; this only decides what to keep and keeps it.
#include "device/protocol/messages.h"
#include "device/telemetry/channel_store.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace dev::tele {

struct HistoryBudget {
    double seconds = 300;  ///< the span every channel keeps at least
    int rateHz = 100;      ///< the highest rate kept; faster streams are thinned to ≤ this
    /// Samples per channel: seconds × rateHz (at least 1).
    std::size_t capacity() const;
};

class HistoryRecorder {
public:
    explicit HistoryRecorder(const HistoryBudget& budget = {});

    const HistoryBudget& budget() const { return m_budget; }
    /// What is recorded of every instrument: per axis these kinds (the telemetry's
    /// positions and error; velocity is their derivative, switches are in the event log).
    static const std::vector<dev::proto::ChannelKind>& recordedKinds();

    /// Keeps every k-th sample (k from the batch period, see above) of `values`
    /// (n samples at t0S, t0S + periodS, …; the device's sample index of the first is
    /// firstIndex). The store is made on the channel's first samples.
    void record(int instrument, const dev::proto::ChannelRef& ref, std::uint32_t firstIndex, double t0S, double periodS,
                const float* values, std::size_t n);

    /// nullptr before the channel's first samples.
    const ChannelStore* store(int instrument, const dev::proto::ChannelRef& ref) const;
    /// Recorded channels of an instrument (axis, then kind).
    std::vector<dev::proto::ChannelRef> channels(int instrument) const;
    /// Newest minus oldest time held by the instrument's channels (0 when empty).
    double spanS(int instrument) const;
    /// Newest time held for the instrument (NaN when empty).
    double latestS(int instrument) const;
    /// Heap held by every store: bounded by channels × (4.53 B × capacity + runs).
    std::size_t memoryBytes() const;
    /// Forgets the instrument (another instrument was put at its index).
    void forget(int instrument);
    /// Thinning factor for a stream of this period: ⌈(1 / rateHz) / periodS⌉ ≥ 1.
    std::size_t strideFor(double periodS) const;

private:
    struct RefLess {
        bool operator()(const dev::proto::ChannelRef& a, const dev::proto::ChannelRef& b) const
        {
            return a.axis != b.axis ? a.axis < b.axis : a.kind < b.kind;
        }
    };
    using Channels = std::map<dev::proto::ChannelRef, std::unique_ptr<ChannelStore>, RefLess>;
    HistoryBudget m_budget;
    std::map<int, Channels> m_instruments;
};

} // namespace dev::tele
