#include "device/camera/dot_reading_source.h"

#include "imaging/dot_finder.h"

#include <cmath>

namespace dev::camera {

DotReadingSource::DotReadingSource(Camera* camera, const DotReadingOptions& options, QObject* parent)
    : CameraReadingSource(camera, parent), m_options(options)
{
}

motion::msg::Message DotReadingSource::describe() const
{
    return motion::msg::make("accuracy.source.camera_plate", {motion::msg::verbatim("camera", cameraName())});
}

void DotReadingSource::take(const dev::jobs::StopContext& stop, TakeDone done)
{
    if (stop.targetsMm.size() != 2) {
        done({{}, false, motion::msg::make("camera.reading.two_axes", {motion::msg::verbatim("camera", cameraName())})});
        return;
    }
    startCapture(stop, std::move(done), stop.targetsMm[0], stop.targetsMm[1]);
}

dev::jobs::TakeResult DotReadingSource::readFrame(const Frame& frame)
{
    imaging::DotFinderOptions o;
    o.polarity = imaging::Polarity::Dark;  // chrome dots on glass, in transmitted light
    const auto found = imaging::findDot(frameToGreyU16(frame), o);
    double exX = 0, exY = 0, eyX = 0, eyY = 0;
    m_options.geometry.axes(&exX, &exY, &eyX, &eyY);
    motion::msg::Message notPlate;
    if (found) {
        const double mmPerPx = m_options.geometry.pixelUm * 1e-3;
        const double diameterMm = found->diameterPx * mmPerPx;
        const double offMm = std::hypot(found->xPx, found->yPx) * mmPerPx;
        if (std::fabs(diameterMm - m_options.dotDiameterMm) > 0.25 * m_options.dotDiameterMm)
            notPlate = motion::msg::make("camera.reading.dot_size", {motion::msg::real("diameter", diameterMm * 1e3, motion::msg::Unit::Um),
                                                                     motion::msg::real("expected", m_options.dotDiameterMm * 1e3, motion::msg::Unit::Um)});
        else if (offMm > 0.5 * m_options.platePitchMm)
            notPlate = motion::msg::make("camera.reading.dot_far", {motion::msg::real("distance", offMm, motion::msg::Unit::Mm),
                                                                    motion::msg::real("max", 0.5 * m_options.platePitchMm, motion::msg::Unit::Mm)});
    }
    if (!found || !notPlate.empty())
        return {{}, false, keepFailedImage(frame, "node", found ? notPlate : found.error(), "camera.reading.no_dot")};
    // The dot sits off the work point by its pixel offset along the image's axes; the
    // work point is therefore that much the other way of the dot's nominal place.
    const double dotFromCentreXMm = found->xPx * exX + found->yPx * eyX;
    const double dotFromCentreYMm = found->xPx * exY + found->yPx * eyY;
    dev::jobs::TakeResult r;
    r.valuesMm = {currentStop().targetsMm[0] - dotFromCentreXMm, currentStop().targetsMm[1] - dotFromCentreYMm};
    return r;
}

} // namespace dev::camera
