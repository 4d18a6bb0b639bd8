#pragma once
// The camera as the accuracy bench's reading source: at each stop the microscope's camera
// looks at a glass line scale lying along the axis, finds the graduation line nearest the
// image centre to a fraction of a pixel (imaging/line_finder.h: a profile fit, no
// threshold), and reports where the work point truly is: that graduation's nominal
// position less the line's offset from the image centre.
//
// What the camera cannot know by itself: its pixel size (from the camera profile) scales
// only the small offset of the line from the centre, so an error in it costs a fraction
// of a micrometre; the scale's own pitch is what the readings are measured against, and
// its calibration certificate, when one is loaded, says where each graduation truly lies.
//
// A stop where no line, or two, can be told is that reading's failure, named with the
// finder's reason; the image is kept beside the run as reading-NNN.tif so a person can
// see why. One axis a reading (X or Y).
#include "device/camera/camera_reading_source.h"
#include "motion/metrology/linear/scale_certificate.h"

#include <optional>

namespace dev::camera {

struct ScaleReadingOptions : CameraReadingOptions {
    double graduationMm = 0.1;        ///< the scale's pitch
    /// The scale's calibration certificate: each graduation read is taken at its
    /// certified place (nominal + deviation) instead of its nominal one.
    std::optional<motion::metrology::ScaleCertificate> certificate;
};

class ScaleReadingSource : public CameraReadingSource {
    Q_OBJECT
public:
    /// `camera` is not owned.
    ScaleReadingSource(Camera* camera, const ScaleReadingOptions& options, QObject* parent = nullptr);

    motion::msg::Message describe() const override;
    void take(const dev::jobs::StopContext& stop, TakeDone done) override;

    void setFailedImagesFolder(const QString& folder) { m_options.failedImagesFolder = folder; }
    /// Where the line the last good reading found sat, px from the centre (for tests and the screen).
    double lastOffsetPx() const { return m_lastOffsetPx; }

protected:
    const CameraReadingOptions& cameraOptions() const override { return m_options; }
    dev::jobs::TakeResult readFrame(const Frame& frame) override;

private:
    /// The nominal position (mm) of the graduation line found `offsetPx` from the centre.
    double graduationOf(const Frame& frame, bool vertical, double offsetPx, double mmPerPx) const;

    ScaleReadingOptions m_options;
    double m_lastOffsetPx = 0;
};

} // namespace dev::camera
