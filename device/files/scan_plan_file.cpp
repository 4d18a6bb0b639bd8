#include "device/files/scan_plan_file.h"

#include "device/files/camera/camera_profile_file.h"

#include <QDir>

#include "device/files/text_file.h"

#include <QFileInfo>

#include <cmath>
#include <cstdlib>

namespace dev::files::scan {

using dev::files::json::ObjectReader;
using dev::files::json::Problems;
using dev::files::json::Value;
using motion::scan::Point2;
using motion::scan::ScanPlan;

namespace {

constexpr double kScanAny = 1e300;  // ranges are the plan validator's job; the reader checks types

/// An array of exactly `n` numbers; each whole when `whole`.
std::optional<std::vector<double>> readNumbers(const Value& v, const std::string& path, std::size_t n, bool whole, Problems& p)
{
    if (!v.isArray() || v.items().size() != n) {
        p.add(v, path, motion::msg::make("file.json.array_of_numbers", {motion::msg::integer("count", static_cast<long long>(n))}));
        return std::nullopt;
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) {
        const Value& item = v.items()[i];
        if (!item.isNumber()) {
            p.add(item, dev::files::json::childPath(path, i), dev::files::json::wrongType(Value::Type::Number, item.type()));
            return std::nullopt;
        }
        if (whole && std::floor(item.asNumber()) != item.asNumber()) {
            p.add(item, dev::files::json::childPath(path, i), motion::msg::make("file.json.not_whole", {motion::msg::real("value", item.asNumber())}));
            return std::nullopt;
        }
        out.push_back(item.asNumber());
    }
    return out;
}

std::optional<Point2> readPoint(const Value& v, const std::string& path, Problems& p)
{
    const auto xy = readNumbers(v, path, 2, false, p);
    if (!xy)
        return std::nullopt;
    return Point2{(*xy)[0], (*xy)[1]};
}

/// A member that is a pair of numbers ([x, y], [w, h]).
std::optional<std::vector<double>> pairMember(ObjectReader& o, std::string_view key, bool required, bool whole = false)
{
    const Value* v = o.get(key, Value::Type::Array, required);
    if (!v)
        return std::nullopt;
    return readNumbers(*v, o.pathOf(key), 2, whole, o.problems());
}

std::optional<std::vector<double>> polyMember(ObjectReader& o, std::string_view key)
{
    const Value* v = o.get(key, Value::Type::Array, false);
    if (!v)
        return std::nullopt;
    std::vector<double> out;
    for (std::size_t i = 0; i < v->items().size(); ++i) {
        const Value& item = v->items()[i];
        if (!item.isNumber()) {
            o.problems().add(item, dev::files::json::childPath(o.pathOf(key), i), dev::files::json::wrongType(Value::Type::Number, item.type()));
            return std::nullopt;
        }
        out.push_back(item.asNumber());
    }
    return out;
}

void readRegion(const Value& v, ScanPlan& plan, Problems& p)
{
    using motion::scan::RegionKind;
    ObjectReader o(v, "region", p);
    const auto kind = o.oneOf("kind", true, {"rectangle", "centre-size", "polygon"});
    if (!kind)
        return;
    auto& r = plan.region;
    if (*kind == "rectangle") {
        r.kind = RegionKind::Corners;
        o.refuseUnknown({"kind", "corners_mm"});
        const Value* corners = o.get("corners_mm", Value::Type::Array, true);
        if (!corners)
            return;
        if (corners->items().size() != 2) {
            p.add(*corners, "region.corners_mm", motion::msg::make("scan.file.two_corners"));
            return;
        }
        const auto a = readPoint(corners->items()[0], "region.corners_mm[0]", p);
        const auto b = readPoint(corners->items()[1], "region.corners_mm[1]", p);
        if (a && b) {
            r.cornerA = *a;
            r.cornerB = *b;
        }
    } else if (*kind == "centre-size") {
        r.kind = RegionKind::CentreSize;
        o.refuseUnknown({"kind", "centre_mm", "size_mm"});
        if (const auto c = pairMember(o, "centre_mm", true))
            r.centre = {(*c)[0], (*c)[1]};
        if (const auto s = pairMember(o, "size_mm", true)) {
            r.widthMm = (*s)[0];
            r.heightMm = (*s)[1];
        }
    } else {
        r.kind = RegionKind::Polygon;
        o.refuseUnknown({"kind", "vertices_mm"});
        const Value* vs = o.get("vertices_mm", Value::Type::Array, true);
        if (!vs)
            return;
        r.vertices.clear();
        for (std::size_t i = 0; i < vs->items().size(); ++i)
            if (const auto pt = readPoint(vs->items()[i], dev::files::json::childPath("region.vertices_mm", i), p))
                r.vertices.push_back(*pt);
    }
}

void readCamera(const Value& v, ScanPlan& plan, Problems& p)
{
    using motion::scan::FieldSource;
    ObjectReader o(v, "camera", p);
    auto& c = plan.camera;
    // A plan naming a camera profile takes its geometry from there (loadPlan): what it
    // says itself is the fallback a reader without the profile shows.
    if (const auto profile = o.string("profile", false))
        c.profile = *profile;
    const auto from = o.oneOf("fov_from", c.profile.empty(), {"sensor", "field"});
    if (!from && !c.profile.empty())
        c.source = FieldSource::Direct;
    if (from && *from == "sensor") {
        c.source = FieldSource::Sensor;
        o.refuseUnknown({"fov_from", "sensor_px", "sensor_pixel_um", "magnification", "rotation_deg", "image_y", "profile"});
        if (const auto px = pairMember(o, "sensor_px", true, true)) {
            c.sensorWidthPx = static_cast<int>(std::fmax(-1e9, std::fmin(1e9, (*px)[0])));
            c.sensorHeightPx = static_cast<int>(std::fmax(-1e9, std::fmin(1e9, (*px)[1])));
        }
        if (const auto um = o.number("sensor_pixel_um", true, -kScanAny, kScanAny))
            c.sensorPixelUm = *um;
        if (const auto m = o.number("magnification", true, -kScanAny, kScanAny))
            c.magnification = *m;
    } else if (from || !c.profile.empty()) {
        c.source = FieldSource::Direct;
        o.refuseUnknown({"fov_from", "field_mm", "pixel_um", "rotation_deg", "image_y", "profile"});
        if (const auto f = pairMember(o, "field_mm", true)) {
            c.fieldWidthMm = (*f)[0];
            c.fieldHeightMm = (*f)[1];
        }
        if (const auto um = o.number("pixel_um", false, -kScanAny, kScanAny))
            c.samplePixelUm = *um;
    }
    if (const auto r = o.number("rotation_deg", false, -kScanAny, kScanAny))
        c.rotationDeg = *r;
    if (const auto y = o.oneOf("image_y", false, {"stage-minus-y", "stage-plus-y"}))
        c.imageY = *y == "stage-plus-y" ? motion::scan::ImageY::StagePlusY : motion::scan::ImageY::StageMinusY;
}

void readOverlap(ObjectReader& o, ScanPlan& plan)
{
    const Value* v = o.value().find("overlap");
    if (!v)
        return;
    if (v->isNumber()) {
        plan.overlapX = plan.overlapY = v->asNumber();
        return;
    }
    if (const auto pair = readNumbers(*v, "overlap", 2, false, o.problems())) {
        plan.overlapX = (*pair)[0];
        plan.overlapY = (*pair)[1];
    }
}

void readRest(ObjectReader& root, ScanPlan& plan, Problems& p)
{
    if (const Value* a = root.get("approach", Value::Type::Object, false)) {
        ObjectReader o(*a, "approach", p);
        o.refuseUnknown({"unidirectional", "overtravel_mm"});
        if (const auto u = o.boolean("unidirectional", false))
            plan.approach.unidirectional = *u;
        if (const auto d = o.number("overtravel_mm", false, -kScanAny, kScanAny))
            plan.approach.overtravelMm = *d;
    }
    if (const Value* m = root.get("motion", Value::Type::Object, false)) {
        ObjectReader o(*m, "motion", p);
        o.refuseUnknown({"speed_mm_s"});
        if (const auto s = o.number("speed_mm_s", false, -kScanAny, kScanAny))
            plan.speedMmS = *s;
    }
    if (const Value* t = root.get("timing", Value::Type::Object, false)) {
        ObjectReader o(*t, "timing", p);
        o.refuseUnknown({"settle_s", "exposure_s", "tolerance_um", "settle_timeout_s"});
        if (const auto v = o.number("settle_s", false, -kScanAny, kScanAny))
            plan.settleS = *v;
        if (const auto v = o.number("exposure_s", false, -kScanAny, kScanAny))
            plan.exposureS = *v;
        if (const auto v = o.number("tolerance_um", false, -kScanAny, kScanAny))
            plan.toleranceUm = *v;
        if (const auto v = o.number("settle_timeout_s", false, -kScanAny, kScanAny))
            plan.settleTimeoutS = *v;
    }
    if (const Value* c = root.get("compensation", Value::Type::Object, false)) {
        ObjectReader o(*c, "compensation", p);
        o.refuseUnknown({"enabled", "x_error_poly_um", "y_error_poly_um"});
        if (const auto e = o.boolean("enabled", false))
            plan.compensation.enabled = *e;
        // Plans from before the device kept its own compensation carried seed 002's
        // curves here; they are read (and checked) but no longer used: the stage's
        // own compensation is (docs/scan.md, "Compensation").
        (void)polyMember(o, "x_error_poly_um");
        (void)polyMember(o, "y_error_poly_um");
    }
    if (const Value* e = root.get("export", Value::Type::Object, false)) {
        ObjectReader o(*e, "export", p);
        o.refuseUnknown({"file_pattern", "first_index", "mm_xy_stage"});
        if (const auto s = o.string("file_pattern", false))
            plan.naming.filePattern = *s;
        if (const auto i = o.integer("first_index", false, 0, 1000000))
            plan.naming.firstIndex = static_cast<int>(*i);
        if (const auto s = o.string("mm_xy_stage", false))
            plan.naming.mmXyStage = *s;
    }
}

Value numberPair(double a, double b)
{
    Value v = Value::array();
    v.push(a);
    v.push(b);
    return v;
}

} // namespace

dev::files::json::Position locate(const Value& root, const std::string& path)
{
    const Value* at = &root;
    dev::files::json::Position best = root.position();
    std::size_t i = 0;
    while (i < path.size() && at) {
        if (path[i] == '.') {
            ++i;
            continue;
        }
        if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            if (close == std::string::npos)
                break;
            const std::size_t index = static_cast<std::size_t>(std::strtoul(path.c_str() + i + 1, nullptr, 10));
            at = at->isArray() && index < at->items().size() ? &at->items()[index] : nullptr;
            i = close + 1;
        } else {
            const std::size_t end = path.find_first_of(".[", i);
            const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
            at = at->find(key);
            i = end == std::string::npos ? path.size() : end;
        }
        if (at)
            best = at->position();
    }
    return best;
}

