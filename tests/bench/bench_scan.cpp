// Google Benchmark program for the stitching scan planner (docs/scan.md).
// Target: plan a 100 × 100 tile region with its time estimate in under 50 ms.
// Counters: tiles (per plan), seconds_per_plan (validate + grid + order + estimate),
// tiles_per_second. Variants: a rectangle, a rectangle with the unidirectional
// approach (half again as many moves), and a 12-vertex polygon (a clip per field).
#include "motion/plans/scan/scan_estimate.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace motion::scan;

/// 1.1 mm fields at 10 % overlap: 0.99 mm steps, 100 per axis over 99.11 mm.
ScanPlan hundredByHundred()
{
    ScanPlan p;
    p.region.cornerA = {0.445, 0.445};
    p.region.cornerB = {99.555, 99.555};
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.1;
    p.overlapX = p.overlapY = 0.1;
    p.order = ScanOrder::SnakeRows;
    return p;
}

void planAndEstimate(benchmark::State& state, const ScanPlan& plan)
{
    const StageModel stage;
    std::size_t tiles = 0;
    for (auto _ : state) {
        const auto problems = validate(plan, stage);
        const ScanLayout layout = layoutScan(plan);
        const ScanEstimate e = estimateScan(plan, layout, stage);
        tiles = layout.tiles.size();
        benchmark::DoNotOptimize(problems);
        benchmark::DoNotOptimize(e.totalS);
    }
    state.counters["tiles"] = static_cast<double>(tiles);
    // Shown with an SI prefix: "2.2m" is 2.2 ms a plan.
    state.counters["seconds_per_plan"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["tiles_per_second"] =
        benchmark::Counter(static_cast<double>(state.iterations() * tiles), benchmark::Counter::kIsRate);
}

void BM_Plan100x100Rectangle(benchmark::State& state) { planAndEstimate(state, hundredByHundred()); }
BENCHMARK(BM_Plan100x100Rectangle)->Unit(benchmark::kMillisecond);

void BM_Plan100x100Unidirectional(benchmark::State& state)
{
    ScanPlan p = hundredByHundred();
    p.region.cornerA = {1, 1};  // room for the overtravel points inside the travel
    p.region.cornerB = {99.11 + 1, 99.11 + 1};
    p.order = ScanOrder::Rows;
    p.approach.unidirectional = true;
    planAndEstimate(state, p);
}
BENCHMARK(BM_Plan100x100Unidirectional)->Unit(benchmark::kMillisecond);

void BM_Plan100x100Polygon(benchmark::State& state)
{
    ScanPlan p = hundredByHundred();
    p.region.kind = RegionKind::Polygon;
    for (int k = 0; k < 12; ++k) {
        const double a = 2 * M_PI * k / 12, r = k % 2 ? 49.5 : 42;
        p.region.vertices.push_back({50 + r * std::cos(a), 50 + r * std::sin(a)});
    }
    planAndEstimate(state, p);
}
BENCHMARK(BM_Plan100x100Polygon)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
