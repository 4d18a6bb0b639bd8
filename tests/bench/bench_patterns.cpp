// Google Benchmark program for the patterns' acceptance figures (docs/patterns.md) and the path queue's costs.
//
// Acceptance (reported as counters, not asserted by time):
//   BM_StageCircle10mmAt2mmS        max_contour_um < 2     (simulated stage, grating measured every tick)
//   BM_AnalyzerLineSeed000_50mm     max_contour_mm < 0.05  (simulated analyzer, tan θ = 4/3, encoder every tick)
//   BM_ShallowJunctionsNeverStop    min_speed_between_segments_mm_s > 0 (a sine by 6° chords)
// Each runs a whole pattern on the simulator through its path queue (appends of at most the
// free slots, as a host does) and judges every 100 µs tick's measured XY against the
// geometric path with the same ContourTracker the Patterns screen uses. Also reported: the
// same figures from 250 Hz samples (what the screen sees through telemetry), duration and
// underruns. Costs: look-ahead re-plan over a full queue, point-by-point walk, contour judging.
#include "device/backends/benchpilot/path_wire.h"
#include "device/sim/path_queue.h"
#include "device/sim/sim_machine.h"
#include "motion/path/contour_tracker.h"
#include "motion/path/grid_walker.h"
#include "motion/path/junction_planner.h"
#include "motion/plans/pattern.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <vector>

