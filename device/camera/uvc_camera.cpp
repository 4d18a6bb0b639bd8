#include "device/camera/uvc_camera.h"

#include "device/camera/uvc_devices.h"
#include "device/camera/video_frame_convert.h"

#include <QCamera>
#include <QMediaCaptureSession>
#include <QMediaDevices>
#include <QVideoSink>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace dev::camera {

namespace {

std::int64_t uvcHostNowUs()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

motion::msg::Problem uvcProblem(const motion::msg::Message& m) { return motion::msg::Problem("", m); }

/// Hands a Qt Multimedia object to the event loop: it may be the sender of the signal
/// being handled now.
template <class T>
void deleteSoon(std::unique_ptr<T>& p)
{
    if (p)
        p.release()->deleteLater();
}

} // namespace

UvcCamera::UvcCamera(const QString& name, QObject* parent) : Camera(parent), m_name(name.trimmed())
{
    m_pool.setMaxThreadCount(1);
    m_openTimer.setSingleShot(true);
    m_captureTimer.setSingleShot(true);
    connect(&m_openTimer, &QTimer::timeout, this, [this] {
        failAll(motion::msg::make("camera.uvc.open_timeout", {motion::msg::verbatim("source", sourceText()),
                                                              motion::msg::real("seconds", kOpenTimeoutMs / 1000.0, motion::msg::Unit::S)}));
    });
    connect(&m_captureTimer, &QTimer::timeout, this, [this] {
        failCapture(motion::msg::make("camera.uvc.timeout", {motion::msg::verbatim("source", sourceText()),
                                                             motion::msg::real("seconds", m_captureTimer.interval() / 1000.0, motion::msg::Unit::S)}));
    });
}

UvcCamera::~UvcCamera()
{
    if (m_camera)
        m_camera->stop();  // the streaming thread stops with it: no frame arrives after this
    if (m_sink)
        QObject::disconnect(m_sink.get(), nullptr, this, nullptr);
    m_pool.waitForDone();
    m_session.reset();  // first: it holds the camera and the sink
    m_camera.reset();
    m_sink.reset();
}

QString UvcCamera::source() const { return m_name.isEmpty() ? QStringLiteral("uvc") : QStringLiteral("uvc:") + m_name; }

Capabilities UvcCamera::capabilities() const
{
    Capabilities c;
    c.live = true;
    if (m_camera) {
        const QCamera::Features f = m_camera->supportedFeatures();
        c.exposure = f.testFlag(QCamera::Feature::ManualExposureTime);
        c.gain = f.testFlag(QCamera::Feature::IsoSensitivity);
    }
    return c;
}

void UvcCamera::open()
{
    if (m_open) {
        emit opened();
        return;
    }
    if (m_opening)
        return;
    m_openProblem.reset();
    const UvcName name = parseUvcName(m_name);
    const auto found = findUvcCamera(name.camera, QMediaDevices::videoInputs());
    if (!found) {
        m_openProblem = found.error();
        emit failed(0, uvcProblem(*m_openProblem));
        return;
    }
    m_device = *found;
    const QCameraFormat format = chooseUvcFormat(m_device, name.size);
    if (format.isNull()) {
        QStringList offered;
        for (const QCameraFormat& f : m_device.videoFormats())
            if (!offered.contains(QString::fromStdString(videoFormatName(f.pixelFormat()))))
                offered << QString::fromStdString(videoFormatName(f.pixelFormat()));
        m_openProblem = name.size ? motion::msg::make("camera.uvc.no_such_resolution", {motion::msg::verbatim("source", sourceText()),
                                                                                        motion::msg::integer("width", name.size->width(), motion::msg::Unit::None),
                                                                                        motion::msg::integer("height", name.size->height(), motion::msg::Unit::None),
                                                                                        motion::msg::verbatim("offered", uvcSizesText(m_device))})
                                  : motion::msg::make("camera.uvc.no_format", {motion::msg::verbatim("source", sourceText()),
                                                                               motion::msg::verbatim("formats", offered.join(QStringLiteral(", ")).toStdString())});
        emit failed(0, uvcProblem(*m_openProblem));
        return;
    }
    m_camera = std::make_unique<QCamera>(m_device);
    m_camera->setCameraFormat(format);
    m_sink = std::make_unique<QVideoSink>();
    m_session = std::make_unique<QMediaCaptureSession>();
    m_session->setCamera(m_camera.get());
    m_session->setVideoSink(m_sink.get());
    // Direct: frames come on Qt Multimedia's thread and are only parked there (onVideoFrame).
    connect(m_sink.get(), &QVideoSink::videoFrameChanged, this, [this](const QVideoFrame& f) { onVideoFrame(f); }, Qt::DirectConnection);
    connect(m_camera.get(), &QCamera::activeChanged, this, &UvcCamera::onActiveChanged);
    connect(m_camera.get(), &QCamera::errorOccurred, this, [this](QCamera::Error error, const QString& detail) {
        if (error != QCamera::NoError)
            onCameraError(detail);
    });
    m_devices = std::make_unique<QMediaDevices>();
    connect(m_devices.get(), &QMediaDevices::videoInputsChanged, this, &UvcCamera::onDevicesChanged);
    m_opening = true;
    m_clock.reset();
    m_openTimer.start(kOpenTimeoutMs);
    m_camera->start();
}

