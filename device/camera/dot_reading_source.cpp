#include "device/camera/dot_reading_source.h"

#include "device/camera/tile_tiff.h"
#include "imaging/dot_finder.h"

#include <QDir>

#include <cmath>
#include <cstring>

namespace dev::camera {

namespace {

/// The frame as 16-bit grey: 8-bit stretched to the same range, colour by its luminance.
imaging::ImageU16 dotGreyOf(const Frame& f)
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

} // namespace

DotReadingSource::DotReadingSource(Camera* camera, const DotReadingOptions& options, QObject* parent)
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
    connect(m_camera, &Camera::captured, this, &DotReadingSource::onCaptured);
    connect(m_camera, &Camera::failed, this, &DotReadingSource::onFailed);
    connect(m_camera, &Camera::opened, this, [this] {
        if (auto done = std::exchange(m_openDone, {}))
            done({});
    });
}

motion::msg::Message DotReadingSource::describe() const
{
    return motion::msg::make("accuracy.source.camera_plate", {motion::msg::verbatim("camera", m_camera->source().toStdString())});
}

void DotReadingSource::open(OpenDone done)
{
    if (m_camera->isOpen()) {
        done({});
        return;
    }
    m_openDone = std::move(done);
    m_camera->open();
}

void DotReadingSource::take(const dev::jobs::StopContext& stop, TakeDone done)
{
    if (stop.targetsMm.size() != 2) {
        done({{}, false, motion::msg::make("camera.reading.two_axes", {motion::msg::verbatim("camera", m_camera->source().toStdString())})});
        return;
    }
    m_stop = stop;
    m_done = std::move(done);
    m_waitingId = m_nextId++;
    CaptureRequest request;
    request.id = m_waitingId;
    request.xMm = stop.targetsMm[0];
    request.yMm = stop.targetsMm[1];
    request.geometry = m_options.geometry;
    m_timeout.start(m_options.timeoutMs);
    m_camera->capture(request);
}

void DotReadingSource::cancel()
{
    m_waitingId = 0;
    m_done = {};
    m_timeout.stop();
}

void DotReadingSource::finish(const dev::jobs::TakeResult& result)
{
    m_timeout.stop();
    if (auto done = std::exchange(m_done, {}))
        done(result);
}

void DotReadingSource::onFailed(std::uint64_t id, const motion::msg::Problem& problem)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    finish({{}, false, problem.message});
}

void DotReadingSource::onCaptured(std::uint64_t id, const Frame& frame)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    imaging::DotFinderOptions o;
    o.polarity = imaging::Polarity::Dark;  // chrome dots on glass, in transmitted light
    const auto found = imaging::findDot(dotGreyOf(frame), o);
    double exX = 0, exY = 0, eyX = 0, eyY = 0;
    m_options.geometry.axes(&exX, &exY, &eyX, &eyY);
    motion::msg::Message notPlate;
    if (found) {
        const double mmPerPx = m_options.geometry.pixelUm * 1e-3;
        const double diameterMm = found->diameterPx * mmPerPx;
        const double offMm = std::hypot(found->xPx, found->yPx) * mmPerPx;
        if (std::fabs(diameterMm - m_options.dotDiameterMm) > 0.25 * m_options.dotDiameterMm)
            notPlate = motion::msg::make("camera.reading.dot_size", {motion::msg::real("diameter", diameterMm * 1e3, motion::msg::Unit::Um),
                                                                     motion::msg::real("expected", m_options.dotDiameterMm * 1e3, motion::msg::Unit::Um)});
        else if (offMm > 0.5 * m_options.platePitchMm)
            notPlate = motion::msg::make("camera.reading.dot_far", {motion::msg::real("distance", offMm, motion::msg::Unit::Mm),
                                                                    motion::msg::real("max", 0.5 * m_options.platePitchMm, motion::msg::Unit::Mm)});
    }
    if (!found || !notPlate.empty()) {
        motion::msg::Message why = found ? notPlate : found.error();
        if (!m_options.failedImagesFolder.isEmpty()) {
            const QString file = QDir(m_options.failedImagesFolder).filePath(QStringLiteral("node-%1.tif").arg(m_stop.index + 1, 3, 10, QLatin1Char('0')));
            TileMetadata meta;
            meta.label = QDir(file).dirName().toStdString();
            meta.source = m_camera->source().toStdString();
            motion::msg::Message error;
            if (writeTileTiff(file.toStdString(), frame, meta, nullptr, &error))
                why = motion::msg::make("camera.reading.no_dot", {motion::msg::nested("cause", why), motion::msg::verbatim("file", QDir::toNativeSeparators(file).toStdString())});
        }
        finish({{}, false, why});
        return;
    }
    // The dot sits off the work point by its pixel offset along the image's axes; the
    // work point is therefore that much the other way of the dot's nominal place.
    const double dotFromCentreXMm = found->xPx * exX + found->yPx * eyX;
    const double dotFromCentreYMm = found->xPx * exY + found->yPx * eyY;
    dev::jobs::TakeResult r;
    r.valuesMm = {m_stop.targetsMm[0] - dotFromCentreXMm, m_stop.targetsMm[1] - dotFromCentreYMm};
    finish(r);
}

} // namespace dev::camera
