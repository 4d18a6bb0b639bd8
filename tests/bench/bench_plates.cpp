// Google Benchmark program for plates and recipes (docs/plates.md): what must stay
// quick however big the plate — planning (which is also validation) of a
// 384-well recipe each time the editor changes it, reading and checking that
// recipe from its JSON, reading a run log to resume, the calibration fit, and
// one paint of the 384-well plate map.
//
// Counters: ops (wells and stations visited), ops_per_s (planning rate),
// plan_ms / read_ms / paint_ms (this thread's CPU per iteration, which the
// shared build machine does not inflate), log_lines, fits_per_s.
#include "device/files/plates/deck_file.h"
#include "device/files/recipes/recipe_file.h"
#include "device/files/recipes/run_log.h"
#include "motion/plans/plates/calibration.h"
#include "motion/plans/recipes/recipe_plan.h"
#include "widgets/plates/plate_map.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QImage>
#include <QPainter>

#include <string>

#include <time.h>

namespace {

/// CPU time of this thread (ms): on a machine shared with others, wall time counts their work too.
double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

/// Sets `name` to the thread's CPU milliseconds per iteration since `startMs`.
void cpuPerIteration(benchmark::State& state, const char* name, double startMs)
{
    state.counters[name] = state.iterations() ? (threadCpuMs() - startMs) / static_cast<double>(state.iterations()) : 0.0;
}

motion::plates::PlanContext context()
{
    motion::plates::PlanContext c;
    c.deck = dev::files::plates::builtinDeck();
    for (auto& lw : motion::plates::builtinLabware())
        c.labware[lw.id] = lw;
    return c;
}

/// Wash, fill all 384 wells from a reservoir well (eight rounds of 48 through the
/// 1000 µL syringe), mix each, wash, then sample each: 1 160 ops.
motion::plates::Recipe recipe384()
{
    motion::plates::Recipe r;
    r.name = "384 fill, mix and sample";
    r.plates = {{"assay", "1", "sbs-384", 55, 70}, {"reagents", "2", "sbs-12", 50, 70}};
    motion::plates::Step wash;
    wash.type = motion::plates::StepType::Wash;
    wash.station = "wash";
    wash.volumeUl = 200;
    wash.cycles = 2;
    motion::plates::Step fill;
    fill.type = motion::plates::StepType::Dispense;
    fill.plate = "assay";
    fill.wells = {"all"};
    fill.volumeUl = 20;
    fill.source = {"reagents", "A1", ""};
    motion::plates::Step mix;
    mix.type = motion::plates::StepType::Mix;
    mix.plate = "assay";
    mix.wells = {"A1:P24"};
    mix.volumeUl = 10;
    mix.cycles = 3;
    motion::plates::Step sample;
    sample.type = motion::plates::StepType::Aspirate;
    sample.plate = "assay";
    sample.wells = {"A1:P24"};
    sample.volumeUl = 2;
    r.steps = {wash, fill, mix, wash, sample};
    return r;
}

void BM_PlanRecipe384(benchmark::State& state)
{
    const motion::plates::PlanContext c = context();
    const motion::plates::Recipe r = recipe384();
    std::size_t ops = 0;
    const double t0 = threadCpuMs();
    for (auto _ : state) {
        const motion::plates::RecipePlan p = motion::plates::planRecipe(r, c);
        ops = p.ops.size();
        if (!p.ok())
            state.SkipWithError(motion::msg::debugString(p.problems.front().message).c_str());
        benchmark::DoNotOptimize(p.totalTimeS);
    }
    state.counters["ops"] = static_cast<double>(ops);
    state.counters["ops_per_s"] = benchmark::Counter(static_cast<double>(ops) * state.iterations(), benchmark::Counter::kIsRate);
    cpuPerIteration(state, "plan_ms", t0);
}
BENCHMARK(BM_PlanRecipe384)->Unit(benchmark::kMillisecond);

void BM_ReadAndValidateRecipe384(benchmark::State& state)
{
    const motion::plates::PlanContext c = context();
    const std::string text = dev::files::plates::writeRecipe(recipe384());
    const double t0 = threadCpuMs();
    for (auto _ : state) {
        dev::files::plates::RecipeRead r = dev::files::plates::parseRecipe(text);
        const motion::plates::RecipePlan p = motion::plates::planRecipe(*r.recipe, c);
        dev::files::plates::placeProblems(r, p.problems);
        benchmark::DoNotOptimize(r.problems.size());
    }
    state.counters["bytes"] = static_cast<double>(text.size());
    cpuPerIteration(state, "read_ms", t0);
}
BENCHMARK(BM_ReadAndValidateRecipe384)->Unit(benchmark::kMillisecond);

/// A run log of every op done (start, pump, done), as a resume reads it.
void BM_ReadRunLog(benchmark::State& state)
{
    const int ops = static_cast<int>(state.range(0));
    std::string text = R"({"schema":"benchpilot.run-log","version":1,"event":"run","recipe":"r","fingerprint":"0a","ops":)" + std::to_string(ops)
        + R"(,"p_ul":0,"time":"2025-01-14T09:12:00.000Z"})" + "\n";
    for (int i = 0; i < ops; ++i) {
        const std::string op = std::to_string(i);
        text += R"({"event":"start","op":)" + op + R"(,"step":2,"kind":"mix","plate":"assay","well":"B7","volume_ul":10,"time":"2025-01-14T09:12:01.000Z"})" "\n";
        text += R"({"event":"pump","op":)" + op + R"(,"p_ul":0,"time":"2025-01-14T09:12:01.500Z"})" "\n";
        text += R"({"event":"done","op":)" + op + R"(,"p_ul":0,"time":"2025-01-14T09:12:02.000Z"})" "\n";
    }
    for (auto _ : state) {
        const dev::files::plates::RunLogState st = dev::files::plates::readRunLog(text);
        if (st.doneCount() != ops)
            state.SkipWithError("the log did not read back");
        benchmark::DoNotOptimize(st.firstOpenOp());
    }
    state.counters["log_lines"] = 1 + 3.0 * ops;
}
BENCHMARK(BM_ReadRunLog)->Arg(96)->Arg(1160)->Unit(benchmark::kMicrosecond);

void BM_CalibrationFit(benchmark::State& state)
{
    const auto model = state.range(0) ? motion::plates::FitModel::ScaledAxes : motion::plates::FitModel::Similarity;
    auto pts = motion::plates::teachWells(*motion::plates::findBuiltinLabware("sbs-96"));
    const motion::plates::PlateTransform truth = motion::plates::PlateTransform::make(8.3, 7.9, 0.4, 1.0003, 0.9998);
    for (auto& p : pts)
        p.machineMm = truth.apply(p.plateMm);
    pts[1].machineMm.x += 0.03;
    motion::msg::Message error;
    for (auto _ : state)
        benchmark::DoNotOptimize(motion::plates::fitCalibration(pts, model, &error));
    state.SetLabel(motion::plates::fitModelName(model));
    state.counters["fits_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CalibrationFit)->Arg(0)->Arg(1);

/// One paint of the 384-well map, 900 × 620 px, every well coloured.
void BM_PaintPlateMap384(benchmark::State& state)
{
    ui::PlateMap map;
    map.resize(900, 620);
    map.setLabware(*motion::plates::findBuiltinLabware("sbs-384"), QStringLiteral("assay in slot 1"));
    QMap<QString, ui::PlateMap::WellState> states;
    int k = 0;
    for (const auto& w : map.labware().wells)
        states[QString::fromStdString(motion::plates::wellName(w.id))] = static_cast<ui::PlateMap::WellState>(1 + (k++ % 4));
    map.setWellStates(states);
    QImage img(map.size(), QImage::Format_ARGB32_Premultiplied);
    const double t0 = threadCpuMs();
    for (auto _ : state) {
        QPainter p(&img);
        map.render(&p);
    }
    cpuPerIteration(state, "paint_ms", t0);
}
BENCHMARK(BM_PaintPlateMap384)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