void UvcCamera::onActiveChanged(bool active)
{
    if (!active || !m_opening)
        return;
    m_opening = false;
    m_open = true;
    m_openTimer.stop();
    if (m_exposureMs > 0)
        setExposureMs(m_exposureMs);
    if (m_gain > 0)
        setGain(m_gain);
    emit opened();
    // A capture asked while the camera was starting: its size is checked now that the camera is there.
    if (m_waiting)
        useFormatFor(m_request);
}

void UvcCamera::onCameraError(const QString& detail)
{
    failAll(motion::msg::make("camera.uvc.error", {motion::msg::verbatim("source", sourceText()), motion::msg::verbatim("detail", detail.toStdString())}));
}

void UvcCamera::onDevicesChanged()
{
    if (!m_open && !m_opening)
        return;
    const auto found = QMediaDevices::videoInputs();
    const bool there = std::any_of(found.begin(), found.end(), [this](const QCameraDevice& d) { return d.id() == m_device.id(); });
    if (!there)
        failAll(motion::msg::make("camera.uvc.unplugged", {motion::msg::verbatim("source", sourceText())}));
}

void UvcCamera::failCapture(const motion::msg::Message& why)
{
    if (!m_waiting)
        return;
    m_waiting = false;
    m_captureTimer.stop();
    emit failed(m_request.id, uvcProblem(why));
}

void UvcCamera::failAll(const motion::msg::Message& why)
{
    const bool wasOpen = m_open;
    if (m_opening)
        m_openProblem = why;
    failCapture(why);
    teardown();
    emit failed(0, uvcProblem(why));
    if (wasOpen)
        emit closed();
}

void UvcCamera::teardown()
{
    m_openTimer.stop();
    m_captureTimer.stop();
    if (m_camera) {
        QObject::disconnect(m_camera.get(), nullptr, this, nullptr);
        m_camera->stop();
    }
    if (m_sink)
        QObject::disconnect(m_sink.get(), nullptr, this, nullptr);
    if (m_devices)
        QObject::disconnect(m_devices.get(), nullptr, this, nullptr);
    deleteSoon(m_session);
    deleteSoon(m_camera);
    deleteSoon(m_sink);
    deleteSoon(m_devices);
    {
        std::lock_guard<std::mutex> lock(m_latestMutex);
        m_latest = QVideoFrame();
    }
    m_opening = false;
    m_open = false;
    m_liveInFlight = false;
}

void UvcCamera::close()
{
    if (!m_open && !m_opening)
        return;
    failCapture(motion::msg::make("camera.closed_during_capture", {motion::msg::verbatim("source", sourceText())}));
    teardown();
    emit closed();
}

void UvcCamera::startLive()
{
    if (!m_open && !m_opening)
        open();
    m_live = true;
    m_liveProblemSaid = false;
}

void UvcCamera::stopLive() { m_live = false; }

void UvcCamera::setExposureMs(double ms)
{
    m_exposureMs = std::max(0.0, ms);
    if (!m_camera || !m_camera->supportedFeatures().testFlag(QCamera::Feature::ManualExposureTime))
        return;
    if (m_exposureMs > 0) {
        if (m_camera->isExposureModeSupported(QCamera::ExposureManual))
            m_camera->setExposureMode(QCamera::ExposureManual);
        m_camera->setManualExposureTime(static_cast<float>(m_exposureMs / 1000.0));
    } else {
        m_camera->setExposureMode(QCamera::ExposureAuto);
    }
}

double UvcCamera::exposureMs() const
{
    if (m_camera && m_camera->exposureTime() > 0)
        return m_camera->exposureTime() * 1000.0;
    return m_exposureMs;
}

void UvcCamera::setGain(double gain)
{
    m_gain = std::max(0.0, gain);
    if (!m_camera || !m_camera->supportedFeatures().testFlag(QCamera::Feature::IsoSensitivity))
        return;
    if (m_gain > 0) {
        const int lo = m_camera->minimumIsoSensitivity(), hi = std::max(lo, m_camera->maximumIsoSensitivity());
        m_camera->setManualIsoSensitivity(std::clamp(static_cast<int>(std::lround(m_gain)), lo, hi));
    } else {
        m_camera->setAutoIsoSensitivity();
    }
}

std::int64_t UvcCamera::framePeriodUs() const
{
    const float fps = m_camera ? m_camera->cameraFormat().maxFrameRate() : 0.f;
    return fps > 0 ? static_cast<std::int64_t>(1e6 / fps) : 0;
}

