#include "device/camera/scale_reading_source.h"

#include "device/camera/tile_tiff.h"
#include "imaging/line_finder.h"

#include <QDir>

#include <cmath>
#include <cstring>

namespace dev::camera {

namespace {

/// The frame as 16-bit grey: 8-bit stretched to the same range, colour by its luminance.
imaging::ImageU16 greyOf(const Frame& f)
{
    imaging::ImageU16 im(f.width, f.height);
    const std::size_t n = im.px.size();
    switch (f.format) {
    case PixelFormat::Grey16:
        std::memcpy(im.px.data(), f.pixels.data(), n * sizeof(std::uint16_t));
        break;
    case PixelFormat::Grey8:
        for (std::size_t i = 0; i < n; ++i)
            im.px[i] = static_cast<std::uint16_t>(f.pixels[i] * 257);
        break;
    case PixelFormat::Rgb8:
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t* p = f.pixels.data() + 3 * i;
            im.px[i] = static_cast<std::uint16_t>(std::lround((0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) * 257));
        }
        break;
    }
    return im;
}

/// How many pixels along itself the mark across the image at `posPx` (a column for a
/// vertical line, a row for a horizontal one) is dark: its longest dark run, where dark
/// is a third below the glass beside it.
int markLengthPx(const imaging::ImageU16& im, bool vertical, double posPx)
{
    const int across = vertical ? im.width : im.height, along = vertical ? im.height : im.width;
    const int c = static_cast<int>(std::lround(posPx));
    constexpr int kBeside = 8;
    if (c - kBeside - 1 < 0 || c + kBeside + 1 >= across)
        return 0;
    auto at = [&](int a, int b) { return static_cast<double>(vertical ? im.at(a, b) : im.at(b, a)); };
    int run = 0, best = 0;
    for (int b = 0; b < along; ++b) {
        const double mark = std::min({at(c - 1, b), at(c, b), at(c + 1, b)});
        const double glass = 0.5 * (at(c - kBeside, b) + at(c + kBeside, b));
        run = glass > 0 && mark < glass * (2.0 / 3.0) ? run + 1 : 0;
        best = std::max(best, run);
    }
    return best;
}

} // namespace

ScaleReadingSource::ScaleReadingSource(Camera* camera, const ScaleReadingOptions& options, QObject* parent)
    : dev::jobs::ReadingSource(parent), m_camera(camera), m_options(options)
{
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        if (!m_waitingId)
            return;
        m_waitingId = 0;
        finish({{}, false, motion::msg::make("camera.reading.silent", {motion::msg::verbatim("camera", m_camera->source().toStdString()),
                                                                       motion::msg::real("seconds", m_options.timeoutMs / 1000.0, motion::msg::Unit::S)})});
    });
    connect(m_camera, &Camera::captured, this, &ScaleReadingSource::onCaptured);
    connect(m_camera, &Camera::failed, this, &ScaleReadingSource::onFailed);
    connect(m_camera, &Camera::opened, this, [this] {
        if (auto done = std::exchange(m_openDone, {}))
            done({});
    });
}

motion::msg::Message ScaleReadingSource::describe() const
{
    return motion::msg::make("accuracy.source.camera_scale", {motion::msg::verbatim("camera", m_camera->source().toStdString()),
                                                              motion::msg::verbatim("axis", m_stop.letters.empty() ? std::string("X") : std::string(1, m_stop.letters.front().toLatin1()))});
}

void ScaleReadingSource::open(OpenDone done)
{
    if (m_camera->isOpen()) {
        done({});
        return;
    }
    m_openDone = std::move(done);
    m_camera->open();
}

void ScaleReadingSource::take(const dev::jobs::StopContext& stop, TakeDone done)
{
    if (stop.axes.size() != 1 || (stop.letters.front() != QLatin1Char('X') && stop.letters.front() != QLatin1Char('Y'))) {
        done({{}, false, motion::msg::make("camera.reading.one_axis", {motion::msg::verbatim("camera", m_camera->source().toStdString())})});
        return;
    }
    m_stop = stop;
    m_done = std::move(done);
    m_waitingId = m_nextId++;
    CaptureRequest request;
    request.id = m_waitingId;
    request.xMm = stop.letters.front() == QLatin1Char('X') ? stop.targetsMm.front() : 0;
    request.yMm = stop.letters.front() == QLatin1Char('Y') ? stop.targetsMm.front() : 0;
    request.geometry = m_options.geometry;
    m_timeout.start(m_options.timeoutMs);
    m_camera->capture(request);
}

void ScaleReadingSource::cancel()
{
    m_waitingId = 0;
    m_done = {};
    m_timeout.stop();
}

