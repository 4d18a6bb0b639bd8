// dev::tele::ChannelStore: the rolling window a plot reads. What a user would notice:
// the window slides without losing anything newer than its start, late samples
// never scramble the trace, gaps stay gaps, and the min/max columns a plot draws
// never hide a spike (every sample lies inside its column's range).
#include "device/telemetry/channel_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <vector>

namespace {

using dev::tele::ChannelStore;
using dev::tele::MinMax;
using dev::tele::Sample;

std::vector<float> ramp(std::size_t n, float from = 0)
{
    std::vector<float> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = from + static_cast<float>(i);
    return v;
}

/// Brute force: min and max per column by looking at every retained sample.
std::vector<MinMax> bruteDecimate(const ChannelStore& s, double t0, double t1, int columns)
{
    std::vector<MinMax> out(static_cast<std::size_t>(columns));
    std::vector<double> edges(static_cast<std::size_t>(columns) + 1);
    for (int c = 0; c <= columns; ++c)
        edges[static_cast<std::size_t>(c)] = ChannelStore::columnEdge(t0, t1, columns, c);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Sample x = s.at(i);
        if (x.tS < t0 || x.tS >= t1 || std::isnan(x.value))
            continue;
        // Column c holds edge(c) ≤ t < edge(c+1).
        const auto c = static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), x.tS) - edges.begin()) - 1;
        if (c >= out.size())
            continue;
        MinMax& m = out[c];
        if (m.empty()) {
            m.min = m.max = x.value;
        } else {
            m.min = std::min(m.min, x.value);
            m.max = std::max(m.max, x.value);
        }
    }
    return out;
}

TEST(TelemetryStore, EmptyStoreAnswersWithoutSamples)
{
    ChannelStore s(100);
    EXPECT_TRUE(s.empty());
    EXPECT_TRUE(std::isnan(s.firstTime()));
    EXPECT_TRUE(std::isnan(s.lastTime()));
    EXPECT_EQ(s.lowerBound(1.0), 0u);
    EXPECT_FALSE(s.nearest(1.0).has_value());
    std::vector<MinMax> cols(10);
    s.decimate(0, 1, 10, cols.data());
    for (const auto& c : cols)
        EXPECT_TRUE(c.empty());
}

TEST(TelemetryStore, KeepsTimesAndValuesOfAPeriodicRun)
{
    ChannelStore s(1000);
    const auto v = ramp(250);
    s.appendRun(10.0, 0.001, v.data(), 100);
    s.appendRun(10.1, 0.001, v.data() + 100, 150);  // continues the run
    ASSERT_EQ(s.size(), 250u);
    EXPECT_DOUBLE_EQ(s.firstTime(), 10.0);
    EXPECT_NEAR(s.lastTime(), 10.249, 1e-12);
    for (std::size_t i = 0; i < 250; i += 7) {
        EXPECT_NEAR(s.at(i).tS, 10.0 + 0.001 * double(i), 1e-12);
        EXPECT_EQ(s.at(i).value, float(i));
    }
    EXPECT_EQ(s.lowerBound(10.0), 0u);
    EXPECT_EQ(s.lowerBound(10.0005), 1u);
    EXPECT_EQ(s.lowerBound(10.001), 1u);
    EXPECT_EQ(s.lowerBound(11.0), 250u);
    ASSERT_TRUE(s.nearest(10.0104).has_value());
    EXPECT_EQ(s.nearest(10.0104)->value, 10.0f);
    EXPECT_EQ(s.nearest(10.0106)->value, 11.0f);
    EXPECT_EQ(s.nearest(-5)->value, 0.0f);
    EXPECT_EQ(s.nearest(99)->value, 249.0f);
}

TEST(TelemetryStore, StrideTakesOneChannelOfSampleMajorValues)
{
    ChannelStore s(16);
    const float interleaved[] = {1, 100, 2, 200, 3, 300};
    s.appendRun(0, 1, interleaved + 1, 3, 2);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s.at(0).value, 100.0f);
    EXPECT_EQ(s.at(2).value, 300.0f);
}

