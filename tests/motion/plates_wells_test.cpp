// Well names and well sets as people write them in recipes.
#include "motion/plans/plates/labware.h"
#include "motion/plans/plates/wells.h"

#include <gtest/gtest.h>

#include <random>

using namespace motion::plates;

namespace {
Labware plate96() { return *findBuiltinLabware("sbs-96"); }
std::vector<std::string> names(const WellSet& s)
{
    std::vector<std::string> out;
    for (const auto& w : s.wells)
        out.push_back(wellName(w));
    return out;
}
} // namespace

TEST(PlateWells, NamesReadAndWriteBothWays)
{
    EXPECT_EQ(wellName({0, 0}), "A1");
    EXPECT_EQ(wellName({7, 11}), "H12");
    EXPECT_EQ(wellName({15, 23}), "P24");
    EXPECT_EQ(wellName({26, 0}), "AA1");
    EXPECT_EQ(wellName({31, 47}), "AF48");
    for (int r = 0; r < kMaxRows; ++r)
        for (int c = 0; c < kMaxColumns; ++c) {
            const auto back = parseWellName(wellName({r, c}));
            ASSERT_TRUE(back) << wellName({r, c});
            EXPECT_EQ(*back, (WellId{r, c}));
        }
    EXPECT_EQ(*parseWellName("a1"), (WellId{0, 0}));
    EXPECT_EQ(*parseWellName("B03"), (WellId{1, 2}));
    for (const char* bad : {"", "A", "1", "A0", "A49", "AG1", "A1B", "ABC1", "A-1", " A1", "🙂"})
        EXPECT_FALSE(parseWellName(bad)) << bad;
}

TEST(PlateWells, RangesRowsColumnsAllAndLists)
{
    const Labware lw = plate96();
    EXPECT_EQ(names(expandWells({"A1:H1"}, lw, "w")), (std::vector<std::string>{"A1", "B1", "C1", "D1", "E1", "F1", "G1", "H1"}));
    EXPECT_EQ(names(expandWells({"row B"}, lw, "w")).size(), 12u);
    EXPECT_EQ(names(expandWells({"row B"}, lw, "w")).front(), "B1");
    EXPECT_EQ(names(expandWells({"column 3"}, lw, "w")), (std::vector<std::string>{"A3", "B3", "C3", "D3", "E3", "F3", "G3", "H3"}));
    EXPECT_EQ(expandWells({"all"}, lw, "w").wells.size(), 96u);
    // A range runs row by row from its first corner, in the direction written.
    EXPECT_EQ(names(expandWells({"B2:A1"}, lw, "w")), (std::vector<std::string>{"B2", "B1", "A2", "A1"}));
    EXPECT_EQ(names(expandWells({"A1, C3", "D4:D5"}, lw, "w")), (std::vector<std::string>{"A1", "C3", "D4", "D5"}));
    const WellSet all = expandWells({"A1:H12"}, lw, "w");
    EXPECT_TRUE(all.problems.empty());
    EXPECT_EQ(all.wells.size(), 96u);
}

TEST(PlateWells, UnknownWellIsNamedWithThePlate)
{
    const WellSet s = expandWells({"I13"}, plate96(), "steps[4].wells");
    ASSERT_EQ(s.problems.size(), 1u);
    EXPECT_EQ(s.problems[0].path, "steps[4].wells");
    EXPECT_EQ(motion::msg::debugString(s.problems[0].message), "plate.unknown_well{well=\"\"I13\"\", wells=96}");
    // In a list, the spec's own index.
    const WellSet l = expandWells({"A1", "A1:I1"}, plate96(), "steps[0].wells");
    ASSERT_EQ(l.problems.size(), 1u);
    EXPECT_EQ(l.problems[0].path, "steps[0].wells[1]");
    EXPECT_EQ(motion::msg::debugString(l.problems[0].message), "plate.unknown_well{well=\"\"I1\"\", wells=96}");
    EXPECT_EQ(motion::msg::debugString(expandWells({"row J"}, plate96(), "w").problems.at(0).message),
              "plate.wells.unknown_row{row=\"\"J\"\", wells=96, last=\"H\"}");
    EXPECT_EQ(motion::msg::debugString(expandWells({"column 13"}, plate96(), "w").problems.at(0).message),
              "plate.wells.unknown_column{column=\"\"13\"\", wells=96, last=12}");
    EXPECT_NE(expandWells({"wells A to H"}, plate96(), "w").problems.at(0).message.id.find("plate.wells.not_a_well_set"), std::string::npos);
    // I13 is a well on a 384-well plate.
    EXPECT_TRUE(expandWells({"I13"}, *findBuiltinLabware("sbs-384"), "w").problems.empty());
}

TEST(PlateWells, AWellNamedTwiceIsAnError)
{
    const WellSet s = expandWells({"A1:A12", "A5"}, plate96(), "w");
    ASSERT_EQ(s.problems.size(), 1u);
    EXPECT_EQ(s.problems[0].path, "w[1]");
    EXPECT_EQ(motion::msg::debugString(s.problems[0].message), "plate.wells.named_twice{well=\"A5\"}");
    EXPECT_EQ(s.wells.size(), 12u);
}

TEST(PlateWells, DescribeGivesBackTheSameWells)
{
    const Labware lw = plate96();
    EXPECT_EQ(describeWells(expandWells({"B2:D5"}, lw, "w").wells), (std::vector<std::string>{"B2:D5"}));
    EXPECT_EQ(describeWells({{0, 0}}), (std::vector<std::string>{"A1"}));
    std::mt19937 rng(8);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<WellId> pick;
        for (const auto& w : lw.wells)
            if (rng() % 3 == 0)
                pick.push_back(w.id);
        const auto specs = describeWells(pick);
        const WellSet back = expandWells(specs.empty() ? std::vector<std::string>{"A1"} : specs, lw, "w");
        if (pick.empty())
            continue;
        ASSERT_TRUE(back.problems.empty());
        std::vector<WellId> sorted = back.wells;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(sorted, pick) << "trial " << trial;
    }
}
