// Words for dev::Instrument::whyNot (ids capability.*) and the instrument terms:
// what a disabled control's tooltip or a screen's note says.
#include "widgets/wording/areas.h"
#include "widgets/wording/wording.h"

#include "device/client/capabilities.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

/// The words, with tr() in one translation context (lupdate reads Class::tr calls).
class CapabilityWords {
    Q_DECLARE_TR_FUNCTIONS(ui::words::CapabilityWords)
public:
    static QString lacking(dev::Capability c);
    static QString term(const std::string& id);
    static QString text(const motion::msg::Message& reason);
};

/// What the instrument lacks, as the object of "has no …".
QString CapabilityWords::lacking(dev::Capability c)
{
    using C = dev::Capability;
    switch (c) {
    case C::Homing: return tr("homing switches");
    case C::SetZero: return tr("way to set an axis' zero");
    case C::MeasuredPosition: return tr("encoder or grating readings");
    case C::ClosedLoop: return tr("closed position loop");
    case C::Telemetry: return tr("telemetry stream");
    case C::VelocityJog: return tr("continuous jog");
    case C::StopsOnHostLoss: return tr("way to stop by itself when BenchPilot goes quiet");
    case C::PathQueue: return tr("path queue to run patterns on");
    case C::PathZFollow: return tr("Z axis that follows a path");
    case C::CoupledXyThenZ: return tr("Z axis that waits for X and Y");
    case C::SoftLimits: return tr("soft limits of its own");
    case C::PidGains: return tr("PID gains to tune");
    case C::TuningTests: return tr("step or relay tests");
    case C::Pump: return tr("plunger pump");
    case C::TriggerOutput: return tr("trigger output for a camera");
    case C::MachineLimits: return tr("report of its acceleration and jerk limits");
    case C::Compensation: return tr("error compensation of its own");
    case C::ArchedMove: return tr("arched move that blends Z with X and Y");
    }
    return {};
}

QString CapabilityWords::term(const std::string& id)
{
    if (id == "instrument.stage")
        return tr("stage");
    if (id == "instrument.analyzer")
        return tr("analyzer");
    if (id == "capability.because.open_loop")
        return tr("it runs open loop");
    if (id == "capability.because.older_firmware")
        return tr("its firmware predates them; estimates assume the reference machine's");
    if (id == "capability.because.not_in_protocol")
        return tr("its protocol has none");
    return {};
}

QString CapabilityWords::text(const motion::msg::Message& reason)
{
    const QString instrument = ui::words::arg(reason, "instrument");
    if (reason.id == dev::kNotConnectedId)
        return instrument.isEmpty() ? tr("The instrument is not connected.")
                                    : tr("The %1 is not connected.").arg(instrument);
    for (dev::Capability c : dev::allCapabilities()) {
        if (reason.id != dev::missingId(c))
            continue;
        const QString family = ui::words::arg(reason, "family");
        const QString who = family.isEmpty() ? tr("The %1").arg(instrument) : tr("The %1 (%2)").arg(instrument, family);
        if (!reason.arg("because"))
            return tr("%1 has no %2.").arg(who, lacking(c));
        return tr("%1 has no %2: %3.").arg(who, lacking(c), ui::words::arg(reason, "because"));
    }
    return {};
}

} // namespace

QString capability(const motion::msg::Message& m) { return CapabilityWords::text(m); }
QString capabilityTerm(const std::string& id) { return CapabilityWords::term(id); }

} // namespace ui::words::areas
