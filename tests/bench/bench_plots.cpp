// Google Benchmark program for the live plots (docs/telemetry.md): one redraw of the Plots
// screen's stacked plots, offscreen at 1600×900, 8 channels in 4 plots, each
// channel holding a 10-minute window at 10 kHz (6 M samples). A frame is what the
// screen's timer does: ask every store for min/max per pixel column, hand
// QCustomPlot those points, replot into its buffer. Target: p95 ≤ 8 ms.
//
// Counters: p50_ms, p95_ms, max_ms (wall time over the timed frames of the final run),
// cpu_ms_mean (this thread's CPU per frame: what the frame costs when others share the
// machine), points_per_frame (points handed to QCustomPlot), samples_per_channel.
// BP_BENCH_SHORT=1 shrinks the window to 10 s so CTest's run proves the program
// works without minutes of filling.
#include "widgets/plot_panel.h"
#include "widgets/plot_source.h"
#include "widgets/plot_stack.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace {

constexpr double kRateHz = 10000;
constexpr int kChannels = 8;
constexpr int kWidth = 1600, kHeight = 900;

/// CPU time of this thread (ms): on a shared machine, wall time also counts others' work.
double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

bool shortMode() { return qEnvironmentVariableIntValue("BP_BENCH_SHORT") == 1; }
double windowS() { return shortMode() ? 10.0 : 600.0; }

/// The stores and the stack, built once (filling 48 M samples takes a few seconds).
struct Scene {
    std::vector<std::unique_ptr<dev::tele::ChannelStore>> stores;
    ui::StorePlotSource source;
    std::unique_ptr<ui::PlotStack> stack;
    double nowS = 0;
    std::mt19937 rng{4242};

    Scene()
    {
        const auto n = static_cast<std::size_t>(windowS() * kRateHz);
        const double period = 1.0 / kRateHz;
        // Stage X/Y commanded, measured, following error, controller output: moves
        // (slow ramps), a servo's noise, and a fast ripple, so every column differs.
        const dev::proto::ChannelKind kinds[4] = {dev::proto::ChannelKind::Commanded, dev::proto::ChannelKind::Measured,
                                             dev::proto::ChannelKind::FollowingError, dev::proto::ChannelKind::ControllerOutput};
        std::normal_distribution<float> noise(0.f, 1.f);
        std::vector<float> values(65536);
        for (int c = 0; c < kChannels; ++c) {
            auto store = std::make_unique<dev::tele::ChannelStore>(n);
            const int axis = c % 2;
            const dev::proto::ChannelKind kind = kinds[c / 2];
            for (std::size_t done = 0; done < n;) {
                const std::size_t chunk = std::min(values.size(), n - done);
                for (std::size_t i = 0; i < chunk; ++i) {
                    const double t = double(done + i) * period;
                    const double path = 40 * std::sin(t * 0.05 * (axis + 1)) + 10 * std::sin(t * 0.7);
                    switch (kind) {
                    case dev::proto::ChannelKind::Commanded: values[i] = float(path); break;
                    case dev::proto::ChannelKind::Measured: values[i] = float(path + 0.001 * noise(rng)); break;
                    case dev::proto::ChannelKind::FollowingError: values[i] = float(2 * std::sin(t * 31) + 0.3 * noise(rng)); break;
                    default: values[i] = float(800 * std::cos(t * 0.7) + 50 * noise(rng)); break;
                    }
                }
                store->appendRun(double(done) * period, period, values.data(), chunk);
                done += chunk;
            }
            const dev::tele::ChannelKey key{1, dev::proto::ChannelRef{std::uint8_t(axis), kind}};
            source.add(key, store.get(), QStringLiteral("Stage %1 %2").arg(QChar(axis ? 'Y' : 'X')).arg(int(kind)), QStringLiteral("mm"));
            stores.push_back(std::move(store));
        }
        nowS = stores.front()->lastTime();
        stack = std::make_unique<ui::PlotStack>(&source);
        for (int p = 1; p < kChannels / 2; ++p)
            stack->addPanel();
        for (int c = 0; c < kChannels; ++c)
            stack->addChannel(c / 2, dev::tele::ChannelKey{1, dev::proto::ChannelRef{std::uint8_t(c % 2), kinds[c / 2]}});
        stack->resize(kWidth, kHeight);
        stack->show();
        QApplication::processEvents();
        stack->setAnchors(std::nan(""), nowS);
        stack->setTimeRange(-windowS(), 0);
        stack->redraw();  // first layout
    }

    int pointsHanded() const
    {
        int points = 0;
        for (int p = 0; p < stack->panelCount(); ++p)
            for (const auto& line : stack->panel(p)->lines())
                points += line.graph->dataCount();
        return points;
    }
};

/// Built on first use, destroyed before the QApplication goes.
std::unique_ptr<Scene> g_scene;

Scene& scene()
{
    if (!g_scene)
        g_scene = std::make_unique<Scene>();
    return *g_scene;
}

