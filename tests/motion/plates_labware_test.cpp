// The built-in SBS plates: the positions the standard and the makers publish.
#include "motion/message_print.h"
#include "motion/plans/plates/labware.h"

#include <gtest/gtest.h>

using namespace motion::plates;

TEST(PlateLabware, The96WellPlateFollowsAnsiSlas4)
{
    const Labware lw = *findBuiltinLabware("sbs-96");
    EXPECT_EQ(lw.rows, 8);
    EXPECT_EQ(lw.columns, 12);
    EXPECT_EQ(lw.wells.size(), 96u);
    EXPECT_DOUBLE_EQ(lw.lengthMm, 127.76);
    EXPECT_DOUBLE_EQ(lw.widthMm, 85.48);
    const Well* a1 = lw.wellNamed("A1");
    ASSERT_TRUE(a1);
    EXPECT_DOUBLE_EQ(a1->xMm, 14.38);  // from the left edge
    EXPECT_DOUBLE_EQ(a1->yMm, 11.24);  // from the top (back) edge
    const Well* h12 = lw.wellNamed("H12");
    EXPECT_NEAR(h12->xMm, 14.38 + 11 * 9, 1e-9);
    EXPECT_NEAR(h12->yMm, 11.24 + 7 * 9, 1e-9);
    EXPECT_NEAR(lw.wellNamed("A2")->xMm - a1->xMm, 9.0, 1e-12);
    EXPECT_EQ(lw.describe(), "96-well plate");
}

TEST(PlateLabware, The384WellPlateFollowsAnsiSlas4)
{
    const Labware lw = *findBuiltinLabware("sbs-384");
    EXPECT_EQ(lw.wells.size(), 384u);
    EXPECT_DOUBLE_EQ(lw.wellNamed("A1")->xMm, 12.13);
    EXPECT_DOUBLE_EQ(lw.wellNamed("A1")->yMm, 8.99);
    EXPECT_NEAR(lw.wellNamed("P24")->xMm, 12.13 + 23 * 4.5, 1e-9);
    EXPECT_NEAR(lw.wellNamed("P24")->yMm, 8.99 + 15 * 4.5, 1e-9);
    EXPECT_NEAR(lw.wellNamed("B1")->yMm - lw.wellNamed("A1")->yMm, 4.5, 1e-12);
    // The standard centres the grid on the footprint.
    EXPECT_NEAR((lw.wells.front().xMm + lw.wells.back().xMm) / 2, kSbsLengthMm / 2, 1e-9);
    EXPECT_NEAR((lw.wells.front().yMm + lw.wells.back().yMm) / 2, kSbsWidthMm / 2, 1e-9);
}

TEST(PlateLabware, EveryBuiltInIsValidAndHoldsNoMoreThanItsWells)
{
    const std::vector<std::pair<const char*, int>> expected = {{"sbs-6", 6}, {"sbs-12", 12}, {"sbs-24", 24},
                                                               {"sbs-48", 48}, {"sbs-96", 96}, {"sbs-384", 384}};
    const auto all = builtinLabware();
    ASSERT_EQ(all.size(), expected.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Labware& lw = all[i];
        EXPECT_EQ(lw.id, expected[i].first);
        EXPECT_EQ(static_cast<int>(lw.wells.size()), expected[i].second);
        EXPECT_TRUE(validateLabware(lw).empty()) << lw.id << ": " << motion::msg::debugString(validateLabware(lw).front().message);
        const Well& first = lw.wells.front();
        // A well holds at most its cylinder.
        const double cylinderUl = 3.14159265 * first.diameterMm * first.diameterMm / 4 * first.depthMm;
        EXPECT_LE(first.volumeUl, cylinderUl * 1.01) << lw.id;
    }
}

TEST(PlateLabware, ValidationNamesTheWellAtFault)
{
    Labware lw = *findBuiltinLabware("sbs-24");
    lw.wells[5].xMm = 130;  // past the 127.76 mm edge
    lw.wells[7].volumeUl = 0;
    lw.wells[9].id = lw.wells[8].id;
    const motion::msg::Problems p = validateLabware(lw);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0].path, "wells[5]");
    EXPECT_NE(motion::msg::debugString(p[0].message).find("length=127.76 mm, width=85.48 mm"), std::string::npos) << motion::msg::debugString(p[0].message);
    EXPECT_EQ(p[0].message.id, "plate.labware.well_off_footprint");
    EXPECT_EQ(p[1].path, "wells[7]");
    EXPECT_EQ(p[2].path, "wells[9]");
    EXPECT_EQ(p[2].message.id, "plate.labware.well_twice");
}
