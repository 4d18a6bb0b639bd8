#include "app/gui/camera_wiring.h"

#include "app/gui/instrument_session.h"
#include "device/camera/camera_source.h"
#if BP_WITH_UVC
#include "device/camera/uvc_devices.h"
#endif
#include "device/link/simulated_link.h"
#include "widgets/wording/wording.h"

#include <QPointer>

namespace app {

std::unique_ptr<dev::camera::Camera> makeCamera(const QString& source, InstrumentSession* stage, QString* error,
                                                dev::camera::SpecimenKind specimen)
{
    dev::camera::SimContext sim;
    sim.settings.specimen = specimen;
    // The true work point, read on the GUI thread where the simulator runs; none while the
    // stage is not on the in-process simulator (the camera says so when asked for a frame).
    QPointer<InstrumentSession> session(stage);
    sim.workPoint = [session]() -> std::optional<dev::camera::WorkPoint> {
        auto* link = session ? qobject_cast<dev::SimulatedLink*>(session->link()) : nullptr;
        if (!link || link->machine().axisCount() < 2)
            return std::nullopt;
        const dev::sim::SimMachine& m = link->machine();
        return dev::camera::WorkPoint{m.workPointLogical(0), m.workPointLogical(1), m.timeUs()};
    };
    motion::msg::Message problem;
    auto camera = dev::camera::makeCamera(source.toStdString(), sim, &problem);
    if (!camera)
        *error = ui::words::text(problem);
    return camera;
}

QStringList listCameras()
{
    QStringList out{QStringLiteral("sim")};
#if BP_WITH_UVC
    for (const dev::camera::UvcDevice& d : dev::camera::listUvcCameras())
        out << QStringLiteral("uvc:") + d.name;
#endif
    return out;
}

} // namespace app
