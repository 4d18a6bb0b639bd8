#include "device/files/accuracy/grid/stage_errors_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::metrology::StageAxisErrors;
using motion::metrology::StageErrors;

namespace {

Value stageNumbers(const std::vector<double>& v)
{
    Value a = Value::array();
    for (double x : v)
        a.push(x);
    return a;
}

void readStageAxis(ObjectReader& root, const char* key, StageAxisErrors& into)
{
    if (const Value* v = root.get(key, Value::Type::Object, false)) {
        ObjectReader a(*v, key, root.problems());
        if (auto p = numberList(a, "pitch_poly_um", false))
            into.pitchPolyUm = *p;
        if (auto s = numberList(a, "straightness_poly_um", false))
            into.straightnessPolyUm = *s;
        a.refuseUnknown({"pitch_poly_um", "straightness_poly_um"});
    }
}

} // namespace

std::optional<std::vector<double>> numberList(ObjectReader& o, std::string_view key, bool required)
{
    const Value* list = o.get(key, Value::Type::Array, required);
    if (!list)
        return std::nullopt;
    std::vector<double> out;
    bool ok = true;
    for (std::size_t i = 0; i < list->items().size(); ++i) {
        const Value& k = list->items()[i];
        if (k.isNumber()) {
            out.push_back(k.asNumber());
        } else {
            o.problems().add(k, dev::files::json::childPath(o.pathOf(key), i), dev::files::json::wrongType(Value::Type::Number, k.type()));
            ok = false;
        }
    }
    if (!ok)
        return std::nullopt;
    return out;
}

std::string stageErrorsToJson(const StageErrors& e)
{
    Value root = dev::files::json::schemaObject(kStageErrorsSchema, kStageErrorsVersion);
    auto axis = [](const StageAxisErrors& a) {
        Value v = Value::object();
        v.set("pitch_poly_um", stageNumbers(a.pitchPolyUm));
        v.set("straightness_poly_um", stageNumbers(a.straightnessPolyUm));
        return v;
    };
    root.set("x", axis(e.x));
    root.set("y", axis(e.y));
    root.set("squareness_urad", e.squarenessUrad);
    Value b = Value::object();
    b.set("x", e.backlashXUm);
    b.set("y", e.backlashYUm);
    root.set("backlash_um", b);
    return dev::files::json::write(root);
}

StageErrorsRead stageErrorsFromJson(std::string_view text, std::string_view fileName)
{
    motion::msg::Problems problems;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        problems.push_back(fromParseError(parsed.error, fileName));
        return StageErrorsRead::refused(std::move(problems));
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kStageErrorsSchema, kStageErrorsVersion, p)) {
        addJsonProblems(p, fileName, problems);
        return StageErrorsRead::refused(std::move(problems));
    }
    StageErrors e = motion::metrology::builtInStageErrors();
    ObjectReader o(root, "", p);
    readStageAxis(o, "x", e.x);
    readStageAxis(o, "y", e.y);
    // The range checks are the model's (validate below), so a file gets the same
    // words as any other source of stage errors.
    if (auto v = o.number("squareness_urad", false, -1e300, 1e300))
        e.squarenessUrad = *v;
    if (const Value* b = o.get("backlash_um", Value::Type::Object, false)) {
        ObjectReader bo(*b, "backlash_um", p);
        if (auto v = bo.number("x", false, -1e300, 1e300))
            e.backlashXUm = *v;
        if (auto v = bo.number("y", false, -1e300, 1e300))
            e.backlashYUm = *v;
        bo.refuseUnknown({"x", "y"});
    }
    (void)o.string("note", false);  // free text for the record
    o.refuseUnknown({"schema", "version", "x", "y", "squareness_urad", "backlash_um", "note"});
    addJsonProblems(p, fileName, problems);
    addModelProblems(motion::metrology::validate(e), root, fileName, problems);
    return StageErrorsRead::from(e, std::move(problems));
}

StageErrorsRead loadStageErrorsFile(const QString& path)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = loadText(path, name, problems);
    return text ? stageErrorsFromJson(*text, name) : StageErrorsRead::refused(std::move(problems));
}

bool saveStageErrorsFile(const QString& path, const StageErrors& e, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, stageErrorsToJson(e), error);
}

} // namespace dev::files::accuracy
