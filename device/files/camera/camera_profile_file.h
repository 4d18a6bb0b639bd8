#pragma once
// A camera's geometry against the stage, as a file people keep: schema
// "benchpilot.camera-profile", version 1 (docs/camera.md, "The camera profile file").
// Written by camera calibration (or by hand), read by scan plans that name it and by
// `scan run --camera-profile`. Every problem at once, with file, line, column and field.
#include "device/files/accuracy/file_problem.h"
#include "motion/checked.h"
#include "motion/plans/scan/scan_plan.h"

#include <QString>

#include <string>
#include <string_view>

namespace dev::files::camera {

constexpr const char* kCameraProfileSchema = "benchpilot.camera-profile";
constexpr int kCameraProfileVersion = 1;

/// How the profile's numbers were found, when a calibration found them.
struct CameraCalibrationRecord {
    std::string method = "stage-steps";  ///< "stage-steps" (calibration) or "entered" (typed in)
    std::string when;                    ///< ISO 8601 UTC
    int images = 0;                      ///< images registered against the first
    double stepUm = 0;                   ///< the largest step, µm
    double residualRmsPx = 0;
    double residualMaxPx = 0;
    double skewDeg = 0;                  ///< image y against square to image x
    double returnPx = 0;                 ///< the image back at the start against the first (drift, backlash)
};

struct CameraProfile {
    std::string camera;          ///< the source as the operator names it ("sim", "uvc:…")
    int sensorWidthPx = 2048, sensorHeightPx = 2048;
    double pixelXUm = 0.65;      ///< along the image's x axis, at the sample
    double pixelYUm = 0.65;      ///< along its y axis
    double rotationDeg = 0;      ///< image x against stage +X, counter-clockwise
    bool imageYAlongPlusY = false;  ///< "image_y": "stage-plus-y" (mirrored against the usual camera)
    bool calibrated = false;     ///< `calibration` is there
    CameraCalibrationRecord calibration;
    std::string note;

    /// One pixel size for what takes one (a scan plan): the mean of x and y.
    double pixelUm() const { return (pixelXUm + pixelYUm) / 2; }
};

using CameraProfileRead = motion::msg::Checked<CameraProfile>;

std::string cameraProfileToJson(const CameraProfile& p);
/// Plain C++: what the fuzzer drives.
CameraProfileRead cameraProfileFromJson(std::string_view text, std::string_view fileName);
CameraProfileRead loadCameraProfileFile(const QString& path);
bool saveCameraProfileFile(const QString& path, const CameraProfile& p, motion::msg::Message* error);

/// A scan plan's camera as the profile has it: the field from the sensor and the mean
/// pixel (a plan has one pixel size), the rotation and image y; `profile` is kept.
void applyCameraProfile(const CameraProfile& p, motion::scan::Camera* camera);

} // namespace dev::files::camera