void report(benchmark::State& state, std::vector<double>& ms, const Scene& s, double cpuMs)
{
    if (ms.empty())
        return;
    state.counters["cpu_ms_mean"] = cpuMs / double(ms.size());
    std::sort(ms.begin(), ms.end());
    auto pct = [&](double p) { return ms[std::min(ms.size() - 1, static_cast<std::size_t>(std::ceil(p * double(ms.size())) - 1))]; };
    state.counters["p50_ms"] = pct(0.50);
    state.counters["p95_ms"] = pct(0.95);
    state.counters["max_ms"] = ms.back();
    state.counters["points_per_frame"] = s.pointsHanded();
    state.counters["samples_per_channel"] = double(s.stores.front()->size());
}

/// The whole window on screen: every frame reduces 6 M samples per channel to pixel columns.
void BM_RedrawWholeWindow(benchmark::State& state)
{
    Scene& s = scene();
    s.stack->setAnchors(std::nan(""), s.nowS);
    s.stack->setTimeRange(-windowS(), 0);
    std::vector<double> ms;
    QElapsedTimer t;
    double cpu = 0;
    for (auto _ : state) {
        const double cpu0 = threadCpuMs();
        t.start();
        s.stack->redraw();
        s.stack->repaint();  // and the widget's paint of the buffer, as the screen would
        const double frame = double(t.nsecsElapsed()) * 1e-6;
        cpu += threadCpuMs() - cpu0;
        ms.push_back(frame);
        state.SetIterationTime(frame * 1e-3);
    }
    report(state, ms, s, cpu);
}
BENCHMARK(BM_RedrawWholeWindow)->UseManualTime()->Unit(benchmark::kMillisecond);

/// Live streaming: between frames each channel gets 1/60 s of samples (167 at 10 kHz,
/// not timed) and the view slides with the newest sample, as on the screen.
void BM_RedrawLive(benchmark::State& state)
{
    Scene& s = scene();
    const double period = 1.0 / kRateHz;
    const std::size_t perFrame = static_cast<std::size_t>(kRateHz / 60);
    std::vector<float> values(perFrame);
    std::vector<double> ms;
    QElapsedTimer t;
    double cpu = 0;
    for (auto _ : state) {
        for (std::size_t c = 0; c < s.stores.size(); ++c) {
            for (std::size_t i = 0; i < perFrame; ++i)
                values[i] = float(std::sin((s.nowS + double(i) * period) * 3.0) * 10 + double(c));
            s.stores[c]->appendRun(s.nowS + period, period, values.data(), perFrame);
        }
        s.nowS += double(perFrame) * period;
        const double cpu0 = threadCpuMs();
        t.start();
        s.stack->setAnchors(std::nan(""), s.nowS);
        s.stack->setTimeRange(-windowS(), 0);
        s.stack->redraw();
        s.stack->repaint();  // and the widget's paint of the buffer, as the screen would
        const double frame = double(t.nsecsElapsed()) * 1e-6;
        cpu += threadCpuMs() - cpu0;
        ms.push_back(frame);
        state.SetIterationTime(frame * 1e-3);
    }
    report(state, ms, s, cpu);
}
BENCHMARK(BM_RedrawLive)->UseManualTime()->Unit(benchmark::kMillisecond);

/// The stores' share of a frame: min/max per pixel column of every channel, nothing drawn.
void BM_DecimateOnly(benchmark::State& state)
{
    Scene& s = scene();
    const int columns = s.stack->columns();
    std::vector<dev::tele::MinMax> out(static_cast<std::size_t>(columns));
    std::vector<double> ms;
    QElapsedTimer t;
    double cpu = 0;
    for (auto _ : state) {
        const double cpu0 = threadCpuMs();
        t.start();
        for (const auto& store : s.stores)
            store->decimate(s.nowS - windowS(), s.nowS, columns, out.data());
        benchmark::DoNotOptimize(out.data());
        const double frame = double(t.nsecsElapsed()) * 1e-6;
        cpu += threadCpuMs() - cpu0;
        ms.push_back(frame);
        state.SetIterationTime(frame * 1e-3);
    }
    report(state, ms, s, cpu);
    state.counters["columns"] = columns;
}
BENCHMARK(BM_DecimateOnly)->UseManualTime()->Unit(benchmark::kMillisecond);

/// Zoomed in to the last 0.1 s: fewer samples than two per column, so raw samples are drawn.
void BM_RedrawZoomedRaw(benchmark::State& state)
{
    Scene& s = scene();
    s.stack->setAnchors(std::nan(""), s.nowS);
    s.stack->setTimeRange(-0.1, 0);
    std::vector<double> ms;
    QElapsedTimer t;
    double cpu = 0;
    for (auto _ : state) {
        const double cpu0 = threadCpuMs();
        t.start();
        s.stack->redraw();
        s.stack->repaint();  // and the widget's paint of the buffer, as the screen would
        const double frame = double(t.nsecsElapsed()) * 1e-6;
        cpu += threadCpuMs() - cpu0;
        ms.push_back(frame);
        state.SetIterationTime(frame * 1e-3);
    }
    report(state, ms, s, cpu);
}
BENCHMARK(BM_RedrawZoomedRaw)->UseManualTime()->Unit(benchmark::kMillisecond);

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
    g_scene.reset();
    return 0;
}
