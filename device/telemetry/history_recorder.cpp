#include "device/telemetry/history_recorder.h"

#include <algorithm>
#include <cmath>

namespace dev::tele {

std::size_t HistoryBudget::capacity() const
{
    const double samples = std::ceil(std::max(0.0, seconds) * std::max(1, rateHz));
    return samples < 1 ? 1 : static_cast<std::size_t>(samples);
}

HistoryRecorder::HistoryRecorder(const HistoryBudget& budget) : m_budget(budget) {}

const std::vector<dev::proto::ChannelKind>& HistoryRecorder::recordedKinds()
{
    static const std::vector<dev::proto::ChannelKind> kinds{dev::proto::ChannelKind::Commanded, dev::proto::ChannelKind::Measured,
                                                       dev::proto::ChannelKind::FollowingError};
    return kinds;
}

std::size_t HistoryRecorder::strideFor(double periodS) const
{
    if (!(periodS > 0))
        return 1;
    const double keepPeriodS = 1.0 / std::max(1, m_budget.rateHz);
    // 1e-6 of slack: a 200 Hz stream (5000 µs) thinned for 100 Hz is k = 2, not 3.
    const double k = std::ceil(keepPeriodS / periodS - 1e-6);
    return k < 1 ? 1 : static_cast<std::size_t>(k);
}

void HistoryRecorder::record(int instrument, const dev::proto::ChannelRef& ref, std::uint32_t firstIndex, double t0S,
                             double periodS, const float* values, std::size_t n)
{
    if (n == 0 || values == nullptr)
        return;
    auto& slot = m_instruments[instrument][ref];
    if (!slot)
        slot = std::make_unique<ChannelStore>(m_budget.capacity());
    const std::size_t k = strideFor(periodS);
    // The samples whose device index is a multiple of k: the same ones whichever
    // batch they come in, so the kept stream is periodic across batches.
    const std::size_t first = (k - firstIndex % k) % k;
    if (first >= n)
        return;
    const std::size_t kept = (n - first + k - 1) / k;
    slot->appendRun(t0S + static_cast<double>(first) * periodS, periodS * static_cast<double>(k), values + first, kept, k);
}

const ChannelStore* HistoryRecorder::store(int instrument, const dev::proto::ChannelRef& ref) const
{
    const auto in = m_instruments.find(instrument);
    if (in == m_instruments.end())
        return nullptr;
    const auto it = in->second.find(ref);
    return it == in->second.end() ? nullptr : it->second.get();
}

std::vector<dev::proto::ChannelRef> HistoryRecorder::channels(int instrument) const
{
    std::vector<dev::proto::ChannelRef> out;
    const auto in = m_instruments.find(instrument);
    if (in != m_instruments.end())
        for (const auto& [ref, store] : in->second)
            out.push_back(ref);
    return out;
}

double HistoryRecorder::latestS(int instrument) const
{
    double latest = std::nan("");
    const auto in = m_instruments.find(instrument);
    if (in != m_instruments.end())
        for (const auto& [ref, s] : in->second)
            if (!s->empty() && !(s->lastTime() <= latest))
                latest = s->lastTime();
    return latest;
}

double HistoryRecorder::spanS(int instrument) const
{
    double first = std::nan(""), last = std::nan("");
    const auto in = m_instruments.find(instrument);
    if (in == m_instruments.end())
        return 0;
    for (const auto& [ref, s] : in->second) {
        if (s->empty())
            continue;
        if (!(s->firstTime() >= first))
            first = s->firstTime();
        if (!(s->lastTime() <= last))
            last = s->lastTime();
    }
    return std::isnan(first) ? 0 : last - first;
}

std::size_t HistoryRecorder::memoryBytes() const
{
    std::size_t bytes = 0;
    for (const auto& [index, channels] : m_instruments)
        for (const auto& [ref, s] : channels)
            bytes += s->memoryBytes();
    return bytes;
}

void HistoryRecorder::forget(int instrument) { m_instruments.erase(instrument); }

} // namespace dev::tele
