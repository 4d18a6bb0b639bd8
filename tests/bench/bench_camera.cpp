// The camera's costs: rendering a simulated 2048 × 2048 16-bit frame (goal ≤ 30 ms on one
// core), converting a frame for display with auto-contrast (goal ≤ 10 ms), and writing a
// tile TIFF with its checksum — what a scan tile costs beyond the move, the settle and the
// exposure (the write overlaps the next move); and turning a USB camera's 1920 × 1080
// frame into a Frame (NV12, YUYV, Motion-JPEG), which runs for every live frame shown.
#include "device/camera/display_image.h"
#include "device/camera/sim_render.h"
#include "device/camera/specimen.h"
#include "device/camera/tile_tiff.h"

#if BP_WITH_UVC
#include "device/camera/video_frame_convert.h"

#include <QBuffer>
#endif

#include <QDir>
#include <QTemporaryDir>

#include <cstring>

#include <benchmark/benchmark.h>

namespace {

namespace cam = dev::camera;

const cam::Specimen& specimen(cam::SpecimenKind kind)
{
    static const cam::Specimen slide(cam::SpecimenKind::Slide, 1), plate(cam::SpecimenKind::GridPlate, 1),
        scales(cam::SpecimenKind::LineScales, 1);
    return kind == cam::SpecimenKind::Slide ? slide : (kind == cam::SpecimenKind::GridPlate ? plate : scales);
}

void renderFrame(benchmark::State& state)
{
    const auto kind = static_cast<cam::SpecimenKind>(state.range(0));
    const cam::CameraGeometry g;  // 2048 × 2048 px, 0.65 µm
    double x = 30;
    for (auto _ : state) {
        cam::Frame f = cam::renderSimFrame(specimen(kind), g, cam::SimOptics{}, x, 40.0, 10, 1);
        benchmark::DoNotOptimize(f.pixels.data());
        x += 0.1;
    }
    state.counters["ms_per_frame"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-3,
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetLabel(cam::specimenName(kind));
}
BENCHMARK(renderFrame)->Arg(static_cast<int>(cam::SpecimenKind::Slide))->Arg(static_cast<int>(cam::SpecimenKind::GridPlate))
    ->Arg(static_cast<int>(cam::SpecimenKind::LineScales))->Unit(benchmark::kMillisecond);

void displayConversion(benchmark::State& state)
{
    const cam::Frame f = cam::renderSimFrame(specimen(cam::SpecimenKind::Slide), cam::CameraGeometry{}, cam::SimOptics{}, 30, 40, 10, 1);
    for (auto _ : state) {
        QImage img = cam::toDisplayImage(f, true);
        benchmark::DoNotOptimize(img.constBits());
    }
    state.counters["ms_per_frame"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-3,
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(displayConversion)->Unit(benchmark::kMillisecond);

#if BP_WITH_UVC
/// A 1920 × 1080 frame from a USB camera, a smooth gradient (so Motion-JPEG is of a usual size).
QVideoFrame usbFrame(QVideoFrameFormat::PixelFormat pf)
{
    const int w = 1920, h = 1080;
    QVideoFrame f(QVideoFrameFormat(QSize(w, h), pf));
    f.map(QVideoFrame::WriteOnly);
    if (pf == QVideoFrameFormat::Format_Jpeg) {
        QImage picture(w, h, QImage::Format_RGB888);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                picture.setPixel(x, y, qRgb(x * 255 / w, y * 255 / h, (x + y) % 256));
        QByteArray jpeg;
        QBuffer buffer(&jpeg);
        buffer.open(QIODevice::WriteOnly);
        picture.save(&buffer, "JPG", 85);
        std::memcpy(f.bits(0), jpeg.constData(), static_cast<std::size_t>(std::min<qsizetype>(jpeg.size(), f.mappedBytes(0))));
    } else {
        for (int p = 0; p < f.planeCount(); ++p)
            for (int i = 0; i < f.mappedBytes(p); ++i)
                f.bits(p)[i] = static_cast<uchar>(i * 7 + p * 50);
    }
    f.unmap();
    return f;
}

void usbFrameConversion(benchmark::State& state)
{
    const auto pf = static_cast<QVideoFrameFormat::PixelFormat>(state.range(0));
    const QVideoFrame frame = usbFrame(pf);
    for (auto _ : state) {
        auto f = cam::frameFromVideo(frame);
        benchmark::DoNotOptimize(f.ok());
    }
    state.counters["ms_per_frame"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-3,
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetLabel(cam::videoFormatName(pf));
}
BENCHMARK(usbFrameConversion)->Arg(QVideoFrameFormat::Format_NV12)->Arg(QVideoFrameFormat::Format_YUYV)
    ->Arg(QVideoFrameFormat::Format_Jpeg)->Unit(benchmark::kMillisecond);
#endif

/// A tile's camera work beyond the exposure: the render (a real camera's transfer) and the
/// TIFF written with its SHA-256, as the scan does it for each tile.
void tileBeyondMoveAndSettle(benchmark::State& state)
{
    QTemporaryDir dir;
    const std::string path = QDir(dir.path()).filePath(QStringLiteral("tile.tif")).toStdString();
    double x = 30;
    for (auto _ : state) {
        const cam::Frame f = cam::renderSimFrame(specimen(cam::SpecimenKind::Slide), cam::CameraGeometry{}, cam::SimOptics{}, x, 40, 10, 1);
        std::string sha;
        motion::msg::Message error;
        if (!cam::writeTileTiff(path, f, {}, &sha, &error))
            state.SkipWithError("cannot write the tile");
        x += 1.1;
    }
    state.counters["ms_per_tile"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-3,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(tileBeyondMoveAndSettle)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
