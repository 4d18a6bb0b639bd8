#pragma once
// How a camera's pixels lie on the sample: what a scan plan says of its camera, in the
// form a source needs to render (the simulated camera) or to check (a real camera whose
// sensor is not the plan's is refused). Plain C++.
namespace dev::camera {

struct CameraGeometry {
    int sensorWidthPx = 2048;
    int sensorHeightPx = 2048;
    double pixelUm = 0.65;       ///< one pixel at the sample (sensor pitch / magnification)
    double pixelYUm = 0;         ///< a pixel's height at the sample where it is not square; 0: pixelUm
    double rotationDeg = 0;      ///< the image's x axis against stage +X, counter-clockwise
    bool imageYAlongMinusY = true;  ///< image rows (down the image) run along stage −Y

    /// Stage displacement (mm) of one pixel step along the image's x and y axes, the same
    /// mapping the scan's exports use (docs/scan.md, TileConfiguration).
    void axes(double* exX, double* exY, double* eyX, double* eyY) const;
};

} // namespace dev::camera
