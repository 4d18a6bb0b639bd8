#include "device/camera/sim_camera.h"

#include <QPointer>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace dev::camera {

namespace {
/// The live view's fastest pace: a person sees no difference above 30 frames a second.
constexpr int kSimLiveMinPeriodMs = 33;
constexpr double kSimMaxExposureMs = 60000;
/// How often a live view with no simulated stage looks again.
constexpr int kSimLiveRetryMs = 1000;

std::int64_t hostNowUs()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

SimCamera::SimCamera(WorkPointSource workPoint, const SimCameraSettings& settings, QObject* parent)
    : Camera(parent), m_workPoint(std::move(workPoint)), m_settings(settings)
{
    m_pool.setMaxThreadCount(1);
    m_liveTimer.setSingleShot(true);
    connect(&m_liveTimer, &QTimer::timeout, this, [this] {
        if (!m_live || m_liveInFlight)
            return;
        const auto at = m_workPoint ? m_workPoint() : std::nullopt;
        if (!at) {
            // Said once, then looked for again now and then: the picture comes back by
            // itself once a simulator is connected.
            if (!m_liveWithoutStage)
                emit failed(0, motion::msg::Problem("", motion::msg::make("camera.sim.no_stage")));
            m_liveWithoutStage = true;
            m_liveTimer.start(kSimLiveRetryMs);
            return;
        }
        m_liveWithoutStage = false;
        renderAsync(*at, m_settings.geometry, 0, true);
    });
}

SimCamera::~SimCamera() { m_pool.waitForDone(); }

Capabilities SimCamera::capabilities() const
{
    Capabilities c;
    c.live = true;
    c.exposure = true;
    return c;
}

void SimCamera::open()
{
    if (!m_open) {
        m_open = true;
        // The specimen's tables take a moment: built on the worker, and every render
        // waits for them there (the caller never does).
        auto promise = std::make_shared<std::promise<std::shared_ptr<const Specimen>>>();
        m_specimen = promise->get_future().share();
        const SimCameraSettings s = m_settings;
        m_pool.start([promise, s] { promise->set_value(std::make_shared<const Specimen>(s.specimen, s.seed, s.blurUm)); });
    }
    emit opened();
}

void SimCamera::close()
{
    if (!m_open)
        return;
    stopLive();
    m_open = false;
    emit closed();
}

void SimCamera::startLive()
{
    if (!m_open)
        open();
    m_live = true;
    scheduleLive();
}

void SimCamera::stopLive()
{
    m_live = false;
    m_liveWithoutStage = false;
    m_liveTimer.stop();
}

void SimCamera::scheduleLive()
{
    if (m_live && !m_liveInFlight && !m_liveTimer.isActive())
        m_liveTimer.start(std::max(kSimLiveMinPeriodMs, static_cast<int>(m_settings.exposureMs)));
}

void SimCamera::setExposureMs(double ms) { m_settings.exposureMs = std::clamp(ms, 0.0, kSimMaxExposureMs); }

void SimCamera::capture(const CaptureRequest& request)
{
    if (!m_open) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.not_open", {motion::msg::verbatim("source", source().toStdString())})));
        return;
    }
    // The exposure starts now: the work point is where the stage is at this moment.
    const auto at = m_workPoint ? m_workPoint() : std::nullopt;
    if (!at) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.sim.no_stage")));
        return;
    }
    renderAsync(*at, request.geometry.value_or(m_settings.geometry), request.id, false);
}

void SimCamera::renderAsync(const WorkPoint& at, const CameraGeometry& geometry, std::uint64_t requestId, bool live)
{
    if (live)
        m_liveInFlight = true;
    const std::int64_t startedUs = hostNowUs();
    const auto specimen = m_specimen;
    const SimOptics optics = m_settings.optics;
    const double exposureMs = m_settings.exposureMs;
    const std::uint64_t seed = m_settings.seed;
    const SimTrueGeometry trueGeometry = m_settings.trueGeometry;
    const std::uint64_t sequence = ++m_sequence;
    m_pool.start([this, specimen, optics, geometry, trueGeometry, at, exposureMs, seed, sequence, startedUs, requestId, live] {
        Frame f = renderSimFrame(*specimen.get(), trueGeometryOf(geometry, trueGeometry), optics, at.xMm, at.yMm, exposureMs, seed);
        f.pixelUm = geometry.pixelUm;  // the camera says what it was asked to be, as a real one would
        f.startedHostUs = startedUs;
        f.deviceTimeUs = at.deviceTimeUs;
        f.sequence = sequence;
        // Back on the camera's thread; the destructor waits for this task, and a queued
        // call to a deleted object is dropped with it.
        // Shared, not copied, on its way to the signal: a 2048² frame is 8 MB.
        auto shared = std::make_shared<const Frame>(std::move(f));
        QMetaObject::invokeMethod(this, [this, shared, requestId, live, startedUs] {
            // The frame is handed over no earlier than its exposure would have ended.
            const auto leftMs = static_cast<int>(std::ceil(shared->exposureMs - static_cast<double>(hostNowUs() - startedUs) / 1000.0));
            auto deliver = [this, shared, requestId, live] {
                const Frame& frame = *shared;
                if (live) {
                    m_liveInFlight = false;
                    if (m_live && m_open)
                        emit liveFrame(frame);
                    scheduleLive();
                } else if (m_open) {
                    emit captured(requestId, frame);
                } else {
                    emit failed(requestId, motion::msg::Problem("", motion::msg::make("camera.closed_during_capture", {motion::msg::verbatim("source", source().toStdString())})));
                }
            };
            if (leftMs > 0)
                QTimer::singleShot(leftMs, Qt::PreciseTimer, this, deliver);
            else
                deliver();
        }, Qt::QueuedConnection);
    });
}

} // namespace dev::camera
