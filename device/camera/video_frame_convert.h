#pragma once
// A USB camera's frame (a QVideoFrame from Qt Multimedia) as a dev::camera::Frame: grey
// stays grey (Y8 → 8-bit, Y16 → 16-bit), every colour format becomes 8-bit RGB, a
// Motion-JPEG frame is decoded. A format not listed in acceptedVideoFormats() is refused
// by name, so the operator knows to pick another of the camera's formats.
//
// YUV is turned into RGB with the frame's own colour space (BT.601 unless it says BT.709)
// and range (limited "video" levels unless it says full, which Motion-JPEG is).
//
// Thread-safe: a pure function of the frame, run on the camera's worker thread.
#include "device/camera/frame.h"
#include "motion/checked.h"

#include <QVideoFrame>
#include <QVideoFrameFormat>

#include <vector>

namespace dev::camera {

/// The QVideoFrame pixel formats frameFromVideo takes.
const std::vector<QVideoFrameFormat::PixelFormat>& acceptedVideoFormats();
bool isAcceptedVideoFormat(QVideoFrameFormat::PixelFormat format);
/// "NV12", "YUYV", "Jpeg": Qt's own name, as docs and `camera list` show it.
std::string videoFormatName(QVideoFrameFormat::PixelFormat format);

/// The pixels of `video` (mapped here for reading; the caller's frame is not changed);
/// refused with camera.uvc.format_unsupported, camera.uvc.cannot_map or
/// camera.uvc.jpeg_unreadable naming the format and size.
motion::msg::Checked<Frame> frameFromVideo(const QVideoFrame& video);

} // namespace dev::camera