bool UvcCamera::useFormatFor(const CaptureRequest& request)
{
    if (!request.geometry || !m_camera)
        return true;
    const QSize want(request.geometry->sensorWidthPx, request.geometry->sensorHeightPx);
    if (m_camera->cameraFormat().resolution() == want)
        return true;
    const QCameraFormat format = chooseUvcFormat(m_device, want);
    if (format.isNull()) {
        const QSize now = m_camera->cameraFormat().resolution();
        failCapture(motion::msg::make("camera.uvc.sensor_mismatch", {motion::msg::verbatim("source", sourceText()),
                                                                     motion::msg::integer("width", now.width(), motion::msg::Unit::None),
                                                                     motion::msg::integer("height", now.height(), motion::msg::Unit::None),
                                                                     motion::msg::integer("plan_width", want.width(), motion::msg::Unit::None),
                                                                     motion::msg::integer("plan_height", want.height(), motion::msg::Unit::None),
                                                                     motion::msg::verbatim("offered", uvcSizesText(m_device))}));
        return false;
    }
    // The stream starts again at the new size: only frames begun after this are the tile's.
    m_camera->setCameraFormat(format);
    m_clock.reset();
    m_requestHostUs = uvcHostNowUs();
    return true;
}

void UvcCamera::capture(const CaptureRequest& request)
{
    if (!m_open && !m_opening) {
        emit failed(request.id, uvcProblem(m_openProblem.value_or(motion::msg::make("camera.not_open", {motion::msg::verbatim("source", sourceText())}))));
        return;
    }
    if (m_waiting) {
        emit failed(request.id, uvcProblem(motion::msg::make("camera.uvc.busy", {motion::msg::verbatim("source", sourceText())})));
        return;
    }
    m_request = request;
    m_requestHostUs = uvcHostNowUs();
    m_waiting = true;
    const double exposureMsNow = std::max(exposureMs(), 0.0);
    m_captureTimer.start(kCaptureTimeoutMs + static_cast<int>(2 * std::min(exposureMsNow, 60000.0)) + (m_opening ? kOpenTimeoutMs : 0));
    if (m_open)
        useFormatFor(request);
}

void UvcCamera::onVideoFrame(const QVideoFrame& frame)
{
    const std::int64_t now = uvcHostNowUs();
    std::lock_guard<std::mutex> lock(m_latestMutex);
    m_latest = frame;  // an older frame not yet picked up is dropped here
    m_latestArrivedUs = now;
    ++m_arrived;
    if (!m_pickUpQueued) {
        m_pickUpQueued = true;
        QMetaObject::invokeMethod(this, &UvcCamera::takeLatest, Qt::QueuedConnection);
    }
}

void UvcCamera::takeLatest()
{
    QVideoFrame frame;
    std::int64_t arrivedUs = 0;
    std::uint64_t sequence = 0;
    {
        std::lock_guard<std::mutex> lock(m_latestMutex);
        frame = m_latest;
        m_latest = QVideoFrame();
        arrivedUs = m_latestArrivedUs;
        sequence = m_arrived;
        m_pickUpQueued = false;
    }
    if (!frame.isValid() || !m_open)
        return;
    const std::int64_t exposureUs = static_cast<std::int64_t>(std::max(0.0, exposureMs()) * 1000.0);
    const std::int64_t startedUs = m_clock.exposureStartHostUs(frame.startTime(), frame.endTime(), arrivedUs, framePeriodUs(), exposureUs);
    const bool forCapture = m_waiting && !m_captureConverting && startedUs >= m_requestHostUs;
    const bool forLive = m_live && !m_liveInFlight;
    if (forCapture || forLive)
        convert(frame, sequence, startedUs, forCapture, forLive);
}

void UvcCamera::convert(const QVideoFrame& frame, std::uint64_t sequence, std::int64_t startedUs, bool forCapture, bool forLive)
{
    if (forCapture)
        m_captureConverting = true;
    if (forLive)
        m_liveInFlight = true;
    const std::uint64_t requestId = forCapture ? m_request.id : 0;
    const double exposure = exposureMs();
    const double gain = m_camera && m_camera->isoSensitivity() > 0 ? m_camera->isoSensitivity() : 0;
    m_pool.start([this, frame, sequence, startedUs, requestId, forCapture, forLive, exposure, gain] {
        auto converted = frameFromVideo(frame);
        if (converted) {
            converted->startedHostUs = startedUs;
            converted->sequence = sequence;
            converted->exposureMs = exposure;
            converted->gain = gain;
        }
        // Back on the camera's thread; the destructor waits for this task.
        QMetaObject::invokeMethod(this, [this, converted, requestId, forCapture, forLive]() mutable {
            if (forCapture)
                m_captureConverting = false;
            deliver(std::move(converted), forCapture && m_waiting && m_request.id == requestId, forLive);
        }, Qt::QueuedConnection);
    });
}

void UvcCamera::deliver(motion::msg::Checked<Frame> frame, bool forCapture, bool forLive)
{
    if (forLive) {
        m_liveInFlight = false;
        if (frame && m_live && m_open) {
            emit liveFrame(*frame);
        } else if (!frame && !m_liveProblemSaid) {
            m_liveProblemSaid = true;  // once: every frame of this format would say the same
            emit failed(0, uvcProblem(frame.error()));
        }
    }
    if (!forCapture)
        return;
    if (!frame) {
        failCapture(frame.error());
        return;
    }
    m_waiting = false;
    m_captureTimer.stop();
    emit captured(m_request.id, *frame);
}

} // namespace dev::camera
