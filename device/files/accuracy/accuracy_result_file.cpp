#include "device/files/accuracy/accuracy_result_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

#include <cmath>

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using namespace motion::metrology;

namespace {

constexpr double kResultAny = 1e12;

Value orNull(const std::optional<double>& v)
{
    return v ? Value(*v) : Value(nullptr);
}

} // namespace

const std::vector<std::string>& figureKeys()
{
    static const std::vector<std::string> keys = {"A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean"};
    return keys;
}

std::optional<double> figureByKey(const Figures& f, const std::string& key)
{
    if (key == "A")
        return f.aMm;
    if (key == "A_up")
        return f.aUpMm;
    if (key == "A_down")
        return f.aDownMm;
    if (key == "E")
        return f.eMm;
    if (key == "E_up")
        return f.eUpMm;
    if (key == "E_down")
        return f.eDownMm;
    if (key == "M")
        return f.mMm;
    if (key == "R")
        return f.rMm;
    if (key == "R_up")
        return f.rUpMm;
    if (key == "R_down")
        return f.rDownMm;
    if (key == "B")
        return f.bMm;
    if (key == "B_mean")
        return f.bMeanMm;
    return std::nullopt;
}

std::string accuracyResultToJson(const AccuracyResult& r)
{
    const Evaluation& e = r.evaluation;
    Value root = dev::files::json::schemaObject(kAccuracyResultSchema, kAccuracyResultVersion);
    root.set("axis", r.axis);
    root.set("standard", "ISO 230-2:2014");
    root.set("bidirectional", e.bidirectional);
    root.set("cycles", e.cycles);
    Value figures = Value::object();
    for (const std::string& key : figureKeys())
        figures.set(key, orNull(figureByKey(e.figures, key)));
    root.set("figures", figures);
    Value targets = Value::array();
    for (const TargetStatistics& t : e.targets) {
        Value v = Value::object();
        v.set("target_mm", t.targetMm);
        v.set("n_up", t.nUp);
        v.set("n_down", t.nDown);
        v.set("mean_up_mm", t.meanUpMm);
        v.set("s_up_mm", t.sUpMm);
        v.set("mean_down_mm", orNull(t.meanDownMm));
        v.set("s_down_mm", orNull(t.sDownMm));
        v.set("mean_mm", t.meanMm);
        v.set("reversal_mm", orNull(t.reversalMm));
        v.set("r_up_mm", t.rUpMm);
        v.set("r_down_mm", orNull(t.rDownMm));
        v.set("r_mm", orNull(t.rMm));
        targets.push(v);
    }
    root.set("targets", targets);
    if (!r.tolerances.empty()) {
        Value tol = Value::object();
        const std::pair<const char*, std::optional<double>> all[] = {
            {"a_mm", r.tolerances.aMm}, {"r_mm", r.tolerances.rMm}, {"e_mm", r.tolerances.eMm}, {"m_mm", r.tolerances.mMm}, {"b_mm", r.tolerances.bMm}};
        for (const auto& [key, value] : all)
            if (value)
                tol.set(key, *value);
        root.set("tolerances", tol);
        Value verdicts = Value::array();
        const auto judged = judge(e, r.tolerances);
        for (const Verdict& v : judged) {
            Value vv = Value::object();
            vv.set("figure", v.figure);
            vv.set("value_mm", v.valueMm);
            vv.set("limit_mm", v.limitMm);
            vv.set("pass", v.pass);
            verdicts.push(vv);
        }
        root.set("verdicts", verdicts);
        root.set("pass", allPass(judged));
    } else {
        root.set("pass", nullptr);
    }
    if (!r.reference.empty())
        root.set("reference", r.reference);
    if (!r.readingsFile.empty())
        root.set("readings_file", r.readingsFile);
    if (!r.createdUtc.empty())
        root.set("created_utc", r.createdUtc);
    return dev::files::json::write(root);
}

