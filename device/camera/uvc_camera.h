#pragma once
// uvc[:NAME] — a USB (UVC) camera through Qt Multimedia: QCamera → QMediaCaptureSession →
// QVideoSink. NAME picks the camera and, optionally, its resolution (uvc_devices.h).
//
// - Resolution: the largest the camera offers in a format BenchPilot converts, or the one
//   asked with "@WxH"; a scan tile asks for its plan's sensor size, the camera switches to
//   the format of that size, and a camera without one refuses the tile naming both sizes.
// - Exposure and gain: set where the camera offers them (ManualExposureTime, and
//   IsoSensitivity as the gain); capabilities() says so once the camera is open.
// - Live frames: the newest frame is kept, older ones dropped; it is converted on the
//   camera's worker only when the previous live frame was delivered (camera.h's contract).
// - capture(): the next frame whose exposure started after the call (uvc_frame_clock.h),
//   within kCaptureTimeoutMs plus twice the exposure; otherwise camera.uvc.timeout.
// - An error from the camera, or the camera leaving the system's list (unplugged), fails
//   the open, the capture in flight and the live view with the reason, and closes it.
//
// Threads: the object lives on the GUI (or CLI) thread. Qt Multimedia hands frames over on
// its own streaming thread: they are parked in one slot under a mutex and picked up by a
// queued call here; the conversion runs on the camera's single worker thread and comes back
// queued. The destructor stops the camera and waits for a conversion in flight.
#include "device/camera/camera.h"
#include "device/camera/uvc_frame_clock.h"
#include "motion/checked.h"

#include <QCameraDevice>
#include <QThreadPool>
#include <QTimer>
#include <QVideoFrame>

#include <memory>
#include <mutex>

class QCamera;
class QMediaCaptureSession;
class QMediaDevices;
class QVideoSink;

namespace dev::camera {

class UvcCamera : public Camera {
    Q_OBJECT
public:
    static constexpr int kOpenTimeoutMs = 10000;
    static constexpr int kCaptureTimeoutMs = 5000;

    /// `name`: what follows "uvc:" ("" = the default camera).
    explicit UvcCamera(const QString& name, QObject* parent = nullptr);
    ~UvcCamera() override;

    QString source() const override;
    Capabilities capabilities() const override;
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void startLive() override;
    void stopLive() override;
    void setExposureMs(double ms) override;
    double exposureMs() const override;
    void setGain(double gain) override;
    void capture(const CaptureRequest& request) override;

    /// The camera found for the name (null until open() found it).
    QCameraDevice device() const { return m_device; }

private:
    void onActiveChanged(bool active);
    void onCameraError(const QString& detail);
    void onDevicesChanged();
    void onVideoFrame(const QVideoFrame& frame);  ///< Qt Multimedia's thread
    void takeLatest();                            ///< the camera's thread
    void convert(const QVideoFrame& frame, std::uint64_t sequence, std::int64_t startedUs, bool forCapture, bool forLive);
    void deliver(motion::msg::Checked<Frame> frame, bool forCapture, bool forLive);
    bool useFormatFor(const CaptureRequest& request);
    void failCapture(const motion::msg::Message& why);
    void failAll(const motion::msg::Message& why);
    void teardown();
    std::string sourceText() const { return source().toStdString(); }
    std::int64_t framePeriodUs() const;

    QString m_name;
    QCameraDevice m_device;
    std::unique_ptr<QMediaDevices> m_devices;
    std::unique_ptr<QMediaCaptureSession> m_session;
    std::unique_ptr<QCamera> m_camera;
    std::unique_ptr<QVideoSink> m_sink;
    std::optional<motion::msg::Message> m_openProblem;  ///< why the last open failed: a capture after it says so
    bool m_opening = false;
    bool m_open = false;
    bool m_live = false;
    bool m_liveInFlight = false;
    bool m_liveProblemSaid = false;
    double m_exposureMs = 0;  ///< as set; 0 = the camera's own automatic exposure
    double m_gain = 0;
    QTimer m_openTimer;

    // The capture waiting for its frame.
    bool m_waiting = false;
    bool m_captureConverting = false;
    CaptureRequest m_request;
    std::int64_t m_requestHostUs = 0;
    QTimer m_captureTimer;

    UvcFrameClock m_clock;
    QThreadPool m_pool;  ///< one thread: conversions in the order the frames came

    // Filled on Qt Multimedia's thread, emptied on the camera's.
    std::mutex m_latestMutex;
    QVideoFrame m_latest;
    std::int64_t m_latestArrivedUs = 0;
    std::uint64_t m_arrived = 0;  ///< every frame that came, taken or dropped: Frame::sequence
    bool m_pickUpQueued = false;
};

} // namespace dev::camera
