#pragma once
// uvc[:NAME] — a USB (UVC) camera through Qt Multimedia: QCamera → QMediaCaptureSession →
// QVideoSink. NAME picks the camera and, optionally, its resolution (uvc_devices.h).
//
// - Resolution: the largest the camera offers in a format BenchPilot converts, or the one
//   asked with "@WxH"; a scan tile asks for its plan's sensor size, the camera switches to
//   the format of that size, and a camera without one refuses the tile naming both sizes.
// - Exposure and gain: set where the camera offers them (ManualExposureTime, and
//   IsoSensitivity as the gain); capabilities() says so once the camera is open.
// - Frames: the newest is kept, older ones dropped; live frames and the capture's frame
//   (the next whose exposure started after the call, within kCaptureTimeoutMs plus twice
//   the exposure) are converted off this thread (uvc_frame_feed.h).
// - An error from the camera, or the camera leaving the system's list (unplugged), fails
//   the open, the capture in flight and the live view with the reason, and closes it.
//
// Threads: the object lives on the GUI (or CLI) thread; Qt Multimedia hands frames over on
// its own streaming thread, straight to the feed. The destructor stops the camera first.
#include "device/camera/camera.h"
#include "device/camera/uvc_frame_feed.h"

#include <QCameraDevice>
#include <QTimer>

#include <memory>

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
    void onDevicesChanged();
    bool useFormatFor(const CaptureRequest& request);
    void failCapture(const motion::msg::Message& why);
    void failAll(const motion::msg::Message& why);
    void teardown();
    void applyFormat(const QCameraFormat& format);
    std::string sourceText() const { return source().toStdString(); }

    QString m_name;
    QCameraDevice m_device;
    std::unique_ptr<QMediaDevices> m_devices;
    std::unique_ptr<QMediaCaptureSession> m_session;
    std::unique_ptr<QCamera> m_camera;
    std::unique_ptr<QVideoSink> m_sink;
    UvcFrameFeed m_feed;
    std::optional<motion::msg::Message> m_openProblem;  ///< why the camera failed to open or was lost: a capture after it says so
    bool m_opening = false;
    bool m_open = false;
    double m_exposureMs = 0;  ///< as set; 0 = the camera's own automatic exposure
    double m_gain = 0;
    QTimer m_openTimer;
    CaptureRequest m_request;  ///< the capture waiting (m_feed.waiting())
};

} // namespace dev::camera
