#include "device/camera/camera_reading_source.h"

#include "device/camera/tile_tiff.h"

#include <QDir>

#include <cmath>
#include <cstring>

namespace dev::camera {

imaging::ImageU16 frameToGreyU16(const Frame& f)
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

CameraReadingSource::CameraReadingSource(Camera* camera, QObject* parent) : dev::jobs::ReadingSource(parent), m_camera(camera)
{
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        if (!m_waitingId)
            return;
        m_waitingId = 0;
        finish({{}, false, motion::msg::make("camera.reading.silent", {motion::msg::verbatim("camera", cameraName()),
                                                                       motion::msg::real("seconds", cameraOptions().timeoutMs / 1000.0, motion::msg::Unit::S)})});
    });
    connect(m_camera, &Camera::captured, this, &CameraReadingSource::onCaptured);
    connect(m_camera, &Camera::failed, this, &CameraReadingSource::onFailed);
    connect(m_camera, &Camera::opened, this, [this] {
        if (auto done = std::exchange(m_openDone, {}))
            done({});
    });
}

std::string CameraReadingSource::cameraName() const { return m_camera->source().toStdString(); }

void CameraReadingSource::open(OpenDone done)
{
    if (m_camera->isOpen()) {
        done({});
        return;
    }
    m_openDone = std::move(done);
    m_camera->open();
}

void CameraReadingSource::startCapture(const dev::jobs::StopContext& stop, TakeDone done, double xMm, double yMm)
{
    m_stop = stop;
    m_done = std::move(done);
    m_waitingId = m_nextId++;
    CaptureRequest request;
    request.id = m_waitingId;
    request.xMm = xMm;
    request.yMm = yMm;
    request.geometry = cameraOptions().geometry;
    m_timeout.start(cameraOptions().timeoutMs);
    m_camera->capture(request);
}

void CameraReadingSource::cancel()
{
    m_waitingId = 0;
    m_done = {};
    m_timeout.stop();
}

void CameraReadingSource::finish(const dev::jobs::TakeResult& result)
{
    m_timeout.stop();
    if (auto done = std::exchange(m_done, {}))
        done(result);
}

void CameraReadingSource::onFailed(std::uint64_t id, const motion::msg::Problem& problem)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    finish({{}, false, problem.message});
}

void CameraReadingSource::onCaptured(std::uint64_t id, const Frame& frame)
{
    if (!m_waitingId || id != m_waitingId)
        return;
    m_waitingId = 0;
    finish(readFrame(frame));
}

motion::msg::Message CameraReadingSource::keepFailedImage(const Frame& frame, const char* stem, const motion::msg::Message& why,
                                                          const char* keptId) const
{
    const QString folder = cameraOptions().failedImagesFolder;
    if (folder.isEmpty())
        return why;
    const QString file = QDir(folder).filePath(QStringLiteral("%1-%2.tif").arg(QLatin1String(stem)).arg(m_stop.index + 1, 3, 10, QLatin1Char('0')));
    TileMetadata meta;
    meta.label = QDir(file).dirName().toStdString();
    meta.source = cameraName();
    motion::msg::Message error;
    if (!writeTileTiff(file.toStdString(), frame, meta, nullptr, &error))
        return why;
    return motion::msg::make(keptId, {motion::msg::nested("cause", why), motion::msg::verbatim("file", QDir::toNativeSeparators(file).toStdString())});
}

} // namespace dev::camera
