#pragma once
// What every reading the microscope's camera takes for the accuracy bench shares,
// whatever it looks at (a grid plate's dots, a glass scale's lines): one capture a take,
// placed where the stop is; a camera silent for the timeout fails the reading; a cancel
// drops the capture the take waited for, and a frame that still comes for it is let be;
// an image the reading cannot use is kept beside the run, so a person can see why.
//
// A source of its own says which stops it reads and where the capture stands (take),
// and what a frame says (readFrame); everything else is here.
#include "device/camera/camera.h"
#include "device/camera/camera_geometry.h"
#include "device/jobs/accuracy/reading_source.h"
#include "imaging/image.h"

#include <QTimer>

#include <cstdint>
#include <string>

namespace dev::camera {

/// The options every camera reading has; a source's own options add to them.
struct CameraReadingOptions {
    CameraGeometry geometry;          ///< the camera profile: pixel size, rotation, image y
    QString failedImagesFolder;       ///< where a failed reading's image goes ("": not kept)
    int timeoutMs = 30000;            ///< a camera silent this long fails the reading
};

/// The frame as 16-bit grey: 8-bit stretched to the same range, colour by its luminance.
imaging::ImageU16 frameToGreyU16(const Frame& frame);

class CameraReadingSource : public dev::jobs::ReadingSource {
    Q_OBJECT
public:
    dev::jobs::ReadingKind kind() const override { return dev::jobs::ReadingKind::Camera; }
    void open(OpenDone done) override;
    void cancel() override;

protected:
    /// `camera` is not owned.
    CameraReadingSource(Camera* camera, QObject* parent);

    /// The options the source was made with (the source of its own holds them).
    virtual const CameraReadingOptions& cameraOptions() const = 0;
    /// What the frame captured for the current take says: its values, or why it has none.
    virtual dev::jobs::TakeResult readFrame(const Frame& frame) = 0;

    /// Captures with the stage at (xMm, yMm) for `stop`; `done` is answered with what
    /// readFrame makes of the frame, or with the camera's failure or silence.
    void startCapture(const dev::jobs::StopContext& stop, TakeDone done, double xMm, double yMm);
    /// The stop of the current (or last) take.
    const dev::jobs::StopContext& currentStop() const { return m_stop; }
    Camera* camera() const { return m_camera; }
    std::string cameraName() const;
    /// Keeps a frame the reading could not use as STEM-NNN.tif (the stop's number) in the
    /// failed-images folder, and says so: `keptId` {cause: why, file}. `why` as it is when
    /// there is no folder or the image could not be written.
    motion::msg::Message keepFailedImage(const Frame& frame, const char* stem, const motion::msg::Message& why, const char* keptId) const;

private:
    void onCaptured(std::uint64_t id, const Frame& frame);
    void onFailed(std::uint64_t id, const motion::msg::Problem& problem);
    void finish(const dev::jobs::TakeResult& result);

    Camera* m_camera;
    QTimer m_timeout;
    std::uint64_t m_nextId = 1;
    std::uint64_t m_waitingId = 0;    ///< the capture a take waits for; 0: none
    dev::jobs::StopContext m_stop;
    TakeDone m_done;
    OpenDone m_openDone;
};

} // namespace dev::camera
