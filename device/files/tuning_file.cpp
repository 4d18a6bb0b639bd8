#include "device/files/tuning_file.h"

#include "device/files/json.h"
#include "device/files/json_fields.h"
#include "device/files/text_file.h"
#include "motion/control/tuning/tuning_rules.h"

#include <QFileInfo>

#include <cmath>

namespace dev::files {

using dev::files::json::ObjectReader;
using dev::files::json::Problems;
using dev::files::json::Value;
using motion::control::TuningResult;

namespace {
constexpr double kBig = 1e12;

Value gainsValue(const motion::control::DiscreteGains& g)
{
    Value v = Value::object();
    v.set("kp", g.kp);
    v.set("ki", g.ki);
    v.set("kd", g.kd);
    return v;
}

std::optional<motion::control::DiscreteGains> readGains(const Value& v, const std::string& path, Problems& p)
{
    ObjectReader o(v, path, p);
    const auto kp = o.number("kp", true, 0, kBig), ki = o.number("ki", true, 0, kBig), kd = o.number("kd", true, 0, kBig);
    o.refuseUnknown({"kp", "ki", "kd"});
    if (!kp || !ki || !kd)
        return std::nullopt;
    return motion::control::DiscreteGains{*kp, *ki, *kd};
}
} // namespace

std::string tuningToJson(const TuningResult& r)
{
    Value root = dev::files::json::schemaObject(kTuningSchema, kTuningVersion);
    root.set("target", r.target);
    root.set("unit", r.unit);
    root.set("method", r.method);
    root.set("created_utc", r.createdUtc);
    root.set("control_period_s", r.controlPeriodS);
    root.set("ku", r.ku);
    root.set("tu_s", r.tuS);
    root.set("runs", r.runs);
    Value env = Value::object();
    env.set("max_excursion", r.envelope.maxExcursion);
    env.set("max_following_error", r.envelope.maxFollowingError);
    env.set("max_duration_s", r.envelope.maxDurationS);
    root.set("envelope", env);
    if (r.method == "relay") {
        Value relay = Value::object();
        relay.set("amplitude", r.relayAmplitude);
        relay.set("hysteresis", r.hysteresis);
        if (r.kuDescribing)
            relay.set("ku_describing", *r.kuDescribing);
        if (r.tuRelayS)
            relay.set("tu_relay_s", *r.tuRelayS);
        relay.set("refined", r.refined);
        Value pts = Value::array();
        for (const auto& p : r.points) {
            Value pv = Value::object();
            pv.set("omega_rad_s", p.omegaRadS);
            pv.set("gain", p.gain);
            pv.set("phase_deg", p.phaseDeg);
            pts.push(pv);
        }
        relay.set("points", pts);
        root.set("relay", relay);
    } else {
        Value ug = Value::object();
        ug.set("step", r.step);
        Value trials = Value::array();
        for (const auto& t : r.trials) {
            Value tv = Value::object();
            tv.set("kp", t.kp);
            tv.set("ratio", t.ratio);
            tv.set("period_s", t.periodS);
            tv.set("outcome", t.outcome);
            trials.push(tv);
        }
        ug.set("trials", trials);
        root.set("ultimate_gain", ug);
    }
    Value rules = Value::object();
    for (const auto& rule : motion::control::tuningRules()) {
        const auto c = motion::control::applyRule(rule, r.ku, r.tuS);
        Value rv = Value::object();
        rv.set("kp", c.kp);
        rv.set("ki_per_s", c.kiPerS);
        rv.set("kd_s", c.kdS);
        if (r.controlPeriodS > 0)
            rv.set("discrete", gainsValue(motion::control::toDiscrete(c, r.controlPeriodS)));
        rules.set(rule.id, rv);
    }
    root.set("rules", rules);
    if (r.verification) {
        const auto& v = *r.verification;
        Value vv = Value::object();
        vv.set("rule", v.rule);
        vv.set("gains", gainsValue(v.gains));
        vv.set("outcome", v.outcome);
        vv.set("rise_time_s", v.metrics.riseTimeS);
        vv.set("overshoot_pct", v.metrics.overshootPct);
        vv.set("settling_time_s", v.metrics.settlingTimeS);
        vv.set("steady_state_error", v.metrics.steadyStateError);
        vv.set("iae", v.metrics.iae);
        vv.set("ise", v.metrics.ise);
        vv.set("peak_output", v.metrics.peakOutput);
        if (v.settledInside5umS >= 0)
            vv.set("settled_inside_5um_s", v.settledInside5umS);
        vv.set("verdict", std::string(motion::control::stepOutcomeName(v.metrics.outcome)));
        if (v.limitCycle.found) {
            Value lc = Value::object();
            lc.set("amplitude", v.limitCycle.amplitude);
            lc.set("period_s", v.limitCycle.periodS);
            lc.set("cycles", v.limitCycle.cycles);
            lc.set("threshold", v.limitCycle.threshold);
            vv.set("limit_cycle", lc);
        }
        root.set("verification", vv);
    }
    if (!r.note.empty())
        root.set("note", r.note);
    return dev::files::json::write(root);
}

TuningRead tuningFromJson(std::string_view text)
{
    TuningRead out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.add(parsed.error.position, "", parsed.error.message);
        return out;
    }
    Problems p;
    const Value& root = *parsed.value;
    if (!dev::files::json::checkSchema(root, kTuningSchema, kTuningVersion, p)) {
        out.problems = std::move(p);
        return out;
    }
    TuningResult r;
    ObjectReader o(root, "", p);
    if (auto v = o.string("target", true))
        r.target = *v;
    if (auto v = o.string("unit", false))
        r.unit = *v;
    if (auto v = o.oneOf("method", true, {"ultimate-gain", "relay"}))
        r.method = *v;
    if (auto v = o.string("created_utc", false))
        r.createdUtc = *v;
    if (auto v = o.number("control_period_s", true, 1e-7, 10))
        r.controlPeriodS = *v;
    if (auto v = o.number("ku", true, 1e-12, kBig))
        r.ku = *v;
    if (auto v = o.number("tu_s", true, 1e-9, 1e6))
        r.tuS = *v;
    if (auto v = o.integer("runs", false, 0, 100000))
        r.runs = static_cast<int>(*v);
    if (const Value* env = o.get("envelope", Value::Type::Object, true)) {
        ObjectReader e(*env, "envelope", p);
        if (auto v = e.number("max_excursion", true, 0, kBig))
            r.envelope.maxExcursion = *v;
        if (auto v = e.number("max_following_error", true, 0, kBig))
            r.envelope.maxFollowingError = *v;
        if (auto v = e.number("max_duration_s", true, 0, 1e6))
            r.envelope.maxDurationS = *v;
        e.refuseUnknown({"max_excursion", "max_following_error", "max_duration_s"});
    }
    const Value* relay = o.get("relay", Value::Type::Object, false);
    const Value* ug = o.get("ultimate_gain", Value::Type::Object, false);
    if (r.method == "relay" && !relay)
        p.add(root, "relay", motion::msg::make("tuning.file.missing_for_method", {motion::msg::verbatim("method", "relay")}));
    if (r.method == "ultimate-gain" && !ug)
        p.add(root, "ultimate_gain", motion::msg::make("tuning.file.missing_for_method", {motion::msg::verbatim("method", "ultimate-gain")}));
    if (relay) {
        ObjectReader rr(*relay, "relay", p);
        if (auto v = rr.number("amplitude", true, 0, kBig))
            r.relayAmplitude = *v;
        if (auto v = rr.number("hysteresis", true, 0, kBig))
            r.hysteresis = *v;
        r.kuDescribing = rr.number("ku_describing", false, 0, kBig);
        r.tuRelayS = rr.number("tu_relay_s", false, 0, 1e6);
        if (auto v = rr.boolean("refined", false))
            r.refined = *v;
        if (const Value* pts = rr.get("points", Value::Type::Array, false)) {
            for (std::size_t i = 0; i < pts->items().size(); ++i) {
                ObjectReader po(pts->items()[i], dev::files::json::childPath("relay.points", i), p);
                const auto w = po.number("omega_rad_s", true, 0, kBig), g = po.number("gain", true, 0, kBig),
                           ph = po.number("phase_deg", true, -3600, 3600);
                po.refuseUnknown({"omega_rad_s", "gain", "phase_deg"});
                if (w && g && ph)
                    r.points.push_back({*w, *g, *ph});
            }
        }
        rr.refuseUnknown({"amplitude", "hysteresis", "ku_describing", "tu_relay_s", "refined", "points"});
    }
    if (ug) {
        ObjectReader uo(*ug, "ultimate_gain", p);
        if (auto v = uo.number("step", true, -kBig, kBig))
            r.step = *v;
        if (const Value* trials = uo.get("trials", Value::Type::Array, false)) {
            for (std::size_t i = 0; i < trials->items().size(); ++i) {
                ObjectReader to(trials->items()[i], dev::files::json::childPath("ultimate_gain.trials", i), p);
                TuningResult::Trial t;
                const auto kp = to.number("kp", true, 0, kBig), ratio = to.number("ratio", true, 0, kBig),
                           period = to.number("period_s", true, 0, 1e6);
                const auto outcome = to.oneOf("outcome", true, {"decays", "sustained", "grows", "no oscillation", "hit the envelope"});
                to.refuseUnknown({"kp", "ratio", "period_s", "outcome"});
                if (kp && ratio && period && outcome)
                    r.trials.push_back({*kp, *ratio, *period, *outcome});
            }
        }
        uo.refuseUnknown({"step", "trials"});
    }
    o.get("rules", Value::Type::Object, false);  // derived from ku and tu_s; recomputed, not read
    if (const Value* ver = o.get("verification", Value::Type::Object, false)) {
        ObjectReader vo(*ver, "verification", p);
        TuningResult::Verification v;
        const auto rule = vo.string("rule", true);
        if (rule && !motion::control::findRule(*rule))
            p.add(*vo.value().find("rule"), "verification.rule", motion::msg::make("tuning.file.unknown_rule", {motion::msg::verbatim("rule", rule->substr(0, 40))}));
        if (rule)
            v.rule = *rule;
        if (const Value* g = vo.get("gains", Value::Type::Object, true))
            if (auto gg = readGains(*g, "verification.gains", p))
                v.gains = *gg;
        if (auto s = vo.string("outcome", false))
            v.outcome = *s;
        auto metric = [&](const char* key, double& into, double lo, double hi) {
            // A metric that does not exist for this response was written as null (NaN).
            const Value* m = vo.value().find(key);
            if (m && m->isNull()) {
                into = std::nan("");
                return;
            }
            if (auto x = vo.number(key, false, lo, hi))
                into = *x;
        };
        metric("rise_time_s", v.metrics.riseTimeS, 0, 1e6);
        metric("overshoot_pct", v.metrics.overshootPct, -1e6, 1e9);
        metric("settling_time_s", v.metrics.settlingTimeS, 0, 1e6);
        metric("steady_state_error", v.metrics.steadyStateError, -kBig, kBig);
        metric("iae", v.metrics.iae, 0, kBig);
        metric("ise", v.metrics.ise, 0, kBig);
        metric("peak_output", v.metrics.peakOutput, 0, kBig);
        if (auto x = vo.number("settled_inside_5um_s", false, 0, 1e6))
            v.settledInside5umS = *x;
        // Files from before the verdict was kept: a response with no settling time did not settle.
        v.metrics.outcome = std::isfinite(v.metrics.settlingTimeS) ? motion::control::StepOutcome::Settled
                                                                   : motion::control::StepOutcome::DidNotSettle;
        if (auto verdict = vo.oneOf("verdict", false, {"settled", "did not settle", "unstable", "limit cycle"}))
            motion::control::stepOutcomeFromName(*verdict, &v.metrics.outcome);
        if (const Value* lcv = vo.get("limit_cycle", Value::Type::Object, false)) {
            ObjectReader lo(*lcv, "verification.limit_cycle", p);
            const auto amplitude = lo.number("amplitude", true, 0, kBig);
            const auto periodS = lo.number("period_s", true, 0, 1e6);
            const auto cycles = lo.number("cycles", false, 0, 1e9);
            const auto threshold = lo.number("threshold", false, 0, kBig);
            lo.refuseUnknown({"amplitude", "period_s", "cycles", "threshold"});
            if (amplitude && periodS) {
                v.limitCycle.found = true;
                v.limitCycle.amplitude = *amplitude;
                v.limitCycle.periodS = *periodS;
                v.limitCycle.cycles = cycles ? static_cast<int>(*cycles) : 0;
                v.limitCycle.threshold = threshold.value_or(0);
            }
        }
        vo.refuseUnknown({"rule", "gains", "outcome", "rise_time_s", "overshoot_pct", "settling_time_s", "steady_state_error", "iae",
                          "ise", "peak_output", "settled_inside_5um_s", "verdict", "limit_cycle"});
        r.verification = v;
    }
    if (auto v = o.string("note", false))
        r.note = *v;
    o.refuseUnknown({"schema", "version", "target", "unit", "method", "created_utc", "control_period_s", "ku", "tu_s", "runs",
                     "envelope", "relay", "ultimate_gain", "rules", "verification", "note"});
    if (!p.empty()) {
        out.problems = std::move(p);
        return out;
    }
    out.result = r;
    return out;
}

bool saveTuningFile(const QString& path, const TuningResult& result, motion::msg::Message* error)
{
    return writeAtomically(path, tuningToJson(result), error);
}

std::optional<TuningResult> loadTuningFile(const QString& path, dev::files::json::Problems* problems)
{
    std::string text;
    motion::msg::Message error;
    if (!readText(path, &text, &error)) {
        if (problems)
            problems->addFileProblem(error);
        return std::nullopt;
    }
    TuningRead r = tuningFromJson(text);
    if (!r.result && problems)
        *problems = std::move(r.problems);
    return r.result;
}

} // namespace dev::files
