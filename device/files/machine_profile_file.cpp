#include "device/files/machine_profile_file.h"

#include "device/files/text_file.h"


#include <cmath>

namespace dev::files {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using Profile = MachineProfile;

namespace {

constexpr double kMinPollHz = 1, kMaxPollHz = 20;
constexpr double kMaxUlPerMm = 1e6;
/// GRBL needs about 10 ms to parse and plan a jog line: the smallest segment the jog plan uses.
constexpr double kMinJogSegmentS = 0.010;

bool isGrblAxis(char c) { return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C'; }

std::string letter(char c) { return std::string(1, c); }

/// A one-letter string field ("X"); nullopt (and a problem) otherwise.
std::optional<char> axisLetter(ObjectReader& o, std::string_view key)
{
    const auto s = o.string(key, true);
    if (!s)
        return std::nullopt;
    if (s->size() != 1 || !(((*s)[0] >= 'A' && (*s)[0] <= 'Z'))) {
        o.problems().add(*o.value().find(key), o.pathOf(key), motion::msg::make("grbl.profile.axis_letter", {motion::msg::verbatim("text", *s)}));
        return std::nullopt;
    }
    return (*s)[0];
}

} // namespace

char MachineProfile::grblAxisOf(char axis) const
{
    if (axis == 'P')
        return pump ? pump->grblAxis : 0;
    for (const auto& a : axes)
        if (a.axis == axis)
            return a.grblAxis;
    return 0;
}

MachineProfile defaultProfile(dev::proto::DeviceKind kind)
{
    MachineProfile p;
    p.instrument = kind;
    p.name = kind == dev::proto::DeviceKind::Stage ? "stage (default wiring)" : "analyzer (default wiring)";
    p.axes = {{'X', 'X'}, {'Y', 'Y'}};
    if (kind == dev::proto::DeviceKind::Analyzer) {
        p.axes.push_back({'Z', 'Z'});
        p.pump = Profile::Pump{'A', 1.0};
    }
    return p;
}

motion::msg::Problems validate(const MachineProfile& p)
{
    motion::msg::Problems out;
    const bool stage = p.instrument == dev::proto::DeviceKind::Stage;
    const std::string wanted = stage ? "XY" : "XYZ";
    std::string have;
    for (const auto& a : p.axes)
        have.push_back(a.axis);
    if (have != wanted)
        out.push_back(motion::msg::error("axes", motion::msg::make("grbl.profile.axes_order", {motion::msg::term("instrument", stage ? "instrument.stage" : "instrument.analyzer"),
                                                                     motion::msg::verbatim("wanted", wanted), motion::msg::verbatim("got", have)})));
    std::string used;
    for (std::size_t i = 0; i < p.axes.size(); ++i) {
        const char g = p.axes[i].grblAxis;
        const std::string field = "axes[" + std::to_string(i) + "].grbl_axis";
        if (!isGrblAxis(g))
            out.push_back(motion::msg::error(field, motion::msg::make("grbl.profile.not_grbl_axis", {motion::msg::verbatim("axis", letter(g))})));
        else if (used.find(g) != std::string::npos)
            out.push_back(motion::msg::error(field, motion::msg::make("grbl.profile.grbl_axis_used", {motion::msg::verbatim("axis", letter(g))})));
        used.push_back(g);
    }
    if (p.pump) {
        if (stage)
            out.push_back(motion::msg::error("pump", motion::msg::make("grbl.profile.stage_no_pump")));
        if (!isGrblAxis(p.pump->grblAxis))
            out.push_back(motion::msg::error("pump.grbl_axis", motion::msg::make("grbl.profile.not_grbl_axis", {motion::msg::verbatim("axis", letter(p.pump->grblAxis))})));
        else if (used.find(p.pump->grblAxis) != std::string::npos)
            out.push_back(motion::msg::error("pump.grbl_axis", motion::msg::make("grbl.profile.pump_axis_used", {motion::msg::verbatim("axis", letter(p.pump->grblAxis))})));
        if (!(p.pump->ulPerMm > 0) || !(p.pump->ulPerMm <= kMaxUlPerMm))
            out.push_back(motion::msg::error("pump.ul_per_mm", motion::msg::make("grbl.profile.ul_per_mm_range", {motion::msg::real("value", p.pump->ulPerMm),
                                                                                       motion::msg::real("max", kMaxUlPerMm)})));
    }
    if (p.trigger && p.trigger->output == Profile::TriggerOutput::GrblHalDigital && (p.trigger->port < 0 || p.trigger->port > 255))
        out.push_back(motion::msg::error("trigger.port", dev::files::json::outOfRange(p.trigger->port, 0, 255)));
    if (!(p.statusPollHz >= kMinPollHz && p.statusPollHz <= kMaxPollHz))
        out.push_back(motion::msg::error("status_poll_hz", dev::files::json::outOfRange(p.statusPollHz, kMinPollHz, kMaxPollHz)));
    const auto& j = p.jog;
    if (!(j.linkLatencyS >= 0 && j.linkLatencyS <= 0.5))
        out.push_back(motion::msg::error("jog.link_latency_s", dev::files::json::outOfRange(j.linkLatencyS, 0, 0.5)));
    if (!(j.refreshS >= 0.005 && j.refreshS <= 0.5))
        out.push_back(motion::msg::error("jog.refresh_s", dev::files::json::outOfRange(j.refreshS, 0.005, 0.5)));
    if (!(j.stopBudgetS >= 0.05 && j.stopBudgetS <= 2))
        out.push_back(motion::msg::error("jog.stop_budget_s", dev::files::json::outOfRange(j.stopBudgetS, 0.05, 2)));
    else if (j.linkLatencyS + j.refreshS + kMinJogSegmentS >= j.stopBudgetS)
        out.push_back(motion::msg::error("jog.stop_budget_s", motion::msg::make("grbl.profile.stop_budget_too_small",
                                                      {motion::msg::real("value", j.stopBudgetS, motion::msg::Unit::S),
                                                       motion::msg::real("least", j.linkLatencyS + j.refreshS + kMinJogSegmentS, motion::msg::Unit::S)})));
    return out;
}

const char* protocolName(MachineProfile::Protocol p)
{
    switch (p) {
    case Profile::Protocol::Auto: return "auto";
    case Profile::Protocol::BenchPilot: return "benchpilot";
    case Profile::Protocol::Grbl: return "grbl";
    }
    return "auto";
}

const char* triggerOutputName(MachineProfile::TriggerOutput t)
{
    return t == Profile::TriggerOutput::CoolantFlood ? "coolant-flood" : "grblhal-digital";
}

MachineProfileReadResult parseMachineProfile(std::string_view text)
{
    MachineProfileReadResult out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.add(parsed.error.position, "", parsed.error.message);
        return out;
    }
    const Value& root = *parsed.value;
    if (!dev::files::json::checkSchema(root, kMachineProfileSchema, kMachineProfileVersion, out.problems))
        return out;
    ObjectReader o(root, "", out.problems);
    Profile p;
    if (auto n = o.string("name", false))
        p.name = *n;
    if (auto k = o.oneOf("instrument", true, {"analyzer", "stage"}))
        p.instrument = *k == "stage" ? dev::proto::DeviceKind::Stage : dev::proto::DeviceKind::Analyzer;
    if (auto pr = o.oneOf("protocol", false, {"auto", "benchpilot", "grbl"}))
        p.protocol = *pr == "grbl" ? Profile::Protocol::Grbl : *pr == "benchpilot" ? Profile::Protocol::BenchPilot : Profile::Protocol::Auto;
    if (auto hz = o.number("status_poll_hz", false, kMinPollHz, kMaxPollHz))
        p.statusPollHz = *hz;
    if (auto in = o.oneOf("inch_reports", false, {"convert", "refuse"}))
        p.inchReports = *in == "refuse" ? Profile::InchReports::Refuse : Profile::InchReports::Convert;
    if (const Value* axes = o.get("axes", Value::Type::Array, true)) {
        for (std::size_t i = 0; i < axes->items().size(); ++i) {
            ObjectReader a(axes->items()[i], dev::files::json::childPath("axes", i), out.problems);
            if (!a.valid())
                continue;
            const auto axis = axisLetter(a, "axis");
            const auto grblAxis = axisLetter(a, "grbl_axis");
            a.refuseUnknown({"axis", "grbl_axis"});
            if (axis && grblAxis)
                p.axes.push_back({*axis, *grblAxis});
        }
    }
    if (const Value* pump = o.get("pump", Value::Type::Object, false)) {
        ObjectReader a(*pump, "pump", out.problems);
        Profile::Pump pp;
        const auto grblAxis = axisLetter(a, "grbl_axis");
        const auto ul = a.number("ul_per_mm", true, 1e-9, kMaxUlPerMm);
        a.refuseUnknown({"grbl_axis", "ul_per_mm"});
        if (grblAxis && ul)
            p.pump = Profile::Pump{*grblAxis, *ul};
    }
    if (const Value* trig = o.get("trigger", Value::Type::Object, false)) {
        ObjectReader a(*trig, "trigger", out.problems);
        Profile::Trigger t;
        const auto kind = a.oneOf("output", true, {"grblhal-digital", "coolant-flood"});
        if (kind && *kind == "coolant-flood") {
            t.output = Profile::TriggerOutput::CoolantFlood;
            a.refuseUnknown({"output"});
        } else {
            if (auto port = a.integer("port", kind.has_value(), 0, 255))
                t.port = static_cast<int>(*port);
            a.refuseUnknown({"output", "port"});
        }
        if (kind)
            p.trigger = t;
    }
    if (const Value* jog = o.get("jog", Value::Type::Object, false)) {
        ObjectReader a(*jog, "jog", out.problems);
        if (auto v = a.number("link_latency_s", false, 0, 0.5))
            p.jog.linkLatencyS = *v;
        if (auto v = a.number("refresh_s", false, 0.005, 0.5))
            p.jog.refreshS = *v;
        if (auto v = a.number("stop_budget_s", false, 0.05, 2))
            p.jog.stopBudgetS = *v;
        a.refuseUnknown({"link_latency_s", "refresh_s", "stop_budget_s"});
    }
    o.refuseUnknown({"schema", "version", "name", "instrument", "protocol", "status_poll_hz", "inch_reports", "axes", "pump",
                     "trigger", "jog"});
    if (!out.problems.empty())
        return out;
    // The profile's own rules, placed at the field they are about (or the nearest one present).
    for (const auto& problem : validate(p)) {
        const std::string top = problem.path.substr(0, problem.path.find_first_of(".["));
        const Value* at = root.find(top);
        out.problems.add(at ? *at : root, problem.path, problem.message);
    }
    if (out.problems.empty())
        out.profile = std::move(p);
    return out;
}

std::string writeMachineProfile(const MachineProfile& p)
{
    Value v = dev::files::json::schemaObject(kMachineProfileSchema, kMachineProfileVersion);
    v.set("name", Value(p.name));
    v.set("instrument", Value(p.instrument == dev::proto::DeviceKind::Stage ? "stage" : "analyzer"));
    v.set("protocol", Value(protocolName(p.protocol)));
    v.set("status_poll_hz", Value(p.statusPollHz));
    v.set("inch_reports", Value(p.inchReports == Profile::InchReports::Refuse ? "refuse" : "convert"));
    Value axes = Value::array();
    for (const auto& a : p.axes) {
        Value m = Value::object();
        m.set("axis", Value(letter(a.axis)));
        m.set("grbl_axis", Value(letter(a.grblAxis)));
        axes.push(std::move(m));
    }
    v.set("axes", std::move(axes));
    if (p.pump) {
        Value m = Value::object();
        m.set("grbl_axis", Value(letter(p.pump->grblAxis)));
        m.set("ul_per_mm", Value(p.pump->ulPerMm));
        v.set("pump", std::move(m));
    }
    if (p.trigger) {
        Value m = Value::object();
        m.set("output", Value(triggerOutputName(p.trigger->output)));
        if (p.trigger->output == Profile::TriggerOutput::GrblHalDigital)
            m.set("port", Value(p.trigger->port));
        v.set("trigger", std::move(m));
    }
    Value jog = Value::object();
    jog.set("link_latency_s", Value(p.jog.linkLatencyS));
    jog.set("refresh_s", Value(p.jog.refreshS));
    jog.set("stop_budget_s", Value(p.jog.stopBudgetS));
    v.set("jog", std::move(jog));
    return dev::files::json::write(v);
}

bool loadMachineProfileFile(const QString& path, MachineProfile* profile, dev::files::json::Problems* problems)
{
    std::string text;
    motion::msg::Message error;
    if (!readText(path, &text, &error)) {
        if (problems)
            problems->addFileProblem(error);
        return false;
    }
    MachineProfileReadResult r = parseMachineProfile(text);
    if (!r.profile) {
        if (problems)
            *problems = std::move(r.problems);
        return false;
    }
    if (profile)
        *profile = std::move(*r.profile);
    return true;
}

bool saveMachineProfileFile(const QString& path, const MachineProfile& profile, motion::msg::Message* error)
{
    return writeAtomically(path, writeMachineProfile(profile), error);
}

} // namespace dev::files
