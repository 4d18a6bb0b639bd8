#pragma once
// The simulator's GRBL personality: GRBL 1.1 (or grblHAL) spoken over the same simulated
// machine as the BenchPilot firmware, with the same host-facing shape as dev::sim::Firmware —
// bytes in, virtual time advanced by the host, bytes out — so the pty host and the
// in-process link can run either.
//
// It follows the GRBL 1.1 interface, commands, jogging and settings documents:
//   - welcome banner at power-up and after 0x18; "[MSG:'$H'|'$X' to unlock]" and the Alarm
//     state while homing is enabled and the machine is not homed (homing init lock);
//   - realtime bytes picked off on arrival: ? status, ! feed hold, ~ resume, 0x18 soft reset,
//     0x85 jog cancel (override bytes are accepted and change nothing, see docs/grbl.md);
//   - a receive buffer of 128 bytes (grblHAL: 1024) of which the ring keeps one free: bytes
//     beyond it are lost as on real hardware — the host must count characters;
//   - one ok or error:N per line, in order; a motion line is answered when it is in the
//     planner (15 blocks; grblHAL 35), G4 and M8/M9 when the motion before them has finished;
//   - ALARM:3 for a reset while moving, ALARM:1 on a limit switch with $21=1, ALARM:2 for a
//     G-code target beyond the travel with $20=1 (both then wait for a reset), error:15 for
//     a jog beyond it, error:5 for $H with homing disabled;
//   - outputs (M8/M9, grblHAL M62–M65) recorded with the machine time they switched;
//   - a board wired to restart when a host opens its port (an Arduino's DTR line), or one that
//     does not (most grblHAL boards, native USB): setRestartsOnPortOpen().
// What it knowingly does differently from real firmware is listed in docs/grbl.md.
#include "device/sim/grbl_sim_gcode.h"
#include "device/sim/grbl_sim_motion.h"
#include "device/sim/grbl_sim_settings.h"
#include "device/sim/serial_device.h"
#include "device/sim/sim_machine.h"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace dev::sim {

class GrblFirmware : public SerialDevice {
public:
    enum class Dialect { Grbl, GrblHal };
    enum class State { Idle, Run, Hold, Jog, Alarm, Home };

    /// An output switching: flood coolant (port -1) or a grblHAL digital output.
    struct OutputEvent {
        double timeS = 0;  ///< machine time
        int port = -1;
        bool on = false;
    };

    GrblFirmware(const MachineConfig& config, Dialect dialect = Dialect::Grbl);

    /// Bytes from the host, in any chunking.
    void receive(const std::uint8_t* data, std::size_t size) override;
    /// Runs the machine for `dtS` of virtual time (whole ticks; the remainder carries).
    void advance(double dtS) override;
    /// Moves the bytes the device has sent since the last call to `out`.
    void drainOutput(std::vector<std::uint8_t>& out) override;
    /// A host opened the port: a board that restarts on it does (restart()).
    void portOpened() override;
    /// Whether the board restarts when a host opens its port (off: it does not, and what it
    /// sent meanwhile was lost on a closed port).
    void setRestartsOnPortOpen(bool restarts) { m_restartsOnOpen = restarts; }
    bool restartsOnPortOpen() const { return m_restartsOnOpen; }
    /// Power-up again (a reset button, a brown-out, DTR): the steppers stop dead, every buffer is
    /// emptied, the step counters start at 0 where the axes stand, the homing lock comes back;
    /// the settings and G54 offset (EEPROM) stay. Then the banner.
    void restart();
    int restarts() const { return m_restarts; }