PlanReadResult parsePlan(std::string_view text)
{
    PlanReadResult out;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        out.problems.add(parsed.error.position, "", parsed.error.message);
        return out;
    }
    const Value& root = *parsed.value;
    if (!dev::files::json::checkSchema(root, kPlanSchema, kPlanVersion, out.problems))
        return out;
    ScanPlan plan;
    ObjectReader o(root, "", out.problems);
    o.refuseUnknown({"schema", "version", "name", "region", "camera", "overlap", "order", "start", "approach", "motion",
                     "timing", "compensation", "export"});
    if (const auto n = o.string("name", false))
        plan.name = *n;
    if (const Value* r = o.get("region", Value::Type::Object, true))
        readRegion(*r, plan, out.problems);
    if (const Value* c = o.get("camera", Value::Type::Object, true))
        readCamera(*c, plan, out.problems);
    readOverlap(o, plan);
    if (const auto order = o.oneOf("order", false, {"rows", "cols", "snake-rows", "snake-cols"}))
        plan.order = *motion::scan::orderFromName(*order);
    if (const auto start = o.oneOf("start", false, {"top-left", "top-right", "bottom-left", "bottom-right"}))
        plan.start = *motion::scan::startCornerFromName(*start);
    readRest(o, plan, out.problems);
    if (!out.problems.empty())
        return out;
    // The plan's own rules, pointed at the member they are about.
    for (const auto& problem : motion::scan::validate(plan))
        out.problems.add(locate(root, problem.path), problem.path, problem.message);
    if (out.problems.empty())
        out.plan = std::move(plan);
    return out;
}