void ScaleReadingSource::finish(const dev::jobs::TakeResult& result)
{
    m_timeout.stop();
    if (auto done = std::exchange(m_done, {}))
        done(result);
}

void ScaleReadingSource::onFailed(std::uint64_t id, const motion::msg::Problem& problem)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    finish({{}, false, problem.message});
}

void ScaleReadingSource::onCaptured(std::uint64_t id, const Frame& frame)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    // Which image axis runs along the stage axis read: the graduation lines cross it.
    double exX = 0, exY = 0, eyX = 0, eyY = 0;
    m_options.geometry.axes(&exX, &exY, &eyX, &eyY);
    const bool readingX = m_stop.letters.front() == QLatin1Char('X');
    const double alongImageX = readingX ? exX : exY;  // mm of the axis for one pixel along image x
    const double alongImageY = readingX ? eyX : eyY;
    const bool acrossImageX = std::fabs(alongImageX) >= std::fabs(alongImageY);
    imaging::LineFinderOptions o;
    o.direction = acrossImageX ? imaging::LineDirection::Vertical : imaging::LineDirection::Horizontal;
    o.polarity = imaging::Polarity::Dark;  // chrome lines on glass, in transmitted light
    const auto found = imaging::findLine(greyOf(frame), o);
    if (!found) {
        motion::msg::Message why = found.error();
        if (!m_options.failedImagesFolder.isEmpty()) {
            const QString file = QDir(m_options.failedImagesFolder).filePath(QStringLiteral("reading-%1.tif").arg(m_stop.index + 1, 3, 10, QLatin1Char('0')));
            TileMetadata meta;
            meta.label = QDir(file).dirName().toStdString();
            meta.source = m_camera->source().toStdString();
            motion::msg::Message error;
            if (writeTileTiff(file.toStdString(), frame, meta, nullptr, &error))
                why = motion::msg::make("camera.reading.no_line", {motion::msg::nested("cause", why), motion::msg::verbatim("file", QDir::toNativeSeparators(file).toStdString())});
        }
        finish({{}, false, why});
        return;
    }
    m_lastOffsetPx = found->offsetPx;
    const double mmPerPx = acrossImageX ? alongImageX : alongImageY;
    const double lineFromCentreMm = found->offsetPx * mmPerPx;
    double graduationMm = graduationOf(frame, acrossImageX, found->offsetPx, mmPerPx);
    if (m_options.certificate)
        graduationMm += m_options.certificate->deviationAtUm(graduationMm) * 1e-3;  // where that line truly lies
    dev::jobs::TakeResult r;
    r.valuesMm = {graduationMm - lineFromCentreMm};
    finish(r);
}

} // namespace dev::camera

namespace dev::camera {

double ScaleReadingSource::graduationOf(const Frame& frame, bool vertical, double offsetPx, double mmPerPx) const
{
    // Which graduation the line is. The stage may be further from where it was sent than
    // half the lines' pitch (an uncompensated stage, tens of µm), so the nearest one to the
    // target is not enough: the long line every tenth graduation (every 1 mm) is found in
    // the image, and the line counted from it; that holds while the stage is within half a
    // millimetre of its target. With no long line in view, the nearest to the target.
    const double pitch = m_options.graduationMm;
    const double target = m_stop.targetsMm.front();
    const double nearest = std::round((target + offsetPx * mmPerPx) / pitch) * pitch;
    const imaging::ImageU16 im = greyOf(frame);
    const double centre = ((vertical ? im.width : im.height) - 1) / 2.0;
    const double pitchPx = pitch / std::fabs(mmPerPx);
    std::vector<std::pair<int, int>> lengths;  // (k, length)
    for (int k = -12; k <= 12; ++k)
        if (const int len = markLengthPx(im, vertical, centre + offsetPx + k * pitchPx); len > 0)
            lengths.push_back({k, len});
    if (lengths.size() < 3)
        return nearest;
    std::vector<int> sorted;
    for (const auto& l : lengths)
        sorted.push_back(l.second);
    std::sort(sorted.begin(), sorted.end());
    const int median = sorted[sorted.size() / 2];
    int longK = 0, longLen = 0, longCount = 0;
    for (const auto& [k, len] : lengths)
        if (len > median * 3 / 2) {
            ++longCount;
            if (longLen == 0 || std::abs(k) < std::abs(longK))
                longK = k, longLen = len;
        }
    if (longCount == 0)
        return nearest;
    const double longStageMm = target + (offsetPx + longK * pitchPx) * mmPerPx;
    const double longNominalMm = std::round(longStageMm / (10 * pitch)) * (10 * pitch);
    return longNominalMm - longK * pitchPx * mmPerPx;
}

} // namespace dev::camera
