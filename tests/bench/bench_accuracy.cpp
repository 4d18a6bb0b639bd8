// Google Benchmark program for the accuracy bench's math (docs/accuracy.md).
// Target: evaluating 41 targets × 10 cycles × 2 directions (820 readings) by ISO
// 230-2 and fitting polynomial orders 1–5 to the 41 mean deviations takes under
// 1 ms. Counters: ms_per_evaluate_and_fit (the target figure: this thread's CPU
// time, which other load on a shared machine does not inflate) with
// wall_ms_per_evaluate_and_fit beside it; us_per_evaluation, readings_per_second;
// us_per_fit (orders 1–5 with the order choice); and for the record the readings
// CSV read + evaluated (us_per_csv_analysis) and an ISO 230-4 circular test of
// 2 × 720 samples (us_per_circle).
#include "device/files/accuracy/readings_csv.h"
#include "motion/metrology/contour/circular_test.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/compensation/polynomial_fit.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <random>

namespace {

using namespace motion::metrology;

constexpr int kTargets = 41;
constexpr int kCycles = 10;

double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/// A 400 mm axis with seed 002's X error curve, 3 µm of backlash and 0.5 µm of noise.
std::vector<Reading> readings()
{
    std::mt19937 gen(18);
    auto noise = [&] { return (static_cast<double>(gen()) / 4294967296.0 - 0.5) * 1e-3; };
    std::vector<Reading> out;
    for (int c = 1; c <= kCycles; ++c)
        for (int d = 0; d < 2; ++d)
            for (int i = 0; i < kTargets; ++i) {
                const double target = 10.0 * i;
                const double errorUm = 1.563 + 0.9473 * target - 0.0006 * target * target + (d == 0 ? -1.5 : 1.5);
                out.push_back({target, d == 0 ? Direction::Up : Direction::Down, c, target + errorUm * 1e-3 + noise()});
            }
    return out;
}

void BM_EvaluateAndFit41x10x2(benchmark::State& state)
{
    const std::vector<Reading> r = readings();
    double cpuMs = 0, wallMs = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        const Evaluation e = evaluate(r);
        std::vector<FitPoint> points;
        for (const TargetStatistics& t : e.targets)
            points.push_back({t.targetMm, t.meanMm * 1e3});
        const FitTable fit = fitPolynomials(points);
        cpuMs += threadCpuMs() - c0;
        wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        benchmark::DoNotOptimize(e.figures.aMm);
        benchmark::DoNotOptimize(fit.chosenOrder);
    }
    state.counters["ms_per_evaluate_and_fit"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    state.counters["wall_ms_per_evaluate_and_fit"] = benchmark::Counter(wallMs, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_EvaluateAndFit41x10x2)->Unit(benchmark::kMicrosecond);

void BM_Evaluate41x10x2(benchmark::State& state)
{
    const std::vector<Reading> r = readings();
    double cpuMs = 0;
    for (auto _ : state) {
        const double c0 = threadCpuMs();
        const Evaluation e = evaluate(r);
        cpuMs += threadCpuMs() - c0;
        benchmark::DoNotOptimize(e.figures.rMm);
    }
    state.counters["us_per_evaluation"] = benchmark::Counter(cpuMs * 1e3, benchmark::Counter::kAvgIterations);
    state.counters["readings_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(r.size()),
                                                               benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Evaluate41x10x2)->Unit(benchmark::kMicrosecond);

void BM_FitOrders1To5At41Points(benchmark::State& state)
{
    const Evaluation e = evaluate(readings());
    std::vector<FitPoint> points;
    for (const TargetStatistics& t : e.targets)
        points.push_back({t.targetMm, t.meanMm * 1e3});
    double cpuMs = 0;
    for (auto _ : state) {
        const double c0 = threadCpuMs();
        const FitTable fit = fitPolynomials(points);
        cpuMs += threadCpuMs() - c0;
        benchmark::DoNotOptimize(fit.chosenOrder);
    }
    state.counters["us_per_fit"] = benchmark::Counter(cpuMs * 1e3, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_FitOrders1To5At41Points)->Unit(benchmark::kMicrosecond);

void BM_ReadAndAnalyzeReadingsCsv(benchmark::State& state)
{
    const std::string csv = dev::files::accuracy::readingsToCsv(readings());
    double cpuMs = 0;
    for (auto _ : state) {
        const double c0 = threadCpuMs();
        const auto a = dev::files::accuracy::analyzeReadingsCsv(csv, "bench.csv");
        cpuMs += threadCpuMs() - c0;
        benchmark::DoNotOptimize(a.evaluation.figures.aMm);
    }
    state.counters["us_per_csv_analysis"] = benchmark::Counter(cpuMs * 1e3, benchmark::Counter::kAvgIterations);
    state.counters["csv_bytes"] = static_cast<double>(csv.size());
}
BENCHMARK(BM_ReadAndAnalyzeReadingsCsv)->Unit(benchmark::kMicrosecond);

void BM_CircularTest2x720(benchmark::State& state)
{
    CircularTest t;
    t.centreMm = {50, 50};
    t.radiusMm = 20;
    std::vector<CircularRun> runs;
    for (Rotation rot : {Rotation::Cw, Rotation::Ccw}) {
        CircularRun run;
        run.rotation = rot;
        for (int k = 0; k < 720; ++k) {
            const double a = (rot == Rotation::Ccw ? 1 : -1) * 2 * 3.14159265358979 * k / 720;
            const double r = 20 + 0.002 * std::cos(2 * a) + (rot == Rotation::Cw ? 0.001 : -0.001);
            run.samplesMm.push_back({50 + r * std::cos(a), 50 + r * std::sin(a)});
        }
        runs.push_back(run);
    }
    double cpuMs = 0;
    for (auto _ : state) {
        const double c0 = threadCpuMs();
        const CircularEvaluation e = evaluate(t, runs);
        cpuMs += threadCpuMs() - c0;
        benchmark::DoNotOptimize(e.hysteresisMm);
    }
    state.counters["us_per_circle"] = benchmark::Counter(cpuMs * 1e3, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_CircularTest2x720)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