Value planToJson(const ScanPlan& plan)
{
    using motion::scan::FieldSource;
    using motion::scan::RegionKind;
    Value root = dev::files::json::schemaObject(kPlanSchema, kPlanVersion);
    root.set("name", Value(plan.name));
    Value region = Value::object();
    const auto& r = plan.region;
    if (r.kind == RegionKind::Corners) {
        region.set("kind", Value("rectangle"));
        Value corners = Value::array();
        corners.push(numberPair(r.cornerA.xMm, r.cornerA.yMm));
        corners.push(numberPair(r.cornerB.xMm, r.cornerB.yMm));
        region.set("corners_mm", std::move(corners));
    } else if (r.kind == RegionKind::CentreSize) {
        region.set("kind", Value("centre-size"));
        region.set("centre_mm", numberPair(r.centre.xMm, r.centre.yMm));
        region.set("size_mm", numberPair(r.widthMm, r.heightMm));
    } else {
        region.set("kind", Value("polygon"));
        Value vs = Value::array();
        for (const Point2& pt : r.vertices)
            vs.push(numberPair(pt.xMm, pt.yMm));
        region.set("vertices_mm", std::move(vs));
    }
    root.set("region", std::move(region));
    Value camera = Value::object();
    const auto& c = plan.camera;
    if (c.source == FieldSource::Sensor) {
        camera.set("fov_from", Value("sensor"));
        camera.set("sensor_px", numberPair(c.sensorWidthPx, c.sensorHeightPx));
        camera.set("sensor_pixel_um", Value(c.sensorPixelUm));
        camera.set("magnification", Value(c.magnification));
    } else {
        camera.set("fov_from", Value("field"));
        camera.set("field_mm", numberPair(c.fieldWidthMm, c.fieldHeightMm));
        camera.set("pixel_um", Value(c.samplePixelUm));
    }
    camera.set("rotation_deg", Value(c.rotationDeg));
    camera.set("image_y", Value(c.imageY == motion::scan::ImageY::StagePlusY ? "stage-plus-y" : "stage-minus-y"));
    if (!c.profile.empty())
        camera.set("profile", Value(c.profile));
    root.set("camera", std::move(camera));
    root.set("overlap", numberPair(plan.overlapX, plan.overlapY));
    root.set("order", Value(motion::scan::orderName(plan.order)));
    root.set("start", Value(motion::scan::startCornerName(plan.start)));
    Value approach = Value::object();
    approach.set("unidirectional", Value(plan.approach.unidirectional));
    approach.set("overtravel_mm", Value(plan.approach.overtravelMm));
    root.set("approach", std::move(approach));
    Value motionV = Value::object();
    motionV.set("speed_mm_s", Value(plan.speedMmS));
    root.set("motion", std::move(motionV));
    Value timing = Value::object();
    timing.set("settle_s", Value(plan.settleS));
    timing.set("exposure_s", Value(plan.exposureS));
    timing.set("tolerance_um", Value(plan.toleranceUm));
    timing.set("settle_timeout_s", Value(plan.settleTimeoutS));
    root.set("timing", std::move(timing));
    Value comp = Value::object();
    comp.set("enabled", Value(plan.compensation.enabled));
    root.set("compensation", std::move(comp));
    Value ex = Value::object();
    ex.set("file_pattern", Value(plan.naming.filePattern));
    ex.set("first_index", Value(plan.naming.firstIndex));
    ex.set("mm_xy_stage", Value(plan.naming.mmXyStage));
    root.set("export", std::move(ex));
    return root;
}

