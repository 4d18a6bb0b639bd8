#pragma once
// The USB cameras Qt Multimedia finds, and which one (and which of its formats) a
// `uvc[:NAME]` source means.
//
//   uvc                       the system's default camera, at its largest resolution
//   uvc:NAME                  the camera whose description is NAME (case-insensitive) or whose id is NAME
//   uvc:NAME@WIDTHxHEIGHT     … at that resolution (a scan picks its plan's sensor size itself)
//
// Finding the cameras asks the multimedia backend (GStreamer's device monitor): tens of
// milliseconds warm, a few hundred on a machine's first run. Call it when a person asks
// for the list or opens a camera, never on a path that does not need a camera.
#include "motion/checked.h"

#include <QCameraDevice>
#include <QSize>
#include <QString>

#include <optional>
#include <vector>

namespace dev::camera {

struct UvcName {
    QString camera;             ///< "" = the default camera
    std::optional<QSize> size;  ///< from "@WxH"
};
/// Splits "Logitech BRIO@1920x1080"; a trailing "@…" that is not WxH stays part of the name.
UvcName parseUvcName(const QString& text);

struct UvcFormat {
    QSize size;
    QVideoFrameFormat::PixelFormat pixelFormat = QVideoFrameFormat::Format_Invalid;
    float minFps = 0, maxFps = 0;
    bool accepted = false;      ///< BenchPilot converts this pixel format (video_frame_convert.h)
};
struct UvcDevice {
    QString name;               ///< what `uvc:NAME` matches (the description)
    QString id;                 ///< the backend's id (a /dev/video path under GStreamer)
    bool isDefault = false;
    std::vector<UvcFormat> formats;
};

/// Every camera found now (see the cost above).
std::vector<UvcDevice> listUvcCameras();

/// The camera `name` means among `found` (the default one for ""): refused with
/// camera.uvc.none_found or camera.uvc.not_found, which name what was asked and what is there.
motion::msg::Checked<QCameraDevice> findUvcCamera(const QString& name, const QList<QCameraDevice>& found);

/// The format to open a camera with, of `formats`: of those BenchPilot takes, the one of
/// `size` (any size when not given: the largest, as a microscope wants the whole sensor),
/// an uncompressed one before Motion-JPEG, then the fastest. −1 when none fits.
int chooseUvcFormat(const std::vector<UvcFormat>& formats, std::optional<QSize> size);
/// The same for a camera found: a null format when none fits.
QCameraFormat chooseUvcFormat(const QCameraDevice& device, std::optional<QSize> size);
/// "1920×1080, 1280×720": the sizes of `formats` BenchPilot takes, largest first.
std::string uvcSizesText(const std::vector<UvcFormat>& formats);
std::string uvcSizesText(const QCameraDevice& device);
/// A camera's formats as BenchPilot lists them.
std::vector<UvcFormat> uvcFormatsOf(const QCameraDevice& device);

} // namespace dev::camera