    SimMachine& machine() { return m_machine; }
    const SimMachine& machine() const { return m_machine; }
    GrblSimSettings& settings() { return m_settings; }
    Dialect dialect() const { return m_dialect; }
    State state() const { return m_state; }
    int alarmCode() const { return m_alarm; }
    /// GRBL machine position (MPos) in mm, one per GRBL axis.
    const std::vector<double>& machinePositionMm() const { return m_motion.positionMm(); }
    /// The G54 work offset (WCO): work position = machine position − offset.
    const std::vector<double>& workOffsetMm() const { return m_workOffset; }
    const std::string& axisLetters() const { return m_letters; }
    const std::vector<OutputEvent>& outputEvents() const { return m_outputs; }
    /// For tests that time a stop on the simulator's clock: when a 0x85 (jog cancel) last
    /// arrived (−1: never), when the motion last came to rest, and how many times it did.
    double lastJogCancelAtS() const { return m_jogCancelsS.empty() ? -1 : m_jogCancelsS.back(); }
    const std::vector<double>& jogCancelTimesS() const { return m_jogCancelsS; }
    /// The most bytes the receive buffer ever held (for tests of the host's character counting).
    std::size_t maxRxBytesQueued() const { return m_maxRx; }
    double lastMotionEndAtS() const { return m_lastMotionEndS; }
    int motionEnds() const { return m_motionEnds; }
    std::size_t rxBufferBytes() const { return m_rxSize; }
    std::size_t rxBytesQueued() const { return m_rx.size(); }
    std::uint64_t lostRxBytes() const { return m_lostRx; }
    int plannerBlocks() const { return m_motion.capacity(); }

private:
    // grbl_firmware.cpp: bytes, time, states.
    void realtime(std::uint8_t b);
    void softReset();
    void tick();
    void readLines();
    void raiseAlarm(int code, bool critical);
    void welcome();
    void send(const std::string& line);  ///< appends "\r\n"
    void answer(int error);              ///< ok or error:N for the line being executed
    void applyPosition();
    void fireOutputs(const std::vector<GrblBlock::Output>& outs);
    bool checkHardLimits();
    bool withinTravel(const std::vector<double>& targetMm) const;
    GrblMotion::Limits limits() const;
    // grbl_firmware_lines.cpp: one line.
    void executeLine(const std::string& raw);
    int systemCommand(const std::string& line);
    int gcodeLine(const std::string& line);
    int jogLine(const std::string& command);
    void continuePending();
    // grbl_firmware_report.cpp: what it prints.
    void statusReport();
    std::string numbers(const std::vector<double>& mm) const;
    void buildInfo();
    void parserState();
    void parameters();

    SimMachine m_machine;
    Dialect m_dialect;
    std::string m_letters;  ///< "XYZ" or "XYZA"
    int m_axes;
    GrblSimSettings m_settings;
    GrblMotion m_motion;
    GrblModalState m_modal;
    std::vector<double> m_origin;  ///< SimMachine reference (machine coordinates) where MPos is 0
    std::vector<double> m_workOffset;  ///< G54 (G10 L2/L20), mm per axis; kept through resets like GRBL's EEPROM copy

    State m_state = State::Idle;
    int m_alarm = 0;
    bool m_critical = false;       ///< hard/soft limit alarm: nothing but a reset is heard
    bool m_homed = false;
    bool m_jogCancel = false;      ///< 0x85 or ! while jogging: stop, then flush
    bool m_softLimitHold = false;  ///< a G-code target beyond the travel: stop, then ALARM:2
    double m_pendingS = 0;

    // Receive side: the ring buffer, and the line GRBL is assembling from it.
    std::size_t m_rxSize;
    std::deque<char> m_rx;
    std::string m_line;
    bool m_lineOverflow = false;
    std::uint64_t m_lostRx = 0;
    bool m_statusRequested = false;

    // A line whose ok waits: points still to queue (arcs, a full planner), a sync (G4, M8/M9),
    // or homing.
    struct Pending {
        bool active = false;
        std::vector<std::vector<double>> points;  ///< targets still to push
        double feedMmS = 0;
        bool jog = false;
        long line = 0;
        std::vector<GrblBlock::Output> outputs;   ///< with the first point pushed
        bool syncOutputs = false;                 ///< outputs once the planner is empty
        double dwellS = -1;                       ///< ≥ 0: dwell once the planner is empty
        double dwellUntilS = -1;
        bool homing = false;
    } m_pending;

    std::string m_out;
    std::vector<OutputEvent> m_outputs;
    int m_reportCount = 0;         ///< WCO in the first report after a reset and every 10th
    std::vector<double> m_jogCancelsS;  ///< bounded: the last 64
    double m_lastMotionEndS = -1;
    std::size_t m_maxRx = 0;
    int m_motionEnds = 0;
    bool m_wasMoving = false;
    bool m_restartsOnOpen = false;
    int m_restarts = 0;
};

} // namespace dev::sim
