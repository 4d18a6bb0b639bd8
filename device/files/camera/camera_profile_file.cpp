#include "device/files/camera/camera_profile_file.h"

#include "device/files/accuracy/grid/stage_errors_file.h"
#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

#include <cmath>

namespace dev::files::camera {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

namespace {

/// Pixels beyond this (1 mm) are no microscope's; sensors beyond 65535 px no TIFF's.
constexpr double kProfileMaxPixelUm = 1000;
constexpr double kProfileMaxSensorPx = 65535;

Value profilePair(double a, double b)
{
    Value v = Value::array();
    v.push(a);
    v.push(b);
    return v;
}

/// A pair of numbers in [lo, hi] at `key`, each element's problem at its own place.
std::optional<std::pair<double, double>> profilePairMember(ObjectReader& o, const char* key, bool required, double lo, double hi, bool whole)
{
    const Value* list = o.get(key, Value::Type::Array, required);
    if (!list)
        return std::nullopt;
    if (list->items().size() != 2) {
        o.problems().add(*list, o.pathOf(key), motion::msg::make("file.json.array_of_numbers", {motion::msg::integer("count", 2)}));
        return std::nullopt;
    }
    double v[2] = {0, 0};
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
        const Value& k = list->items()[i];
        const std::string path = dev::files::json::childPath(o.pathOf(key), i);
        if (!k.isNumber()) {
            o.problems().add(k, path, dev::files::json::wrongType(Value::Type::Number, k.type()));
            ok = false;
            continue;
        }
        v[i] = k.asNumber();
        if (!(v[i] >= lo && v[i] <= hi) || (whole && std::floor(v[i]) != v[i])) {
            o.problems().add(k, path, !(v[i] >= lo && v[i] <= hi) ? dev::files::json::outOfRange(v[i], lo, hi)
                                                                  : motion::msg::make("file.json.not_whole", {motion::msg::real("value", v[i])}));
            ok = false;
        }
    }
    if (!ok)
        return std::nullopt;
    return std::make_pair(v[0], v[1]);
}

} // namespace

std::string cameraProfileToJson(const CameraProfile& p)
{
    Value root = dev::files::json::schemaObject(kCameraProfileSchema, kCameraProfileVersion);
    root.set("camera", Value(p.camera));
    root.set("sensor_px", profilePair(p.sensorWidthPx, p.sensorHeightPx));
    root.set("pixel_um", profilePair(p.pixelXUm, p.pixelYUm));
    root.set("rotation_deg", Value(p.rotationDeg));
    root.set("image_y", Value(p.imageYAlongPlusY ? "stage-plus-y" : "stage-minus-y"));
    if (p.calibrated) {
        const CameraCalibrationRecord& c = p.calibration;
        Value cal = Value::object();
        cal.set("method", Value(c.method));
        if (!c.when.empty())
            cal.set("when", Value(c.when));
        cal.set("images", Value(c.images));
        cal.set("step_um", Value(c.stepUm));
        cal.set("residual_rms_px", Value(c.residualRmsPx));
        cal.set("residual_max_px", Value(c.residualMaxPx));
        cal.set("skew_deg", Value(c.skewDeg));
        cal.set("return_px", Value(c.returnPx));
        root.set("calibration", std::move(cal));
    }
    if (!p.note.empty())
        root.set("note", Value(p.note));
    return dev::files::json::write(root);
}

CameraProfileRead cameraProfileFromJson(std::string_view text, std::string_view fileName)
{
    using dev::files::accuracy::addJsonProblems;
    motion::msg::Problems problems;
    const dev::files::json::ParseResult parsed = dev::files::json::parse(text);
    if (!parsed) {
        problems.push_back(dev::files::accuracy::fromParseError(parsed.error, fileName));
        return CameraProfileRead::refused(std::move(problems));
    }
    const Value& root = *parsed.value;
    dev::files::json::Problems p;
    if (!dev::files::json::checkSchema(root, kCameraProfileSchema, kCameraProfileVersion, p)) {
        addJsonProblems(p, fileName, problems);
        return CameraProfileRead::refused(std::move(problems));
    }
    CameraProfile out;
    ObjectReader o(root, "", p);
    if (auto c = o.string("camera", false))
        out.camera = *c;
    if (auto s = profilePairMember(o, "sensor_px", true, 1, kProfileMaxSensorPx, true)) {
        out.sensorWidthPx = static_cast<int>(s->first);
        out.sensorHeightPx = static_cast<int>(s->second);
    }
    if (auto px = profilePairMember(o, "pixel_um", true, 1e-6, kProfileMaxPixelUm, false)) {
        out.pixelXUm = px->first;
        out.pixelYUm = px->second;
    }
    if (auto r = o.number("rotation_deg", true, -360, 360))
        out.rotationDeg = *r;
    if (auto y = o.oneOf("image_y", true, {"stage-minus-y", "stage-plus-y"}))
        out.imageYAlongPlusY = *y == "stage-plus-y";
    if (const Value* c = o.get("calibration", Value::Type::Object, false)) {
        ObjectReader co(*c, "calibration", p);
        out.calibrated = true;
        CameraCalibrationRecord& r = out.calibration;
        if (auto m = co.oneOf("method", true, {"stage-steps", "entered"}))
            r.method = *m;
        if (auto w = co.string("when", false))
            r.when = *w;
        if (auto n = co.integer("images", false, 0, 100000))
            r.images = static_cast<int>(*n);
        if (auto v = co.number("step_um", false, 0, 1e6))
            r.stepUm = *v;
        if (auto v = co.number("residual_rms_px", false, 0, 1e6))
            r.residualRmsPx = *v;
        if (auto v = co.number("residual_max_px", false, 0, 1e6))
            r.residualMaxPx = *v;
        if (auto v = co.number("skew_deg", false, -90, 90))
            r.skewDeg = *v;
        if (auto v = co.number("return_px", false, 0, 1e6))
            r.returnPx = *v;
        co.refuseUnknown({"method", "when", "images", "step_um", "residual_rms_px", "residual_max_px", "skew_deg", "return_px"});
    }
    if (auto n = o.string("note", false))
        out.note = *n;
    o.refuseUnknown({"schema", "version", "camera", "sensor_px", "pixel_um", "rotation_deg", "image_y", "calibration", "note"});
    addJsonProblems(p, fileName, problems);
    return CameraProfileRead::from(out, std::move(problems));
}

CameraProfileRead loadCameraProfileFile(const QString& path)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = dev::files::accuracy::loadText(path, name, problems);
    return text ? cameraProfileFromJson(*text, name) : CameraProfileRead::refused(std::move(problems));
}

bool saveCameraProfileFile(const QString& path, const CameraProfile& p, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, cameraProfileToJson(p), error);
}

void applyCameraProfile(const CameraProfile& p, motion::scan::Camera* c)
{
    c->source = motion::scan::FieldSource::Direct;
    c->samplePixelUm = p.pixelUm();
    c->fieldWidthMm = p.sensorWidthPx * c->samplePixelUm / 1000.0;
    c->fieldHeightMm = p.sensorHeightPx * c->samplePixelUm / 1000.0;
    c->rotationDeg = p.rotationDeg;
    c->imageY = p.imageYAlongPlusY ? motion::scan::ImageY::StagePlusY : motion::scan::ImageY::StageMinusY;
}

} // namespace dev::files::camera
