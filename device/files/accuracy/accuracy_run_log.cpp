#include "device/files/accuracy/accuracy_run_log.h"

#include "device/files/json_lines.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>

namespace dev::files::accuracy {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

namespace {

Value list(const std::vector<double>& xs)
{
    Value v = Value::array();
    for (double x : xs)
        v.push(x);
    return v;
}

std::optional<std::vector<double>> readPositions(ObjectReader& o, std::string_view key, bool nullAllowed, bool& wasNull)
{
    wasNull = false;
    const Value* raw = o.value().find(key);
    if (nullAllowed && raw && raw->type() == Value::Type::Null) {
        wasNull = true;
        return std::vector<double>{};
    }
    const Value* v = o.get(key, Value::Type::Array, true);
    if (!v)
        return std::nullopt;
    std::vector<double> out;
    for (const Value& item : v->items()) {
        if (!item.isNumber()) {
            o.problems().add(item, o.pathOf(key), motion::msg::make("accuracy.log.positions_not_numbers"));
            return std::nullopt;
        }
        out.push_back(item.asNumber());
    }
    if (out.empty() || out.size() > 2) {
        o.problems().add(*v, o.pathOf(key), motion::msg::make("accuracy.log.positions_count"));
        return std::nullopt;
    }
    return out;
}

} // namespace

std::uint64_t fingerprintOf(std::string_view text)
{
    std::uint64_t h = 14695981039346656037ull;
    for (char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return h;
}

std::string fingerprintText(std::uint64_t fingerprint)
{
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, fingerprint);
    return buf;
}

std::string runLogHeader(const RunLogHeader& h)
{
    Value v = dev::files::json::schemaObject(kRunLogSchema, kRunLogVersion);
    v.set("test", Value(h.test));
    v.set("kind", Value(h.kind));
    v.set("fingerprint", Value(fingerprintText(h.fingerprint)));
    v.set("stops", Value(h.stops));
    v.set("source", Value(h.source));
    return dev::files::json::write(v, false) + "\n";
}

std::string runLogLine(const RunLogEntry& e)
{
    Value v = Value::object();
    v.set("stop", Value(e.stop));
    v.set("cycle", Value(e.cycle));
    v.set("direction", Value(motion::metrology::directionName(e.direction)));
    v.set("target_mm", list(e.targetMm));
    v.set("measured_mm", e.measuredMm ? list(*e.measuredMm) : Value(nullptr));
    v.set("settled", Value(e.settled));
    v.set("device_time_us", Value(static_cast<double>(e.deviceTimeUs)));
    v.set("time_s", Value(e.timeS));
    return dev::files::json::write(v, false) + "\n";
}

RunLogRead parseRunLog(std::string_view text)
{
    RunLogRead out;
    RunLog log;
    bool header = false;
    dev::files::json::TextLines lines(text);
    while (const auto line = lines.next()) {
        if (dev::files::json::isBlank(line->text))
            continue;
        const int lineNo = line->number;
        dev::files::json::ParseResult parsed;
        if (const auto read = dev::files::json::parseLine(*line, header, parsed, out.problems); read != dev::files::json::LineOutcome::Value) {
            log.tornTail = read == dev::files::json::LineOutcome::Torn;  // the write a crash interrupted: that stop is simply not read
            break;
        }
        dev::files::json::Problems lp;
        if (!header) {
            if (dev::files::json::checkSchema(*parsed.value, kRunLogSchema, kRunLogVersion, lp)) {
                ObjectReader o(*parsed.value, "", lp);
                o.refuseUnknown({"schema", "version", "test", "kind", "fingerprint", "stops", "source"});
                const auto name = o.string("test", true);
                const auto kind = o.oneOf("kind", true, {"axis", "xy-line"});
                const auto fp = o.string("fingerprint", true);
                const auto stops = o.integer("stops", true, 1, 1000000);
                const auto source = o.string("source", true);
                if (fp && (fp->size() != 16 || fp->find_first_not_of("0123456789abcdef") != std::string::npos))
                    lp.add(*parsed.value->find("fingerprint"), "fingerprint", motion::msg::make("file.log.bad_fingerprint"));
                else if (name && kind && fp && stops && source) {
                    log.header.test = *name;
                    log.header.kind = *kind;
                    log.header.fingerprint = std::strtoull(fp->c_str(), nullptr, 16);
                    log.header.stops = static_cast<int>(*stops);
                    log.header.source = *source;
                }
            }
            dev::files::json::addAtLine(out.problems, lp, lineNo);
            if (!out.problems.empty())
                return out;
            header = true;
            continue;
        }
        ObjectReader o(*parsed.value, "", lp);
        o.refuseUnknown({"stop", "cycle", "direction", "target_mm", "measured_mm", "settled", "device_time_us", "time_s"});
        RunLogEntry e;
        const auto stop = o.integer("stop", true, 0, log.header.stops - 1);
        const auto cycle = o.integer("cycle", true, 1, 1000000);
        const auto direction = o.oneOf("direction", true, {"up", "down"});
        bool targetNull = false, measuredNull = false;
        const auto target = readPositions(o, "target_mm", false, targetNull);
        const auto measured = readPositions(o, "measured_mm", true, measuredNull);
        const auto settled = o.boolean("settled", true);
        const auto time = o.number("device_time_us", true, 0, 9007199254740992.0);
        const auto seconds = o.number("time_s", true, 0, 1e9);
        if (stop && cycle && direction && target && measured && settled && time && seconds) {
            if (*stop != static_cast<long long>(log.entries.size()))
                lp.add(*parsed.value->find("stop"), "stop",
                       motion::msg::make("accuracy.log.stop_out_of_order",
                                 {motion::msg::integer("stop", *stop), motion::msg::integer("expected", static_cast<long long>(log.entries.size()))}));
            else if (!measuredNull && measured->size() != target->size())
                lp.add(*parsed.value->find("measured_mm"), "measured_mm", motion::msg::make("accuracy.log.measured_count"));
            else {
                e.stop = static_cast<int>(*stop);
                e.cycle = static_cast<int>(*cycle);
                e.direction = *direction == "up" ? motion::metrology::Direction::Up : motion::metrology::Direction::Down;
                e.targetMm = *target;
                if (!measuredNull)
                    e.measuredMm = *measured;
                e.settled = *settled;
                e.deviceTimeUs = static_cast<std::uint64_t>(*time);
                e.timeS = *seconds;
                log.entries.push_back(std::move(e));
            }
        }
        dev::files::json::addAtLine(out.problems, lp, lineNo);
        if (!out.problems.empty())
            return out;
    }
    if (!header && out.problems.empty())
        out.problems.add(dev::files::json::Position{1, 1}, "", motion::msg::make("file.log.empty"));
    if (out.problems.empty())
        out.log = std::move(log);
    return out;
}

} // namespace dev::files::accuracy
