#include "device/camera/uvc_frame_feed.h"

#include "device/camera/video_frame_convert.h"

#include <algorithm>
#include <chrono>

namespace dev::camera {

namespace {

std::int64_t feedHostNowUs()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

UvcFrameFeed::UvcFrameFeed(QObject* parent) : QObject(parent), m_nowUs(&feedHostNowUs)
{
    m_pool.setMaxThreadCount(1);
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        if (!m_waiting)
            return;
        m_waiting = false;
        emit captureFailed(m_requestId, motion::msg::make("camera.uvc.timeout", {motion::msg::verbatim("source", m_source),
                                                                                 motion::msg::real("seconds", m_timeout.interval() / 1000.0, motion::msg::Unit::S)}));
    });
}

UvcFrameFeed::~UvcFrameFeed() { m_pool.waitForDone(); }

void UvcFrameFeed::offer(const QVideoFrame& frame)
{
    const std::int64_t now = m_nowUs();
    std::lock_guard<std::mutex> lock(m_latestMutex);
    m_latest = frame;  // an older frame not yet picked up is dropped here
    m_latestArrivedUs = now;
    ++m_arrived;
    if (!m_pickUpQueued) {
        m_pickUpQueued = true;
        QMetaObject::invokeMethod(this, &UvcFrameFeed::takeLatest, Qt::QueuedConnection);
    }
}

void UvcFrameFeed::setLive(bool on)
{
    if (on && !m_live)
        m_liveProblemSaid = false;
    m_live = on;
}

void UvcFrameFeed::waitForFrame(std::uint64_t requestId, int timeoutMs)
{
    m_requestId = requestId;
    m_requestHostUs = m_nowUs();
    m_waiting = true;
    m_timeout.start(std::max(1, timeoutMs));
}

void UvcFrameFeed::cancel()
{
    m_waiting = false;
    m_timeout.stop();
}

void UvcFrameFeed::restartStream()
{
    m_clock.reset();
    if (m_waiting)
        m_requestHostUs = m_nowUs();
}

void UvcFrameFeed::clear()
{
    std::lock_guard<std::mutex> lock(m_latestMutex);
    m_latest = QVideoFrame();
    m_clock.reset();
}

void UvcFrameFeed::takeLatest()
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
    if (!frame.isValid())
        return;
    const auto exposureUs = static_cast<std::int64_t>(std::max(0.0, m_exposureMs) * 1000.0);
    const std::int64_t startedUs = m_clock.exposureStartHostUs(frame.startTime(), frame.endTime(), arrivedUs, m_framePeriodUs, exposureUs);
    const bool forCapture = m_waiting && !m_captureConverting && startedUs >= m_requestHostUs;
    const bool forLive = m_live && !m_liveInFlight;
    if (!forCapture && !forLive)
        return;  // nobody wants it: dropped unconverted
    if (forCapture)
        m_captureConverting = true;
    if (forLive)
        m_liveInFlight = true;
    const std::uint64_t requestId = forCapture ? m_requestId : 0;
    const double exposureMs = m_exposureMs, gain = m_gain;
    m_pool.start([this, frame, sequence, startedUs, forCapture, requestId, forLive, exposureMs, gain] {
        auto converted = frameFromVideo(frame);
        if (converted) {
            converted->startedHostUs = startedUs;
            converted->sequence = sequence;
            converted->exposureMs = exposureMs;
            converted->gain = gain;
        }
        // Back on the feed's thread; the destructor waits for this task.
        QMetaObject::invokeMethod(this, [this, converted, forCapture, requestId, forLive]() mutable { deliver(std::move(converted), forCapture, requestId, forLive); },
                                  Qt::QueuedConnection);
    });
}

void UvcFrameFeed::deliver(motion::msg::Checked<Frame> frame, bool forCapture, std::uint64_t requestId, bool forLive)
{
    if (forLive) {
        m_liveInFlight = false;
        if (frame && m_live) {
            emit liveFrame(*frame);
        } else if (!frame && m_live && !m_liveProblemSaid) {
            m_liveProblemSaid = true;  // once: every frame of this format would say the same
            emit liveFailed(frame.error());
        }
    }
    if (!forCapture)
        return;
    m_captureConverting = false;
    // The capture may have timed out, or been cancelled and another asked, meanwhile.
    if (!m_waiting || m_requestId != requestId)
        return;
    m_waiting = false;
    m_timeout.stop();
    if (frame)
        emit captured(requestId, *frame);
    else
        emit captureFailed(requestId, frame.error());
}

} // namespace dev::camera
