// Google Benchmark program for imaging/: registration and the whole stitch.
// Goals (docs/stitching.md, "Speed"): one 2048 × 2048 pair registered in ≤ 60 ms on
// one core; a 10 × 10 grid of 2048² 16-bit tiles with 10 % overlap registered, placed
// and fused into a pyramidal OME-TIFF in ≤ 20 s on two cores with a peak memory
// ≤ 1.5 GB; global placement after the last tile (the live delay) ≤ 2 s; the line or
// the dot nearest the centre of a 2048² image found in ≤ 5 ms each.
// Counters (the pair's time is the Time column): registration_s, placement_ms, fusion_s, peak_rss_mb, rms_error_px.
// The live scan (BM_LiveStitchDelay10x10/interval_ms): the same grid fed one tile at a
// time from its files at the scan's pace; delay_s is from the last tile to the finished
// placement, mosaic_s to the written mosaic, behind_tiles how many tiles the worker had
// still to register when the last came.
// BP_BENCH_SHORT=1 (CTest's short run) uses a 4 × 4 grid of 512² tiles instead, and
// finds the line and the dot in 512² images.
#include "imaging/dot_finder.h"
#include "imaging/line_finder.h"
#include "imaging/live_stitch.h"
#include "imaging/registration.h"
#include "imaging/stitch.h"
#include "imaging/tiff_write.h"

#include "tests/imaging/marks.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <chrono>
#include <random>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

bool shortRun()
{
    const char* s = std::getenv("BP_BENCH_SHORT");
    return s && *s && *s != '0';
}

std::uint32_t hash3(std::int64_t x, std::int64_t y, std::uint32_t s)
{
    std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^ s * 0x165667B19E3779F9ull;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return static_cast<std::uint32_t>(h);
}

/// Value noise at three scales (4, 16 and 64 px), a texture defined at every
/// integer point of the plane, cheap enough for 100 tiles of 2048².
double texture(std::int64_t x, std::int64_t y)
{
    double v = 20000;
    const int scales[] = {4, 16, 64};
    const double amps[] = {1500, 3000, 5000};
    for (int k = 0; k < 3; ++k) {
        const int s = scales[k];
        const std::int64_t ix = x >= 0 ? x / s : (x - s + 1) / s, iy = y >= 0 ? y / s : (y - s + 1) / s;
        const double fx = static_cast<double>(x - ix * s) / s, fy = static_cast<double>(y - iy * s) / s;
        auto r = [&](std::int64_t a, std::int64_t b) { return (hash3(a, b, static_cast<std::uint32_t>(k)) & 0xFFFF) / 65535.0 - 0.5; };
        const double top = r(ix, iy) * (1 - fx) + r(ix + 1, iy) * fx, bottom = r(ix, iy + 1) * (1 - fx) + r(ix + 1, iy + 1) * fx;
        v += amps[k] * (top * (1 - fy) + bottom * fy);
    }
    return v;
}

imaging::ImageU16 tileAt(std::int64_t x0, std::int64_t y0, int size, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, 50);
    imaging::ImageU16 t(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            t.at(x, y) = static_cast<std::uint16_t>(std::clamp(texture(x0 + x, y0 + y) + noise(rng), 0.0, 65535.0));
    return t;
}

double peakRssMb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

void BM_RegisterPair2048(benchmark::State& state)
{
    const int size = shortRun() ? 512 : 2048;
    const int step = size - size / 10;  // 10 % overlap
    static const imaging::ImageU16 a = tileAt(0, 0, size, 1);
    static const imaging::ImageU16 b = tileAt(step + 3, -2, size, 2);  // the stage 3 px and 2 px wrong
    imaging::PairRegistration r;
    for (auto _ : state) {
        r = imaging::registerPair(a, b, Eigen::Vector2d(step, 0), {});
        benchmark::DoNotOptimize(r);
    }
    state.counters["error_px"] = (r.shiftPx - Eigen::Vector2d(step + 3, -2)).norm();
    state.counters["ncc"] = r.ncc;
}
BENCHMARK(BM_RegisterPair2048)->Unit(benchmark::kMillisecond);

