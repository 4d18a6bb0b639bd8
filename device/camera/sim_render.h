#pragma once
// What the simulated camera's sensor records: the specimen seen through the camera's
// geometry at a work point, dimmed towards the corners (vignetting), turned into
// electrons for the exposure, with shot and read noise, and quantised to 8 or 16 bits.
// Deterministic: the same specimen, geometry, work point, exposure and seed give the same
// pixels. Plain C++; safe to call from any thread on a const Specimen.
#include "device/camera/camera_geometry.h"
#include "device/camera/frame.h"
#include "device/camera/specimen.h"

namespace dev::camera {

struct SimOptics {
    double fluxEPerMs = 1300;    ///< electrons a pixel collects per ms through transmittance 1, at the centre
    double fullWellE = 20000;    ///< a pixel saturates here
    double readNoiseE = 3;       ///< σ of the read noise
    double vignetting = 0.25;    ///< light lost in the corners (0: none)
    int bitDepth = 16;           ///< 8 (Grey8) or 16 (Grey16)
};

/// Renders one frame centred on the work point (xMm, yMm), in stage millimetres.
Frame renderSimFrame(const Specimen& specimen, const CameraGeometry& geometry, const SimOptics& optics, double xMm,
                     double yMm, double exposureMs, std::uint64_t seed);

} // namespace dev::camera
