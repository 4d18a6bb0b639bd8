// Fuzz targets "scan-plan" and "scan-run-log": the stitching scan's plan file and
// its run log. Invariants: the readers never crash; an accepted plan is valid,
// writes out and reads back to the same text, and lays out and times a grid whose
// every neighbour overlap is the one asked for; an accepted run log's records
// write back to the same lines.
#include "fuzz_files.h"

#include "device/files/scan_plan_file.h"
#include "device/files/scan_run_log.h"
#include "motion/plans/scan/scan_estimate.h"

#include <cmath>

namespace {

std::vector<std::string> planSeeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".scan.json");
    s.push_back(dev::files::scan::writePlan(motion::scan::ScanPlan{}));
    return s;
}

void checkPlan(std::string_view input)
{
    const auto r = dev::files::scan::parsePlan(input);
    if (!r.plan) {
        if (r.problems.empty())
            fuzzfiles::fail("a refused plan without a problem");
        for (const auto& p : r.problems.list())
            if (p.message.empty() || p.line < 1)
                fuzzfiles::fail("a problem without a message or a place");
        return;
    }
    if (!motion::scan::validate(*r.plan).empty())
        fuzzfiles::fail("an accepted plan does not validate");
    const std::string once = dev::files::scan::writePlan(*r.plan);
    const auto again = dev::files::scan::parsePlan(once);
    if (!again.plan)
        fuzzfiles::fail("a written plan does not read back: " + again.problems.format("plan"));
    if (dev::files::scan::writePlan(*again.plan) != once)
        fuzzfiles::fail("write → read → write changed the plan");
    // Lay out only grids a fuzz loop can afford; the planner's own bound is far larger.
    const auto g = motion::scan::gridSize(*r.plan);
    if (static_cast<long>(g.columns) * g.rows > 5000)
        return;
    const auto layout = motion::scan::layoutScan(*r.plan);
    if (layout.tiles.empty() && r.plan->region.kind != motion::scan::RegionKind::Polygon)
        fuzzfiles::fail("a valid rectangle gave no tiles");
    for (std::size_t k = 1; k < layout.tiles.size(); ++k) {
        const auto& a = layout.tiles[k - 1];
        const auto& b = layout.tiles[k];
        if (a.row == b.row && std::abs(a.col - b.col) == 1) {
            const double overlap = 1.0 - std::fabs(a.centre.xMm - b.centre.xMm) / g.fieldWidthMm;
            if (std::fabs(overlap - r.plan->overlapX) > 1e-3)
                fuzzfiles::fail("neighbours overlap by " + std::to_string(overlap));
        }
    }
    const auto e = motion::scan::estimateScan(*r.plan, layout, motion::scan::StageModel{});
    if (!(e.totalS >= 0) || !std::isfinite(e.totalS))
        fuzzfiles::fail("the estimate is not a finite time");
}

std::vector<std::string> logSeeds()
{
    motion::PositionRecord r;
    r.target = 1;
    r.label = "tile_002.tif";
    r.plannedMm = {10, 20};
    r.commandedMm = {9.99, 19.98};
    r.measuredMm = {9.9905, 19.9795};
    r.deviceTimeUs = 987654321;
    r.settleS = 0.04;
    const std::string head = dev::files::scan::runLogHeader("plan", 0xfeedfacecafebeefull, 6);
    return {head, head + dev::files::scan::runLogLine(r), head + dev::files::scan::runLogLine(r) + "{\"tile\": 2, \"la"};
}

void checkLog(std::string_view input)
{
    const auto r = dev::files::scan::parseRunLog(input);
    if (!r.log) {
        if (r.problems.empty())
            fuzzfiles::fail("a refused run log without a problem");
        return;
    }
    std::string again = dev::files::scan::runLogHeader(r.log->planName, r.log->fingerprint, r.log->tiles);
    for (const auto& rec : r.log->records)
        again += dev::files::scan::runLogLine(rec);
    const auto back = dev::files::scan::parseRunLog(again);
    if (!back.log || back.log->records.size() != r.log->records.size() || back.log->tornTail)
        fuzzfiles::fail("an accepted run log does not write back");
}

} // namespace

BP_FUZZ_FILE_TARGET({"scan-plan", planSeeds, checkPlan});
BP_FUZZ_FILE_TARGET({"scan-run-log", logSeeds, checkLog});
