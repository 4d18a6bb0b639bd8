#include "device/files/accuracy/compensation/compensation_file.h"

#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;
using motion::metrology::CompensationModel;
using motion::metrology::TablePoint;

namespace {
constexpr double kCompensationAny = 1e12;
} // namespace

std::string compensationToJson(const CompensationFile& c)
{
    const CompensationModel& m = c.model;
    Value root = dev::files::json::schemaObject(kCompensationSchema, kCompensationVersion);
    root.set("axis", m.axis);
    if (m.kind == CompensationModel::Kind::Polynomial) {
        root.set("kind", "polynomial");
        Value poly = Value::object();
        Value coeffs = Value::array();
        for (double k : m.polynomial.coefficientsUm)
            coeffs.push(k);
        poly.set("coefficients_um", coeffs);
        poly.set("valid_from_mm", m.validFromMm);
        poly.set("valid_to_mm", m.validToMm);
        root.set("polynomial", poly);
    } else {
        root.set("kind", "table");
        Value table = Value::object();
        table.set("per_direction", m.perDirection);
        Value points = Value::array();
        for (const TablePoint& p : m.table) {
            Value v = Value::object();
            v.set("nominal_mm", p.nominalMm);
            if (m.perDirection) {
                v.set("correction_up_um", p.correctionUpUm);
                v.set("correction_down_um", p.correctionDownUm);
            } else {
                v.set("correction_um", p.correctionUpUm);
            }
            points.push(v);
        }
        table.set("points", points);
        root.set("table", table);
    }
    root.set("backlash_um", m.backlashUm);
    if (c.fit) {
        Value f = Value::object();
        f.set("order", c.fit->order);
        f.set("sse_um2", c.fit->sseUm2);
        f.set("r2", c.fit->r2);
        f.set("adjusted_r2", c.fit->adjustedR2);
        f.set("points", c.fit->points);
        f.set("chosen_by", c.fit->chosenByOperator ? "operator" : "adjusted-r2");
        root.set("fit", f);
    }
    if (!c.source.empty())
        root.set("source", c.source);
    return dev::files::json::write(root);
}

CompensationRead compensationFromJson(std::string_view text, std::string_view fileName)
{
    CompensationRead out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.push_back(fromParseError(parsed.error, fileName));
        return out;
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kCompensationSchema, kCompensationVersion, p)) {
        addJsonProblems(p, fileName, out.problems);
        return out;
    }
    CompensationFile c;
    CompensationModel& m = c.model;
    ObjectReader o(root, "", p);
    if (auto v = o.string("axis", true))
        m.axis = *v;
    const auto kind = o.oneOf("kind", true, {"polynomial", "table"});
    if (kind && *kind == "polynomial") {
        m.kind = CompensationModel::Kind::Polynomial;
        if (const Value* poly = o.get("polynomial", Value::Type::Object, true)) {
            ObjectReader po(*poly, "polynomial", p);
            if (const Value* list = po.get("coefficients_um", Value::Type::Array, true))
                for (std::size_t i = 0; i < list->items().size(); ++i) {
                    const Value& k = list->items()[i];
                    if (k.isNumber())
                        m.polynomial.coefficientsUm.push_back(k.asNumber());
                    else
                        p.add(k, dev::files::json::childPath("polynomial.coefficients_um", i), dev::files::json::wrongType(Value::Type::Number, k.type()));
                }
            if (auto v = po.number("valid_from_mm", true, -kCompensationAny, kCompensationAny))
                m.validFromMm = *v;
            if (auto v = po.number("valid_to_mm", true, -kCompensationAny, kCompensationAny))
                m.validToMm = *v;
            po.refuseUnknown({"coefficients_um", "valid_from_mm", "valid_to_mm"});
        }
    } else if (kind) {
        m.kind = CompensationModel::Kind::Table;
        if (const Value* table = o.get("table", Value::Type::Object, true)) {
            ObjectReader to(*table, "table", p);
            m.perDirection = to.boolean("per_direction", false).value_or(false);
            if (const Value* list = to.get("points", Value::Type::Array, true))
                for (std::size_t i = 0; i < list->items().size(); ++i) {
                    ObjectReader po(list->items()[i], dev::files::json::childPath("table.points", i), p);
                    TablePoint tp;
                    const auto nominal = po.number("nominal_mm", true, -kCompensationAny, kCompensationAny);
                    std::optional<double> up, down;
                    if (m.perDirection) {
                        up = po.number("correction_up_um", true, -kCompensationAny, kCompensationAny);
                        down = po.number("correction_down_um", true, -kCompensationAny, kCompensationAny);
                        po.refuseUnknown({"nominal_mm", "correction_up_um", "correction_down_um"});
                    } else {
                        up = down = po.number("correction_um", true, -kCompensationAny, kCompensationAny);
                        po.refuseUnknown({"nominal_mm", "correction_um"});
                    }
                    if (nominal && up && down)
                        m.table.push_back({*nominal, *up, *down});
                }
            to.refuseUnknown({"per_direction", "points"});
        }
    }
    if (auto v = o.number("backlash_um", false, -kCompensationAny, kCompensationAny))
        m.backlashUm = *v;
    if (const Value* f = o.get("fit", Value::Type::Object, false)) {
        ObjectReader fo(*f, "fit", p);
        FitRecord r;
        const auto order = fo.integer("order", true, 1, motion::metrology::kMaxFitOrder);
        const auto sse = fo.number("sse_um2", true, 0, kCompensationAny);
        const auto r2 = fo.number("r2", true, -kCompensationAny, 1);
        const auto adj = fo.number("adjusted_r2", true, -kCompensationAny, 1);
        const auto points = fo.integer("points", true, 0, 100000000);
        const auto by = fo.oneOf("chosen_by", true, {"adjusted-r2", "operator"});
        fo.refuseUnknown({"order", "sse_um2", "r2", "adjusted_r2", "points", "chosen_by"});
        if (order && sse && r2 && adj && points && by)
            c.fit = FitRecord{static_cast<int>(*order), *sse, *r2, *adj, static_cast<int>(*points), *by == "operator"};
    }
    if (auto v = o.string("source", false))
        c.source = *v;
    o.refuseUnknown({"schema", "version", "axis", "kind", "polynomial", "table", "backlash_um", "fit", "source"});
    addJsonProblems(p, fileName, out.problems);
    if (hasErrors(out.problems))
        return out;
    addModelProblems(motion::metrology::validate(m), root, fileName, out.problems);
    if (!hasErrors(out.problems))
        out.compensation = c;
    return out;
}

CompensationRead loadCompensationFile(const QString& path)
{
    CompensationRead out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? compensationFromJson(*text, name) : out;
}

bool saveCompensationFile(const QString& path, const CompensationFile& c, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, compensationToJson(c), error);
}

} // namespace dev::files::accuracy
