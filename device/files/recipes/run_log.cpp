#include "device/files/recipes/run_log.h"

#include "device/files/json_lines.h"

namespace dev::files::plates {

using dev::files::json::ObjectReader;
using dev::files::json::Value;

int RunLogState::doneCount() const
{
    int n = 0;
    for (const OpRecord& r : ops)
        n += r.state == OpState::Done || r.state == OpState::Skipped;
    return n;
}

int RunLogState::firstOpenOp() const
{
    for (std::size_t i = 0; i < ops.size(); ++i)
        if (ops[i].state != OpState::Done && ops[i].state != OpState::Skipped)
            return static_cast<int>(i);
    return opCount;
}

RunLogState readRunLog(std::string_view text)
{
    RunLogState st;
    bool header = false;
    dev::files::json::TextLines lines(text);
    while (const auto line = lines.next()) {
        if (line->text.empty())
            continue;
        const int lineNo = line->number;
        dev::files::json::ParseResult parsed;
        const auto read = dev::files::json::parseLine(*line, true, parsed, st.problems);
        if (read == dev::files::json::LineOutcome::Torn) {
            st.tornTail = true;  // written up to a crash: the line never completed
            break;
        }
        if (read == dev::files::json::LineOutcome::Error)
            continue;
        const Value& v = *parsed.value;
        dev::files::json::Problems local;
        ObjectReader o(v, "", local);
        const auto event = o.oneOf("event", true, {"run", "resume", "start", "pump", "done", "skip", "redo", "stop", "finished"});
        if (event && *event == "run") {
            if (header)
                local.add(v, "event", motion::msg::make("file.log.second_header"));
            dev::files::json::checkSchema(v, kRunLogSchema, kRunLogVersion, local);
            o.refuseUnknown({"schema", "version", "event", "recipe", "fingerprint", "ops", "p_ul", "orders", "time"});
            if (const Value* orders = o.get("orders", Value::Type::Array, false))
                for (const Value& item : orders->items())
                    st.orders.push_back(item.isString() ? item.asString() : std::string());
            st.startPumpUl = o.number("p_ul", false, -1e9, 1e9);
            st.recipe = o.string("recipe", false).value_or("");
            st.fingerprint = o.string("fingerprint", true).value_or("");
            st.opCount = static_cast<int>(o.integer("ops", true, 0, 1000000).value_or(0));
            st.ops.assign(static_cast<std::size_t>(st.opCount), OpRecord{});
            header = true;
            ++st.runs;
        } else if (event && !header) {
            local.add(v, "event", motion::msg::make("file.log.no_header_first"));
        } else if (event) {
            o.refuseUnknown({"event", "op", "time", "kind", "step", "plate", "well", "station", "volume_ul", "p_ul", "reason", "device"});
            o.string("time", false);
            const bool perOp = *event == "start" || *event == "pump" || *event == "done" || *event == "skip" || *event == "redo";
            long long opIndex = -1;
            if (perOp) {
                opIndex = o.integer("op", true, 0, 1000000).value_or(-1);
                if (opIndex >= 0 && static_cast<std::size_t>(opIndex) >= st.ops.size()) {
                    local.add(*v.find("op"), "op", motion::msg::make("file.log.op_beyond", {motion::msg::integer("op", opIndex, motion::msg::Unit::None),
                                                                                    motion::msg::integer("count", static_cast<long long>(st.ops.size()))}));
                    opIndex = -1;
                }
            }
            const motion::msg::Arg opArg = motion::msg::integer("op", opIndex, motion::msg::Unit::None);
            const auto pUl = o.number("p_ul", false, -1e9, 1e9);
            if (*event == "resume") {
                ++st.runs;
                st.finished = false;
            } else if (*event == "stop") {
                st.lastStop = o.string("reason", false).value_or("");
            } else if (*event == "finished") {
                st.finished = true;
            } else if (opIndex >= 0 && local.empty()) {
                OpRecord& r = st.ops[static_cast<std::size_t>(opIndex)];
                const bool closed = r.state == OpState::Done || r.state == OpState::Skipped;
                if (*event == "start") {
                    if (closed)
                        local.add(v, "op", motion::msg::make("file.log.op_restarted", {opArg}));
                    r.state = OpState::Started;
                    r.kind = o.string("kind", false).value_or("");
                    r.plate = o.string("plate", false).value_or("");
                    r.well = o.string("well", false).value_or("");
                    r.station = o.string("station", false).value_or("");
                    r.volumeUl = o.number("volume_ul", false, -1e9, 1e9).value_or(0);
                    o.integer("step", false, 0, 1000000);
                    r.pumpStartUl.reset();
                    r.pumpEndUl.reset();
                    ++r.starts;
                } else if (*event == "pump") {
                    if (r.state != OpState::Started)
                        local.add(v, "op", motion::msg::make("file.log.pump_before_start", {opArg}));
                    r.state = OpState::Interrupted;
                    r.pumpStartUl = pUl;
                } else if (*event == "done") {
                    if (r.state != OpState::Started && r.state != OpState::Interrupted)
                        local.add(v, "op", motion::msg::make("file.log.done_not_started", {opArg}));
                    r.state = OpState::Done;
                    r.pumpEndUl = pUl;
                    if (pUl)
                        st.lastPumpUl = pUl;
                } else if (*event == "skip") {
                    if (r.state != OpState::Interrupted)
                        local.add(v, "op", motion::msg::make("file.log.skip_not_interrupted", {opArg}));
                    r.state = OpState::Skipped;
                    o.string("reason", false);
                    if (pUl)
                        st.lastPumpUl = pUl;
                } else {  // redo: informational; the next start line begins it again
                    o.string("reason", false);
                }
                r.line = lineNo;
            }
        }
        dev::files::json::addAtLine(st.problems, local, lineNo);
        if (st.problems.size() > 100)
            break;
    }
    if (!header && st.problems.empty())
        st.problems.add(dev::files::json::Position{1, 1}, "", motion::msg::make(text.empty() ? "file.log.empty" : "file.log.no_header"));
    return st;
}

} // namespace dev::files::plates
