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
#include "device/camera/camera_reading_source.h"

namespace dev::camera {

struct DotReadingOptions : CameraReadingOptions {
    /// The plate's dots: what the finder finds is refused as not one of them when its
    /// diameter is more than a quarter off, or when it lies further from the centre than
    /// half the pitch (a speck of dust, the dark corner of a blank field).
    double platePitchMm = 1.0;
    double dotDiameterMm = 0.1;
};

class DotReadingSource : public CameraReadingSource {
    Q_OBJECT
public:
    /// `camera` is not owned.
    DotReadingSource(Camera* camera, const DotReadingOptions& options, QObject* parent = nullptr);

    motion::msg::Message describe() const override;
    int maxAxes() const override { return 2; }
    /// X and Y of the work point against the dot taken to sit at the stop's targets.
    void take(const dev::jobs::StopContext& stop, TakeDone done) override;

    void setFailedImagesFolder(const QString& folder) { m_options.failedImagesFolder = folder; }
    const DotReadingOptions& options() const { return m_options; }

protected:
    const CameraReadingOptions& cameraOptions() const override { return m_options; }
    dev::jobs::TakeResult readFrame(const Frame& frame) override;

private:
    DotReadingOptions m_options;
};

} // namespace dev::camera
