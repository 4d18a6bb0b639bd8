#pragma once
// Lines from a GRBL 1.1 or grblHAL controller: splitting the byte stream into lines
// (bounded: a flood without line ends, or a half line before a reset, never grows memory
// or crashes), and telling what each line is. Parsers of the lines that carry data sit
// beside it: grbl_status.h (<…> reports), grbl_build_info.h ($I), grbl_settings.h ($N=V).
//
// Every kind of line the interface document lists is recognised; anything else is
// LineKind::Unknown, for the client to log and otherwise ignore (never fatal).
#include "device/backends/grbl/grbl_protocol.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::grbl {

/// Splits bytes into lines at '\n'; a '\r' before it is dropped (GRBL ends lines with
/// "\r\n"). A line longer than kMaxLineBytes is cut there and marked truncated: the rest
/// up to the next '\n' is dropped and counted, so garbage without line ends costs nothing.
class LineReader {
public:
    static constexpr std::size_t kMaxLineBytes = 1024;
    struct Line {
        std::string text;
        bool truncated = false;
    };
    /// Appends every line completed by `bytes` to `out`.
    void feed(std::string_view bytes, std::vector<Line>& out);
    /// The half line received so far (e.g. to drop it on a reset).
    const std::string& partial() const { return m_partial; }
    void clear();
    std::size_t droppedBytes() const { return m_dropped; }

private:
    std::string m_partial;
    bool m_overflow = false;
    std::size_t m_dropped = 0;
};

enum class LineKind {
    Empty,
    Ok,             ///< response: the oldest unacknowledged line succeeded
    Error,          ///< response "error:N": the oldest unacknowledged line failed; code = N
    Alarm,          ///< push "ALARM:N"; code = N
    Status,         ///< "<…>" status report (grbl_status.h)
    Banner,         ///< welcome message after power-up or reset: the firmware forgot everything
    Message,        ///< "[MSG:…]" feedback
    ParserState,    ///< "[GC:…]" answer to $G
    Help,           ///< "[HLP:…]" answer to $
    Version,        ///< "[VER:…]" first line of $I
    Options,        ///< "[OPT:…]" second line of $I
    Probe,          ///< "[PRB:x,y,z:ok]"
    Echo,           ///< "[echo:…]"
    Bracketed,      ///< any other "[TAG:…]": $# parameters ([G54:…], [TLO:…]) and grblHAL's $I extras
    Setting,        ///< "$N=V"
    StartupBlock,   ///< "$Nn=line" (answer to $N) or ">line:ok" (a startup line ran)
    Unknown,
};

struct Line {
    LineKind kind = LineKind::Unknown;
    int code = 0;               ///< Error, Alarm; grblHAL's "error:N" variants included
    std::string_view tag;       ///< Bracketed and the named bracket kinds: "MSG", "G54", "AXS"…
    std::string_view payload;   ///< text after "TAG:" up to the closing ']' (or after "<" for Status)
};

/// What one line is. `text` has no line end; the result's views point into it.
Line classifyLine(std::string_view text);

struct Banner {
    Firmware firmware = Firmware::Unknown;
    std::string version;  ///< "1.1h"
};
/// "Grbl 1.1h ['$' for help]", "GrblHAL 1.1f ['$' or '$HELP' for help]"; also tolerates a
/// prefix of noise before "Grbl" (a half line cut by the reset).
std::optional<Banner> parseBanner(std::string_view text);

/// "$110=500.000": id and value; the text keeps what came after '=' (grblHAL may send
/// strings, e.g. "$341=Zz"). nullopt when the line is not a numbered setting.
struct SettingLine {
    int id = 0;
    std::optional<double> value;
    std::string text;
};
std::optional<SettingLine> parseSettingLine(std::string_view text);

/// "[PRB:1.000,2.000,-3.500:1]": position in report units and whether the probe touched.
struct ProbeLine {
    std::vector<double> position;
    bool succeeded = false;
};
std::optional<ProbeLine> parseProbeLine(std::string_view payload);

/// Comma-separated numbers ("1.000,-2.5,3"); nullopt if any field is not a number or there
/// are more than `maxCount`.
std::optional<std::vector<double>> parseNumberList(std::string_view text, std::size_t maxCount = 9);
/// A whole string as a finite number ("-12.5", "3", ".5"); nullopt otherwise.
std::optional<double> parseNumber(std::string_view text);

} // namespace dev::grbl
