#include "device/files/scan_run_log.h"

#include "device/files/json_lines.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>

namespace dev::files::scan {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

std::string fingerprintText(std::uint64_t fingerprint)
{
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, fingerprint);
    return buf;
}

std::string runLogHeader(const std::string& planName, std::uint64_t fingerprint, int tiles)
{
    Value v = dev::files::json::schemaObject(kRunLogSchema, kRunLogVersion);
    v.set("plan", Value(planName));
    v.set("fingerprint", Value(fingerprintText(fingerprint)));
    v.set("tiles", Value(tiles));
    return dev::files::json::write(v, false) + "\n";
}

namespace {

Value list(const std::vector<double>& xs)
{
    Value v = Value::array();
    for (double x : xs)
        v.push(x);
    return v;
}

std::optional<std::vector<double>> readAxes(ObjectReader& o, std::string_view key)
{
    const Value* v = o.get(key, Value::Type::Array, true);
    if (!v)
        return std::nullopt;
    std::vector<double> out;
    for (const Value& item : v->items()) {
        if (!item.isNumber()) {
            o.problems().add(item, o.pathOf(key), dev::files::json::wrongType(dev::files::json::Value::Type::Number, item.type()));
            return std::nullopt;
        }
        out.push_back(item.asNumber());
    }
    if (out.size() != 2) {
        o.problems().add(*v, o.pathOf(key), motion::msg::make("file.json.array_of_numbers", {motion::msg::integer("count", 2)}));
        return std::nullopt;
    }
    return out;
}

} // namespace

std::string runLogLine(const motion::PositionRecord& r, const TileImageRef& image)
{
    Value v = Value::object();
    v.set("tile", Value(r.target));
    v.set("label", Value(r.label));
    v.set("planned_mm", list(r.plannedMm));
    v.set("commanded_mm", list(r.commandedMm));
    v.set("measured_mm", list(r.measuredMm));
    v.set("device_time_us", Value(static_cast<double>(r.deviceTimeUs)));
    v.set("settle_s", Value(r.settleS));
    if (!image.file.empty()) {
        v.set("image", Value(image.file));
        v.set("sha256", Value(image.sha256));
    }
    return dev::files::json::write(v, false) + "\n";
}

RunLogReadResult parseRunLog(std::string_view text)
{
    RunLogReadResult out;
    RunLog log;
    bool header = false;
    dev::files::json::TextLines lines(text);
    while (const auto line = lines.next()) {
        if (dev::files::json::isBlank(line->text))
            continue;
        const int lineNo = line->number;
        dev::files::json::ParseResult parsed;
        if (const auto read = dev::files::json::parseLine(*line, header, parsed, out.problems); read != dev::files::json::LineOutcome::Value) {
            log.tornTail = read == dev::files::json::LineOutcome::Torn;  // the write a crash interrupted: that tile is simply not taken
            break;
        }
        dev::files::json::Problems lp;
        if (!header) {
            if (dev::files::json::checkSchema(*parsed.value, kRunLogSchema, kRunLogVersion, lp)) {
                ObjectReader o(*parsed.value, "", lp);
                o.refuseUnknown({"schema", "version", "plan", "fingerprint", "tiles"});
                const auto name = o.string("plan", true);
                const auto fp = o.string("fingerprint", true);
                const auto tiles = o.integer("tiles", true, 1, 1000000000);
                if (fp && (fp->size() != 16 || fp->find_first_not_of("0123456789abcdef") != std::string::npos))
                    lp.add(*parsed.value->find("fingerprint"), "fingerprint", motion::msg::make("file.log.bad_fingerprint"));
                else if (name && fp && tiles) {
                    log.planName = *name;
                    log.fingerprint = std::strtoull(fp->c_str(), nullptr, 16);
                    log.tiles = static_cast<int>(*tiles);
                }
            }
            dev::files::json::addAtLine(out.problems, lp, lineNo);
            if (!out.problems.empty())
                return out;
            header = true;
            continue;
        }
        ObjectReader o(*parsed.value, "", lp);
        o.refuseUnknown({"tile", "label", "planned_mm", "commanded_mm", "measured_mm", "device_time_us", "settle_s", "image", "sha256"});
        motion::PositionRecord r;
        const auto tile = o.integer("tile", true, 0, log.tiles - 1);
        const auto label = o.string("label", true);
        const auto planned = readAxes(o, "planned_mm");
        const auto commanded = readAxes(o, "commanded_mm");
        const auto measured = readAxes(o, "measured_mm");
        const auto time = o.number("device_time_us", true, 0, 9007199254740992.0);
        const auto settle = o.number("settle_s", true, 0, 1e6);
        const auto image = o.string("image", false);
        const auto sha = o.string("sha256", false);
        const bool shaOk = !sha || (sha->size() == 64 && sha->find_first_not_of("0123456789abcdef") == std::string::npos);
        if (!shaOk)
            lp.add(*parsed.value->find("sha256"), "sha256", motion::msg::make("file.log.bad_sha256"));
        // The image is a file in the run's folder: a path out of it is not one this log wrote.
        const bool imageOk = !image || (!image->empty() && *image != "." && *image != ".." && image->find_first_of("/\\") == std::string::npos);
        if (!imageOk)
            lp.add(*parsed.value->find("image"), "image", motion::msg::make("file.log.bad_image_name"));
        if (image.has_value() != sha.has_value())
            lp.add(*parsed.value, image ? "sha256" : "image", motion::msg::make("file.log.image_without_sha256"));
        if (tile && label && planned && commanded && measured && time && settle && shaOk && imageOk && image.has_value() == sha.has_value()) {
            r.target = static_cast<int>(*tile);
            r.label = *label;
            r.plannedMm = *planned;
            r.commandedMm = *commanded;
            r.measuredMm = *measured;
            r.deviceTimeUs = static_cast<std::uint64_t>(*time);
            r.settleS = *settle;
            log.records.push_back(std::move(r));
            log.images.push_back({image.value_or(std::string()), sha.value_or(std::string())});
        }
        dev::files::json::addAtLine(out.problems, lp, lineNo);
    }
    if (!header && out.problems.empty())
        out.problems.add(dev::files::json::Position{1, 1}, "", motion::msg::make("file.log.empty"));
    if (out.problems.empty())
        out.log = std::move(log);
    return out;
}

} // namespace dev::files::scan
