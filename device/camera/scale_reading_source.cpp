#include "device/camera/scale_reading_source.h"

#include "imaging/line_finder.h"

#include <algorithm>
#include <cmath>

namespace dev::camera {

namespace {

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
    : CameraReadingSource(camera, parent), m_options(options)
{
}

motion::msg::Message ScaleReadingSource::describe() const
{
    const std::vector<QChar>& letters = currentStop().letters;
    return motion::msg::make("accuracy.source.camera_scale", {motion::msg::verbatim("camera", cameraName()),
                                                              motion::msg::verbatim("axis", letters.empty() ? std::string("X") : std::string(1, letters.front().toLatin1()))});
}

void ScaleReadingSource::take(const dev::jobs::StopContext& stop, TakeDone done)
{
    if (stop.axes.size() != 1 || (stop.letters.front() != QLatin1Char('X') && stop.letters.front() != QLatin1Char('Y'))) {
        done({{}, false, motion::msg::make("camera.reading.one_axis", {motion::msg::verbatim("camera", cameraName())})});
        return;
    }
    startCapture(stop, std::move(done), stop.letters.front() == QLatin1Char('X') ? stop.targetsMm.front() : 0,
                 stop.letters.front() == QLatin1Char('Y') ? stop.targetsMm.front() : 0);
}

dev::jobs::TakeResult ScaleReadingSource::readFrame(const Frame& frame)
{
    // Which image axis runs along the stage axis read: the graduation lines cross it.
    double exX = 0, exY = 0, eyX = 0, eyY = 0;
    m_options.geometry.axes(&exX, &exY, &eyX, &eyY);
    const bool readingX = currentStop().letters.front() == QLatin1Char('X');
    const double alongImageX = readingX ? exX : exY;  // mm of the axis for one pixel along image x
    const double alongImageY = readingX ? eyX : eyY;
    const bool acrossImageX = std::fabs(alongImageX) >= std::fabs(alongImageY);
    imaging::LineFinderOptions o;
    o.direction = acrossImageX ? imaging::LineDirection::Vertical : imaging::LineDirection::Horizontal;
    o.polarity = imaging::Polarity::Dark;  // chrome lines on glass, in transmitted light
    const auto found = imaging::findLine(frameToGreyU16(frame), o);
    if (!found)
        return {{}, false, keepFailedImage(frame, "reading", found.error(), "camera.reading.no_line")};
    m_lastOffsetPx = found->offsetPx;
    const double mmPerPx = acrossImageX ? alongImageX : alongImageY;
    const double lineFromCentreMm = found->offsetPx * mmPerPx;
    double graduationMm = graduationOf(frame, acrossImageX, found->offsetPx, mmPerPx);
    if (m_options.certificate)
        graduationMm += m_options.certificate->deviationAtUm(graduationMm) * 1e-3;  // where that line truly lies
    dev::jobs::TakeResult r;
    r.valuesMm = {graduationMm - lineFromCentreMm};
    return r;
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
    const double target = currentStop().targetsMm.front();
    const double nearest = std::round((target + offsetPx * mmPerPx) / pitch) * pitch;
    const imaging::ImageU16 im = frameToGreyU16(frame);
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
