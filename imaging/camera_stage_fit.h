#pragma once
// The camera–stage mapping from images taken at known stage steps (what Micro-Manager's
// Pixel Calibrator and OpenFlexure's camera–stage mapping measure): each step's stage
// displacement d (µm) and the image shift s (px: the moved image's top-left in the
// first image's pixels, as registerPair gives it) obey d = M·s. The 2×2 matrix M is
// fitted by least squares and read as the camera's geometry: a pixel's size along the
// image's x and y axes, the image x axis's angle against stage +X, whether the image is
// mirrored against the usual camera (image rows running down along stage −Y), and how far
// the two axes are from square.
//
// What it cannot know: the steps are the stage's own, so a pixel size calibrated this way
// carries the stage's scale error (a grating reading 0.1 % long makes every pixel 0.1 %
// large); only a certified scale under the camera (the accuracy bench's scale reading)
// separates the two. Plain C++ + Eigen.
#include <Eigen/Core>

#include <optional>
#include <vector>

namespace imaging {

struct CameraStageSample {
    Eigen::Vector2d stageStepUm{0, 0};  ///< stage displacement from the reference image, µm
    Eigen::Vector2d imageShiftPx{0, 0}; ///< the registered shift of the image taken there, px
};

struct CameraStageFit {
    Eigen::Matrix2d stageUmPerPx = Eigen::Matrix2d::Identity();  ///< M: stage µm for one px along image x (column 0) and y (column 1)
    double pixelXUm = 0;       ///< |M column 0|
    double pixelYUm = 0;       ///< |M column 1|
    double rotationDeg = 0;    ///< image x axis against stage +X, counter-clockwise, (−180, 180]
    /// True when image y runs along stage +Y (det M > 0): mirrored against the usual camera,
    /// whose rows run down the image along stage −Y.
    bool imageYAlongPlusY = false;
    /// The image y axis's angle from where a square camera would have it, degrees (skew).
    double skewDeg = 0;
    double residualRmsPx = 0;  ///< of the measured shifts against the fit's prediction
    double residualMaxPx = 0;
    int samples = 0;
};

/// Least squares over the samples (the shifts carry the noise, so the fit is s = A·d and
/// M = A⁻¹). Nullopt when the steps do not span both stage axes (fewer than two
/// non-parallel steps) or the fitted mapping is singular.
std::optional<CameraStageFit> fitCameraStage(const std::vector<CameraStageSample>& samples);

/// The matrix a camera of this geometry has (the inverse of the decomposition above, with
/// no skew): for predictions and tests.
Eigen::Matrix2d cameraStageMatrix(double pixelXUm, double pixelYUm, double rotationDeg, bool imageYAlongPlusY);

/// Wraps an angle to (−180, 180] degrees.
double wrapDegrees(double deg);

} // namespace imaging