TEST(TelemetryStore, WrapOverwritesTheOldestAndKeepsTheNewest)
{
    ChannelStore s(100);
    const auto v = ramp(250);
    for (std::size_t i = 0; i < 250; ++i)
        s.append(double(i) * 0.5, v[i]);
    ASSERT_EQ(s.size(), 100u);
    EXPECT_EQ(s.capacity(), 100u);
    EXPECT_DOUBLE_EQ(s.firstTime(), 150 * 0.5);
    EXPECT_DOUBLE_EQ(s.lastTime(), 249 * 0.5);
    for (std::size_t i = 0; i < 100; ++i) {
        EXPECT_EQ(s.at(i).value, float(150 + i));
        EXPECT_DOUBLE_EQ(s.at(i).tS, double(150 + i) * 0.5);
    }
    // A run longer than the whole ring keeps its newest capacity() samples.
    const auto big = ramp(1000, 5000);
    s.appendRun(1000, 1, big.data(), big.size());
    ASSERT_EQ(s.size(), 100u);
    EXPECT_EQ(s.at(0).value, 5900.0f);
    EXPECT_DOUBLE_EQ(s.at(0).tS, 1900.0);
    EXPECT_EQ(s.at(99).value, 5999.0f);
}

TEST(TelemetryStore, TrimmingSlidesTheWindowStartExactly)
{
    ChannelStore s(10000);
    const auto v = ramp(5000);
    s.appendRun(0, 0.01, v.data(), v.size());  // 0 … 49.99 s
    s.trimBefore(20.0);
    EXPECT_EQ(s.size(), 3000u);
    EXPECT_NEAR(s.firstTime(), 20.0, 1e-9);
    EXPECT_EQ(s.at(0).value, 2000.0f);
    s.trimBefore(20.0);  // idempotent
    EXPECT_EQ(s.size(), 3000u);
    s.trimBefore(10.0);  // the past is gone, trimming it again changes nothing
    EXPECT_EQ(s.size(), 3000u);
    s.trimBefore(1e9);
    EXPECT_TRUE(s.empty());
    // After trimming everything, the store takes new samples as if fresh.
    s.append(60, 1.5f);
    EXPECT_EQ(s.size(), 1u);
    EXPECT_DOUBLE_EQ(s.firstTime(), 60.0);
}

TEST(TelemetryStore, LateAndRepeatedSamplesAreDroppedAndCounted)
{
    ChannelStore s(100);
    s.append(1.0, 1);
    s.append(2.0, 2);
    s.append(1.5, 99);  // older than the newest
    s.append(2.0, 99);  // same time as the newest
    s.append(std::nan(""), 99);
    EXPECT_EQ(s.size(), 2u);
    EXPECT_EQ(s.outOfOrderDropped(), 3u);
    // A run overlapping the newest keeps only its newer part.
    const float v[] = {10, 11, 12, 13, 14};
    s.appendRun(1.8, 0.1, v, 5);  // 1.8 1.9 2.0 | 2.1 2.2
    EXPECT_EQ(s.size(), 4u);
    EXPECT_EQ(s.outOfOrderDropped(), 6u);
    EXPECT_EQ(s.at(2).value, 13.0f);
    EXPECT_NEAR(s.at(2).tS, 2.1, 1e-12);
    EXPECT_EQ(s.at(3).value, 14.0f);
}

TEST(TelemetryStore, GapsStayGapsInTimeAndColumns)
{
    // A paused stream: 1 s of data, 3 s nothing, 1 s of data at another rate.
    ChannelStore s(10000);
    const auto a = ramp(1000);
    const auto b = ramp(500, 2000);
    s.appendRun(0, 0.001, a.data(), a.size());
    s.appendRun(4.0, 0.002, b.data(), b.size());
    ASSERT_EQ(s.size(), 1500u);
    EXPECT_EQ(s.lowerBound(2.0), 1000u);  // inside the gap: the first sample after it
    EXPECT_DOUBLE_EQ(s.at(1000).tS, 4.0);
    EXPECT_NEAR(s.at(1499).tS, 4.998, 1e-12);
    EXPECT_EQ(s.nearest(1.2)->value, 999.0f);
    EXPECT_EQ(s.nearest(3.9)->value, 2000.0f);
    std::vector<MinMax> cols(5);
    s.decimate(0, 5, 5, cols.data());
    EXPECT_EQ(cols[0].min, 0.0f);
    EXPECT_EQ(cols[0].max, 999.0f);
    EXPECT_TRUE(cols[1].empty());
    EXPECT_TRUE(cols[2].empty());
    EXPECT_TRUE(cols[3].empty());
    EXPECT_EQ(cols[4].min, 2000.0f);
    EXPECT_EQ(cols[4].max, 2499.0f);
}

TEST(TelemetryStore, ColumnEdgesMeetExactlyAtTheEnds)
{
    EXPECT_EQ(ChannelStore::columnEdge(1.1, 7.3, 13, 0), 1.1);
    EXPECT_EQ(ChannelStore::columnEdge(1.1, 7.3, 13, 13), 7.3);
    for (int c = 0; c < 13; ++c)
        EXPECT_LT(ChannelStore::columnEdge(1.1, 7.3, 13, c), ChannelStore::columnEdge(1.1, 7.3, 13, c + 1));
}