namespace {

using motion::path::Segment;
using motion::path::Vec2;

bool shortMode() { return std::getenv("BP_BENCH_SHORT") != nullptr; }

struct RunResult {
    motion::path::ContourSummary everyTick, at250Hz;
    double durationS = 0;
    double minSpeedInsideMmS = 1e300;  ///< path speed between the first and the last segment's middles
    int underruns = 0;
    bool done = false;
};

void runTicks(dev::sim::SimMachine& m, double seconds)
{
    for (long k = 0, n = std::lround(seconds / dev::sim::SimMachine::kTickS); k < n; ++k) {
        m.tick();
        m.takeEvents();
    }
}

std::unique_ptr<dev::sim::SimMachine> homed(const dev::sim::MachineConfig& cfg)
{
    auto m = std::make_unique<dev::sim::SimMachine>(cfg);
    m->home(0);
    runTicks(*m, 40);  // every axis homed and settled
    return m;
}

/// Moves to the path's start, then streams it through the queue and judges the measured XY.
RunResult runPath(dev::sim::SimMachine& m, const std::vector<Segment>& path)
{
    dev::proto::MoveRequest mv;
    mv.axisMask = 0b11;
    mv.targets = {static_cast<std::int32_t>(std::lround(path.front().start.x * 1e6)),
                  static_cast<std::int32_t>(std::lround(path.front().start.y * 1e6))};
    m.move(mv);
    runTicks(m, 15);
    RunResult out;
    m.paths().begin({});
    motion::path::ContourTracker every(path), sampled(path);
    std::size_t sent = 0;
    const double t0 = m.timeS();
    long tick = 0;
    while (m.timeS() - t0 < 600) {
        if (tick % 100 == 0 && sent < path.size()) {
            const auto st = m.paths().status();
            const std::size_t n = std::min<std::size_t>(st.freeSlots, path.size() - sent);
            if (n > 0) {
                dev::proto::PathAppendRequest a;
                a.firstIndex = static_cast<std::uint32_t>(sent);
                a.flags = static_cast<std::uint8_t>(dev::proto::PathAppendStart | (sent + n == path.size() ? dev::proto::PathAppendLast : 0));
                for (std::size_t k = sent; k < sent + n; ++k)
                    a.segments.push_back(dev::toWire(path[k]));
                if (!m.paths().append(a))
                    sent += n;
            }
        }
        m.tick();
        for (const auto& e : m.takeEvents())
            out.underruns += e.kind == dev::proto::EventKind::PathUnderrun;
        const Vec2 meas{m.measuredLogical(0), m.measuredLogical(1)};
        every.add(meas);
        if (tick % 40 == 0)
            sampled.add(meas);
        const auto st = m.paths().status();
        if (st.executingIndex >= 1 && st.executingIndex + 1 < path.size() && st.state == dev::proto::PathState::Running)
            out.minSpeedInsideMmS = std::min(out.minSpeedInsideMmS, m.paths().speedMmS());
        ++tick;
        if (st.state == dev::proto::PathState::Done || st.state == dev::proto::PathState::Aborted) {
            out.done = st.state == dev::proto::PathState::Done;
            break;
        }
    }
    out.durationS = m.timeS() - t0;
    out.everyTick = every.summary();
    out.at250Hz = sampled.summary();
    return out;
}

/// Runs `path` once per iteration on a freshly homed machine (homing not timed); `tweak` sees the machine first.
RunResult runHomed(benchmark::State& state, const dev::sim::MachineConfig& cfg, const std::vector<Segment>& path,
                   const std::function<void(dev::sim::SimMachine&)>& tweak = {})
{
    RunResult r;
    for (auto _ : state) {
        state.PauseTiming();
        auto m = homed(cfg);
        if (tweak)
            tweak(*m);
        state.ResumeTiming();
        r = runPath(*m, path);
    }
    return r;
}

void report(benchmark::State& state, const RunResult& r, double unitScale, const char* unit)
{
    state.counters[std::string("max_contour_") + unit] = r.everyTick.maxAbsMm * unitScale;
    state.counters[std::string("rms_contour_") + unit] = r.everyTick.rmsMm * unitScale;
    state.counters[std::string("max_contour_250Hz_") + unit] = r.at250Hz.maxAbsMm * unitScale;
    state.counters["duration_s"] = r.durationS;
    state.counters["underruns"] = r.underruns;
    state.counters["completed"] = r.done ? 1 : 0;
    state.counters["samples_judged"] = static_cast<double>(r.everyTick.samples);
}

void BM_StageCircle10mmAt2mmS(benchmark::State& state)
{
    motion::plans::Pattern p;  // the defaults: a 10 mm circle at 2 mm/s round (50, 50)
    p.shape = motion::plans::PatternShape::Circle;
    p.feedMmS = 2;
    const RunResult r = runHomed(state, dev::sim::stageConfig(), motion::plans::plan(p));
    report(state, r, 1e3, "um");
}
BENCHMARK(BM_StageCircle10mmAt2mmS)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_AnalyzerLineSeed000_50mm(benchmark::State& state)
{
    // Seed 000 §4.1: XY along tan θ = 4/3, 50 mm, at Table 2's Y speed (50 mm/s path, X at 30).
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Line;
    p.line = {{20, 30}, {50, 70}};
    p.feedMmS = 50;
    const auto path = motion::plans::plan(p);
    const bool coupled = state.range(0) != 0;
    const RunResult r = runHomed(state, dev::sim::analyzerConfig(), path, [&](dev::sim::SimMachine& m) {
        if (!coupled)
            m.paths().setCrossCouplingGain(0);
    });
    report(state, r, 1.0, "mm");
    state.counters["cross_coupled"] = coupled ? 1 : 0;
}
// Arg 1: with seed 000's cross-coupled correction from the encoders (the default); 0: without.
BENCHMARK(BM_AnalyzerLineSeed000_50mm)->Unit(benchmark::kMillisecond)->Iterations(1)->Arg(1)->Arg(0);

void BM_ShallowJunctionsNeverStop(benchmark::State& state)
{
    // A sine by seed 002's chords (every junction a few degrees): the speed between segments.
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Sine;
    p.feedMmS = 5;
    p.wave.toleranceMm = 0.005;
    p.wave.lengthMm = shortMode() ? 20 : 60;
    const auto path = motion::plans::plan(p);
    double maxDeflectionDeg = 0;
    for (std::size_t k = 1; k < path.size(); ++k)
        maxDeflectionDeg = std::max(maxDeflectionDeg, motion::path::deflectionRad(motion::path::endTangent(path[k - 1]),
                                                                                   motion::path::startTangent(path[k])) * 180 / 3.14159265358979);
    const RunResult r = runHomed(state, dev::sim::stageConfig(), path);
    report(state, r, 1e3, "um");
    state.counters["segments"] = static_cast<double>(path.size());
    state.counters["largest_junction_deg"] = maxDeflectionDeg;
    state.counters["min_speed_between_segments_mm_s"] = r.minSpeedInsideMmS;
}
BENCHMARK(BM_ShallowJunctionsNeverStop)->Unit(benchmark::kMillisecond)->Iterations(1);

// ---- costs ---------------------------------------------------------------------------

void BM_LookAheadReplanFullQueue(benchmark::State& state)
{
    // What the device does on every append and segment change: a plan over 33 blocks.
    std::vector<motion::path::PlanBlock> blocks(33);
    for (std::size_t k = 0; k < blocks.size(); ++k)
        blocks[k] = {0.2 + 0.01 * k, 10.0, 6.0 + (k % 3), false, 0, 0};
    for (auto _ : state) {
        motion::path::planSpeeds(blocks, 100, {4.0}, {0.0});
        benchmark::DoNotOptimize(blocks.front().exitMmS);
    }
    state.counters["replans_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LookAheadReplanFullQueue);

void BM_PointByPointArcWalk(benchmark::State& state)
{
    // The stage's grid (0.3125 µm steps): a 5 mm radius circle is about 128 000 steps.
    const std::int64_t r = 16000;
    std::int64_t steps = 0;
    for (auto _ : state) {
        auto w = motion::path::GridWalker::arc({r, 0}, {r, 0}, {0, 0}, true);
        steps += w->advanceTo(1.0);
        benchmark::DoNotOptimize(w->position());
    }
    state.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PointByPointArcWalk)->Unit(benchmark::kMillisecond);

void BM_ContourJudging(benchmark::State& state)
{
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Raster;
    const auto path = motion::plans::plan(p);
    const double total = motion::path::pathLengthMm(path);
    std::vector<Vec2> pts;
    motion::path::ContourTracker walk(path);
    for (double s = 0; s < total; s += 0.01) {
        std::size_t k = 0;
        double at = s;
        while (k + 1 < path.size() && at > motion::path::lengthMm(path[k]))
            at -= motion::path::lengthMm(path[k++]);
        const Vec2 q = motion::path::pointAt(path[k], at);
        pts.push_back({q.x + 0.0003, q.y - 0.0002});
    }
    std::size_t n = 0;
    for (auto _ : state) {
        motion::path::ContourTracker t(path);
        for (const Vec2& q : pts)
            benchmark::DoNotOptimize(t.add(q));
        n += pts.size();
    }
    state.counters["samples_per_second"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ContourJudging)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