// A glass scale under the camera: lines 6 px wide every 150 px, blurred, 1 % noise.
void BM_FindLine2048(benchmark::State& state)
{
    static const int size = shortRun() ? 512 : 2048;
    const double truth = 4.37;
    static const imaging::ImageU16 im = [&] {
        std::vector<imagingtest::LineMark> lines;
        for (int k = -size / 300; k <= size / 300; ++k)
            lines.push_back({0.5 * (size - 1) + truth + 150 * k, 6});
        return imagingtest::renderLines(size, size, true, lines, 1.5, 200, 21);
    }();
    imaging::LineFinderOptions o;
    o.direction = imaging::LineDirection::Vertical;
    double offset = 0;
    for (auto _ : state) {
        const auto found = imaging::findLine(im, o);
        offset = found.ok() ? found->offsetPx : NAN;
        benchmark::DoNotOptimize(offset);
    }
    state.counters["error_px"] = std::abs(offset - truth);
}
BENCHMARK(BM_FindLine2048)->Unit(benchmark::kMillisecond);

// A grid plate under the camera: dots 60 px across every 400 px, blurred, 1 % noise.
void BM_FindDot2048(benchmark::State& state)
{
    static const int size = shortRun() ? 512 : 2048;
    const double tx = -3.21, ty = 6.58;
    static const imaging::ImageU16 im = [&] {
        std::vector<imagingtest::DotMark> dots;
        for (int j = -size / 1000; j <= size / 1000; ++j)
            for (int i = -size / 1000; i <= size / 1000; ++i)
                dots.push_back({0.5 * (size - 1) + tx + 400 * i, 0.5 * (size - 1) + ty + 400 * j, 30});
        return imagingtest::renderDots(size, size, dots, 1.5, 200, 22);
    }();
    double ex = 0, ey = 0;
    for (auto _ : state) {
        const auto found = imaging::findDot(im);
        ex = found.ok() ? found->xPx - tx : NAN;
        ey = found.ok() ? found->yPx - ty : NAN;
        benchmark::DoNotOptimize(ex);
    }
    state.counters["error_px"] = std::hypot(ex, ey);
}
BENCHMARK(BM_FindDot2048)->Unit(benchmark::kMillisecond);

void BM_StitchGrid10x10(benchmark::State& state)
{
    const int n = shortRun() ? 4 : 10, size = shortRun() ? 512 : 2048;
    const int step = size - size / 10;
    const std::string dir = "/tmp/bench_imaging_" + std::to_string(::getpid());
    std::system(("mkdir -p " + dir).c_str());
    std::vector<imaging::StitchTile> tiles;
    std::vector<Eigen::Vector2d> truth;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> err(-3, 3);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const Eigen::Vector2d stage(c * step, r * step);
            const Eigen::Vector2i t = (stage + Eigen::Vector2d(err(rng), err(rng))).array().round().cast<int>();
            truth.push_back(t.cast<double>());
            const std::string name = "tile_" + std::to_string(1000 + r * n + c).substr(1) + ".tif";
            imaging::writeTiff(dir + "/" + name, tileAt(t.x(), t.y(), size, static_cast<unsigned>(r * n + c)));
            tiles.push_back({name, dir + "/" + name, stage});
        }
    imaging::StitchOptions o;
    o.mosaicPath = dir + "/mosaic.ome.tif";
    o.mosaic.pixelSizeUm = 0.65;
    o.threads = 2;
    imaging::StitchResult last;
    for (auto _ : state) {
        auto r = imaging::stitch(tiles, o);
        if (!r) {
            state.SkipWithError(motion::msg::debugFormat(r.problems()).c_str());
            break;
        }
        last = r.take();
    }
    if (!last.tiles.empty()) {
        double sum2 = 0;
        Eigen::Vector2d mean(0, 0);
        for (std::size_t i = 0; i < truth.size(); ++i)
            mean += last.placement.positionsPx[i] - truth[i];
        mean /= static_cast<double>(truth.size());
        for (std::size_t i = 0; i < truth.size(); ++i)
            sum2 += (last.placement.positionsPx[i] - truth[i] - mean).squaredNorm();
        state.counters["rms_error_px"] = std::sqrt(sum2 / static_cast<double>(truth.size()));
        state.counters["registration_s"] = last.registrationS;
        state.counters["placement_ms"] = last.placementS * 1e3;
        state.counters["fusion_s"] = last.fusionS;
        state.counters["pairs"] = static_cast<double>(last.pairs.size());
    }
    state.counters["peak_rss_mb"] = peakRssMb();
    std::system(("rm -rf " + dir).c_str());
}
BENCHMARK(BM_StitchGrid10x10)->Unit(benchmark::kSecond)->Iterations(1);

