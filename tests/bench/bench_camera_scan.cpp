// What the camera adds to each tile of a scan (goal: no more than the exposure + 20 ms).
// The same 10 × 10 plan of 2048 × 2048 px tiles runs twice on the in-process simulated
// stage in real time: once with the simulated camera, once without (the exposure then a
// dwell on the device's clock). Real time, because the image of one tile is written
// while the stage moves to the next: a sped-up stage would leave the writes behind, as
// no real stage does. So (with − without) / tiles, plus the exposure the run without
// the camera spent, is the camera's time per tile beyond the move and settle: the render
// (a real camera's transfer) and the hand-over, and any write the move did not hide.
//
// Counters: ms_per_tile_beyond_move_and_settle, goal_ms (exposure + 20), and each run's
// wall seconds. BP_BENCH_SHORT=1 (CTest's short run) runs 2 × 2 tiles of 512² px.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/camera/scan_camera.h"
#include "device/camera/sim_camera.h"
#include "device/jobs/scan_runner.h"
#include "device/link/simulated_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <functional>
#include <memory>

namespace {

namespace cam = dev::camera;
constexpr double kTimeScale = 1;
constexpr double kExposureS = 0.010;

bool shortMode() { return qEnvironmentVariableIntValue("BP_BENCH_SHORT") == 1; }

bool spinUntil(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    return true;
}

motion::scan::ScanPlan plan()
{
    const int n = shortMode() ? 2 : 10;
    const int px = shortMode() ? 512 : 2048;
    motion::scan::ScanPlan p;
    p.name = "bench";
    p.camera.source = motion::scan::FieldSource::Sensor;
    p.camera.sensorWidthPx = p.camera.sensorHeightPx = px;
    p.camera.sensorPixelUm = 6.5;
    p.camera.magnification = 10;
    const double field = px * 0.65e-3, step = field * 0.9;
    p.region.cornerA = {20, 20};
    p.region.cornerB = {20 + field + (n - 1) * step - 0.01, 20 + field + (n - 1) * step - 0.01};
    p.overlapX = p.overlapY = 0.1;
    p.speedMmS = 20;
    p.settleS = 0.02;
    p.exposureS = kExposureS;
    return p;
}

/// One scan of plan() on a fresh homed simulated stage; its wall seconds, or −1.
double runScan(bool withCamera, int* tiles, std::string* why)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Stage, 0);
    dev::BenchPilotClient client;
    client.setTransport(link.hostEnd());
    client.connectLink();
    if (!spinUntil([&] { return client.state() == dev::LinkState::Ready; }, 10000)) {
        *why = "the simulated stage did not connect";
        return -1;
    }
    link.host().setTimeScale(50);
    client.home(0, {});
    const bool homed = spinUntil(
        [&] {
            for (const auto& a : client.status().axes)
                if (!a.homed || a.moving)
                    return false;
            return !client.status().axes.isEmpty();
        },
        60000);
    if (!homed) {
        *why = "the simulated stage did not home";
        return -1;
    }
    link.host().setTimeScale(kTimeScale);

    dev::sim::SimMachine* m = &link.machine();
    cam::SimCamera camera([m]() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()}; },
                          cam::SimCameraSettings{});
    cam::ScanCamera scanCamera(&camera);
    dev::jobs::ScanRunner runner(&client);
    if (withCamera) {
        camera.open();
        // One shot first: the specimen's tables are built once when the camera opens,
        // which is not a tile's cost.
        bool warm = false;
        const auto warming = QObject::connect(&camera, &cam::Camera::captured, [&warm](std::uint64_t, const cam::Frame&) { warm = true; });
        cam::CaptureRequest first;
        first.id = 1000000;
        camera.capture(first);
        const bool warmed = spinUntil([&] { return warm; }, 30000);
        QObject::disconnect(warming);
        if (!warmed) {
            *why = "the simulated camera gave no first frame";
            return -1;
        }
        runner.setCamera(&scanCamera);
    }
    QTemporaryDir dir;
    motion::msg::Message error;
    if (!runner.prepare(plan(), dir.path(), false, &error) || !runner.start(&error)) {
        *why = "the scan would not start";
        return -1;
    }
    *tiles = runner.totalTiles();
    QElapsedTimer wall;
    wall.start();
    const bool finished = spinUntil([&] { return runner.state() == dev::jobs::ScanRunner::State::Finished
                                               || runner.state() == dev::jobs::ScanRunner::State::Stopped; },
                                    600000);
    const double seconds = wall.nsecsElapsed() / 1e9;
    client.setTransport(nullptr);
    if (!finished || runner.state() != dev::jobs::ScanRunner::State::Finished) {
        *why = "the scan did not finish";
        return -1;
    }
    return seconds;
}

void cameraTimePerTile(benchmark::State& state)
{
    double with = 0, without = 0;
    int tiles = 0;
    for (auto _ : state) {
        std::string why;
        without = runScan(false, &tiles, &why);
        with = without < 0 ? -1 : runScan(true, &tiles, &why);
        if (with < 0 || tiles <= 0) {
            state.SkipWithError(why.c_str());
            return;
        }
    }
    const double perTileMs = (with - without) / tiles * 1e3 + kExposureS * 1e3;
    state.counters["tiles"] = tiles;
    state.counters["wall_s_with_camera"] = with;
    state.counters["wall_s_without"] = without;
    state.counters["ms_per_tile_beyond_move_and_settle"] = perTileMs;
    state.counters["goal_ms"] = kExposureS * 1e3 + 20;
}
BENCHMARK(cameraTimePerTile)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