AccuracyResultRead accuracyResultFromJson(std::string_view text, std::string_view fileName)
{
    AccuracyResultRead out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.push_back(fromParseError(parsed.error, fileName));
        return out;
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kAccuracyResultSchema, kAccuracyResultVersion, p)) {
        addJsonProblems(p, fileName, out.problems);
        return out;
    }
    AccuracyResult r;
    ObjectReader o(root, "", p);
    if (auto v = o.string("axis", true))
        r.axis = *v;
    o.string("standard", false);
    const bool bidirectional = o.boolean("bidirectional", true).value_or(false);
    o.integer("cycles", false, 0, 1000000);
    std::vector<TargetStatistics> table;
    if (const Value* list = o.get("targets", Value::Type::Array, true)) {
        for (std::size_t i = 0; i < list->items().size(); ++i) {
            ObjectReader to(list->items()[i], dev::files::json::childPath("targets", i), p);
            TargetStatistics t;
            const auto target = to.number("target_mm", true, -kResultAny, kResultAny);
            const auto nUp = to.integer("n_up", true, 0, 1000000);
            const auto meanUp = to.number("mean_up_mm", true, -kResultAny, kResultAny);
            const auto sUp = to.number("s_up_mm", true, 0, kResultAny);
            const auto nDown = to.integer("n_down", false, 0, 1000000);
            // A unidirectional table writes null for the ↓ columns.
            auto optional = [&](const char* key, double min) -> std::optional<double> {
                const Value* v = to.value().find(key);
                if (!v || v->isNull())
                    return std::nullopt;
                return to.number(key, false, min, kResultAny);
            };
            t.meanDownMm = optional("mean_down_mm", -kResultAny);
            t.sDownMm = optional("s_down_mm", 0);
            for (const char* derived : {"mean_mm", "reversal_mm", "r_up_mm", "r_down_mm", "r_mm"})
                optional(derived, -kResultAny);  // recomputed, not read; only their type is checked
            to.refuseUnknown({"target_mm", "n_up", "n_down", "mean_up_mm", "s_up_mm", "mean_down_mm", "s_down_mm", "mean_mm", "reversal_mm", "r_up_mm",
                              "r_down_mm", "r_mm"});
            if (bidirectional && (!t.meanDownMm || !t.sDownMm))
                p.add(list->items()[i], dev::files::json::childPath("targets", i), motion::msg::make("accuracy.result.needs_down_statistics"));
            if (target && nUp && meanUp && sUp) {
                t.targetMm = *target;
                t.nUp = static_cast<int>(*nUp);
                t.nDown = static_cast<int>(nDown.value_or(0));
                t.meanUpMm = *meanUp;
                t.sUpMm = *sUp;
                table.push_back(t);
            }
        }
    }
    if (const Value* tol = o.get("tolerances", Value::Type::Object, false)) {
        ObjectReader to(*tol, "tolerances", p);
        r.tolerances.aMm = to.number("a_mm", false, -kResultAny, kResultAny);
        r.tolerances.rMm = to.number("r_mm", false, -kResultAny, kResultAny);
        r.tolerances.eMm = to.number("e_mm", false, -kResultAny, kResultAny);
        r.tolerances.mMm = to.number("m_mm", false, -kResultAny, kResultAny);
        r.tolerances.bMm = to.number("b_mm", false, -kResultAny, kResultAny);
        to.refuseUnknown({"a_mm", "r_mm", "e_mm", "m_mm", "b_mm"});
    }
    o.get("verdicts", Value::Type::Array, false);  // recomputed from the figures and tolerances
    if (auto v = o.string("reference", false))
        r.reference = *v;
    if (auto v = o.string("readings_file", false))
        r.readingsFile = *v;
    if (auto v = o.string("created_utc", false))
        r.createdUtc = *v;
    const Value* figures = o.get("figures", Value::Type::Object, true);
    o.refuseUnknown({"schema", "version", "axis", "standard", "bidirectional", "cycles", "figures", "targets", "tolerances", "verdicts", "pass",
                     "reference", "readings_file", "created_utc"});
    addJsonProblems(p, fileName, out.problems);
    if (hasErrors(out.problems))
        return out;

    r.evaluation = summarize(table, bidirectional);
    motion::msg::Problems model = r.evaluation.problems;
    validateTolerances(r.tolerances, "tolerances", model);
    addModelProblems(model, root, fileName, out.problems);
    if (hasErrors(out.problems))
        return out;

    // The figures written must be the ones the table gives.
    dev::files::json::Problems figureProblems;
    ObjectReader fo(*figures, "figures", figureProblems);
    for (const std::string& key : figureKeys()) {
        const std::optional<double> computed = figureByKey(r.evaluation.figures, key);
        const Value* v = figures->find(key);
        const dev::files::json::Position at = v ? v->position() : figures->position();
        const bool written = v && v->isNumber();
        if (v && !v->isNumber() && !v->isNull()) {
            out.problems.push_back({std::string(fileName), at.line, at.column, "figures." + key,
                                    motion::msg::make("file.json_field", {motion::msg::nested("detail", motion::msg::make("file.json.number_or_null", {motion::msg::term("actual", dev::files::json::typeTerm(v->type()))}))})});
            continue;
        }
        if (written != computed.has_value() || (written && std::fabs(v->asNumber() - *computed) > kFigureAgreementMm))
            out.problems.push_back({std::string(fileName), at.line, at.column, "figures." + key,
                                    motion::msg::make("accuracy.result.figure_disagrees",
                                              {motion::msg::verbatim("figure", key), computed ? motion::msg::real("computed", *computed, motion::msg::Unit::Mm) : motion::msg::verbatim("computed", "null"),
                                               written ? motion::msg::real("value", v->asNumber(), motion::msg::Unit::Mm) : motion::msg::verbatim("value", "null")})});
    }
    std::vector<std::string_view> known(figureKeys().begin(), figureKeys().end());
    fo.refuseUnknown(known);
    addJsonProblems(figureProblems, fileName, out.problems);
    if (!hasErrors(out.problems))
        out.result = r;
    return out;
}

AccuracyResultRead loadAccuracyResultFile(const QString& path)
{
    AccuracyResultRead out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? accuracyResultFromJson(*text, name) : out;
}

bool saveAccuracyResultFile(const QString& path, const AccuracyResult& result, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, accuracyResultToJson(result), error);
}

} // namespace dev::files::accuracy