TEST(TelemetryStore, DecimationFindsASingleSpikeInMillions)
{
    // The reason for min/max columns: one bad encoder reading among 2 M must show.
    const std::size_t n = 2'000'000;
    ChannelStore s(n);
    std::vector<float> v(n, 1.0f);
    v[1'234'567] = 250.0f;
    v[77] = -3.0f;
    s.appendRun(0, 1e-4, v.data(), n);
    std::vector<MinMax> cols(1600);
    s.decimate(0, 200, 1600, cols.data());
    float hi = -1e9f, lo = 1e9f;
    for (const auto& c : cols) {
        ASSERT_FALSE(c.empty());
        hi = std::max(hi, c.max);
        lo = std::min(lo, c.min);
    }
    EXPECT_EQ(hi, 250.0f);
    EXPECT_EQ(lo, -3.0f);
    // …and in the column its time falls into.
    const int spikeColumn = static_cast<int>(123.4567 / 200 * 1600);
    EXPECT_EQ(cols[static_cast<std::size_t>(spikeColumn)].max, 250.0f);
}

TEST(TelemetryStore, NaNValuesAreKeptButNeverAnExtreme)
{
    ChannelStore s(64);
    const float v[] = {1, std::nanf(""), 3, std::nanf("")};
    s.appendRun(0, 1, v, 4);
    std::vector<MinMax> cols(4);
    s.decimate(0, 4, 4, cols.data());
    EXPECT_EQ(cols[0].min, 1.0f);
    EXPECT_TRUE(cols[1].empty());
    EXPECT_EQ(cols[2].max, 3.0f);
    EXPECT_TRUE(cols[3].empty());
}

/// A reference model of what the store should hold: a deque with the same rules.
struct Model {
    std::size_t capacity;
    std::deque<Sample> samples;
    void append(double t, float v)
    {
        if (!samples.empty() && !(t > samples.back().tS))
            return;
        samples.push_back({t, v});
        if (samples.size() > capacity)
            samples.pop_front();
    }
    void trimBefore(double t)
    {
        while (!samples.empty() && samples.front().tS < t)
            samples.pop_front();
    }
};

// Property test, fixed seed: random streams (periodic batches, rate changes, gaps,
// jittery single samples, wraps, trims, clears) against a brute-force model; every
// decimation of a random range into random columns must equal brute force exactly.
TEST(TelemetryStore, DecimationEqualsBruteForceOnRandomStreams)
{
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> u01(0, 1);
    std::normal_distribution<float> noise(0, 1);
    const std::size_t capacities[] = {1, 2, 15, 16, 17, 100, 255, 256, 257, 1000, 4099, 70001};
    int decimations = 0;
    for (const std::size_t cap : capacities) {
        ChannelStore s(cap);
        Model m{cap, {}};
        double t = u01(rng) * 100;
        double period = 0.001 * (1 + std::floor(u01(rng) * 10));
        float level = 0;
        const int ops = cap > 10000 ? 120 : 250;
        for (int op = 0; op < ops; ++op) {
            const double r = u01(rng);
            if (r < 0.55) {  // a periodic batch, like the device's
                const auto n = static_cast<std::size_t>(1 + u01(rng) * (cap > 1000 ? 3000 : 80));
                std::vector<float> v(n);
                for (auto& x : v) {
                    level += noise(rng);
                    x = u01(rng) < 0.01f ? level + 100 * noise(rng) : level;  // now and then a spike
                }
                s.appendRun(t, period, v.data(), n);
                for (std::size_t k = 0; k < n; ++k)
                    m.append(t + double(k) * period, v[k]);
                t += double(n) * period;
            } else if (r < 0.65) {  // a gap, maybe at another rate
                t += period * (2 + u01(rng) * 5000);
                if (u01(rng) < 0.5)
                    period = 0.0001 * (1 + std::floor(u01(rng) * 50));
            } else if (r < 0.75) {  // jittery single samples
                const int n = 1 + static_cast<int>(u01(rng) * 40);
                for (int k = 0; k < n; ++k) {
                    t += period * (0.5 + u01(rng));
                    level += noise(rng);
                    s.append(t, level);
                    m.append(t, level);
                }
            } else if (r < 0.8) {  // a late batch, partly overlapping
                std::vector<float> v(10, 1e6f);
                const double t0 = t - period * 4.5;  // half-period offsets: no time lands on the newest
                s.appendRun(t0, period, v.data(), v.size());
                for (std::size_t k = 0; k < v.size(); ++k)
                    m.append(t0 + double(k) * period, v[k]);
                t = std::max(t, t0 + 10 * period);
            } else if (r < 0.88 && !m.samples.empty()) {  // the window slides
                const double from = m.samples.front().tS, to = m.samples.back().tS;
                const double cut = from + (to - from) * u01(rng) * 0.5;
                s.trimBefore(cut);
                m.trimBefore(cut);
            } else if (r < 0.89) {
                s.clear();
                m.samples.clear();
            } else {
                // Compare contents, then decimate random ranges.
                ASSERT_EQ(s.size(), m.samples.size()) << "capacity " << cap << " op " << op;
                for (std::size_t i = 0; i < m.samples.size(); i += 1 + m.samples.size() / 50) {
                    ASSERT_NEAR(s.at(i).tS, m.samples[i].tS, 1e-6) << "capacity " << cap << " i " << i;
                    ASSERT_EQ(s.at(i).value, m.samples[i].value);
                }
                if (m.samples.empty())
                    continue;
                const double from = m.samples.front().tS, to = m.samples.back().tS;
                for (int q = 0; q < 6; ++q) {
                    double a = from + (to - from) * (u01(rng) * 1.2 - 0.1);
                    double b = from + (to - from) * (u01(rng) * 1.2 - 0.1);
                    if (q == 0) {  // the whole range, like an unzoomed plot
                        a = from;
                        b = to + period;
                    }
                    if (a > b)
                        std::swap(a, b);
                    const int columns = 1 + static_cast<int>(u01(rng) * (q % 2 ? 1600 : 60));
                    std::vector<MinMax> got(static_cast<std::size_t>(columns));
                    s.decimate(a, b, columns, got.data());
                    const auto want = bruteDecimate(s, a, b, columns);
                    for (int c = 0; c < columns; ++c) {
                        const auto& g = got[static_cast<std::size_t>(c)];
                        const auto& w = want[static_cast<std::size_t>(c)];
                        ASSERT_EQ(g.empty(), w.empty()) << "capacity " << cap << " column " << c << " of " << columns;
                        if (!w.empty()) {
                            ASSERT_EQ(g.min, w.min) << "capacity " << cap << " column " << c;
                            ASSERT_EQ(g.max, w.max) << "capacity " << cap << " column " << c;
                        }
                    }
                    ++decimations;
                }
            }
        }
    }
    EXPECT_GT(decimations, 300);
}

