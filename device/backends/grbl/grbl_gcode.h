#pragma once
// The lines the GRBL client sends, built in one place so every one is valid for GRBL 1.1:
// millimetres (G21) said on every motion line, feeds in mm/min, numbers in plain decimal
// (GRBL reads no exponents) with 4 decimals at most and trailing zeros dropped, at most
// kMaxLineChars bytes. A line that cannot be built (a non-finite number, a zero feed, a
// line too long) comes back empty with a Message saying why.
//
// Arcs use the centre form (I, J: the centre's offset from the start, incremental as GRBL's
// only arc distance mode G91.1 has it). GRBL refuses an arc whose end is off the circle
// through its start by more than 0.005 mm and 0.1 % of the radius (error:33); 4 decimals
// (0.05 µm rounding per word) stay far inside that.
#include "device/backends/grbl/grbl_protocol.h"
#include "motion/message.h"

#include <optional>
#include <string>
#include <vector>

namespace dev::grbl {

/// "12.5", "-0.0001", "100" ("-0" never): fixed point with at most `decimals` decimals.
std::string formatNumber(double value, int decimals = 4);

struct GcodeLine {
    std::string text;       ///< without '\n'; empty when refused
    motion::msg::Message problem;   ///< grbl.gcode.not_finite{word}, grbl.gcode.bad_feed{feed}, grbl.gcode.too_long{line, limit}
    bool ok() const { return !text.empty(); }
};

struct AxisValue {
    char letter = 'X';
    double mm = 0;
};

enum class Motion { Rapid, Feed };  ///< G0, G1

/// "G90 G21 G1 X10 Y5 F600" (absolute) or "G91 G21 G0 Z-2" (relative). Feed is required
/// for Motion::Feed (GRBL: error:22 without one) and ignored for rapids.
GcodeLine moveLine(Motion motion, bool relative, const std::vector<AxisValue>& axes, double feedMmMin = 0);

enum class ArcDirection { Clockwise, CounterClockwise };  ///< G2, G3 (seen from +Z)
/// "G90 G21 G17 G2 X10 Y0 I5 J0 F600": absolute end point, centre as offsets from the start.
GcodeLine arcLine(ArcDirection dir, double endXMm, double endYMm, double centreOffsetIMm, double centreOffsetJMm,
                  double feedMmMin);
/// A full circle of `radiusMm` around (cx, cy), starting and ending at (cx + r, cy), as
/// `quarters` arcs of 90° each (4 for a circle): GRBL's arc check is most forgiving of
/// short arcs, and each line stays short.
std::vector<GcodeLine> circleLines(double cxMm, double cyMm, double radiusMm, ArcDirection dir, double feedMmMin);

/// "G4 P0.5": dwell, P in seconds (GRBL 1.1; older GRBL and LinuxCNC-style ms do not apply).
/// Waits for every motion before it to finish, so its ok also says "arrived" (the interface
/// document's synchronisation trick).
GcodeLine dwellLine(double seconds);

/// "$J=G91 G21 X1 Y-0.5 F600": an incremental jog, millimetres, feed in mm/min.
GcodeLine jogLine(const std::vector<AxisValue>& deltas, double feedMmMin);

/// How a trigger pulse reaches the outside world.
enum class TriggerOutput {
    GrblHalDigital,  ///< M62/M63 P<port> (with the next motion) or M64/M65 P<port> (at once)
    Coolant,         ///< M8 on / M9 off: stock GRBL's only spare output (flood coolant)
};
/// One switch of a trigger output. `synchronized` (grblHAL only): switch when the motion
/// queued before it has finished (M62/M63) rather than at once (M64/M65). Coolant M8/M9 in
/// GRBL 1.1 waits for the planner to empty first anyway.
GcodeLine outputLine(TriggerOutput kind, bool on, int port = 0, bool synchronized = false);

// System commands.
inline std::string homingLine() { return "$H"; }
inline std::string unlockLine() { return "$X"; }
inline std::string settingsLine() { return "$$"; }
inline std::string buildInfoLine() { return "$I"; }
inline std::string parserStateLine() { return "$G"; }
/// "$110=6000": writes a setting (EEPROM: send it alone, waiting for its ok — the interface
/// document forbids streaming settings with character counting).
GcodeLine settingWriteLine(int id, double value);

} // namespace dev::grbl
