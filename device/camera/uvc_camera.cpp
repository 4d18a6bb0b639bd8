#include "device/camera/uvc_camera.h"

#include "device/camera/uvc_devices.h"
#include "device/camera/video_frame_convert.h"

#include <QCamera>
#include <QMediaCaptureSession>
#include <QMediaDevices>
#include <QVideoSink>

#include <algorithm>
#include <cmath>

namespace dev::camera {

namespace {

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
    m_feed.setSourceName(sourceText());
    m_openTimer.setSingleShot(true);
    connect(&m_openTimer, &QTimer::timeout, this, [this] {
        failAll(motion::msg::make("camera.uvc.open_timeout", {motion::msg::verbatim("source", sourceText()),
                                                              motion::msg::real("seconds", kOpenTimeoutMs / 1000.0, motion::msg::Unit::S)}));
    });
    connect(&m_feed, &UvcFrameFeed::liveFrame, this, [this](const Frame& f) {
        if (m_open)
            emit liveFrame(f);
    });
    connect(&m_feed, &UvcFrameFeed::captured, this, &Camera::captured);
    connect(&m_feed, &UvcFrameFeed::captureFailed, this, [this](std::uint64_t id, const motion::msg::Message& why) { emit failed(id, uvcProblem(why)); });
    connect(&m_feed, &UvcFrameFeed::liveFailed, this, [this](const motion::msg::Message& why) { emit failed(0, uvcProblem(why)); });
}

UvcCamera::~UvcCamera()
{
    if (m_camera)
        m_camera->stop();  // the streaming thread stops with it: no frame is offered after this
    if (m_sink)
        QObject::disconnect(m_sink.get(), nullptr, this, nullptr);
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
    m_sink = std::make_unique<QVideoSink>();
    m_session = std::make_unique<QMediaCaptureSession>();
    m_session->setCamera(m_camera.get());
    m_session->setVideoSink(m_sink.get());
    applyFormat(format);
    // Direct: frames come on Qt Multimedia's thread; the feed only parks them there.
    UvcFrameFeed* feed = &m_feed;
    connect(m_sink.get(), &QVideoSink::videoFrameChanged, this, [feed](const QVideoFrame& f) { feed->offer(f); }, Qt::DirectConnection);
    connect(m_camera.get(), &QCamera::activeChanged, this, &UvcCamera::onActiveChanged);
    connect(m_camera.get(), &QCamera::errorOccurred, this, [this](QCamera::Error error, const QString& detail) {
        if (error != QCamera::NoError)
            failAll(motion::msg::make("camera.uvc.error", {motion::msg::verbatim("source", sourceText()), motion::msg::verbatim("detail", detail.toStdString())}));
    });
    m_devices = std::make_unique<QMediaDevices>();
    connect(m_devices.get(), &QMediaDevices::videoInputsChanged, this, &UvcCamera::onDevicesChanged);
    m_opening = true;
    m_feed.clear();
    m_openTimer.start(kOpenTimeoutMs);
    m_camera->start();
}

void UvcCamera::applyFormat(const QCameraFormat& format)
{
    m_camera->setCameraFormat(format);
    m_feed.setFramePeriodUs(format.maxFrameRate() > 0 ? static_cast<std::int64_t>(1e6 / format.maxFrameRate()) : 0);
    m_feed.restartStream();
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
    if (m_feed.waiting())
        useFormatFor(m_request);
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
    if (!m_feed.waiting())
        return;
    const std::uint64_t id = m_feed.waitingFor();
    m_feed.cancel();
    emit failed(id, uvcProblem(why));
}

void UvcCamera::failAll(const motion::msg::Message& why)
{
    const bool wasOpen = m_open;
    m_openProblem = why;  // a capture asked after this says why, not just "not open"
    failCapture(why);
    teardown();
    emit failed(0, uvcProblem(why));
    if (wasOpen)
        emit closed();
}

void UvcCamera::teardown()
{
    m_openTimer.stop();
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
    m_feed.clear();
    m_opening = false;
    m_open = false;
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
    m_feed.setLive(true);
}

void UvcCamera::stopLive() { m_feed.setLive(false); }

void UvcCamera::setExposureMs(double ms)
{
    m_exposureMs = std::max(0.0, ms);
    m_feed.setExposureMs(m_exposureMs);
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
    m_feed.setGain(m_gain);
    if (!m_camera || !m_camera->supportedFeatures().testFlag(QCamera::Feature::IsoSensitivity))
        return;
    if (m_gain > 0) {
        const int lo = m_camera->minimumIsoSensitivity(), hi = std::max(lo, m_camera->maximumIsoSensitivity());
        m_camera->setManualIsoSensitivity(std::clamp(static_cast<int>(std::lround(m_gain)), lo, hi));
    } else {
        m_camera->setAutoIsoSensitivity();
    }
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
    applyFormat(format);
    return true;
}

void UvcCamera::capture(const CaptureRequest& request)
{
    if (!m_open && !m_opening) {
        emit failed(request.id, uvcProblem(m_openProblem.value_or(motion::msg::make("camera.not_open", {motion::msg::verbatim("source", sourceText())}))));
        return;
    }
    if (m_feed.waiting()) {
        emit failed(request.id, uvcProblem(motion::msg::make("camera.uvc.busy", {motion::msg::verbatim("source", sourceText())})));
        return;
    }
    m_request = request;
    const double exposure = std::clamp(exposureMs(), 0.0, 60000.0);
    m_feed.waitForFrame(request.id, kCaptureTimeoutMs + static_cast<int>(2 * exposure) + (m_opening ? kOpenTimeoutMs : 0));
    if (m_open)
        useFormatFor(request);
}

} // namespace dev::camera
