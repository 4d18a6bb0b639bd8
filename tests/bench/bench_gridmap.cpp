// Fitting a grid plate's map: the placement and the ISO 230-1 decomposition of a
// 19 × 19 map (the goal: within 1 ms), and a 2D compensation table made from it.
#include "motion/metrology/grid/compensation_table_2d.h"
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/grid/stage_errors.h"

#include <benchmark/benchmark.h>

using namespace motion::metrology;

namespace {

GridMapInput benchMap(int n)
{
    StageErrors s;
    s.x.pitchPolyUm = {0, 0.5, -0.004};
    s.x.straightnessPolyUm = {0, 0, 0.002};
    s.y.pitchPolyUm = {0, 0.3};
    s.y.straightnessPolyUm = {0, 0, -0.003};
    s.squarenessUrad = 40;
    GridMapInput in;
    for (int k = 0; k < n; ++k) {
        in.xMm.push_back(5.0 * k);
        in.yMm.push_back(5.0 * k);
    }
    for (double y : in.yMm)
        for (double x : in.xMm) {
            const auto e = stageErrorUm(s, x, y);
            in.exUm.push_back(e.xUm + 3 - 0.1 * y);
            in.eyUm.push_back(e.yUm - 2 + 0.1 * x);
        }
    return in;
}

void BM_FitGridMap(benchmark::State& state)
{
    const GridMapInput in = benchMap(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        auto r = analyseGridMap(in);
        benchmark::DoNotOptimize(r);
    }
    state.counters["nodes"] = static_cast<double>(in.exUm.size());
    state.counters["maps_per_second"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FitGridMap)->Arg(19)->Arg(41)->Unit(benchmark::kMicrosecond);

void BM_Table2DFromMap(benchmark::State& state)
{
    const auto map = analyseGridMap(benchMap(19));
    for (auto _ : state) {
        auto t = compensationFromMap(*map);
        benchmark::DoNotOptimize(t);
    }
}
BENCHMARK(BM_Table2DFromMap)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
