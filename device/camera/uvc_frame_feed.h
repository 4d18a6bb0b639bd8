#pragma once
// What a USB camera does with its frames, apart from the camera itself (so it is tested with
// synthetic frames, uvc_camera.h is the glue to QCamera):
// - offer() parks the newest frame in one slot (an older one not yet picked up is dropped:
//   a slow consumer never builds a queue) and asks the feed's thread to pick it up;
// - a picked-up frame is converted on the feed's single worker thread only when someone
//   wants it: the live view, when the previous live frame was delivered, or the capture
//   waiting, when the frame's exposure started after the capture was asked (uvc_frame_clock.h);
// - a capture that gets no such frame within its timeout fails with camera.uvc.timeout.
//
// Threads: offer() from any thread (Qt Multimedia's streaming thread); everything else, and
// every signal, on the feed's thread. The destructor waits for a conversion in flight.
#include "device/camera/frame.h"
#include "device/camera/uvc_frame_clock.h"
#include "motion/checked.h"

#include <QObject>
#include <QThreadPool>
#include <QTimer>
#include <QVideoFrame>

#include <functional>
#include <mutex>

namespace dev::camera {

class UvcFrameFeed : public QObject {
    Q_OBJECT
public:
    explicit UvcFrameFeed(QObject* parent = nullptr);
    ~UvcFrameFeed() override;

    /// The source as the operator named it, for the messages ("uvc:HD Webcam").
    void setSourceName(const std::string& source) { m_source = source; }
    /// What the frames are said to have been taken with.
    void setExposureMs(double ms) { m_exposureMs = ms; }
    void setGain(double gain) { m_gain = gain; }
    /// The format's frame period, for frames that do not say their own (0: not known).
    void setFramePeriodUs(std::int64_t us) { m_framePeriodUs = us; }

    /// The host's steady clock in µs (the default); a test gives its own to place frames.
    void setHostClock(std::function<std::int64_t()> nowUs) { m_nowUs = std::move(nowUs); }

    /// Any thread: the camera's newest frame.
    void offer(const QVideoFrame& frame);

    void setLive(bool on);
    bool live() const { return m_live; }

    /// Answers `requestId` with the next frame whose exposure starts from now on
    /// (captured), or fails it (captureFailed) after `timeoutMs` or when that frame cannot
    /// be converted. One at a time: the caller refuses a second while waiting().
    void waitForFrame(std::uint64_t requestId, int timeoutMs);
    bool waiting() const { return m_waiting; }
    std::uint64_t waitingFor() const { return m_waiting ? m_requestId : 0; }
    /// Stops waiting without an answer (the caller gives it).
    void cancel();
    /// The stream started again (a new format): its clock is learnt anew, and a capture
    /// waiting takes only frames begun from now on.
    void restartStream();
    /// Forgets a frame not yet picked up and the stream's clock (the camera stopped).
    void clear();

signals:
    void liveFrame(const dev::camera::Frame& frame);
    void captured(std::uint64_t requestId, const dev::camera::Frame& frame);
    void captureFailed(std::uint64_t requestId, const motion::msg::Message& why);
    /// Live frames cannot be converted: said once each time live starts.
    void liveFailed(const motion::msg::Message& why);

private:
    void takeLatest();
    void deliver(motion::msg::Checked<Frame> frame, bool forCapture, std::uint64_t requestId, bool forLive);

    std::function<std::int64_t()> m_nowUs;
    std::string m_source = "uvc";
    double m_exposureMs = 0;
    double m_gain = 0;
    std::int64_t m_framePeriodUs = 0;
    bool m_live = false;
    bool m_liveInFlight = false;
    bool m_liveProblemSaid = false;

    bool m_waiting = false;
    bool m_captureConverting = false;
    std::uint64_t m_requestId = 0;
    std::int64_t m_requestHostUs = 0;
    QTimer m_timeout;

    UvcFrameClock m_clock;
    QThreadPool m_pool;  ///< one thread: conversions in the order the frames came

    // Filled by offer() on any thread, emptied by takeLatest() on the feed's.
    std::mutex m_latestMutex;
    QVideoFrame m_latest;
    std::int64_t m_latestArrivedUs = 0;
    std::uint64_t m_arrived = 0;  ///< every frame offered, taken or dropped: Frame::sequence
    bool m_pickUpQueued = false;
};

} // namespace dev::camera
