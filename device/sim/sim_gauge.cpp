#include "device/sim/sim_gauge.h"

#include <cmath>
#include <cstdio>

namespace dev::sim {

SimGauge::SimGauge(std::function<double()> truePositionMm, const GaugeConfig& config)
    : m_truePosition(std::move(truePositionMm)), m_cfg(config), m_rng(config.seed)
{
}

void SimGauge::receive(const std::uint8_t* data, std::size_t size)
{
    for (std::size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\r' || c == '\n') {
            // A request is "?" alone on its line; spaces around it are forgiven.
            const auto first = m_line.find_first_not_of(" \t");
            const auto last = m_line.find_last_not_of(" \t");
            const bool request = !m_overlong && first != std::string::npos && first == last && m_line[first] == '?';
            m_line.clear();
            m_overlong = false;
            if (request)
                answer();
            continue;
        }
        if (m_line.size() >= kMaxLineBytes) {
            m_overlong = true;  // dropped up to the next line end
            continue;
        }
        m_line.push_back(c);
    }
}

std::string SimGauge::format(double valueMm, double resolutionMm)
{
    int decimals = 0;
    for (double r = resolutionMm; decimals < 6 && r < 0.999999; r *= 10)
        ++decimals;
    const double steps = std::round(valueMm / resolutionMm);
    const double v = steps * resolutionMm;
    char buf[64];
    const double mag = std::fabs(v);
    // Three integer digits at least, zero-padded, as gauges print a fixed-width field.
    const int width = decimals > 0 ? 4 + decimals : 3;
    std::snprintf(buf, sizeof buf, "%c%0*.*f mm", (v < 0 && steps != 0) ? '-' : '+', width, decimals, mag);
    return buf;
}

void SimGauge::answer()
{
    ++m_requests;
    std::string line;
    switch (m_fault) {
    case Fault::Silent: return;
    case Fault::Garbage: line = "Err 7"; break;
    case Fault::None: {
        const double noise = m_cfg.noiseMm > 0 ? std::normal_distribution<double>(0, m_cfg.noiseMm)(m_rng) : 0.0;
        line = format(m_truePosition() + noise, m_cfg.resolutionMm);
        break;
    }
    }
    line += "\r\n";
    m_out.insert(m_out.end(), line.begin(), line.end());
}

void SimGauge::drainOutput(std::vector<std::uint8_t>& out)
{
    out.insert(out.end(), m_out.begin(), m_out.end());
    m_out.clear();
}

} // namespace dev::sim
