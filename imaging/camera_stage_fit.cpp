#include "imaging/camera_stage_fit.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace imaging {

namespace {
constexpr double kCamFitPi = 3.14159265358979323846;
double camFitDeg(double rad) { return rad * 180.0 / kCamFitPi; }
double camFitRad(double deg) { return deg * kCamFitPi / 180.0; }
} // namespace

double wrapDegrees(double deg)
{
    double d = std::fmod(deg, 360.0);
    if (d <= -180)
        d += 360;
    if (d > 180)
        d -= 360;
    return d;
}

Eigen::Matrix2d cameraStageMatrix(double pixelXUm, double pixelYUm, double rotationDeg, bool imageYAlongPlusY)
{
    const double th = camFitRad(rotationDeg);
    const double c = std::cos(th), s = std::sin(th);
    Eigen::Matrix2d m;
    m(0, 0) = c * pixelXUm;
    m(1, 0) = s * pixelXUm;
    // The usual camera: image y a quarter turn clockwise from image x on the stage (rows
    // run down the image while stage +Y is up); mirrored, a quarter turn anticlockwise.
    m(0, 1) = (imageYAlongPlusY ? -s : s) * pixelYUm;
    m(1, 1) = (imageYAlongPlusY ? c : -c) * pixelYUm;
    return m;
}

std::optional<CameraStageFit> fitCameraStage(const std::vector<CameraStageSample>& samples)
{
    if (samples.size() < 2)
        return std::nullopt;
    Eigen::Matrix2d ddT = Eigen::Matrix2d::Zero();
    Eigen::Matrix2d sdT = Eigen::Matrix2d::Zero();
    double scale = 0;
    for (const auto& p : samples)
        scale = std::max(scale, p.stageStepUm.norm());
    if (!(scale > 0))
        return std::nullopt;
    for (const auto& p : samples) {
        ddT += p.stageStepUm * p.stageStepUm.transpose();
        sdT += p.imageShiftPx * p.stageStepUm.transpose();
    }
    // Steps along one line only (or none) leave the other direction unknown: the normal
    // matrix's smaller eigenvalue is then ~0 against its scale.
    const double det = ddT.determinant();
    if (!(std::fabs(det) > 1e-9 * std::pow(ddT.trace(), 2)))
        return std::nullopt;
    const Eigen::Matrix2d a = sdT * ddT.inverse();  // px per µm
    if (!(std::fabs(a.determinant()) > 0) || !a.allFinite())
        return std::nullopt;
    CameraStageFit f;
    f.stageUmPerPx = a.inverse();
    f.samples = static_cast<int>(samples.size());
    const Eigen::Vector2d ex = f.stageUmPerPx.col(0), ey = f.stageUmPerPx.col(1);
    f.pixelXUm = ex.norm();
    f.pixelYUm = ey.norm();
    f.imageYAlongPlusY = f.stageUmPerPx.determinant() > 0;
    const double thX = std::atan2(ex.y(), ex.x());
    // Where image y points, turned back by the quarter turn the (mirrored) usual camera has.
    const double thY = f.imageYAlongPlusY ? std::atan2(-ey.x(), ey.y()) : std::atan2(ey.x(), -ey.y());
    const double skew = std::remainder(thY - thX, 2 * kCamFitPi);
    f.rotationDeg = wrapDegrees(camFitDeg(thX + skew / 2));
    f.skewDeg = camFitDeg(skew);
    double sum2 = 0;
    for (const auto& p : samples) {
        const double r = (p.imageShiftPx - a * p.stageStepUm).norm();
        sum2 += r * r;
        f.residualMaxPx = std::max(f.residualMaxPx, r);
    }
    f.residualRmsPx = std::sqrt(sum2 / static_cast<double>(samples.size()));
    return f;
}

} // namespace imaging