void BM_LiveStitchDelay10x10(benchmark::State& state)
{
    using Clock = std::chrono::steady_clock;
    const int n = shortRun() ? 4 : 10, size = shortRun() ? 512 : 2048;
    const int step = size - size / 10;
    const auto interval = std::chrono::milliseconds(shortRun() ? 50 : state.range(0));
    const std::string dir = "/tmp/bench_imaging_live_" + std::to_string(::getpid());
    std::system(("mkdir -p " + dir).c_str());
    std::vector<imaging::StitchTile> tiles;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> err(-3, 3);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const Eigen::Vector2d stage(c * step, r * step);
            const Eigen::Vector2i t = (stage + Eigen::Vector2d(err(rng), err(rng))).array().round().cast<int>();
            const std::string name = "tile_" + std::to_string(1000 + r * n + c).substr(1) + ".tif";
            imaging::writeTiff(dir + "/" + name, tileAt(t.x(), t.y(), size, static_cast<unsigned>(r * n + c)));
            tiles.push_back({name, dir + "/" + name, stage});
        }
    // The scan's order: rows, every other one backwards.
    std::vector<int> order;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            order.push_back(r * n + (r % 2 ? n - 1 - c : c));
    imaging::StitchOptions so;
    so.mosaicPath = dir + "/mosaic.ome.tif";
    so.mosaic.pixelSizeUm = 0.65;
    for (auto _ : state) {
        imaging::LiveStitchOptions o;
        o.registration = so.registration;
        o.placement = so.placement;
        imaging::LiveStitcher live(tiles, o);
        Clock::time_point next = Clock::now();
        int behind = 0;
        for (int i : order) {
            std::this_thread::sleep_until(next);
            next += interval;
            // As the scan hands it: the tile's file is written, its position measured.
            live.add(i, tiles[static_cast<std::size_t>(i)].stagePx);
        }
        const Clock::time_point last = Clock::now();
        behind = live.tilesAdded() - live.tilesRegistered();
        auto r = live.finish();
        const double delay = std::chrono::duration<double>(Clock::now() - last).count();
        if (!r) {
            state.SkipWithError(motion::msg::debugFormat(r.problems()).c_str());
            break;
        }
        const motion::msg::Problems fused = imaging::writeMosaic(*r, so);
        if (motion::msg::hasErrors(fused)) {
            state.SkipWithError(motion::msg::debugFormat(fused).c_str());
            break;
        }
        state.counters["delay_s"] = delay;
        state.counters["mosaic_s"] = std::chrono::duration<double>(Clock::now() - last).count();
        state.counters["placement_ms"] = r->placementS * 1e3;
        state.counters["registration_s"] = r->registrationS;
        state.counters["behind_tiles"] = behind;
        state.counters["held_mb_peak"] = live.peakHeldMegabytes();
        state.counters["pairs"] = static_cast<double>(r->pairs.size());
    }
    state.counters["peak_rss_mb"] = peakRssMb();
    std::system(("rm -rf " + dir).c_str());
}
// 500 ms a tile: a 1.2 mm step, the settle and a short exposure on this stage; 250 ms is
// a fast stage, where registration (two pairs a tile) has to keep up on two cores.
BENCHMARK(BM_LiveStitchDelay10x10)->Arg(500)->Arg(250)->ArgName("interval_ms")->Unit(benchmark::kSecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
