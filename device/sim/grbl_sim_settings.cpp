#include "device/sim/grbl_sim_settings.h"

#include "device/backends/grbl/grbl_protocol.h"

#include <cmath>
#include <cstdio>

namespace dev::sim {

GrblSimSettings::GrblSimSettings(const MachineConfig& machine, int grblAxes) : m_axes(grblAxes)
{
    // GRBL 1.1's documented defaults for what the machine does not decide…
    m_values = {{0, 10},   {1, 25},    {2, 0},   {3, 0},  {4, 0},     {5, 0},     {6, 0},  {10, 1},
                {11, 0.010}, {12, 0.002}, {13, 0}, {24, 25.0}, {25, 500.0}, {26, 250}, {27, 1.0},
                {30, 1000}, {31, 0},   {32, 0}};
    // …and a machine set up the way a lab would: homing (towards the switches at the low end
    // of every axis), soft and hard limits on.
    m_values[20] = 1;
    m_values[21] = 1;
    m_values[22] = 1;
    m_values[23] = (1 << grblAxes) - 1;
    for (int k = 0; k < grblAxes; ++k) {
        const bool real = k < static_cast<int>(machine.axes.size());
        const AxisConfig a = real ? machine.axes[static_cast<std::size_t>(k)] : AxisConfig{};
        m_values[100 + k] = real ? 1.0 / a.stepSize : 250;
        m_values[110 + k] = real ? a.maxSpeed * 60 : 1000;
        m_values[120 + k] = real ? a.maxAccel : 100;
        m_values[130 + k] = real ? a.travel : 50;
    }
}

double GrblSimSettings::get(int id) const
{
    const auto it = m_values.find(id);
    return it == m_values.end() ? 0.0 : it->second;
}

int GrblSimSettings::write(int id, double value)
{
    if (!has(id))
        return dev::grbl::err::kInvalidStatement;
    if (!std::isfinite(value))
        return dev::grbl::err::kBadNumberFormat;
    if (value < 0)
        return dev::grbl::err::kNegativeValue;
    const bool axisRate = (id >= 100 && id < 100 + m_axes) || (id >= 110 && id < 110 + m_axes)
                          || (id >= 120 && id < 120 + m_axes);
    if (axisRate && value <= 0)
        return dev::grbl::err::kNegativeValue;  // a zero rate would stall the planner (grblHAL says error:19)
    if (id == 20 && value != 0 && !homingEnabled())
        return dev::grbl::err::kSoftLimitNeedsHoming;
    m_values[id] = value;
    if (id == 22 && value == 0)
        m_values[20] = 0;  // soft limits cannot stay on without homing
    return 0;
}

std::string GrblSimSettings::printout() const
{
    std::string out;
    char buf[64];
    for (const auto& [id, v] : m_values) {
        // GRBL prints masks and counts as integers and lengths and rates with 3 decimals.
        const bool integer = id < 11 || (id >= 13 && id <= 23) || id == 26 || id == 32;
        if (integer)
            std::snprintf(buf, sizeof buf, "$%d=%d\r\n", id, static_cast<int>(v));
        else
            std::snprintf(buf, sizeof buf, "$%d=%.3f\r\n", id, v);
        out += buf;
    }
    return out;
}

} // namespace dev::sim
