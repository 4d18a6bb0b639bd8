#include "app/gui/camera_wiring.h"

#include "app/gui/instrument_session.h"
#include "device/camera/sim_camera.h"
#include "device/link/simulated_link.h"

#include <QCoreApplication>
#include <QPointer>

namespace app {

std::unique_ptr<dev::camera::Camera> makeCamera(const QString& source, InstrumentSession* stage, QString* error)
{
    if (source == QLatin1String("sim")) {
        // The true work point, read on the GUI thread where the simulator runs; none while the
        // stage is not on the in-process simulator (the camera says so when asked for a frame).
        QPointer<InstrumentSession> session(stage);
        auto workPoint = [session]() -> std::optional<dev::camera::WorkPoint> {
            auto* link = session ? qobject_cast<dev::SimulatedLink*>(session->link()) : nullptr;
            if (!link)
                return std::nullopt;
            const sim::SimMachine& m = link->machine();
            return dev::camera::WorkPoint{m.workPointLogical(0), m.workPointLogical(1), m.timeUs()};
        };
        return std::make_unique<dev::camera::SimCamera>(workPoint, dev::camera::SimCameraSettings{});
    }
    // The USB, command and folder sources are not linked into this build yet.
    *error = QCoreApplication::translate("app::CameraWiring", "Camera %1: this build cannot open this kind of source yet.").arg(source);
    return nullptr;
}

QStringList listCameras() { return {QStringLiteral("sim")}; }

} // namespace app
