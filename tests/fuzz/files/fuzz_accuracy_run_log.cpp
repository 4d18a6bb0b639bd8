// Fuzz targets "accuracy-run-log" and "gauge-answer": the accuracy run's journal and a
// gauge's answer line. Invariants: no crash; a log accepted has its stops in order,
// each once, and writes back line for line; a gauge value is finite.
#include "fuzz_files.h"

#include "device/files/accuracy/accuracy_run_log.h"
#include "device/link/gauge_dialect.h"

#include <cmath>

namespace {

std::string seedLog()
{
    dev::files::accuracy::RunLogHeader h;
    h.test = "stage-x";
    h.kind = "axis";
    h.fingerprint = 0x0123456789abcdefull;
    h.stops = 4;
    h.source = "gauge";
    std::string text = dev::files::accuracy::runLogHeader(h);
    for (int k = 0; k < 3; ++k) {
        dev::files::accuracy::RunLogEntry e;
        e.stop = k;
        e.cycle = 1;
        e.direction = k < 2 ? motion::metrology::Direction::Up : motion::metrology::Direction::Down;
        e.targetMm = {10.0 * (k + 1)};
        if (k != 1)
            e.measuredMm = std::vector<double>{10.0 * (k + 1) + 0.001};
        e.deviceTimeUs = 1000000u * static_cast<unsigned>(k + 1);
        e.timeS = k + 1;
        text += dev::files::accuracy::runLogLine(e);
    }
    return text;
}

void checkLog(std::string_view input)
{
    const auto r = dev::files::accuracy::parseRunLog(input);
    if (!r.log)
        return;
    std::string again = dev::files::accuracy::runLogHeader(r.log->header);
    for (std::size_t k = 0; k < r.log->entries.size(); ++k) {
        const auto& e = r.log->entries[k];
        if (e.stop != static_cast<int>(k))
            fuzzfiles::fail("a log accepted with a stop out of order or twice");
        if (e.measuredMm && e.measuredMm->size() != e.targetMm.size())
            fuzzfiles::fail("a reading without a value per axis");
        again += dev::files::accuracy::runLogLine(e);
    }
    const auto back = dev::files::accuracy::parseRunLog(again);
    if (!back.log || back.log->entries.size() != r.log->entries.size())
        fuzzfiles::fail("a log that does not read back as written");
    std::string twice = dev::files::accuracy::runLogHeader(back.log->header);
    for (const auto& e : back.log->entries)
        twice += dev::files::accuracy::runLogLine(e);
    if (twice != again)
        fuzzfiles::fail("a log that does not write back the same");
}

void checkGauge(std::string_view input)
{
    const auto a = dev::gaugewire::parseAnswer(input, "fuzz");
    if (a.valueMm && !std::isfinite(*a.valueMm))
        fuzzfiles::fail("a gauge value that is not finite");
    if (!a.valueMm && a.problem.id.empty())
        fuzzfiles::fail("a refused answer without a reason");
    if (dev::gaugewire::printable(input).size() > 80 * 4 + 3)
        fuzzfiles::fail("printable() longer than its cut");
}

} // namespace

BP_FUZZ_FILE_TARGET({"accuracy-run-log", [] { return std::vector<std::string>{seedLog()}; }, checkLog});
BP_FUZZ_FILE_TARGET({"gauge-answer",
                     [] { return std::vector<std::string>{"+012.3456 mm", "-0.5 \xC2\xB5m", "12.3in", "Err 7"}; }, checkGauge});