TEST(TelemetryStore, ResizedCopyKeepsTheNewestSamplesAndTheirTimes)
{
    // A wrapped ring with runs of two rates and a gap, copied bigger and smaller.
    ChannelStore s(1000);
    const auto a = ramp(1500), b = ramp(300, 5000);
    s.appendRun(3.0, 0.001, a.data(), a.size());
    s.appendRun(10.0, 0.0005, b.data(), b.size());
    s.append(11.0, -1);
    ASSERT_EQ(s.size(), 1000u);
    for (const std::size_t cap : {5000u, 1000u, 301u, 7u}) {
        const ChannelStore c(s, cap);
        ASSERT_EQ(c.capacity(), cap);
        ASSERT_EQ(c.size(), std::min<std::size_t>(cap, 1000));
        const std::size_t skip = s.size() - c.size();
        for (std::size_t i = 0; i < c.size(); ++i) {
            ASSERT_NEAR(c.at(i).tS, s.at(skip + i).tS, 1e-12) << "capacity " << cap << " i " << i;
            ASSERT_EQ(c.at(i).value, s.at(skip + i).value);
        }
        std::vector<MinMax> got(37);
        c.decimate(c.firstTime(), 11.5, 37, got.data());
        const auto want = bruteDecimate(c, c.firstTime(), 11.5, 37);
        for (std::size_t k = 0; k < got.size(); ++k) {
            ASSERT_EQ(got[k].empty(), want[k].empty());
            if (!want[k].empty()) {
                EXPECT_EQ(got[k].min, want[k].min);
                EXPECT_EQ(got[k].max, want[k].max);
            }
        }
    }
}

TEST(TelemetryStore, PeriodicStreamMemoryStaysPut)
{
    // An hour-long periodic stream through a small ring: no per-batch growth.
    ChannelStore s(10'000);
    const auto v = ramp(100);
    double t = 0;
    for (int b = 0; b < 200; ++b, t += 0.01)
        s.appendRun(t, 1e-4, v.data(), v.size());
    const std::size_t settled = s.memoryBytes();
    for (int b = 0; b < 20'000; ++b, t += 0.01) {
        s.appendRun(t, 1e-4, v.data(), v.size());
        if (b % 1000 == 0)
            s.trimBefore(t - 0.5);
        if (b % 3000 == 0)
            t += 0.25;  // a pause now and then starts a new run
    }
    EXPECT_EQ(s.memoryBytes(), settled);
}

} // namespace
