#pragma once
// The camera reading a grid plate for a grid map: at each node the stage stands at, the
// microscope's camera finds the plate's dot nearest the image centre to a fraction of a
// pixel (imaging/dot_finder.h) and reports where the work point truly is against the
// plate: the node's nominal position (the dot's) less the dot's offset from the image
// centre, X and Y in one reading.
//
// What the camera cannot know by itself: its pixel size (from the camera profile) scales
// only the dot's small offset from the centre; the plate's certified pitch is what the
// map is measured against, so a pixel size calibrated by moving this same stage costs the
// map nothing of its scale (the scale comes from the plate, not from the pixels).
//
// A node where no dot, or two equally near, can be told is that reading's failure, named
// with the finder's reason, and so is one that is not the plate's (its size is not the
// plate's dots', or it is further off the centre than half the plate's pitch); the image is
// kept beside the run as node-NNN.tif.
#include "device/camera/camera.h"
#include "device/camera/camera_geometry.h"
#include "device/jobs/accuracy/reading_source.h"

#include <QTimer>

#include <cstdint>

namespace dev::camera {

struct DotReadingOptions {
    CameraGeometry geometry;          ///< the camera profile: pixel size, rotation, image y
    QString failedImagesFolder;       ///< where a failed reading's image goes ("": not kept)
    /// The plate's dots: what the finder finds is refused as not one of them when its
    /// diameter is more than a quarter off, or when it lies further from the centre than
    /// half the pitch (a speck of dust, the dark corner of a blank field).
    double platePitchMm = 1.0;
    double dotDiameterMm = 0.1;
    int timeoutMs = 30000;            ///< a camera silent this long fails the reading
};

class DotReadingSource : public dev::jobs::ReadingSource {
    Q_OBJECT
public:
    /// `camera` is not owned.
    DotReadingSource(Camera* camera, const DotReadingOptions& options, QObject* parent = nullptr);

    dev::jobs::ReadingKind kind() const override { return dev::jobs::ReadingKind::Camera; }
    motion::msg::Message describe() const override;
    int maxAxes() const override { return 2; }
    void open(OpenDone done) override;
    /// X and Y of the work point against the dot taken to sit at the stop's targets.
    void take(const dev::jobs::StopContext& stop, TakeDone done) override;
    void cancel() override;

    void setFailedImagesFolder(const QString& folder) { m_options.failedImagesFolder = folder; }
    const DotReadingOptions& options() const { return m_options; }

private:
    void onCaptured(std::uint64_t id, const Frame& frame);
    void onFailed(std::uint64_t id, const motion::msg::Problem& problem);
    void finish(const dev::jobs::TakeResult& result);

    Camera* m_camera;
    DotReadingOptions m_options;
    QTimer m_timeout;
    std::uint64_t m_nextId = 1;
    std::uint64_t m_waitingId = 0;    ///< the capture a take waits for; 0: none
    dev::jobs::StopContext m_stop;
    TakeDone m_done;
    OpenDone m_openDone;
};

} // namespace dev::camera
