#pragma once
// The simulated GRBL's G-code parser: the subset a motion controller for lab instruments
// needs, with GRBL 1.1's modal state and its error codes for what it refuses.
//   motion   G0 G1 G2 G3 (centre form I J; the R form is refused), G4 P<seconds>
//   modes    G17 G20 G21 G53 G54 G90 G91 G94; F in units per minute
//   offsets  G10 L2 / L20 with P0 or P1: the G54 work offset (the only coordinate system here)
//   outputs  M8 M9 (coolant), M62–M65 P<n> (grblHAL only), M3 M5 accepted and ignored
//   words    N (line number), S accepted
// Everything else is error:20, as on a GRBL built without it. Positions come out in mm
// (G20 converts inches here), absolute or relative to the parser's current position.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::sim {

struct GrblModalState {
    int motion = 0;            ///< 0, 1, 2, 3
    bool relative = false;     ///< G91
    bool inches = false;       ///< G20
    double feedMmMin = 0;      ///< F, always stored in mm/min
    bool flood = false;        ///< M8
};

struct GrblBlock {
    enum class Kind { None, Line, Arc, Dwell, Output, SetWorkOffset };
    Kind kind = Kind::None;
    bool rapid = false;
    bool machineCoordinates = false;   ///< G53
    std::vector<double> targetMm;      ///< absolute machine coordinates, one per axis (SetWorkOffset: the new G54 offset)
    bool clockwise = false;            ///< G2
    double centreMm[2] = {0, 0};       ///< absolute XY centre of an arc
    double feedMmMin = 0;
    double dwellS = 0;
    // Output changes in this block, in order (M8/M9, M62–M65).
    struct Output {
        int port = -1;                 ///< -1: flood coolant
        bool on = false;
        bool synchronized = true;      ///< M8/M9 and M62/M63 wait for motion; M64/M65 act at once
    };
    std::vector<Output> outputs;
    long lineNumber = 0;
};

struct GrblParse {
    int error = 0;  ///< error:N code; 0 = parsed
    GrblBlock block;
};

/// Parses one line (without '\n') against `state`, updating it only when the line is
/// accepted. `positionMm`: where the previous motion ends, per axis, in machine coordinates.
/// `workOffsetMm`: the G54 offset (work = machine − offset); empty means none. `axisLetters`
/// e.g. "XYZA".
GrblParse parseGrblLine(std::string_view line, GrblModalState& state, const std::vector<double>& positionMm,
                        std::string_view axisLetters, bool grblHal, const std::vector<double>& workOffsetMm = {});

/// "$J=" jogs: `command` is what follows '='. G20/G21/G90/G91/G53 apply to this line only;
/// anything but them, axis words, F and N is error:16; F is required (error:22).
GrblParse parseGrblJog(std::string_view command, const GrblModalState& state, const std::vector<double>& positionMm,
                       std::string_view axisLetters, const std::vector<double>& workOffsetMm = {});

/// Line after GRBL's pre-parser: spaces and comments "(…)" and ";…" removed, letters upper case.
std::string grblCleanLine(std::string_view line);

} // namespace dev::sim
