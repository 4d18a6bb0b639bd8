#pragma once
// Does the scan plan's camera match the images? The registered shifts between neighbours
// are what the camera truly did for the stage steps between them; fitted as in camera–
// stage calibration (camera_stage_fit.h), they give the true rotation, mirror and pixel
// size, compared here with the plan's. A wrong mirror or a rotation of a few degrees
// leaves the neighbours' overlaps where the plan did not look, so a pair the stitch could
// not register is tried again under the mirrored and half-turned readings of its step
// and a wider bound; only a few pairs each way, and only those the stitch did not accept.
// Plain C++.
#include "imaging/camera_stage_fit.h"
#include "imaging/image.h"
#include "imaging/placement.h"
#include "imaging/registration.h"
#include "motion/message.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace imaging {

/// What the plan says of its camera (the stage pixels of the stitch came from it).
struct PlanCameraGeometry {
    double pixelUm = 0.65;
    double rotationDeg = 0;
    bool imageYAlongPlusY = false;
};

struct GeometryCheckOptions {
    /// Below this the plan's rotation is close enough: 0.25° drifts a 2048 px tile's far
    /// edge by 9 px, which registration takes up without help.
    double rotationToleranceDeg = 0.25;
    double pixelToleranceShare = 0.01;  ///< 1 % on a pixel is 20 px across a 2048 px tile
    int pairsEachWay = 4;               ///< pairs along image x and along image y tried again at most
    double searchShareOfTile = 0.1;     ///< the wider bound, as a share of the tile's smaller side
    double maxResidualPx = 2;           ///< a fit worse than this says nothing
};

struct GeometryCheck {
    bool measured = false;  ///< enough pairs each way, and they agree with one mapping
    int pairsUsed = 0;
    CameraStageFit fit;     ///< the camera the images show
    bool rotationOff = false;
    bool mirrorOff = false;
    bool pixelOff = false;
    double measuredPixelUm() const { return (fit.pixelXUm + fit.pixelYUm) / 2; }
    bool anythingOff() const { return measured && (rotationOff || mirrorOff || pixelOff); }
};

using GeometryTileLoader = std::function<std::shared_ptr<const ImageU16>(int tile)>;

/// `stagePx` and `pairs` as the stitch has them (pairs registered); `load` gives a
/// tile for the pairs tried again (nullptr: skip it).
GeometryCheck checkGeometry(const std::vector<Eigen::Vector2d>& stagePx, const std::vector<TilePair>& pairs, int tileW, int tileH,
                            const PlanCameraGeometry& plan, const GeometryTileLoader& load, const RegistrationOptions& registration,
                            const GeometryCheckOptions& options = {});

/// Which plan setting to change, one message each (imaging.camera_check.*), with the
/// measured value: empty when the images agree with the plan or say too little.
std::vector<motion::msg::Message> geometryAdvice(const GeometryCheck& check, const PlanCameraGeometry& plan);

} // namespace imaging
