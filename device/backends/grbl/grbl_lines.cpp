#include "device/backends/grbl/grbl_lines.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dev::grbl {

// ---- LineReader -------------------------------------------------------------------------

void LineReader::feed(std::string_view bytes, std::vector<Line>& out)
{
    for (const char c : bytes) {
        if (c == '\n') {
            if (!m_partial.empty() && m_partial.back() == '\r')
                m_partial.pop_back();
            out.push_back({std::move(m_partial), m_overflow});
            m_partial.clear();
            m_overflow = false;
            continue;
        }
        if (m_partial.size() >= kMaxLineBytes) {
            m_overflow = true;
            ++m_dropped;
            continue;
        }
        m_partial.push_back(c);
    }
}

void LineReader::clear()
{
    m_dropped += m_partial.size();
    m_partial.clear();
    m_overflow = false;
}

// ---- numbers --------------------------------------------------------------------------

std::optional<double> parseNumber(std::string_view text)
{
    // strtod would also take "inf", "nan", hex and leading spaces: GRBL prints none of these.
    if (text.empty() || text.size() > 32)
        return std::nullopt;
    std::size_t i = 0;
    if (text[0] == '-' || text[0] == '+')
        ++i;
    bool digits = false, dot = false;
    for (std::size_t k = i; k < text.size(); ++k) {
        const char c = text[k];
        if (c >= '0' && c <= '9')
            digits = true;
        else if (c == '.' && !dot)
            dot = true;
        else
            return std::nullopt;
    }
    if (!digits)
        return std::nullopt;
    const std::string s(text);
    errno = 0;
    const double v = std::strtod(s.c_str(), nullptr);
    if (errno == ERANGE || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<std::vector<double>> parseNumberList(std::string_view text, std::size_t maxCount)
{
    std::vector<double> out;
    while (true) {
        const std::size_t comma = text.find(',');
        const auto v = parseNumber(text.substr(0, comma));
        if (!v || out.size() >= maxCount)
            return std::nullopt;
        out.push_back(*v);
        if (comma == std::string_view::npos)
            return out;
        text.remove_prefix(comma + 1);
    }
}

namespace {

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

/// A decimal code of 1–3 digits (error:N, ALARM:N); -1 otherwise.
int parseCode(std::string_view s)
{
    if (s.empty() || s.size() > 3)
        return -1;
    int v = 0;
    for (const char c : s) {
        if (c < '0' || c > '9')
            return -1;
        v = v * 10 + (c - '0');
    }
    return v;
}

} // namespace

// ---- classification ---------------------------------------------------------------------

Line classifyLine(std::string_view t)
{
    Line l;
    if (t.empty()) {
        l.kind = LineKind::Empty;
        return l;
    }
    if (t == "ok") {
        l.kind = LineKind::Ok;
        return l;
    }
    if (startsWith(t, "error:")) {
        const int code = parseCode(t.substr(6));
        l.kind = code >= 0 ? LineKind::Error : LineKind::Unknown;
        l.code = std::max(code, 0);
        return l;
    }
    if (startsWith(t, "ALARM:")) {
        const int code = parseCode(t.substr(6));
        l.kind = code >= 0 ? LineKind::Alarm : LineKind::Unknown;
        l.code = std::max(code, 0);
        return l;
    }
    // A reset can cut a report or message short; the banner then follows on the same line.
    if ((t.front() == '<' || t.front() == '[') && parseBanner(t)) {
        l.kind = LineKind::Banner;
        return l;
    }
    const bool complete = t.size() >= 3 && ((t.front() == '<' && t.back() == '>') || (t.front() == '[' && t.back() == ']'));
    if ((t.front() == '<' || t.front() == '[') && !complete)
        return l;
    if (t.front() == '<') {
        l.kind = LineKind::Status;
        l.payload = t.substr(1, t.size() - 2);
        return l;
    }
    if (t.front() == '[') {
        const std::string_view inner = t.substr(1, t.size() - 2);
        const std::size_t colon = inner.find(':');
        l.tag = inner.substr(0, colon);
        l.payload = colon == std::string_view::npos ? std::string_view{} : inner.substr(colon + 1);
        if (l.tag == "MSG")
            l.kind = LineKind::Message;
        else if (l.tag == "GC")
            l.kind = LineKind::ParserState;
        else if (l.tag == "HLP")
            l.kind = LineKind::Help;
        else if (l.tag == "VER")
            l.kind = LineKind::Version;
        else if (l.tag == "OPT")
            l.kind = LineKind::Options;
        else if (l.tag == "PRB")
            l.kind = LineKind::Probe;
        else if (l.tag == "echo")
            l.kind = LineKind::Echo;
        else
            l.kind = LineKind::Bracketed;
        return l;
    }
    if (t.front() == '$') {
        if (startsWith(t, "$N") && t.find('=') != std::string_view::npos) {
            l.kind = LineKind::StartupBlock;
            l.payload = t.substr(t.find('=') + 1);
        } else if (parseSettingLine(t)) {
            l.kind = LineKind::Setting;
        }
        return l;
    }
    if (t.front() == '>') {
        l.kind = LineKind::StartupBlock;
        l.payload = t.substr(1);
        return l;
    }
    if (parseBanner(t)) {
        l.kind = LineKind::Banner;
        return l;
    }
    return l;
}

std::optional<Banner> parseBanner(std::string_view t)
{
    // The banner follows a reset, so the byte before it may be the tail of a line the
    // reset cut: look for the name anywhere, then require the help hint after it.
    for (const auto& [name, fw] : {std::pair<std::string_view, Firmware>{"GrblHAL ", Firmware::GrblHal},
                                   std::pair<std::string_view, Firmware>{"Grbl ", Firmware::Grbl}}) {
        const std::size_t at = t.find(name);
        if (at == std::string_view::npos)
            continue;
        std::string_view rest = t.substr(at + name.size());
        const std::size_t space = rest.find(' ');
        if (space == std::string_view::npos || space == 0)
            continue;
        const std::string_view version = rest.substr(0, space);
        if (version.front() < '0' || version.front() > '9' || rest.find("for help]", space) == std::string_view::npos)
            continue;
        return Banner{fw, std::string(version)};
    }
    return std::nullopt;
}

std::optional<SettingLine> parseSettingLine(std::string_view t)
{
    if (t.size() < 3 || t[0] != '$')
        return std::nullopt;
    const std::size_t eq = t.find('=');
    if (eq == std::string_view::npos || eq < 2 || eq > 6)
        return std::nullopt;
    int id = 0;
    for (std::size_t i = 1; i < eq; ++i) {
        if (t[i] < '0' || t[i] > '9')
            return std::nullopt;
        id = id * 10 + (t[i] - '0');
    }
    SettingLine s;
    s.id = id;
    s.text = std::string(t.substr(eq + 1));
    s.value = parseNumber(s.text);
    return s;
}

std::optional<ProbeLine> parseProbeLine(std::string_view payload)
{
    const std::size_t colon = payload.rfind(':');
    if (colon == std::string_view::npos)
        return std::nullopt;
    const std::string_view flag = payload.substr(colon + 1);
    if (flag != "0" && flag != "1")
        return std::nullopt;
    auto pos = parseNumberList(payload.substr(0, colon));
    if (!pos)
        return std::nullopt;
    return ProbeLine{std::move(*pos), flag == "1"};
}

} // namespace dev::grbl
