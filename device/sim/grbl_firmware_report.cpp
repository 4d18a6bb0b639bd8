// What the GRBL personality prints: the status report, $I, $G and $#.
#include "device/sim/grbl_firmware.h"

#include "device/backends/grbl/grbl_protocol.h"

#include <cmath>
#include <cstdio>

namespace dev::sim {

std::string GrblFirmware::numbers(const std::vector<double>& mm) const
{
    // mm with 3 decimals, or inches with 4 when $13=1 (GRBL's N_DECIMAL_COORDVALUE_*).
    const bool inches = m_settings.reportInches();
    std::string s;
    char buf[32];
    for (std::size_t i = 0; i < mm.size(); ++i) {
        double v = inches ? mm[i] / dev::grbl::kMmPerInch : mm[i];
        if (std::fabs(v) < 5e-5)
            v = 0;  // never "-0.000"
        std::snprintf(buf, sizeof buf, inches ? "%.4f" : "%.3f", v);
        if (i)
            s += ',';
        s += buf;
    }
    return s;
}

void GrblFirmware::statusReport()
{
    std::string r = "<";
    switch (m_state) {
    case State::Idle: r += "Idle"; break;
    case State::Run: r += "Run"; break;
    case State::Hold: r += m_motion.holdComplete() ? "Hold:0" : "Hold:1"; break;
    case State::Jog: r += "Jog"; break;
    case State::Alarm: r += "Alarm"; break;
    case State::Home: r += "Home"; break;
    }
    // During homing the step counters follow the machine's own cycle.
    std::vector<double> pos = m_motion.positionMm();
    if (m_state == State::Home)
        for (int i = 0; i < m_machine.axisCount(); ++i)
            pos[static_cast<std::size_t>(i)] = m_machine.axis(i).reference() - m_origin[static_cast<std::size_t>(i)];
    // WPos = MPos − WCO (G54 only: no G92, no tool length offset here).
    if (!m_settings.reportMachinePosition())
        for (std::size_t i = 0; i < pos.size() && i < m_workOffset.size(); ++i)
            pos[i] -= m_workOffset[i];
    r += m_settings.reportMachinePosition() ? "|MPos:" : "|WPos:";
    r += numbers(pos);
    if (m_settings.reportBuffers())
        r += "|Bf:" + std::to_string(m_motion.freeBlocks()) + "," + std::to_string(m_rxSize - 1 - m_rx.size());
    if (m_motion.currentLine() > 0)
        r += "|Ln:" + std::to_string(m_motion.currentLine());
    const double feed = m_motion.speedMmS() * 60 / (m_settings.reportInches() ? dev::grbl::kMmPerInch : 1.0);
    r += "|FS:" + std::to_string(static_cast<long>(std::lround(feed))) + ",0";
    std::string pins;
    for (int i = 0; i < m_machine.axisCount(); ++i)
        if (m_machine.axis(i).homeSwitch() || m_machine.axis(i).limitSwitch())
            pins += m_letters[static_cast<std::size_t>(i)];
    if (!pins.empty())
        r += "|Pn:" + pins;
    // WCO in the first report after a reset and every 10th; Ov (with A) in the one after,
    // never beside WCO, as the interface document describes.
    const int n = m_reportCount++;
    if (n % 10 == 0) {
        r += "|WCO:" + numbers(m_workOffset);
    } else if (n % 10 == 1) {
        r += "|Ov:100,100,100";
        bool flood = false;
        for (const auto& e : m_outputs)
            if (e.port < 0)
                flood = e.on;
        if (flood)
            r += "|A:F";
    }
    send(r + ">");
}

void GrblFirmware::buildInfo()
{
    if (m_dialect == Dialect::Grbl) {
        send("[VER:1.1h.20190830:BenchPilot simulator]");
        send("[OPT:VZ," + std::to_string(m_motion.capacity()) + "," + std::to_string(m_rxSize) + "]");
        return;
    }
    send("[VER:1.1f.20231210:BenchPilot simulator]");
    send("[OPT:VNZ," + std::to_string(m_motion.capacity()) + "," + std::to_string(m_rxSize) + "," + std::to_string(m_axes)
         + ",0]");
    send("[AXS:" + std::to_string(m_axes) + ":" + m_letters + "]");
    send("[NEWOPT:ENUMS,RT+,HOME]");
    send("[FIRMWARE:grblHAL]");
    send("[DRIVER:BenchPilot simulator]");
    send("[AUX IO:0,4,0,0]");
}

void GrblFirmware::parserState()
{
    char feed[32];
    std::snprintf(feed, sizeof feed, "%g", m_modal.inches ? m_modal.feedMmMin / dev::grbl::kMmPerInch : m_modal.feedMmMin);
    send(std::string("[GC:G") + std::to_string(m_modal.motion) + " G54 G17 " + (m_modal.inches ? "G20" : "G21") + " "
         + (m_modal.relative ? "G91" : "G90") + " G94 M5 " + (m_modal.flood ? "M8" : "M9") + " T0 F" + feed + " S0]");
}

void GrblFirmware::parameters()
{
    const std::string zero = numbers(std::vector<double>(static_cast<std::size_t>(m_axes), 0.0));
    send("[G54:" + numbers(m_workOffset) + "]");
    for (const char* g : {"G55", "G56", "G57", "G58", "G59", "G28", "G30", "G92"})
        send(std::string("[") + g + ":" + zero + "]");
    send("[TLO:0.000]");
    send("[PRB:" + zero + ":0]");
}

} // namespace dev::sim
