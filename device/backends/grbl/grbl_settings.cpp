#include "device/backends/grbl/grbl_settings.h"

#include <cmath>

namespace dev::grbl {

void Settings::add(const SettingLine& s)
{
    // grblHAL sends text settings too ($341=…); only numbers matter for limits.
    if (s.value)
        m_values[s.id] = *s.value;
}

std::optional<double> Settings::value(int id) const
{
    const auto it = m_values.find(id);
    if (it == m_values.end())
        return std::nullopt;
    return it->second;
}

namespace {

bool bit(double mask, int i)
{
    if (!(mask >= 0) || mask > 65535)
        return false;
    return (static_cast<unsigned>(mask) >> i) & 1u;
}

} // namespace

LimitsRead machineLimits(const Settings& s, std::string_view axisLetters)
{
    LimitsRead out;
    MachineLimits m;
    auto flag = [&](int id, bool fallback) {
        const auto v = s.value(id);
        return v ? bit(*v, 0) : fallback;
    };
    m.softLimits = flag(setting::kSoftLimits, false);
    m.hardLimits = flag(setting::kHardLimits, false);
    m.homingEnabled = flag(setting::kHomingCycle, false);
    m.reportInches = flag(setting::kReportInches, false);
    m.reportsMachinePosition = flag(setting::kStatusReportMask, true);
    if (const auto v = s.value(setting::kJunctionDeviationMm); v && *v >= 0)
        m.junctionDeviationMm = *v;
    if (const auto v = s.value(setting::kArcToleranceMm); v && *v > 0)
        m.arcToleranceMm = *v;
    if (const auto v = s.value(setting::kHomingPulloffMm); v && *v >= 0)
        m.homingPulloffMm = *v;
    const double dirMask = s.value(setting::kDirInvertMask).value_or(0);
    const double homeMask = s.value(setting::kHomingDirInvertMask).value_or(0);

    if (axisLetters.empty() || axisLetters.size() > 9)
        axisLetters = "XYZ";
    for (std::size_t i = 0; i < axisLetters.size(); ++i) {
        const int k = static_cast<int>(i);
        AxisLimits a;
        a.letter = axisLetters[i];
        a.directionInverted = bit(dirMask, k);
        a.homesNegative = bit(homeMask, k);
        a.stepsPerMm = s.value(setting::kStepsPerMmX + k).value_or(0);
        auto required = [&](int id, double& field, double scale) {
            const auto v = s.value(id);
            if (!v) {
                out.problems.push_back(motion::msg::make("grbl.settings.missing",
                                                 {motion::msg::integer("setting", id, motion::msg::Unit::None), motion::msg::verbatim("axis", std::string(1, a.letter))}));
                return;
            }
            if (!(*v > 0) || !std::isfinite(*v)) {
                out.problems.push_back(motion::msg::make("grbl.settings.invalid", {motion::msg::integer("setting", id, motion::msg::Unit::None),
                                                                          motion::msg::verbatim("axis", std::string(1, a.letter)),
                                                                          motion::msg::real("value", *v)}));
                return;
            }
            field = *v * scale;
        };
        required(setting::kMaxRateMmMinX + k, a.maxRateMmS, 1.0 / 60.0);
        required(setting::kAccelMmS2X + k, a.accelMmS2, 1.0);
        required(setting::kMaxTravelMmX + k, a.maxTravelMm, 1.0);
        m.axes.push_back(a);
    }
    if (m.reportInches)
        out.warnings.push_back(motion::msg::make("grbl.settings.report_inches"));
    if (m.softLimits && !m.homingEnabled)
        out.warnings.push_back(motion::msg::make("grbl.settings.soft_limits_without_homing"));
    if (out.problems.empty())
        out.limits = std::move(m);
    return out;
}

} // namespace dev::grbl
