// Fuzz targets "stage-errors", "grid-map-result", "grid-map-test" and "compensation-2d": the readers of
// the simulated stage's error file, a grid map's result and the 2D compensation table.
// Invariants: no crash; a refusal says where and what; an accepted file writes out,
// reads back and writes out the same; an accepted map's table, if it makes one,
// is one a device takes or is refused with a reason.
#include "fuzz_files.h"

#include "device/files/accuracy/grid/compensation_2d_file.h"
#include "device/files/accuracy/grid/grid_map_result_file.h"
#include "device/files/accuracy/grid/grid_map_test_file.h"
#include "device/files/accuracy/grid/stage_errors_file.h"

namespace {

void checkProblemsSayWhere(const motion::msg::Problems& problems, bool accepted)
{
    for (const motion::msg::Problem& p : problems)
        if (p.file != "fuzz.json" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(problems));
    if (!accepted && problems.empty())
        fuzzfiles::fail("refused without a problem");
}

void checkStageErrors(std::string_view input)
{
    using namespace dev::files::accuracy;
    const StageErrorsRead r = stageErrorsFromJson(input, "fuzz.json");
    checkProblemsSayWhere(r.problems(), r.ok());
    if (!r.ok())
        return;
    const std::string once = stageErrorsToJson(*r);
    const StageErrorsRead again = stageErrorsFromJson(once, "again.json");
    if (!again.ok())
        fuzzfiles::fail("written stage errors do not read back: " + motion::msg::debugFormat(again.problems()));
    if (stageErrorsToJson(*again) != once)
        fuzzfiles::fail("write → read → write changed the stage errors");
}

void checkGridMapResult(std::string_view input)
{
    using namespace dev::files::accuracy;
    const GridMapResultRead r = gridMapResultFromJson(input, "fuzz.json");
    checkProblemsSayWhere(r.problems(), r.ok());
    if (!r.ok())
        return;
    const std::string once = gridMapResultToJson(*r);
    const GridMapResultRead again = gridMapResultFromJson(once, "again.json");
    if (!again.ok())
        fuzzfiles::fail("a written map does not read back: " + motion::msg::debugFormat(again.problems()));
    if (gridMapResultToJson(*again) != once)
        fuzzfiles::fail("write → read → write changed the map");
    (void)motion::metrology::compensationFromMap(r->result);
}

void checkCompensation2D(std::string_view input)
{
    using namespace dev::files::accuracy;
    const Compensation2DRead r = compensation2DFromJson(input, "fuzz.json");
    checkProblemsSayWhere(r.problems(), r.ok());
    if (!r.ok())
        return;
    const std::string once = compensation2DToJson(*r);
    const Compensation2DRead again = compensation2DFromJson(once, "again.json");
    if (!again.ok())
        fuzzfiles::fail("a written table does not read back: " + motion::msg::debugFormat(again.problems()));
    if (compensation2DToJson(*again) != once)
        fuzzfiles::fail("write → read → write changed the table");
    (void)compensation2DToCsv(r->table);
}

void checkGridMapTest(std::string_view input)
{
    using namespace dev::files::accuracy;
    const GridMapTestRead r = gridMapTestFromJson(input, "fuzz.json");
    checkProblemsSayWhere(r.problems(), r.ok());
    if (!r.ok())
        return;
    const std::string once = gridMapTestToJson(*r);
    const GridMapTestRead again = gridMapTestFromJson(once, "again.json");
    if (!again.ok())
        fuzzfiles::fail("a written grid map test does not read back: " + motion::msg::debugFormat(again.problems()));
    if (gridMapTestToJson(*again) != once)
        fuzzfiles::fail("write → read → write changed the grid map test");
    // The plan reads every node once per pass, and the reverse pass from the other side.
    const auto plan = motion::metrology::planGridMap(*r, 0, 0);
    const std::size_t nodes = static_cast<std::size_t>(r->columns) * static_cast<std::size_t>(r->rows);
    if (plan.size() != nodes * (r->bidirectional ? 2 : 1))
        fuzzfiles::fail("the plan does not read every node once per pass");
    std::vector<int> seen(2 * nodes, 0);
    for (const auto& s : plan) {
        const int node = s.node(r->columns);
        if (node < 0 || static_cast<std::size_t>(node) >= nodes || s.approachSide() != (s.reverse ? 1.0 : -1.0))
            fuzzfiles::fail("a stop of the plan is off the grid or approached from the wrong side");
        if (++seen[static_cast<std::size_t>(node) + (s.reverse ? nodes : 0)] != 1)
            fuzzfiles::fail("the plan reads a node twice in one pass");
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"stage-errors", [] { return fuzzfiles::exampleFiles(".stage-errors.json"); }, checkStageErrors});
BP_FUZZ_FILE_TARGET({"grid-map-result", [] { return fuzzfiles::exampleFiles(".grid-map-result.json"); }, checkGridMapResult});
BP_FUZZ_FILE_TARGET({"compensation-2d", [] { return fuzzfiles::exampleFiles(".compensation-2d.json"); }, checkCompensation2D});
BP_FUZZ_FILE_TARGET({"grid-map-test", [] { return fuzzfiles::exampleFiles(".grid-map-test.json"); }, checkGridMapTest});
