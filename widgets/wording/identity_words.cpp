// The instrument's model as a person reads it. BenchPilot's own simulator (the reference
// firmware, whose firmware name is "benchpilot-sim …") sends its model in English; the
// host knows what it simulates from its kind and names it in the operator's language.
// A real controller's model is a name its maker gave: shown as the controller gives it.
#include "widgets/wording/wording.h"

#include "device/client/instrument_types.h"

#include <QCoreApplication>

namespace ui::words {

QString modelName(const dev::DeviceIdentity& id)
{
    if (!id.firmware.startsWith(QLatin1String("benchpilot-sim")))
        return id.model;
    switch (id.kind) {
    case dev::proto::DeviceKind::Analyzer:
        return QCoreApplication::translate("ui::words::IdentityWords", "BenchPilot analyzer manipulator (simulated)");
    case dev::proto::DeviceKind::Stage:
        return QCoreApplication::translate("ui::words::IdentityWords", "BenchPilot microscope stage (simulated)");
    }
    return id.model;
}

} // namespace ui::words
