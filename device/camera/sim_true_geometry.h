#pragma once
// What the simulated camera truly is where that differs from what it is asked to be: a
// pixel of another size, a sensor turned on its mount, an image mirrored. A scan plan or
// a calibration that assumes the nominal camera then sees what it would see under a
// real microscope whose camera was never measured. Written as the operator types it
// (docs/camera.md, "A simulated camera that is not what the plan says"):
//   pixel-um=0.70            the true pixel at the sample (square)
//   pixel-um=0.70:0.69       width and height differing
//   rotation-deg=1.5         the image x axis against stage +X, counter-clockwise
//   mirror                   image y runs along stage +Y (mirrored against the usual camera)
// joined by commas, e.g. "pixel-um=0.7,rotation-deg=-2,mirror". Plain C++.
#include "device/camera/camera_geometry.h"

#include <optional>
#include <string>

namespace dev::camera {

struct SimTrueGeometry {
    std::optional<double> pixelXUm, pixelYUm, rotationDeg;
    bool mirrored = false;
    bool any() const { return pixelXUm || pixelYUm || rotationDeg || mirrored; }
};

/// False with the part that is not understood (or out of range) in `badPart`.
bool parseSimTrueGeometry(const std::string& text, SimTrueGeometry* out, std::string* badPart);
/// The spec again, as parseSimTrueGeometry reads it ("" when nothing differs).
std::string simTrueGeometryText(const SimTrueGeometry& g);

/// The geometry the camera truly renders with when asked for `asked`: the sensor stays
/// the one asked for; pixel, rotation and mirror are the true ones where given (absolute,
/// as a real camera's are: a plan that already says stage-plus-y sees no mirror).
CameraGeometry trueGeometryOf(const CameraGeometry& asked, const SimTrueGeometry& truth);

} // namespace dev::camera
