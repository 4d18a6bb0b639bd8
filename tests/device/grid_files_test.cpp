// The grid map's files (docs/accuracy.md): the stage-error file the simulator
// reads, the grid map's result file and the 2D compensation table with its CSV.
// Every reader reports every problem at once, at the file's line and column; the
// examples under resources/examples/ read cleanly, and the derived ones are what the
// writers make (BP_REGENERATE_EXAMPLES=1 writes them again).
#include "device/files/accuracy/grid/compensation_2d_file.h"
#include "device/files/accuracy/grid/grid_map_result_file.h"
#include "device/files/accuracy/grid/stage_errors_file.h"
#include "motion/metrology/grid/stage_errors.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace dev::files::accuracy;
using namespace motion::metrology;

namespace {

std::string examplePath(const std::string& name) { return std::string(BP_SOURCE_DIR) + "/resources/examples/" + name; }

std::string readExample(const std::string& name)
{
    std::ifstream f(examplePath(name), std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// The map of the stage-error example on a 7 × 7 grid (20–80 mm), as a camera would
/// read it, with the plate 12 µm and 150 µrad off.
GridMapResultFile exampleMap()
{
    const auto e = stageErrorsFromJson(readExample("stage-example.stage-errors.json"), "stage-example.stage-errors.json");
    GridMapInput in;
    for (int k = 0; k < 7; ++k) {
        in.xMm.push_back(20 + 10.0 * k);
        in.yMm.push_back(20 + 10.0 * k);
    }
    for (double y : in.yMm)
        for (double x : in.xMm) {
            const auto v = stageErrorUm(*e, x, y, Direction::Up, Direction::Up);
            in.exUm.push_back(v.xUm + 12 - 150e-3 * y);
            in.eyUm.push_back(v.yUm + 150e-3 * x);
            // The reverse pass, approached from above.
            const auto w = stageErrorUm(*e, x, y, Direction::Down, Direction::Down);
            in.reverseExUm.push_back(w.xUm + 12 - 150e-3 * y);
            in.reverseEyUm.push_back(w.yUm + 150e-3 * x);
        }
    return {*analyseGridMap(in), "stage-example.stage-errors.json, 7 x 7 nodes over 20-80 mm both ways, the plate 12 µm and 150 µrad off"};
}

std::map<std::string, std::string> derived()
{
    const auto map = exampleMap();
    const auto table = *compensationFromMap(map.result);
    return {{"stage-example.grid-map-result.json", gridMapResultToJson(map)},
            {"stage-example.compensation-2d.json", compensation2DToJson({table, "stage-example.grid-map-result.json"})},
            {"stage-example.compensation-2d.csv", compensation2DToCsv(table)}};
}

} // namespace

TEST(GridFiles, TheStageErrorExampleIsTheFileOfTheDocs)
{
    const auto r = stageErrorsFromJson(readExample("stage-example.stage-errors.json"), "stage-example.stage-errors.json");
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r->x.pitchPolyUm, (std::vector<double>{0, 0.5, -0.004}));
    EXPECT_EQ(r->y.straightnessPolyUm, (std::vector<double>{0, 0, -0.003}));
    EXPECT_EQ(r->squarenessUrad, 40);
    EXPECT_EQ(r->backlashYUm, 2.0);
    // Written and read again: the same errors.
    const auto again = stageErrorsFromJson(stageErrorsToJson(*r), "again.json");
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->x.straightnessPolyUm, r->x.straightnessPolyUm);
}

TEST(GridFiles, AStageErrorFileLeavingMembersOutKeepsTheBuiltInStage)
{
    const auto r = stageErrorsFromJson(R"({"schema": "benchpilot.stage-errors", "version": 1, "squareness_urad": -25})", "s.json");
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r->x.pitchPolyUm, builtInStageErrors().x.pitchPolyUm);
    EXPECT_EQ(r->squarenessUrad, -25);
}

TEST(GridFiles, AStageErrorFileWithEveryProblemAtOnceNamesLineAndColumn)
{
    const std::string text = "{\"schema\": \"benchpilot.stage-errors\", \"version\": 1,\n"
                             " \"x\": {\"pitch_poly_um\": [0, \"a\"], \"straightnes_poly_um\": []},\n"
                             " \"y\": {\"pitch_poly_um\": [0, 0, 0, 0, 0, 0, 1]},\n"
                             " \"squareness_urad\": 1e9,\n"
                             " \"backlash_um\": {\"x\": -1}}";
    const auto r = stageErrorsFromJson(text, "bad.stage-errors.json");
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.problems().size(), 5u) << motion::msg::debugFormat(r.problems());
    for (const auto& p : r.problems())
        EXPECT_EQ(p.file, "bad.stage-errors.json");
    EXPECT_EQ(r.problems()[0].path, "x.pitch_poly_um[1]");
    EXPECT_EQ(r.problems()[0].line, 2);
    EXPECT_EQ(r.problems()[0].column, 29);
    EXPECT_EQ(r.problems()[1].path, "x.straightnes_poly_um");  // unknown, with the nearest name suggested
    EXPECT_EQ(r.problems()[2].path, "y.pitch_poly_um");
    EXPECT_EQ(r.problems()[2].message.id, "stage_errors.too_many_coefficients");
    EXPECT_EQ(r.problems()[2].line, 3);
    EXPECT_EQ(r.problems()[3].path, "squareness_urad");
    EXPECT_EQ(r.problems()[3].line, 4);
    EXPECT_EQ(r.problems()[4].path, "backlash_um.x");
    EXPECT_EQ(r.problems()[4].line, 5);
}

