#include "app/gui/camera_wiring.h"

#include <QCoreApplication>

namespace app {

// No camera source is linked into this build yet: every source answers that it cannot be
// opened, and the screens say so.
std::unique_ptr<dev::camera::Camera> makeCamera(const QString& source, QString* error)
{
    *error = QCoreApplication::translate("app::CameraWiring", "Camera %1: this build has no camera sources.").arg(source);
    return nullptr;
}

QStringList listCameras() { return {QStringLiteral("sim")}; }

} // namespace app
