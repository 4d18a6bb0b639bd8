// Google Benchmark program for the mosaic viewer (docs/stitching.md, "The mosaic viewer"):
// a screen's worth (1366 × 768) read from the full level of a pyramidal OME-TIFF, and the
// viewer's canvas painted at 1366 × 768 with its block cache cold (a view opened or jumped
// to) and warm (a pan within what was read). The mosaic is 8192 × 8192 16-bit, written by
// imaging's writer (BP_BENCH_SHORT=1, CTest's short run: 2048 × 2048).
// Counters: mb_per_s (region reads), blocks (read for one cold paint).
#include "imaging/ome_tiff_writer.h"
#include "imaging/pyramid_reader.h"
#include "widgets/scan/mosaic_canvas.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QImage>
#include <QPainter>

#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <unistd.h>

namespace {

struct MosaicFile {
    std::string path;
    int side = 0;
    MosaicFile()
    {
        side = qEnvironmentVariableIsSet("BP_BENCH_SHORT") ? 2048 : 8192;
        path = "/tmp/bp_bench_mosaic_" + std::to_string(::getpid()) + ".ome.tif";
        imaging::OmeTiffOptions o;
        o.pixelSizeUm = 0.65;
        auto w = imaging::OmeTiffWriter::open(path, side, side, o);
        std::vector<std::uint16_t> rows(static_cast<std::size_t>(side) * 256);
        std::mt19937 rng(7);
        for (int y0 = 0; y0 < side; y0 += 256) {
            for (std::size_t i = 0; i < rows.size(); ++i)
                rows[i] = static_cast<std::uint16_t>(rng() & 0xffff);
            (void)(*w)->writeRows(rows.data(), 256);
        }
        (void)(*w)->finish();
    }
    ~MosaicFile() { std::remove(path.c_str()); }
};

MosaicFile& mosaic()
{
    static MosaicFile file;
    return file;
}

void BM_ReadScreenRegion(benchmark::State& state)
{
    auto reader = imaging::PyramidReader::open(mosaic().path);
    std::mt19937 rng(3);
    const int side = mosaic().side;
    std::uniform_int_distribution<int> x(0, side - 1366), y(0, side - 768);
    for (auto _ : state) {
        auto px = (*reader)->readRegion(0, x(rng), y(rng), 1366, 768);
        benchmark::DoNotOptimize(px->px.data());
    }
    state.counters["mb_per_s"] = benchmark::Counter(1366.0 * 768 * 2 / 1e6 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReadScreenRegion)->Unit(benchmark::kMillisecond);

/// One paint of the canvas at 1366 × 768, at 1:1 in the middle of the mosaic (cold: the
/// mosaic set again first, so every block in view is read; warm: painted again).
void paintCanvas(benchmark::State& state, bool cold)
{
    auto reader = imaging::PyramidReader::open(mosaic().path);
    std::shared_ptr<imaging::PyramidReader> shared = reader.take();
    ui::MosaicCanvas canvas;
    canvas.resize(1366, 768);
    QImage target(1366, 768, QImage::Format_RGB32);
    long blocks = 0;
    auto setUp = [&] {
        canvas.setMosaic(shared, ui::MosaicStageFrame());
        canvas.zoomBy(1.0 / canvas.zoom());  // 1:1, the full level
    };
    setUp();
    if (!cold)
        canvas.render(&target);
    for (auto _ : state) {
        if (cold) {
            state.PauseTiming();
            setUp();
            state.ResumeTiming();
        }
        const long before = canvas.blocksRead();
        canvas.render(&target);
        blocks = canvas.blocksRead() - before;
    }
    state.counters["blocks"] = static_cast<double>(blocks);
}

void BM_CanvasPaintCold(benchmark::State& state) { paintCanvas(state, true); }
void BM_CanvasPaintWarm(benchmark::State& state) { paintCanvas(state, false); }
BENCHMARK(BM_CanvasPaintCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CanvasPaintWarm)->Unit(benchmark::kMillisecond);

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
