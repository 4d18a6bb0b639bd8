#include "device/camera/camera_geometry.h"

#include <cmath>

namespace dev::camera {

void CameraGeometry::axes(double* exX, double* exY, double* eyX, double* eyY) const
{
    const double th = rotationDeg * M_PI / 180.0;
    const double mmPerPx = pixelUm * 1e-3;
    *exX = std::cos(th) * mmPerPx;
    *exY = std::sin(th) * mmPerPx;
    // Down the image: a quarter turn clockwise from the x axis for stage-minus-y.
    const double mmPerPxY = (pixelYUm > 0 ? pixelYUm : pixelUm) * 1e-3;
    *eyX = (imageYAlongMinusY ? std::sin(th) : -std::sin(th)) * mmPerPxY;
    *eyY = (imageYAlongMinusY ? -std::cos(th) : std::cos(th)) * mmPerPxY;
}

} // namespace dev::camera
