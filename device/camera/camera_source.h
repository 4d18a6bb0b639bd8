#pragma once
// A camera as the operator names it, and the camera made from that name:
//   sim               the simulated camera on the in-process simulator's stage
//   sim:PATH          the simulated camera benchpilot-sim serves on a local socket (sim_socket_camera.h)
//   uvc[:NAME]        a USB camera through Qt Multimedia (uvc_camera.h; not in a build without it)
//   command:CMD       the operator's capture program, run per image (command_camera.h)
//   folder:DIR        the next complete new file a camera's own software saves in DIR (folder_camera.h)
// A name that is none of these, or a source this build cannot open, is refused with a
// message saying what was given and what would do (camera.source.*).
#include "device/camera/camera.h"
#include "device/camera/sim_camera.h"

#include <memory>
#include <string>

namespace dev::camera {

enum class SourceKind { Sim, SimSocket, Uvc, Command, Folder };

struct SourceSpec {
    SourceKind kind = SourceKind::Sim;
    std::string argument;  ///< the socket, camera name, command line or folder; may be empty for sim and uvc
};

/// Reads "sim", "uvc:Logitech", "command:…", "folder:…"; false with camera.source.* in `error`.
bool parseSource(const std::string& text, SourceSpec* spec, motion::msg::Message* error);

/// What a simulated camera needs from the place it runs: the stage's true work point.
struct SimContext {
    WorkPointSource workPoint;   ///< empty: no in-process simulator here
    SimCameraSettings settings;
};

/// Makes the camera `text` names; nullptr with the reason.
std::unique_ptr<Camera> makeCamera(const std::string& text, const SimContext& sim, motion::msg::Message* error, QObject* parent = nullptr);

} // namespace dev::camera