std::string writePlan(const ScanPlan& plan) { return dev::files::json::write(planToJson(plan)) + "\n"; }

bool loadPlan(const QString& path, ScanPlan* plan, dev::files::json::Problems* problems)
{
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(path, &text, &error)) {
        problems->addFileProblem(error);
        return false;
    }
    PlanReadResult r = parsePlan(text);
    if (!r.plan) {
        *problems = std::move(r.problems);
        return false;
    }
    if (!r.plan->camera.profile.empty()) {
        // The profile lies beside the plan unless the plan says where.
        const QString named = QString::fromStdString(r.plan->camera.profile);
        const QString profilePath = QDir(QFileInfo(path).absolutePath()).filePath(named);
        const auto profile = dev::files::camera::loadCameraProfileFile(profilePath);
        if (!profile.ok()) {
            const auto parsed = dev::files::json::parse(text);
            const dev::files::json::Position at = parsed ? locate(*parsed.value, "camera.profile") : dev::files::json::Position{};
            for (const motion::msg::Problem& p : profile.problems())
                problems->add(at, "camera.profile",
                              motion::msg::make("scan.plan.camera_profile_problem",
                                                {motion::msg::verbatim("file", p.file.empty() ? named.toStdString() : p.file),
                                                 motion::msg::integer("line", p.line), motion::msg::integer("column", p.column),
                                                 motion::msg::nested("cause", p.message)}));
            return false;
        }
        dev::files::camera::applyCameraProfile(*profile, &r.plan->camera);
    }
    *plan = std::move(*r.plan);
    return true;
}

bool savePlan(const QString& path, const ScanPlan& plan, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, writePlan(plan), error);
}

} // namespace dev::files::scan
