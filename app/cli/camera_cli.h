#pragma once
// The camera a command was given (--camera SOURCE, with --specimen and --camera-seed for the
// simulated one), made for benchpilot-cli's session: the simulated camera reads the
// in-process simulator's true work point (--sim stage).
#include "command.h"

#include "device/camera/camera.h"

#include <memory>

namespace app::cli {

class CliSession;

/// nullptr after a usage message naming what was wrong with --camera. `defaultSpecimen`
/// is what the simulated camera looks at without --specimen.
std::unique_ptr<dev::camera::Camera> cameraFor(Invocation& inv, CliSession* session, const QString& source,
                                               const char* defaultSpecimen = "slide");

/// Opens `camera` and waits until it is open (a USB camera starts asynchronously, and
/// its exposure can be set only once it is there): Ok, or Refused with the reason printed.
int openCamera(Invocation& inv, dev::camera::Camera* camera);

/// `camera calibrate` (camera_calibrate.cpp).
Command cameraCalibrateCommand();

/// The options that go with --camera (specimen, seed), for a command's option list.
QList<QCommandLineOption> cameraOptions(const char* defaultSpecimen = "slide");

} // namespace app::cli
