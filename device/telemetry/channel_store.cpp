#include "device/telemetry/channel_store.h"

#include <algorithm>
#include <cmath>

namespace dev::tele {
namespace {
/// A sample (or run) continues the last run when its time is within this fraction
/// of a period of where the run expects it; it is then stored at the expected time.
/// Device clocks tick in whole microseconds, so their runs join exactly.
constexpr double kJoinTolerance = 1e-4;
/// Periods of two runs are "the same" within this relative difference.
constexpr double kPeriodTolerance = 1e-9;
}

ChannelStore::ChannelStore(std::size_t capacity)
    : m_capacity(std::max<std::size_t>(capacity, 1)),
      // Not value-initialised: pages of a large ring stay untouched until written.
      m_values(new float[m_capacity])
{
    if (m_capacity > kFan) {
        std::size_t blocks = (m_capacity + kFanMask) >> kFanShift;
        m_levels.emplace_back(blocks);
        while (blocks > kFan) {
            blocks = (blocks + kFanMask) >> kFanShift;
            m_levels.emplace_back(blocks);
        }
    }
    m_runs.reserve(16);
}

ChannelStore::ChannelStore(const ChannelStore& other, std::size_t capacity) : ChannelStore(capacity)
{
    m_outOfOrder = other.m_outOfOrder;
    if (other.m_count == 0)
        return;
    const std::size_t n = std::min(other.m_count, m_capacity);
    const std::uint64_t firstSeq = other.m_nextSeq - n;
    std::size_t slot = (other.oldestSlot() + (other.m_count - n)) % other.m_capacity;
    // Run by run, each cut at the other ring's seam: periods and times carry over.
    for (std::size_t r = other.runOf(firstSeq); r < other.m_runs.size(); ++r) {
        const Run& run = other.m_runs[r];
        std::uint64_t k = firstSeq > run.firstSeq ? firstSeq - run.firstSeq : 0;
        while (k < run.count) {
            const std::size_t chunk = static_cast<std::size_t>(
                std::min<std::uint64_t>(run.count - k, other.m_capacity - slot));
            if (run.count == 1)
                append(run.t0S, other.m_values[slot]);
            else
                appendRun(run.timeAt(k), run.periodS, other.m_values.get() + slot, chunk);
            k += chunk;
            slot = (slot + chunk) % other.m_capacity;
        }
    }
}

std::size_t ChannelStore::capacity() const { return m_capacity; }
std::size_t ChannelStore::size() const { return m_count; }
std::uint64_t ChannelStore::outOfOrderDropped() const { return m_outOfOrder; }

double ChannelStore::columnEdge(double t0S, double t1S, int columns, int c)
{
    if (c <= 0)
        return t0S;
    if (c >= columns)
        return t1S;
    return t0S + (t1S - t0S) * static_cast<double>(c) / static_cast<double>(columns);
}

std::size_t ChannelStore::memoryBytes() const
{
    std::size_t bytes = sizeof(*this) + m_capacity * sizeof(float) + m_runs.capacity() * sizeof(Run);
    for (const auto& level : m_levels)
        bytes += level.capacity() * sizeof(Extent);
    return bytes;
}

// ---- time runs ------------------------------------------------------------------

std::size_t ChannelStore::runOf(std::uint64_t seq) const
{
    // Usually one run, and readers walk forwards: try the newest run first.
    if (m_runs.back().firstSeq <= seq)
        return m_runs.size() - 1;
    std::size_t lo = m_firstRun, hi = m_runs.size() - 1;  // answer in [lo, hi)
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (m_runs[mid].firstSeq <= seq)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

double ChannelStore::timeOfSeq(std::uint64_t seq) const
{
    const Run& r = m_runs[runOf(seq)];
    return r.timeAt(seq - r.firstSeq);
}

void ChannelStore::addTimes(double t0S, double periodS, std::size_t n)
{
    if (m_firstRun < m_runs.size()) {
        Run& r = m_runs.back();
        if (r.count == 1) {
            // Two samples make a period; a run of more must match it.
            const double gap = t0S - r.t0S;
            if (n == 1 || std::abs(gap - periodS) <= kJoinTolerance * periodS) {
                r.periodS = gap;
                r.count += n;
                return;
            }
        } else {
            const bool samePeriod = n == 1 || std::abs(periodS - r.periodS) <= kPeriodTolerance * r.periodS;
            if (samePeriod && std::abs(t0S - r.timeAt(r.count)) <= kJoinTolerance * r.periodS) {
                r.count += n;
                return;
            }
        }
    }
    m_runs.push_back(Run{m_nextSeq, n, t0S, n > 1 ? periodS : 0.0});
}

void ChannelStore::dropRunsBeforeOldest()
{
    const std::uint64_t oldest = oldestSeq();
    while (m_firstRun < m_runs.size() && m_runs[m_firstRun].firstSeq + m_runs[m_firstRun].count <= oldest)
        ++m_firstRun;
    if (m_firstRun == m_runs.size()) {
        m_runs.clear();  // keeps its capacity: no allocation on the next run
        m_firstRun = 0;
    } else if (m_firstRun >= 64 && 2 * m_firstRun >= m_runs.size()) {
        m_runs.erase(m_runs.begin(), m_runs.begin() + static_cast<std::ptrdiff_t>(m_firstRun));
        m_firstRun = 0;
    }
}

// ---- values and the pyramid ---------------------------------------------------------

void ChannelStore::finishBlock(std::size_t lastSlot)
{
    std::size_t b = lastSlot >> kFanShift;
    Extent e;
    for (std::size_t s = b << kFanShift; s <= lastSlot; ++s) {
        const float v = m_values[s];
        e.min = v < e.min ? v : e.min;  // NaN never wins a comparison: it is skipped
        e.max = v > e.max ? v : e.max;
    }
    m_levels[0][b] = e;
    for (std::size_t k = 1; k < m_levels.size(); ++k) {
        const auto& children = m_levels[k - 1];
        if (((b + 1) & kFanMask) != 0 && b + 1 != children.size())
            break;  // not the last child: the parent is finished later
        const std::size_t p = b >> kFanShift;
        const std::size_t end = std::min((p + 1) << kFanShift, children.size());
        Extent pe;
        for (std::size_t c = p << kFanShift; c < end; ++c) {
            pe.min = std::min(pe.min, children[c].min);
            pe.max = std::max(pe.max, children[c].max);
        }
        m_levels[k][p] = pe;
        b = p;
    }
}

void ChannelStore::writeValues(const float* values, std::size_t n, std::size_t stride)
{
    while (n > 0) {
        const std::size_t chunk = std::min(n, m_capacity - m_head);
        float* dst = m_values.get() + m_head;
        if (stride == 1)
            std::copy(values, values + chunk, dst);
        else
            for (std::size_t i = 0; i < chunk; ++i)
                dst[i] = values[i * stride];
        if (!m_levels.empty()) {
            const std::size_t end = m_head + chunk;
            for (std::size_t s = m_head | kFanMask; s < end; s += kFan)
                finishBlock(s);
            if (end == m_capacity && (m_capacity & kFanMask) != 0)
                finishBlock(m_capacity - 1);  // the short last block
        }
        m_head += chunk;
        if (m_head == m_capacity)
            m_head = 0;
        values += chunk * stride;
        n -= chunk;
    }
}

void ChannelStore::extentOfSlots(std::size_t lo, std::size_t hi, Extent& e) const
{
    auto takeValue = [&e](float v) {
        e.min = v < e.min ? v : e.min;
        e.max = v > e.max ? v : e.max;
    };
    auto takeBlock = [&e](const Extent& x) {
        e.min = std::min(e.min, x.min);
        e.max = std::max(e.max, x.max);
    };
    if (m_levels.empty() || hi - lo < 2 * kFan) {
        for (std::size_t s = lo; s < hi; ++s)
            takeValue(m_values[s]);
        return;
    }
    // Raw values up to block boundaries; the ring's end counts as a boundary
    // because the last block of every level is cut there.
    while (lo < hi && (lo & kFanMask) != 0)
        takeValue(m_values[lo++]);
    while (hi > lo && (hi & kFanMask) != 0 && hi != m_capacity)
        takeValue(m_values[--hi]);
    if (lo >= hi)
        return;
    std::size_t bl = lo >> kFanShift;
    std::size_t bh = hi == m_capacity ? m_levels[0].size() : hi >> kFanShift;
    for (std::size_t k = 0;; ++k) {
        const auto& level = m_levels[k];
        if (k + 1 == m_levels.size() || bh - bl < 2 * kFan) {
            for (std::size_t b = bl; b < bh; ++b)
                takeBlock(level[b]);
            return;
        }
        while (bl < bh && (bl & kFanMask) != 0)
            takeBlock(level[bl++]);
        while (bh > bl && (bh & kFanMask) != 0 && bh != level.size())
            takeBlock(level[--bh]);
        if (bl >= bh)
            return;
        bl >>= kFanShift;
        bh = bh == level.size() ? m_levels[k + 1].size() : bh >> kFanShift;
    }
}

// ---- public ---------------------------------------------------------------------

void ChannelStore::append(double tS, float value)
{
    if (!std::isfinite(tS) || (m_count > 0 && !(tS > lastTime()))) {
        ++m_outOfOrder;
        return;
    }
    addTimes(tS, 0, 1);
    writeValues(&value, 1, 1);
    ++m_nextSeq;
    if (m_count < m_capacity)
        ++m_count;
    else
        dropRunsBeforeOldest();
}

void ChannelStore::appendRun(double t0S, double periodS, const float* values, std::size_t n, std::size_t stride)
{
    if (n == 0 || values == nullptr)
        return;
    if (!(periodS > 0) || !std::isfinite(periodS)) {
        // No time between the samples: only the first can be newer than the rest.
        append(t0S, values[0]);
        m_outOfOrder += n - 1;
        return;
    }
    if (!std::isfinite(t0S)) {
        m_outOfOrder += n;
        return;
    }
    if (m_count > 0) {
        const double last = lastTime();
        if (!(t0S > last)) {
            // Skip the samples that are not newer than what the store holds.
            const double behind = (last - t0S) / periodS;
            if (behind >= static_cast<double>(n)) {
                m_outOfOrder += n;
                return;
            }
            std::size_t k = static_cast<std::size_t>(behind);
            while (k > 0 && t0S + static_cast<double>(k - 1) * periodS > last)
                --k;
            while (k < n && !(t0S + static_cast<double>(k) * periodS > last))
                ++k;
            if (k >= n) {
                m_outOfOrder += n;
                return;
            }
            m_outOfOrder += k;
            t0S += static_cast<double>(k) * periodS;
            values += k * stride;
            n -= k;
        }
    }
    if (n > m_capacity) {
        // The first ones would be overwritten by the last ones at once.
        const std::size_t skip = n - m_capacity;
        t0S += static_cast<double>(skip) * periodS;
        values += skip * stride;
        n = m_capacity;
    }
    addTimes(t0S, periodS, n);
    writeValues(values, n, stride);
    m_nextSeq += n;
    m_count = std::min(m_count + n, m_capacity);
    dropRunsBeforeOldest();
}

void ChannelStore::trimBefore(double tS)
{
    const std::size_t k = lowerBound(tS);
    if (k == 0)
        return;
    m_count -= k;
    dropRunsBeforeOldest();
}

void ChannelStore::clear()
{
    m_count = 0;
    m_head = 0;
    m_runs.clear();
    m_firstRun = 0;
}

double ChannelStore::firstTime() const
{
    if (m_count == 0)
        return std::numeric_limits<double>::quiet_NaN();
    const Run& r = m_runs[m_firstRun];
    return r.timeAt(oldestSeq() - r.firstSeq);
}

double ChannelStore::lastTime() const
{
    if (m_count == 0)
        return std::numeric_limits<double>::quiet_NaN();
    return m_runs.back().lastTime();
}

Sample ChannelStore::at(std::size_t i) const
{
    const std::uint64_t seq = oldestSeq() + i;
    return Sample{timeOfSeq(seq), m_values[(oldestSlot() + i) % m_capacity]};
}

std::size_t ChannelStore::lowerBound(double tS) const
{
    if (m_count == 0 || !(tS > firstTime()))
        return 0;  // also for NaN: nothing is "before" it
    if (tS > lastTime())
        return m_count;
    // The first run that ends at or after tS (the last run does).
    std::size_t lo = m_firstRun, hi = m_runs.size() - 1;
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (m_runs[mid].lastTime() >= tS)
            hi = mid;
        else
            lo = mid + 1;
    }
    const Run& r = m_runs[lo];
    const std::uint64_t oldest = oldestSeq();
    const std::uint64_t kMin = r.firstSeq < oldest ? oldest - r.firstSeq : 0;
    std::uint64_t k = 0;
    if (r.count > 1) {
        const double f = std::ceil((tS - r.t0S) / r.periodS);
        k = f <= 0 ? 0 : (f >= static_cast<double>(r.count - 1) ? r.count - 1 : static_cast<std::uint64_t>(f));
    }
    k = std::max(k, kMin);
    // The estimate is exact up to rounding: settle it against the times at() reports.
    while (k > kMin && r.timeAt(k - 1) >= tS)
        --k;
    while (r.timeAt(k) < tS)
        ++k;
    return static_cast<std::size_t>(r.firstSeq + k - oldest);
}

std::optional<Sample> ChannelStore::nearest(double tS) const
{
    if (m_count == 0 || std::isnan(tS))
        return std::nullopt;
    const std::size_t k = lowerBound(tS);
    if (k == 0)
        return at(0);
    if (k == m_count)
        return at(m_count - 1);
    const Sample before = at(k - 1), after = at(k);
    return tS - before.tS <= after.tS - tS ? before : after;
}

void ChannelStore::decimate(double t0S, double t1S, int columns, MinMax* out) const
{
    if (columns <= 0 || out == nullptr)
        return;
    std::fill(out, out + columns, MinMax{});
    if (m_count == 0 || !(t1S > t0S) || !std::isfinite(t0S) || !std::isfinite(t1S))
        return;
    const std::size_t slot0 = oldestSlot();
    std::size_t i = lowerBound(t0S);
    for (int c = 0; c < columns && i < m_count; ++c) {
        const std::size_t j = std::max(i, lowerBound(columnEdge(t0S, t1S, columns, c + 1)));
        if (j == i)
            continue;
        // Logical [i, j) is at most two stretches of slots: before and after the seam.
        Extent e;
        const std::size_t p = (slot0 + i) % m_capacity;
        const std::size_t n = j - i;
        if (p + n <= m_capacity) {
            extentOfSlots(p, p + n, e);
        } else {
            extentOfSlots(p, m_capacity, e);
            extentOfSlots(0, p + n - m_capacity, e);
        }
        if (e.min <= e.max)
            out[c] = MinMax{e.min, e.max};
        i = j;
    }
}

} // namespace dev::tele
