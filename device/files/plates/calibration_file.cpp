#include "device/files/plates/calibration_file.h"

#include "device/files/plates/json_path.h"

#include <set>

namespace dev::files::plates {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

CalibrationRead parseCalibration(std::string_view text)
{
    CalibrationRead r;
    const std::optional<Value> parsed = parseOrReport(text, r.problems);
    if (!parsed)
        return r;
    const Value& root = *parsed;
    if (!dev::files::json::checkSchema(root, kCalibrationSchema, kCalibrationVersion, r.problems))
        return r;
    ObjectReader o(root, "", r.problems);
    o.refuseUnknown({"schema", "version", "deck", "slots"});
    r.deck = o.string("deck", true).value_or("");
    const Value* list = o.get("slots", Value::Type::Array, true);
    if (!list)
        return r;
    std::set<std::string> seen;
    for (std::size_t k = 0; k < list->items().size() && k < 64; ++k) {
        const std::string at = dev::files::json::childPath("slots", k);
        const std::size_t before = r.problems.size();
        ObjectReader s(list->items()[k], at, r.problems);
        s.refuseUnknown({"slot", "labware", "model", "taught_at", "points", "fit"});
        motion::plates::SlotCalibration c;
        c.slot = s.string("slot", true).value_or("");
        c.labware = s.string("labware", false).value_or("");
        c.taughtAt = s.string("taught_at", false).value_or("");
        const auto model = s.oneOf("model", false, {"similarity", "scaled-axes"});
        c.model = model && *model == "scaled-axes" ? motion::plates::FitModel::ScaledAxes : motion::plates::FitModel::Similarity;
        s.get("fit", Value::Type::Object, false);  // written for people; recomputed below
        if (!c.slot.empty() && !seen.insert(c.slot).second)
            r.problems.add(*list->items()[k].find("slot"), s.pathOf("slot"), motion::msg::make("plate.file.slot_calibrated_twice", {motion::msg::verbatim("slot", c.slot)}));
        if (const Value* pts = s.get("points", Value::Type::Array, true)) {
            for (std::size_t j = 0; j < pts->items().size() && j < 16; ++j) {
                ObjectReader p(pts->items()[j], dev::files::json::childPath(s.pathOf("points"), j), r.problems);
                p.refuseUnknown({"well", "plate_x_mm", "plate_y_mm", "machine_x_mm", "machine_y_mm"});
                motion::plates::TeachPoint t;
                t.well = p.string("well", true).value_or("");
                t.plateMm.x = p.number("plate_x_mm", true, -1e6, 1e6).value_or(0);
                t.plateMm.y = p.number("plate_y_mm", true, -1e6, 1e6).value_or(0);
                t.machineMm.x = p.number("machine_x_mm", true, -1e6, 1e6).value_or(0);
                t.machineMm.y = p.number("machine_y_mm", true, -1e6, 1e6).value_or(0);
                c.points.push_back(t);
            }
        }
        if (r.problems.size() != before)
            continue;
        motion::msg::Message error;
        const auto fit = motion::plates::fitCalibration(c.points, c.model, &error);
        if (!fit) {
            r.problems.add(list->items()[k], at, motion::msg::make("plate.file.cannot_fit", {motion::msg::nested("cause", error)}));
            continue;
        }
        c.fit = *fit;
        r.calibrations.push_back(std::move(c));
    }
    return r;
}

std::string writeCalibration(const std::string& deckId, const std::vector<motion::plates::SlotCalibration>& calibrations)
{
    Value v = dev::files::json::schemaObject(kCalibrationSchema, kCalibrationVersion);
    v.set("deck", deckId);
    Value list = Value::array();
    for (const motion::plates::SlotCalibration& c : calibrations) {
        Value s = Value::object();
        s.set("slot", c.slot);
        if (!c.labware.empty())
            s.set("labware", c.labware);
        s.set("model", motion::plates::fitModelName(c.model));
        if (!c.taughtAt.empty())
            s.set("taught_at", c.taughtAt);
        Value pts = Value::array();
        for (const motion::plates::TeachPoint& t : c.points) {
            Value p = Value::object();
            p.set("well", t.well);
            p.set("plate_x_mm", t.plateMm.x);
            p.set("plate_y_mm", t.plateMm.y);
            p.set("machine_x_mm", t.machineMm.x);
            p.set("machine_y_mm", t.machineMm.y);
            pts.push(std::move(p));
        }
        s.set("points", std::move(pts));
        Value fit = Value::object();
        fit.set("rotation_deg", c.fit.rotationDeg);
        fit.set("scale_x", c.fit.scaleX);
        fit.set("scale_y", c.fit.scaleY);
        fit.set("offset_x_mm", c.fit.transform.txMm);
        fit.set("offset_y_mm", c.fit.transform.tyMm);
        Value res = Value::array();
        for (double d : c.fit.residualMm)
            res.push(d);
        fit.set("residual_mm", std::move(res));
        s.set("fit", std::move(fit));
        list.push(std::move(s));
    }
    v.set("slots", std::move(list));
    return dev::files::json::write(v);
}

std::map<std::string, motion::plates::PlateTransform> calibrationTransforms(const std::vector<motion::plates::SlotCalibration>& calibrations)
{
    std::map<std::string, motion::plates::PlateTransform> out;
    for (const auto& c : calibrations)
        out[c.slot] = c.fit.transform;
    return out;
}

} // namespace dev::files::plates
