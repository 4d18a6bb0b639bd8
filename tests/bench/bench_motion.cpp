// Google Benchmark program for motion/: planning latency and step-generation throughput.
// Targets: jerk-limited plan ≤ 0.12 µs (1 axis), ≤ 0.6 µs (3 axes synchronised);
// point-by-point interpolation ≥ 100 M steps/s; Taylor delay recurrence ≥ 100 M delays/s.
// Derived figures are counters: plans_per_second, steps_per_second, delays_per_second.
// Inputs are generated once with a fixed seed so runs compare.
#include "motion/any_profile.h"
#include "motion/blocks.h"
#include "motion/interpolation.h"
#include "motion/jerk_limited.h"
#include "motion/linear_move.h"
#include "motion/seed_scurve.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

constexpr std::size_t kMoves = 4096;  // power of two: index with a mask

struct Move3 {
    double distanceMm[3];
    motion::JerkLimits limits[3];
};

/// Random moves over three decades of distance and limits, so every branch of the planner
/// (cruise / aMax only / neither) is exercised in proportion.
const std::vector<Move3>& randomMoves()
{
    static const std::vector<Move3> moves = [] {
        std::mt19937_64 rng(12345);
        std::uniform_real_distribution<double> logU(-1.5, 1.5), sign(-1, 1);
        std::vector<Move3> out(kMoves);
        for (auto& m : out)
            for (int i = 0; i < 3; ++i) {
                m.distanceMm[i] = 20.0 * std::pow(10.0, logU(rng)) * (sign(rng) < 0 ? -1 : 1);
                m.limits[i] = {100.0 * std::pow(10.0, logU(rng) / 3), 1000.0 * std::pow(10.0, logU(rng) / 3),
                               20000.0 * std::pow(10.0, logU(rng) / 3)};
            }
        return out;
    }();
    return moves;
}

void BM_JerkLimitedPlan1Axis(benchmark::State& state)
{
    const auto& moves = randomMoves();
    std::size_t i = 0;
    for (auto _ : state) {
        const Move3& m = moves[i++ & (kMoves - 1)];
        auto p = motion::JerkLimitedProfile::plan(m.distanceMm[0], m.limits[0]);
        benchmark::DoNotOptimize(p);
    }
    state.counters["plans_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_JerkLimitedPlan1Axis);

void BM_JerkLimitedPlan3AxesSynchronized(benchmark::State& state)
{
    const auto& moves = randomMoves();
    std::size_t i = 0;
    for (auto _ : state) {
        const Move3& m = moves[i++ & (kMoves - 1)];
        auto move = motion::planLinearJerkLimited(m.distanceMm, m.limits, 3);
        benchmark::DoNotOptimize(move);
    }
    state.counters["plans_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_JerkLimitedPlan3AxesSynchronized);

void BM_SeedSCurvePlan(benchmark::State& state)
{
    const auto& moves = randomMoves();
    std::size_t i = 0;
    for (auto _ : state) {
        const Move3& m = moves[i++ & (kMoves - 1)];
        auto p = motion::SeedSCurve::plan(m.distanceMm[0], m.limits[0].vMaxMmS, 0.1);
        benchmark::DoNotOptimize(p);
    }
}
BENCHMARK(BM_SeedSCurvePlan);

void BM_JerkLimitedSample(benchmark::State& state)
{
    // The simulator samples every tick: cost of one at() on a long move.
    const auto p = *motion::JerkLimitedProfile::plan(123.4, {100, 1000, 20000});
    const double T = p.duration();
    double t = 0;
    for (auto _ : state) {
        t += 0.000731;
        if (t > T)
            t -= T;
        auto s = p.at(t);
        benchmark::DoNotOptimize(s);
    }
    state.counters["samples_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_JerkLimitedSample);

void BM_LineInterpolationSteps(benchmark::State& state)
{
    // One line of ~64 k steps per iteration, direction changing so all octants are hit.
    constexpr std::int64_t kSteps = 1 << 16;
    std::vector<std::uint8_t> codes(kSteps + 8);
    const std::int64_t xs[4] = {40000, -25536, 65536 - 20000, -(65536 - 31111)};
    std::int64_t total = 0;
    std::size_t k = 0;
    for (auto _ : state) {
        const std::int64_t xe = xs[k & 3];
        const std::int64_t ye = (k & 1 ? -1 : 1) * (kSteps - std::llabs(xe));
        ++k;
        total += motion::interpolateLineCodes(xe, ye, codes.data());
        benchmark::DoNotOptimize(codes.data());
        benchmark::ClobberMemory();
    }
    state.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LineInterpolationSteps);

void BM_LineInterpolationStepper(benchmark::State& state)
{
    // Step-at-a-time object the simulator uses (one call per step, as a timer ISR would).
    std::int64_t total = 0;
    for (auto _ : state) {
        motion::LineInterpolator line(30000, -17000);
        std::int64_t x = 0;
        while (!line.done())
            x += line.next().dx;
        benchmark::DoNotOptimize(x);
        total += 47000;
    }
    state.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LineInterpolationStepper);

void BM_ArcInterpolationSteps(benchmark::State& state)
{
    std::int64_t total = 0;
    for (auto _ : state) {
        auto arc = *motion::ArcInterpolator::create({5000, 0}, {5000, 0}, true);  // full circle, 40 000 steps
        std::int64_t n = 0;
        while (!arc.done()) {
            arc.next();
            ++n;
        }
        benchmark::DoNotOptimize(n);
        total += n;
    }
    state.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ArcInterpolationSteps);

void BM_TaylorDelayRecurrence(benchmark::State& state)
{
    constexpr std::int64_t kDelays = 4096;
    std::vector<double> out(kDelays);
    const double F = 1e6, a = 2000.0;
    const double m = -a / (F * F);
    std::int64_t total = 0;
    for (auto _ : state) {
        const double last = motion::taylorRecurrence(F / 1000.0, m, kDelays, out.data());
        benchmark::DoNotOptimize(last);
        benchmark::ClobberMemory();
        total += kDelays;
    }
    state.counters["delays_per_second"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TaylorDelayRecurrence);

void BM_ExactSqrtDelays(benchmark::State& state)
{
    // The square root the recurrence replaces, for comparison.
    constexpr std::int64_t kDelays = 4096;
    std::vector<double> out(kDelays);
    const double F = 1e6, a = 2000.0;
    std::int64_t total = 0;
    for (auto _ : state) {
        double vSq = 1000.0 * 1000.0;
        for (std::int64_t i = 0; i < kDelays; ++i) {
            vSq += 2.0 * a;
            out[static_cast<std::size_t>(i)] = F / std::sqrt(vSq);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
        total += kDelays;
    }
    state.counters["delays_per_second"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ExactSqrtDelays);

}  // namespace

BENCHMARK_MAIN();
