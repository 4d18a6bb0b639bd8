#pragma once
// The GUI's cameras: how a source string becomes a camera, and which sources can be
// listed (a USB camera is found; a command or a folder is whatever the operator types).
#include "device/camera/camera.h"
#include "device/camera/specimen.h"

#include <QString>
#include <QStringList>

#include <memory>

namespace app {

class InstrumentSession;

/// The camera for `source` ("sim", "uvc:NAME", "command:CMD", "folder:DIR"), not yet
/// opened; nullptr with `error` worded when this build cannot make it. The simulated
/// camera looks at `stage`'s in-process simulator, where `specimen` lies.
std::unique_ptr<dev::camera::Camera> makeCamera(const QString& source, InstrumentSession* stage, QString* error,
                                                dev::camera::SpecimenKind specimen = dev::camera::SpecimenKind::Slide);
/// The sources known to exist now: "sim" and "uvc:NAME" for each USB camera found. Asks
/// the multimedia backend (tens to hundreds of ms): call it when the choice is opened.
QStringList listCameras();

} // namespace app
