#pragma once
// The realtime status report "<Idle|MPos:0.000,0.000,0.000|FS:0,0|WCO:0.000,0.000,0.000>".
//
// The interface document's rules, which this parser follows:
//   - the first field is the state, with an optional ":N" sub-state (Hold:0, Door:1; grblHAL
//     adds Run:1, Alarm:N and the Tool state); the second is MPos or WPos; every later field
//     may be missing and may come in any order;
//   - only one of MPos/WPos is sent; WCO comes now and then (every 10–30 reports, and at once
//     when it changes), so a host remembers the last WCO and computes the other vector:
//     WPos = MPos − WCO (StatusTracker);
//   - Ov and A come intermittently too; A lists only what is on, so an absent A while Ov
//     is present means everything is off;
//   - with $13=1 positions, WCO and the feed are in inches: StatusTracker converts to mm.
// Unknown fields (grblHAL's H:, WCS:, T:, FW:… or a future firmware's) are kept, not fatal.
// 3 to 6 axes (XYZ + ABC) are accepted; more is refused.
#include "device/backends/grbl/grbl_protocol.h"
#include "motion/message.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dev::grbl {

enum class MachineState { Unknown, Idle, Run, Hold, Jog, Alarm, Door, Check, Home, Sleep, Tool };

/// "Idle" → Idle …; Unknown for anything else.
MachineState machineStateFromName(std::string_view name);
const char* machineStateName(MachineState s);

constexpr std::size_t kMinStatusAxes = 3;
constexpr std::size_t kMaxStatusAxes = 6;
/// Override percentages above this are refused as a damaged report (GRBL's own reach 200).
constexpr double kMaxOverridePercent = 1000;

struct StatusReport {
    MachineState state = MachineState::Unknown;
    int subState = -1;                  ///< Hold:0 → 0; -1 when none was given
    std::string stateName;              ///< as sent, e.g. "Hold"
    std::vector<double> position;       ///< report units (mm, or inch with $13=1)
    bool positionIsMachine = true;      ///< MPos (true) or WPos (false)
    std::optional<std::vector<double>> workOffset;  ///< WCO, same units
    std::optional<int> plannerBlocksFree;           ///< Bf first value
    std::optional<int> rxBytesFree;                 ///< Bf second value
    std::optional<long> lineNumber;                 ///< Ln
    std::optional<double> feedPerMin;               ///< FS/F first value: report units per minute
    std::optional<double> spindleRpm;               ///< FS second value
    std::string pins;                               ///< Pn letters ("XZP"); empty = none triggered
    std::optional<std::array<int, 3>> overridesPercent;  ///< Ov: feed, rapid, spindle
    std::optional<std::string> accessories;         ///< A letters ("SFM"); set only when A was sent
    std::vector<std::pair<std::string, std::string>> unknownFields;  ///< name, value as sent

    bool pinTriggered(char letter) const { return pins.find(letter) != std::string::npos; }
};

struct StatusParse {
    std::optional<StatusReport> report;
    motion::msg::Message problem;  ///< grbl.status.malformed{line, reason} when report is empty
};

/// `payload` is the text between '<' and '>' (Line::payload of a LineKind::Status line).
StatusParse parseStatusReport(std::string_view payload);

/// Positions a person can use, in mm, from a stream of reports: remembers the last WCO,
/// converts inches, and gives both machine and work coordinates.
class StatusTracker {
public:
    /// $13: reports in inches. Positions, WCO and feed are then multiplied by 25.4.
    void setReportInches(bool inches) { m_inches = inches; }
    bool reportInches() const { return m_inches; }
    /// A reset or a new connection: the firmware will send WCO again in its first report.
    void reset();

    /// Takes a report; false (and nothing changes) if its axis count differs from the WCO's.
    bool update(const StatusReport& r);

    MachineState state() const { return m_state; }
    int subState() const { return m_subState; }
    bool havePosition() const { return !m_machineMm.empty(); }
    /// True once a WCO has been seen: until then a WPos report cannot give MPos and vice versa
    /// (GRBL sends WCO in its first report after a reset, so this is short).
    bool haveWorkOffset() const { return !m_wcoMm.empty(); }
    const std::vector<double>& machineMm() const { return m_machineMm; }
    const std::vector<double>& workMm() const { return m_workMm; }
    const std::vector<double>& workOffsetMm() const { return m_wcoMm; }
    std::optional<double> feedMmMin() const { return m_feedMmMin; }
    const std::string& pins() const { return m_pins; }
    const std::array<int, 3>& overridesPercent() const { return m_ov; }
    const std::string& accessories() const { return m_acc; }

private:
    bool m_inches = false;
    MachineState m_state = MachineState::Unknown;
    int m_subState = -1;
    std::vector<double> m_machineMm, m_workMm, m_wcoMm;
    std::optional<double> m_feedMmMin;
    std::string m_pins;
    std::array<int, 3> m_ov{100, 100, 100};
    std::string m_acc;
};

} // namespace dev::grbl