TEST(GridFiles, DerivedExamplesAreWhatTheWritersMake)
{
    for (const auto& [name, text] : derived()) {
        if (std::getenv("BP_REGENERATE_EXAMPLES")) {
            std::ofstream(examplePath(name), std::ios::binary) << text;
            continue;
        }
        EXPECT_EQ(readExample(name), text) << name << " differs from what the writers make";
    }
}

TEST(GridFiles, TheExampleResultAndTableReadBackAsWritten)
{
    const auto map = gridMapResultFromJson(readExample("stage-example.grid-map-result.json"), "stage-example.grid-map-result.json");
    ASSERT_TRUE(map.ok()) << motion::msg::debugFormat(map.problems());
    EXPECT_EQ(map->result.nodes.size(), 49u);
    ASSERT_TRUE(map->result.figures.maxReversalUm);
    EXPECT_NEAR(*map->result.figures.maxReversalUm, 2.5, 1e-9);  // √(1.5² + 2²)
    // Read both ways: the mean reversal is −b per axis, and each node keeps both directions.
    ASSERT_TRUE(map->result.figures.meanReversalXUm && map->result.figures.meanReversalYUm);
    EXPECT_NEAR(*map->result.figures.meanReversalXUm, -1.5, 1e-9);
    EXPECT_NEAR(*map->result.figures.meanReversalYUm, -2.0, 1e-9);
    const auto& n = map->result.nodes.front();
    ASSERT_TRUE(n.forwardExUm && n.reverseExUm);
    EXPECT_NEAR(n.exUm, 0.5 * (*n.forwardExUm + *n.reverseExUm), 1e-9) << "the map is the mean of both directions";
    // Written again, the same file.
    EXPECT_EQ(gridMapResultToJson(*map), readExample("stage-example.grid-map-result.json"));
    const auto table = compensation2DFromJson(readExample("stage-example.compensation-2d.json"), "stage-example.compensation-2d.json");
    ASSERT_TRUE(table.ok()) << motion::msg::debugFormat(table.problems());
    EXPECT_EQ(table->table.columns, 7);
    EXPECT_NEAR(table->table.pitchXMm, 10, 1e-12);
    // The table the example map gives is the example table.
    const auto fitted = compensationFromMap(map->result);
    ASSERT_TRUE(fitted);
    for (std::size_t k = 0; k < fitted->correctionXUm.size(); ++k)
        EXPECT_NEAR(fitted->correctionXUm[k], table->table.correctionXUm[k], 1e-6);
}

TEST(GridFiles, AResultWhoseNodesLeaveTheGridIsRefusedAtTheNode)
{
    std::string text = gridMapResultToJson(exampleMap());
    const std::string node = "\"x_mm\": 40,";
    const auto at = text.find(node, text.find("\"nodes\""));
    ASSERT_NE(at, std::string::npos);
    text.replace(at, node.size(), "\"x_mm\": 41,");
    const auto r = gridMapResultFromJson(text, "moved.json");
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.problems().size(), 1u) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r.problems()[0].message.id, "grid.node_off_grid");
    EXPECT_EQ(r.problems()[0].path, "nodes[2]");
    EXPECT_GT(r.problems()[0].line, 1);
}

TEST(GridFiles, ATableFileWithEveryProblemAtOnce)
{
    const std::string text = "{\"schema\": \"benchpilot.compensation-2d\", \"version\": 1,\n"
                             " \"grid\": {\"origin_x_mm\": 0, \"origin_y_mm\": 0, \"pitch_x_mm\": 0.01, \"pitch_y_mm\": 5, \"columns\": 2, \"rows\": 2},\n"
                             " \"nodes\": [{\"x_mm\": 0, \"y_mm\": 0, \"correction_x_um\": 1, \"correction_y_um\": 2},\n"
                             "  {\"x_mm\": 0.01, \"y_mm\": 0, \"correction_x_um\": 1e6, \"correction_y_um\": 2},\n"
                             "  {\"x_mm\": 0, \"y_mm\": 5, \"correction_x_um\": 1, \"correction_y_um\": 2},\n"
                             "  {\"x_mm\": 0.01, \"y_mm\": 5, \"correction_x_um\": 1, \"correction_y_um\": 2}]}";
    const auto r = compensation2DFromJson(text, "t.compensation-2d.json");
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.problems().size(), 2u) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r.problems()[0].path, "grid.pitch_x_mm");
    EXPECT_EQ(r.problems()[0].line, 2);
    EXPECT_EQ(r.problems()[1].path, "nodes[1].correction_x_um");
    EXPECT_EQ(r.problems()[1].line, 4);
}
