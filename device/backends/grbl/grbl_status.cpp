#include "device/backends/grbl/grbl_status.h"

#include "device/backends/grbl/grbl_lines.h"

#include <algorithm>

namespace dev::grbl {

namespace {

constexpr std::pair<const char*, MachineState> kStates[] = {
    {"Idle", MachineState::Idle}, {"Run", MachineState::Run},     {"Hold", MachineState::Hold},
    {"Jog", MachineState::Jog},   {"Alarm", MachineState::Alarm}, {"Door", MachineState::Door},
    {"Check", MachineState::Check}, {"Home", MachineState::Home}, {"Sleep", MachineState::Sleep},
    {"Tool", MachineState::Tool},
};

StatusParse refuse(std::string_view payload, const char* reason)
{
    StatusParse p;
    p.problem = motion::msg::make("grbl.status.malformed",
                          {motion::msg::verbatim("line", "<" + std::string(payload.substr(0, 200)) + ">"), motion::msg::term("reason", reason)});
    return p;
}

std::optional<int> subStateNumber(std::string_view s)
{
    const auto v = parseNumber(s);
    if (!v || *v < -1e9 || *v > 1e9 || *v != static_cast<double>(static_cast<long>(*v)))
        return std::nullopt;
    return static_cast<int>(*v);
}

bool onlyLetters(std::string_view s)
{
    for (const char c : s)
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
            return false;
    return true;
}

} // namespace

MachineState machineStateFromName(std::string_view name)
{
    for (const auto& [n, s] : kStates)
        if (name == n)
            return s;
    return MachineState::Unknown;
}

const char* machineStateName(MachineState s)
{
    for (const auto& [n, st] : kStates)
        if (st == s)
            return n;
    return "Unknown";
}

StatusParse parseStatusReport(std::string_view payload)
{
    const std::string_view whole = payload;
    StatusReport r;
    bool havePosition = false;
    std::size_t fieldIndex = 0;
    while (true) {
        const std::size_t bar = payload.find('|');
        const std::string_view field = payload.substr(0, bar);
        if (fieldIndex == 0) {
            // State, with an optional ":N" sub-state.
            const std::size_t colon = field.find(':');
            r.stateName = std::string(field.substr(0, colon));
            r.state = machineStateFromName(r.stateName);
            if (r.state == MachineState::Unknown)
                return refuse(whole, "grbl.status.unknown_state");
            if (colon != std::string_view::npos) {
                const auto sub = subStateNumber(field.substr(colon + 1));
                if (!sub || *sub < 0)
                    return refuse(whole, "grbl.status.bad_substate");
                r.subState = *sub;
            }
        } else {
            const std::size_t colon = field.find(':');
            const std::string_view name = field.substr(0, colon);
            const std::string_view value = colon == std::string_view::npos ? std::string_view{} : field.substr(colon + 1);
            if (name == "MPos" || name == "WPos") {
                auto v = parseNumberList(value, kMaxStatusAxes);
                if (!v || v->size() < kMinStatusAxes || havePosition)
                    return refuse(whole, "grbl.status.bad_position");
                r.position = std::move(*v);
                r.positionIsMachine = name == "MPos";
                havePosition = true;
            } else if (name == "WCO") {
                auto v = parseNumberList(value, kMaxStatusAxes);
                if (!v || v->size() < kMinStatusAxes)
                    return refuse(whole, "grbl.status.bad_offset");
                r.workOffset = std::move(*v);
            } else if (name == "Bf") {
                const auto v = parseNumberList(value, 2);
                if (!v || v->size() != 2 || (*v)[0] < 0 || (*v)[1] < 0 || (*v)[0] > 1e6 || (*v)[1] > 1e6)
                    return refuse(whole, "grbl.status.bad_buffer");
                r.plannerBlocksFree = static_cast<int>((*v)[0]);
                r.rxBytesFree = static_cast<int>((*v)[1]);
            } else if (name == "Ln") {
                const auto v = parseNumber(value);
                if (!v || *v < 0 || *v > 1e9)
                    return refuse(whole, "grbl.status.bad_line_number");
                r.lineNumber = static_cast<long>(*v);
            } else if (name == "FS" || name == "F") {
                // grblHAL may append the measured spindle speed as a third value.
                const auto v = parseNumberList(value, 3);
                if (!v || v->empty() || (name == "F" && v->size() != 1))
                    return refuse(whole, "grbl.status.bad_feed");
                r.feedPerMin = (*v)[0];
                if (v->size() > 1)
                    r.spindleRpm = (*v)[1];
            } else if (name == "Pn") {
                if (!onlyLetters(value))
                    return refuse(whole, "grbl.status.bad_pins");
                r.pins = std::string(value);
            } else if (name == "Ov") {
                const auto v = parseNumberList(value, 3);
                // Percentages (GRBL: feed and spindle 10–200, rapid 25/50/100); anything past
                // 1000 is a damaged line, and a double beyond int is never cast (undefined).
                if (!v || v->size() != 3
                    || std::any_of(v->begin(), v->end(), [](double p) { return !(p >= 0 && p <= kMaxOverridePercent); }))
                    return refuse(whole, "grbl.status.bad_overrides");
                r.overridesPercent = std::array<int, 3>{static_cast<int>((*v)[0]), static_cast<int>((*v)[1]),
                                                        static_cast<int>((*v)[2])};
            } else if (name == "A") {
                if (!onlyLetters(value))
                    return refuse(whole, "grbl.status.bad_accessories");
                r.accessories = std::string(value);
            } else if (!name.empty()) {
                if (r.unknownFields.size() < 16)
                    r.unknownFields.emplace_back(std::string(name.substr(0, 32)), std::string(value.substr(0, 64)));
            }
        }
        ++fieldIndex;
        if (bar == std::string_view::npos)
            break;
        payload.remove_prefix(bar + 1);
    }
    if (!havePosition)
        return refuse(whole, "grbl.status.no_position");
    StatusParse p;
    p.report = std::move(r);
    return p;
}

// ---- StatusTracker ----------------------------------------------------------------------

void StatusTracker::reset()
{
    m_state = MachineState::Unknown;
    m_subState = -1;
    m_machineMm.clear();
    m_workMm.clear();
    m_wcoMm.clear();
    m_feedMmMin.reset();
    m_pins.clear();
    m_ov = {100, 100, 100};
    m_acc.clear();
}

bool StatusTracker::update(const StatusReport& r)
{
    const double k = m_inches ? kMmPerInch : 1.0;
    auto mm = [k](const std::vector<double>& v) {
        std::vector<double> out(v);
        for (double& x : out)
            x *= k;
        return out;
    };
    if (r.workOffset && r.workOffset->size() != r.position.size())
        return false;
    if (r.workOffset)
        m_wcoMm = mm(*r.workOffset);
    else if (!m_wcoMm.empty() && m_wcoMm.size() != r.position.size())
        m_wcoMm.clear();  // the axis count changed (another board answered): the old WCO means nothing
    const std::vector<double> pos = mm(r.position);
    if (m_wcoMm.empty()) {
        // No offset known yet: only the vector that was sent is known. The other one is
        // left empty rather than guessed, so nothing reads a work position off MPos.
        m_machineMm = r.positionIsMachine ? pos : std::vector<double>{};
        m_workMm = r.positionIsMachine ? std::vector<double>{} : pos;
    } else {
        m_machineMm = pos;
        m_workMm = pos;
        for (std::size_t i = 0; i < pos.size(); ++i) {
            if (r.positionIsMachine)
                m_workMm[i] = pos[i] - m_wcoMm[i];  // WPos = MPos − WCO
            else
                m_machineMm[i] = pos[i] + m_wcoMm[i];
        }
    }
    m_state = r.state;
    m_subState = r.subState;
    if (r.feedPerMin)
        m_feedMmMin = *r.feedPerMin * k;
    m_pins = r.pins;  // Pn is absent when nothing is triggered: an absent field means none
    if (r.overridesPercent) {
        m_ov = *r.overridesPercent;
        m_acc = r.accessories.value_or(std::string());  // A rides with Ov: absent means all off
    } else if (r.accessories) {
        m_acc = *r.accessories;
    }
    return true;
}

} // namespace dev::grbl
