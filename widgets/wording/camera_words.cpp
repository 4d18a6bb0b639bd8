// Words for the camera.* ids (docs/camera.md): one row per id, the English source with
// %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"camera.none", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "no camera is chosen", "camera.none")},
    {"camera.reading.silent", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 gave no image in %2", "camera.reading.silent"), "camera,seconds"},
    {"camera.reading.one_axis", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 reads a glass scale along one axis, X or Y, at a time", "camera.reading.one_axis"), "camera"},
    {"camera.reading.no_line", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "%1; the image is kept as %2", "camera.reading.no_line"), "cause,file"},
    {"camera.reading.no_dot", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "%1; the image is kept as %2", "camera.reading.no_dot"), "cause,file"},
    {"camera.reading.dot_size", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "what the camera found is %1 across, not one of the plate's dots of %2", "camera.reading.dot_size"), "diameter,expected"},
    {"camera.reading.dot_far", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the nearest dot is %1 from the image centre, more than half the plate's pitch (%2): not this node's dot", "camera.reading.dot_far"), "distance,max"},
    {"camera.reading.two_axes", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 reads a grid plate's dot in X and Y at once: a reading needs both", "camera.reading.two_axes"), "camera"},
    {"camera.not_open", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 is not open", "camera.not_open"), "source"},
    {"camera.closed_during_capture", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 was closed while it took an image", "camera.closed_during_capture"), "source"},
    {"camera.sim.no_stage", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera has no simulated stage to look at (is the simulator connected?)", "camera.sim.no_stage")},
    {"camera.sim.needs_simulator", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera 'sim' looks at the in-process simulator's stage: use it with --sim stage (benchpilot-sim's camera is sim:PATH)", "camera.sim.needs_simulator")},
    {"camera.source.unknown", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "'%1' is not a camera: give sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR", "camera.source.unknown"), "source"},
    {"camera.source.needs_argument", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "'%1': %2: needs what follows the colon (%2:…)", "camera.source.needs_argument"), "source,kind"},
    {"camera.source.not_available", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera source '%1' is not in this build of BenchPilot yet; 'camera list' shows what is", "camera.source.not_available"), "source"},
    {"camera.socket.no_server", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "no simulated camera is served at %1: start benchpilot-sim with --camera-socket %1", "camera.socket.no_server"), "socket"},
    {"camera.socket.lost", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera at %1 went away (has benchpilot-sim stopped?)", "camera.socket.lost"), "socket"},
    {"camera.socket.timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera at %1 did not answer within %2", "camera.socket.timeout"), "socket,seconds"},
    {"camera.socket.garbled", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera at %1 sent what cannot be read: %2", "camera.socket.garbled"), "socket,reason"},
    {"camera.socket.server_error", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the simulated camera at %1 refused the request: %2 (%3)", "camera.socket.server_error"), "socket,code,detail"},
    {"camera.socket.path_too_long", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the socket path %1 is empty or too long (a local socket's path has at most %2)", "camera.socket.path_too_long"), "socket,max"},
    {"camera.socket.not_a_socket", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "%1 exists and is not a socket: refusing to replace it", "camera.socket.not_a_socket"), "socket"},
    {"camera.socket.in_use", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a simulated camera is already served at %1 (another benchpilot-sim?): stop it or give another path", "camera.socket.in_use"), "socket"},
    {"camera.socket.cannot_listen", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "cannot serve the simulated camera at %1: %2", "camera.socket.cannot_listen"), "socket,detail"},
    {"camera.wire.header_too_long", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a header line longer than %1", "camera.wire.header_too_long"), "max"},
    {"camera.wire.not_json", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a header that is not a JSON object (%1)", "camera.wire.not_json"), "detail"},
    {"camera.wire.schema", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a message of schema '%1', not benchpilot.sim-camera", "camera.wire.schema"), "got"},
    {"camera.wire.version", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a message of version %1; this BenchPilot reads version %2", "camera.wire.version"), "version,supported"},
    {"camera.wire.field", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the field '%1' is missing or out of range", "camera.wire.field"), "field"},
    {"camera.wire.unexpected", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a '%1' message where none belongs", "camera.wire.unexpected"), "type"},
    {"camera.wire.size", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a frame of %3 × %4 px announces %1 of pixels where it needs %2", "camera.wire.size"), "bytes,expected,width,height"},
    {"camera.sensor_mismatch", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 gives images of %2 × %3 px, but the plan's camera has %4 × %5 px: correct the plan's sensor (or the camera's resolution), or every tile lands in the wrong place", "camera.sensor_mismatch"), "camera,width,height,plan_width,plan_height"},
    {"camera.uvc.none_found", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "no USB camera is attached (Qt Multimedia finds none), so '%1' cannot be opened", "camera.uvc.none_found"), "source"},
    {"camera.uvc.not_found", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "there is no USB camera '%1'; the cameras found are: %2 (give uvc:NAME with a name or an id from 'camera list')", "camera.uvc.not_found"), "source,found"},
    {"camera.uvc.no_such_resolution", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 has no %2 × %3 px format that BenchPilot can read; it offers %4", "camera.uvc.no_such_resolution"), "source,width,height,offered"},
    {"camera.uvc.no_format", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 sends none of the pixel formats BenchPilot reads (it offers %2)", "camera.uvc.no_format"), "source,formats"},
    {"camera.uvc.sensor_mismatch", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 gives %2 × %3 px, and has no format of the plan's sensor, %4 × %5 px (it offers %6): correct the plan's sensor, or every tile lands in the wrong place", "camera.uvc.sensor_mismatch"), "source,width,height,plan_width,plan_height,offered"},
    {"camera.uvc.open_timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 did not start within %2: is another program using it?", "camera.uvc.open_timeout"), "source,seconds"},
    {"camera.uvc.timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 gave no new frame within %2", "camera.uvc.timeout"), "source,seconds"},
    {"camera.uvc.error", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 failed: %2", "camera.uvc.error"), "source,detail"},
    {"camera.uvc.unplugged", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 was unplugged (it is no longer in the system's list of cameras)", "camera.uvc.unplugged"), "source"},
    {"camera.uvc.busy", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 is still taking the previous image", "camera.uvc.busy"), "source"},
    {"camera.uvc.format_unsupported", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera sends %1 frames (%2 × %3 px), which BenchPilot cannot read: choose one of its other formats (see docs/camera.md)", "camera.uvc.format_unsupported"), "format,width,height"},
    {"camera.uvc.cannot_map", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a %1 frame of %2 × %3 px from the camera could not be read from its buffer", "camera.uvc.cannot_map"), "format,width,height"},
    {"camera.uvc.short_frame", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a %1 frame from the camera holds fewer bytes than %2 × %3 px need", "camera.uvc.short_frame"), "format,width,height"},
    {"camera.uvc.jpeg_unreadable", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a %1 (Motion-JPEG) frame from the camera, %2 × %3 px, could not be decoded", "camera.uvc.jpeg_unreadable"), "format,width,height"},
    {"camera.command.failed", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the capture command '%1' failed (exit code %2): %3", "camera.command.failed"), "command,code,stderr"},
    {"camera.command.timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the capture command '%1' did not finish within %2 and was stopped: %3", "camera.command.timeout"), "command,seconds,stderr"},
    {"camera.command.no_file", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the capture command '%1' ended without writing %2: %3", "camera.command.no_file"), "command,file,stderr"},
    {"camera.command.cannot_start", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the capture command '%1' cannot be started: %2", "camera.command.cannot_start"), "command,detail"},
    {"camera.command.busy", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the capture command '%1' is still taking the previous image", "camera.command.busy"), "command"},
    {"camera.folder.missing", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera's folder %1 is not there (or not a folder)", "camera.folder.missing"), "folder"},
    {"camera.folder.timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "no new image arrived in %1 within %2: is the camera's software running and saving there, and is it fired by the stage's trigger output?", "camera.folder.timeout"), "folder,seconds"},
    {"camera.folder.busy", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "still waiting for the previous image in %1", "camera.folder.busy"), "folder"},
    {"camera.tiff.cannot_write", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "cannot write the image %1: %2", "camera.tiff.cannot_write"), "file,detail"},
    {"camera.tiff.cannot_read", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "cannot read the image %1: %2", "camera.tiff.cannot_read"), "file,detail"},
    {"camera.tiff.unsupported", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the image %1 is %2 a pixel; BenchPilot reads 8- or 16-bit grey and 8-bit RGB", "camera.tiff.unsupported"), "file,detail"},
    {"camera.tiff.empty_frame", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera gave an empty image; nothing was written to %1", "camera.tiff.empty_frame"), "file,detail"},
    {"camera.calibration.already_running", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a camera calibration is already running", "camera.calibration.already_running")},
    {"camera.calibration.not_connected", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the stage is not connected", "camera.calibration.not_connected")},
    {"camera.calibration.not_a_stage", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera is calibrated against the microscope stage; this instrument is not one", "camera.calibration.not_a_stage")},
    {"camera.calibration.estop_latched", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the E-stop is latched: reset it before calibrating the camera", "camera.calibration.estop_latched")},
    {"camera.calibration.not_homed", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the stage is not homed: home it before calibrating the camera", "camera.calibration.not_homed")},
    {"camera.calibration.moving", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the stage is moving: wait until it stands still", "camera.calibration.moving")},
    {"camera.calibration.bad_steps", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a step of %1 px taken %2 times each way is not a calibration: the step must be 1 to 10000 px and the count 1 to 10", "camera.calibration.bad_steps"), "step,steps"},
    {"camera.calibration.no_pixel_size", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera %1 does not say its pixel size: give the nominal one (--pixel-um)", "camera.calibration.no_pixel_size"), "source"},
    {"camera.calibration.steps_too_long", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the steps reach %1 px from the start, more than half of the %2 × %3 px image: take shorter or fewer steps", "camera.calibration.steps_too_long"), "reach,width,height"},
    {"camera.calibration.beyond_limits", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a step would take %1 to %2, outside its soft limits %3 … %4: move the stage further in first", "camera.calibration.beyond_limits"), "axis,target,min,max"},
    {"camera.calibration.size_changed", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera's image changed size during the calibration (%1 × %2 px, the first was %3 × %4 px)", "camera.calibration.size_changed"), "width,height,first_width,first_height"},
    {"camera.calibration.stopped", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera calibration was stopped; the stage was stopped where it stood", "camera.calibration.stopped")},
    {"camera.calibration.link_lost", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the link to the stage was lost during the camera calibration", "camera.calibration.link_lost")},
    {"camera.calibration.stage_event", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera calibration stopped: %1 %2", "camera.calibration.stage_event"), "event,detail"},
    {"camera.calibration.move_refused", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the stage refused a calibration step: %1", "camera.calibration.move_refused"), "cause"},
    {"camera.calibration.move_timeout", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "a calibration step did not end within %1", "camera.calibration.move_timeout"), "seconds"},
    {"camera.calibration.no_image", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera gave no image within %1", "camera.calibration.no_image"), "seconds"},
    {"camera.calibration.camera_failed", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the camera failed during the calibration: %1", "camera.calibration.camera_failed"), "cause"},
    {"camera.calibration.not_registered", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "only %1 of %2 images could be registered against the first: the specimen has too little texture here, or the steps are too long", "camera.calibration.not_registered"), "registered,total"},
    {"camera.calibration.no_fit", QT_TRANSLATE_NOOP3("ui::words::CameraWords", "the registered shifts do not give a camera mapping (the steps do not span both axes)", "camera.calibration.no_fit")},
};
// clang-format on

} // namespace

QString camera(const motion::msg::Message& m) { return fromRows("ui::words::CameraWords", kRows, m); }

} // namespace ui::words::areas
