// GrblClient, part 3: what the controller is, as an instrument. The machine profile's wiring
// (instrument axis → GRBL axis, the pump's µL per mm), the limits $$ gave, the machine space
// that follows from homing and $23, the work offset, and the capabilities with their reasons.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/client/grbl_path_client.h"

#include <cmath>

namespace dev {

std::string GrblClient::axisLettersOfController() const
{
    if (!m_controller.build.axisLetters.empty())
        return m_controller.build.axisLetters;  // grblHAL's [AXS:n:XYZA]
    // Stock GRBL has X, Y and Z; a four- to six-axis build has the settings of its extra axes.
    std::string letters = "XYZ";
    for (int k = 3; k < 6; ++k)
        if (m_controller.settings.has(dev::grbl::setting::kMaxRateMmMinX + k))
            letters.push_back("XYZABC"[k]);
        else
            break;
    return letters;
}

bool GrblClient::buildIdentity(motion::msg::Message* why)
{
    const std::string letters = axisLettersOfController();
    dev::grbl::LimitsRead read = dev::grbl::machineLimits(m_controller.settings, letters);
    if (!read.limits) {
        // The refusal names the first problem and how many there are; each one is noted.
        for (const auto& p : read.problems)
            note(p);
        *why = motion::msg::make("grbl.identify.no_limits",
                         {motion::msg::nested("problem", read.problems.front()),  // machineLimits() has no limits only with problems
                          motion::msg::integer("count", static_cast<long long>(read.problems.size()))});
        return false;
    }
    m_controller.limits = *read.limits;
    if (m_controller.limits.reportInches) {
        if (m_profile.inchReports == dev::files::MachineProfile::InchReports::Refuse) {
            *why = motion::msg::make("grbl.identify.inches_refused");
            return false;
        }
        m_reports.tracker.setReportInches(true);
    }
    for (const auto& w : read.warnings)
        note(w);
    if (m_controller.build.firmware == dev::grbl::Firmware::GrblHal)
        m_controller.firmware = dev::grbl::Firmware::GrblHal;
    if (m_controller.firmware == dev::grbl::Firmware::Unknown)
        m_controller.firmware = dev::grbl::Firmware::Grbl;

    // The wiring: every axis the profile names must exist on this controller.
    QVector<AxisMap> map;
    std::vector<char> instrumentLetters;
    auto indexOf = [&](char g) {
        const std::size_t at = letters.find(g);
        return at == std::string::npos ? -1 : static_cast<int>(at);
    };
    for (const auto& a : m_profile.axes) {
        const int g = indexOf(a.grblAxis);
        if (g < 0) {
            *why = motion::msg::make("grbl.identify.axis_missing", {motion::msg::verbatim("axis", std::string(1, a.axis)),
                                                             motion::msg::verbatim("grbl_axis", std::string(1, a.grblAxis)),
                                                             motion::msg::verbatim("axes", letters)});
            return false;
        }
        map.push_back({g, 1.0});
        instrumentLetters.push_back(a.axis);
    }
    if (m_profile.pump) {
        const int g = indexOf(m_profile.pump->grblAxis);
        if (g >= 0) {
            map.push_back({g, m_profile.pump->ulPerMm});
            instrumentLetters.push_back('P');
        } else if (!m_lenient) {
            *why = motion::msg::make("grbl.identify.pump_axis_missing", {motion::msg::verbatim("grbl_axis", std::string(1, m_profile.pump->grblAxis)),
                                                                  motion::msg::verbatim("axes", letters)});
            return false;
        } else {
            m_profile.pump.reset();  // the default wiring: no fourth axis, no pump
        }
    }
    m_map = map;
    m_lines.streamer.setRxBufferBytes(m_controller.build.rxBufferOrDefault(m_controller.firmware));

    DeviceIdentity id;
    id.kind = m_profile.instrument;
    std::string version = m_controller.bannerVersion;
    if (version.empty())
        version = m_controller.build.version.substr(0, m_controller.build.version.find('.', m_controller.build.version.find('.') + 1));
    id.family = QStringLiteral("%1 %2").arg(m_controller.firmware == dev::grbl::Firmware::GrblHal ? QStringLiteral("grblHAL") : QStringLiteral("Grbl"),
                                            QString::fromStdString(version));
    id.model = m_profile.name.empty() ? tr("GRBL controller") : QString::fromStdString(m_profile.name);
    id.firmware = QString::fromStdString(m_controller.build.version.empty() ? version : m_controller.build.version);
    id.protocolVersion = 0;
    id.motionProfile = dev::proto::MotionProfile::Trapezoid;  // GRBL plans trapezoids: no jerk limit
    id.maxTelemetryRateHz = static_cast<std::uint32_t>(std::lround(m_profile.statusPollHz));
    id.jogWatchdogMs = 0;  // nothing on the controller stops a jog the host stops renewing
    for (int i = 0; i < map.size(); ++i) {
        const dev::grbl::AxisLimits& l = m_controller.limits.axes[static_cast<std::size_t>(map[i].grbl)];
        AxisDescriptor d;
        d.letter = QChar::fromLatin1(instrumentLetters[static_cast<std::size_t>(i)]);
        d.unit = d.letter == QLatin1Char('P') ? dev::proto::AxisUnit::Microlitre : dev::proto::AxisUnit::Millimetre;
        const double k = map[i].scale;
        d.maxSpeed = l.maxRateMmS * k;
        d.maxAccel = l.accelMmS2 * k;
        d.maxJerk = 0;
        d.defaultSpeed = d.maxSpeed;  // a move without a speed is a rapid (G0) at the axis' max rate
        d.resolution = l.stepsPerMm > 0 ? k / l.stepsPerMm : 0;
        id.axes.push_back(d);
    }
    m_identity = id;
    m_status = InstrumentStatus{};
    m_status.axes.resize(id.axes.size());
    m_softLimits = QVector<SoftLimits>(id.axes.size());
    updateTravel();
    return true;
}

void GrblClient::updateTravel()
{
    // Machine space per GRBL axis: with homing forcing the origin (OPT Z, grblHAL $22 bit 3) it
    // lies on the side homing comes from; otherwise GRBL's [−travel, 0]. With homing disabled
    // nothing anchors it: the travel is taken from the point set as home towards +.
    const bool homing = m_controller.limits.homingEnabled;
    const bool forceOrigin = m_controller.build.hasOption('Z')
                             || (m_controller.firmware == dev::grbl::Firmware::GrblHal
                                 && ((static_cast<unsigned>(m_controller.settings.value(dev::grbl::setting::kHomingCycle).value_or(0)) >> 3) & 1u));
    // Until the controller of this connection is identified the wiring is the last one's and the
    // limits are not read yet: nothing to anchor (buildIdentity calls this once they are).
    if (m_map.isEmpty() || m_controller.limits.axes.empty())
        return;
    bool changed = false;
    for (int i = 0; i < m_map.size() && i < m_identity.axes.size(); ++i) {
        const auto g = static_cast<std::size_t>(m_map[i].grbl);
        if (g >= m_controller.limits.axes.size())
            continue;
        const dev::grbl::AxisLimits& l = m_controller.limits.axes[g];
        const double wco = g < m_reports.wcoMm.size() ? m_reports.wcoMm[g] : 0.0;
        double lo = 0, hi = l.maxTravelMm;  // work coordinates
        if (homing) {
            const bool positive = forceOrigin && l.homesNegative;
            lo = (positive ? 0.0 : -l.maxTravelMm) - wco;
            hi = (positive ? l.maxTravelMm : 0.0) - wco;
        }
        const double k = m_map[i].scale;
        AxisDescriptor& d = m_identity.axes[i];
        const SoftLimits s{lo * k, hi * k};
        if (d.travelMin != s.min || d.travelMax != s.max || m_softLimits[i].min != s.min || m_softLimits[i].max != s.max)
            changed = true;
        d.travelMin = s.min;
        d.travelMax = s.max;
        m_softLimits[i] = s;
    }
    if (changed && m_phase == Phase::Ready)
        emit limitsChanged();
}

double GrblClient::scaleOf(int axis) const { return axis >= 0 && axis < m_map.size() ? m_map[axis].scale : 1.0; }

motion::msg::Unit GrblClient::unitOf(int axis) const
{
    if (axis >= 0 && axis < m_identity.axes.size() && m_identity.axes[axis].unit == dev::proto::AxisUnit::Microlitre)
        return motion::msg::Unit::Ul;
    return motion::msg::Unit::Mm;
}

char GrblClient::grblLetterOf(int axis) const
{
    const std::string letters = axisLettersOfController();
    if (axis < 0 || axis >= m_map.size() || m_map[axis].grbl >= static_cast<int>(letters.size()))
        return 0;
    return letters[static_cast<std::size_t>(m_map[axis].grbl)];
}

int GrblClient::grblIndexOf(int axis) const { return axis >= 0 && axis < m_map.size() ? m_map[axis].grbl : -1; }

double GrblClient::instrumentValue(int axis, const std::vector<double>& workMm) const
{
    const int g = grblIndexOf(axis);
    return g >= 0 && g < static_cast<int>(workMm.size()) ? workMm[static_cast<std::size_t>(g)] * scaleOf(axis) : 0.0;
}

dev::grbl::JogPlan GrblClient::jogPlan(int axis, double speed) const
{
    dev::grbl::JogPlanInput in;
    const int g = grblIndexOf(axis);
    if (g < 0 || g >= static_cast<int>(m_controller.limits.axes.size()))
        return {};
    const double k = scaleOf(axis);
    in.speedMmS = std::fabs(speed) / k;
    in.maxRateMmS = m_controller.limits.axes[static_cast<std::size_t>(g)].maxRateMmS;
    in.accelMmS2 = m_controller.limits.axes[static_cast<std::size_t>(g)].accelMmS2;
    in.plannerBlocks = m_controller.build.plannerBlocksOrDefault();
    in.refreshPeriodS = m_profile.jog.refreshS;
    in.linkLatencyS = m_profile.jog.linkLatencyS;
    in.stopBudgetS = m_profile.jog.stopBudgetS;
    return dev::grbl::planContinuousJog(in);
}

Capabilities GrblClient::capabilities() const
{
    if (m_identity.axes.isEmpty())
        return {};
    Capabilities c = Capability::SetZero | Capability::Telemetry | Capability::VelocityJog | Capability::MachineLimits;
    // Arcs are G2/G3 in GRBL's XY plane: paths need the instrument's X and Y on GRBL's X and Y.
    if (grblLetterOf(0) == 'X' && grblLetterOf(1) == 'Y')
        c |= Capability::PathQueue;
    if (m_controller.limits.homingEnabled)
        c |= Capability::Homing;
    if (m_identity.kind == dev::proto::DeviceKind::Analyzer && m_identity.axisIndex(QLatin1Char('Z')) >= 0)
        c |= Capability::CoupledXyThenZ;  // moves are sent as XY, then Z
    if (m_identity.axisIndex(QLatin1Char('P')) >= 0)
        c |= Capability::Pump;
    if (m_profile.trigger)
        c |= Capability::TriggerOutput;
    return c;
}

motion::msg::Message GrblClient::missingReason(Capability c) const
{
    motion::msg::Message m = Instrument::missingReason(c);
    const char* because = nullptr;
    switch (c) {
    case Capability::Homing: because = "capability.because.grbl_homing_disabled"; break;
    case Capability::MeasuredPosition:
    case Capability::ClosedLoop:
    case Capability::PidGains:
    case Capability::TuningTests: because = "capability.because.grbl_open_loop"; break;
    case Capability::StopsOnHostLoss: because = "capability.because.grbl_no_watchdog"; break;
    case Capability::SoftLimits: because = "capability.because.grbl_machine_travel"; break;
    case Capability::PathZFollow:
    case Capability::ArchedMove: because = "capability.because.not_in_protocol"; break;
    case Capability::PathQueue: because = "capability.because.grbl_xy_plane"; break;
    case Capability::Pump: because = "capability.because.no_pump_in_profile"; break;
    case Capability::TriggerOutput: because = "capability.because.no_trigger_in_profile"; break;
    default: break;
    }
    if (because)
        m.args.push_back(motion::msg::term("because", because));
    return m;
}

double GrblClient::toAxisUnits(const dev::proto::ChannelRef& c, std::int32_t value) const
{
    switch (c.kind) {
    case dev::proto::ChannelKind::Switches:
    case dev::proto::ChannelKind::ControllerOutput: return value;
    case dev::proto::ChannelKind::ContourError: return value / 1e6;
    default:
        if (c.axis < m_identity.axes.size())
            return value / m_identity.axes[c.axis].wireScale();
        return value;
    }
}

PathClient* GrblClient::paths() { return m_paths; }

} // namespace dev
