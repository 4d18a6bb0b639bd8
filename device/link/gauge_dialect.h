#pragma once
// The line dialect of a digital indicator or length gauge on a serial port, as
// BenchPilot speaks it (docs/accuracy.md, "Gauge dialect"). Plain C++, fuzzed.
//
// The host sends '?' and CR. The gauge answers one line, ended by CR, LF or CR LF:
//
//   [spaces] [sign] digits [. digits] [spaces] unit [spaces]
//
//  - sign: '+' or '-', or none (positive);
//  - the number: decimal with '.', at least one digit, no exponent, at most 15
//    significant characters; a ',' decimal, "1e-3", "--.--", "Err 7" are not readings;
//  - unit: mm, um, µm (UTF-8 µ or the micro sign U+00B5 or Greek mu U+03BC), in,
//    inch; case-insensitive. A reading without a unit is refused: a gauge set to
//    inches would otherwise be read as millimetres.
// Anything else is refused with what the gauge sent, made printable.
#include "motion/message.h"

#include <optional>
#include <string>
#include <string_view>

namespace dev::gaugewire {

/// What the host writes to ask for one reading.
constexpr const char* kRequest = "?\r";
/// Longest line the host keeps: a gauge that sends more without a line end is talking nonsense.
constexpr std::size_t kMaxAnswerBytes = 64;

struct Answer {
    std::optional<double> valueMm;  ///< the reading, converted to mm
    /// Why there is no value: gauge.not_a_reading {port, text} or
    /// gauge.unknown_unit {port, text, unit}.
    motion::msg::Message problem;
};

/// One answer line (without its line end). `port` names the port in messages.
Answer parseAnswer(std::string_view line, const std::string& port);

/// Bytes as a person can read them in a message: printable ASCII and UTF-8 as they
/// are, control and invalid bytes as \r, \n, \t or \xHH; cut to 80 characters with "…".
std::string printable(std::string_view bytes);

} // namespace dev::gaugewire
