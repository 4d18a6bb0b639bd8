// Google Benchmark program for motion/control (docs/tuning.md).
// Target: 10 s of a plant + incremental PID at 10 kHz (100 000 control periods)
// simulated in under 5 ms. Counters: ms_per_10s_simulated (the target figure:
// this thread's CPU time, which other load on a shared machine does not
// inflate), wall_ms_per_10s_simulated beside it, ns_per_period (CPU),
// periods_per_second. Also whole tunings of a model plant, for the record
// (ms_per_tuning, CPU).
#include "motion/control/loop_sim.h"
#include "motion/control/tuning/model_tuning.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

namespace {

using namespace motion::control;

double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

void simulate10s(benchmark::State& state, const char* spec, DiscreteGains gains)
{
    const PlantSpec p = *parsePlant(spec);
    const double seconds = 10;
    double wallMs = 0, cpuMs = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        Record r = simulatePid(p, gains, 1.0, seconds);
        benchmark::DoNotOptimize(r.measured.data());
        cpuMs += threadCpuMs() - c0;
        wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    const double periods = seconds / p.periodS;
    state.counters["ms_per_10s_simulated"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    state.counters["wall_ms_per_10s_simulated"] = benchmark::Counter(wallMs, benchmark::Counter::kAvgIterations);
    state.counters["ns_per_period"] = benchmark::Counter(cpuMs * 1e6 / periods, benchmark::Counter::kAvgIterations);
    state.counters["periods_per_second"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * periods, benchmark::Counter::kIsRate);
}

void BM_Fopdt10sAt10kHz(benchmark::State& state) { simulate10s(state, "fopdt:K=2,tau=0.5,L=0.1234", {0.5, 0.0005, 2}); }
BENCHMARK(BM_Fopdt10sAt10kHz)->Unit(benchmark::kMillisecond);

void BM_Lag3_10sAt10kHz(benchmark::State& state) { simulate10s(state, "lag:K=1.5,tau=0.2,n=3", {2, 0.0005, 10}); }
BENCHMARK(BM_Lag3_10sAt10kHz)->Unit(benchmark::kMillisecond);

void BM_Lag8_10sAt10kHz(benchmark::State& state) { simulate10s(state, "lag:K=1.5,tau=0.05,n=8", {0.5, 0.0005, 2}); }
BENCHMARK(BM_Lag8_10sAt10kHz)->Unit(benchmark::kMillisecond);

void tuneWhole(benchmark::State& state, TuningMethod method)
{
    const PlantSpec p = *parsePlant("fopdt:K=2,tau=0.5,L=0.1");
    ModelTuningOptions o;
    o.method = method;
    o.relayAmplitude = 0.15;
    o.hysteresis = 0.002;
    double simulated = 0, cpuMs = 0;
    for (auto _ : state) {
        const double c0 = threadCpuMs();
        ModelTuning t = tuneModel(p, o);
        cpuMs += threadCpuMs() - c0;
        simulated = t.simulatedS;
        benchmark::DoNotOptimize(t.ku);
    }
    state.counters["ms_per_tuning"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    state.counters["simulated_s_per_tuning"] = simulated;
}

void BM_TuneUltimateGainFopdt(benchmark::State& state) { tuneWhole(state, TuningMethod::UltimateGain); }
BENCHMARK(BM_TuneUltimateGainFopdt)->Unit(benchmark::kMillisecond);

void BM_TuneRelayFopdt(benchmark::State& state) { tuneWhole(state, TuningMethod::Relay); }
BENCHMARK(BM_TuneRelayFopdt)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
