#pragma once
// A simulated length gauge on its own serial line: a digital indicator or length
// gauge that reads where the work point truly is, in the dialect docs/accuracy.md
// ("Gauge dialect") gives. The host sends '?' and CR; the gauge answers one line,
// a signed reading with its unit and CR LF:
//
//   ?\r            →  +012.3456 mm\r\n
//
// The reading is the true position (a function the host of the simulator hands in,
// usually SimMachine::workPointLogical) plus Gaussian noise, rounded to the gauge's
// resolution. Anything else the host sends is ignored, as real gauges do; a line
// longer than kMaxLineBytes is dropped. Faults for tests: answer garbage, or nothing.
#include "device/sim/serial_device.h"

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace dev::sim {

struct GaugeConfig {
    double resolutionMm = 0.0001;  ///< the last digit: 0.1 µm prints four decimals
    double noiseMm = 0.0001;       ///< σ of the Gaussian noise on each reading
    std::uint64_t seed = 2718;
};

class SimGauge : public SerialDevice {
public:
    static constexpr std::size_t kMaxLineBytes = 64;
    enum class Fault { None, Garbage, Silent };

    SimGauge(std::function<double()> truePositionMm, const GaugeConfig& config);

    void receive(const std::uint8_t* data, std::size_t size) override;
    void advance(double) override {}
    void drainOutput(std::vector<std::uint8_t>& out) override;

    void setFault(Fault f) { m_fault = f; }
    const GaugeConfig& config() const { return m_cfg; }
    /// The reading as the gauge prints it: sign, three or more integer digits, the
    /// resolution's decimals, " mm" (no line end).
    static std::string format(double valueMm, double resolutionMm);
    std::uint64_t requests() const { return m_requests; }

private:
    void answer();

    std::function<double()> m_truePosition;
    GaugeConfig m_cfg;
    std::mt19937_64 m_rng;
    std::string m_line;
    bool m_overlong = false;
    std::vector<std::uint8_t> m_out;
    Fault m_fault = Fault::None;
    std::uint64_t m_requests = 0;
};

} // namespace dev::sim
