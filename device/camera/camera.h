#pragma once
// The camera interface: every image source (the simulated camera, a USB camera through
// Qt Multimedia, an operator's capture command, a camera's own software writing into a
// folder) is one of these, so the scan, the live view and the CLI take any of them.
//
// Contract:
// - Everything is asynchronous and answered on the object's thread: open() ends in
//   opened() or failed(); capture() ends in captured() or failed() carrying the same
//   request id; nothing blocks the caller.
// - capture() takes the next frame whose exposure STARTS after the call (a frame that
//   was already being exposed when the stage settled is never used for a tile).
// - Live frames are for looking at: a slow consumer misses frames (liveFrame is sent
//   only when the previous one was taken), it never builds a queue.
// - failed() carries a problem whose message names the source and what went wrong
//   (and, for a command, its own stderr); after a capture fails, the tile is not taken.
#include "device/camera/camera_geometry.h"
#include "device/camera/frame.h"
#include "motion/problem.h"

#include <QObject>
#include <QString>

#include <optional>
#include <string>

namespace dev::camera {

/// What a source can do, so a screen offers only what works.
struct Capabilities {
    bool live = false;            ///< frames without a capture request (a preview)
    bool exposure = false;        ///< setExposureMs() changes the exposure
    bool gain = false;            ///< setGain() changes the gain
    bool needsTriggerOutput = false;  ///< capture() waits for an image fired by the stage's trigger output
};

/// What a capture is for: where the stage stood and, for sources that write files, the
/// name to give it. Sources that make pixels ignore `fileHint`.
struct CaptureRequest {
    std::uint64_t id = 0;
    int tile = -1;                ///< -1: a snap, not a scan tile
    double xMm = 0, yMm = 0;      ///< the stage's measured position when asked
    std::string fileHint;         ///< absolute path a command may be told to write ({file})
    /// The scan plan's camera, in a scan: the simulated camera renders with it, a real
    /// one refuses a tile when its sensor is not this size. Empty: the source's own.
    std::optional<CameraGeometry> geometry;
};

class Camera : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Camera() override = default;

    /// "sim", "uvc:Logitech BRIO", "command:gphoto2 …", "folder:/data/in": what the
    /// operator chose, as they would type it.
    virtual QString source() const = 0;
    virtual Capabilities capabilities() const = 0;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;

    virtual void startLive() {}
    virtual void stopLive() {}

    virtual void setExposureMs(double ms) = 0;
    virtual double exposureMs() const = 0;
    virtual void setGain(double) {}

    /// Takes one image for `request` (see the contract above).
    virtual void capture(const CaptureRequest& request) = 0;

signals:
    void opened();
    void closed();
    void liveFrame(const dev::camera::Frame& frame);
    void captured(std::uint64_t requestId, const dev::camera::Frame& frame);
    void failed(std::uint64_t requestId, const motion::msg::Problem& problem);  ///< requestId 0: not a capture (open, live)
};

} // namespace dev::camera
