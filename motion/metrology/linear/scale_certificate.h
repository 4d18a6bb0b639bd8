#pragma once
// A glass line scale's calibration certificate: at each graduation the laboratory
// measured, how far the line truly lies from its nominal place (deviation = true −
// nominal, µm). Between the certified graduations the deviation is interpolated
// linearly; outside them it is held at the nearest one's. Applied to a camera's reading
// of the scale, the reading becomes the graduation's certified place less the line's
// offset from the image centre (device/camera/scale_reading_source.h).
// Plain C++; no Qt.
#include <vector>

namespace motion::metrology {

struct ScaleCertificate {
    std::vector<double> graduationMm;  ///< increasing, on the scale's pitch
    std::vector<double> deviationUm;   ///< true − nominal at each

    /// The deviation at `mm` (µm): interpolated, held at the ends; 0 for an empty certificate.
    double deviationAtUm(double mm) const;
};

} // namespace motion::metrology
