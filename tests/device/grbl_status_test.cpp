// GRBL status reports: every field, any order, sub-states, WPos with a remembered WCO,
// inches, unknown fields; and the refusals of broken ones.
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_status.h"

#include <gtest/gtest.h>

namespace {

using namespace dev::grbl;

StatusReport parsed(std::string_view line)
{
    const Line l = classifyLine(line);
    EXPECT_EQ(l.kind, LineKind::Status) << line;
    StatusParse p = parseStatusReport(l.payload);
    EXPECT_TRUE(p.report) << line << " " << motion::msg::debugString(p.problem);
    return p.report ? *p.report : StatusReport{};
}

TEST(GrblStatus, AStockGrblIdleReport)
{
    const StatusReport r = parsed("<Idle|MPos:0.000,0.000,0.000|FS:0,0|WCO:0.000,0.000,0.000>");
    EXPECT_EQ(r.state, MachineState::Idle);
    EXPECT_EQ(r.subState, -1);
    EXPECT_TRUE(r.positionIsMachine);
    EXPECT_EQ(r.position, (std::vector<double>{0, 0, 0}));
    ASSERT_TRUE(r.workOffset);
    EXPECT_EQ(r.feedPerMin, 0.0);
    EXPECT_EQ(r.spindleRpm, 0.0);
    EXPECT_FALSE(r.overridesPercent);
}

TEST(GrblStatus, AReportWithEveryFieldInAnOrderTheDocumentDoesNotUse)
{
    const StatusReport r = parsed(
        "<Hold:1|WPos:-2.500,0.000,11.000|A:SFM|Ov:120,50,100|Pn:XZP|FS:1500.5,8000|Ln:99999|Bf:15,128|WCO:0.000,1.551,5.664>");
    EXPECT_EQ(r.state, MachineState::Hold);
    EXPECT_EQ(r.subState, 1);
    EXPECT_FALSE(r.positionIsMachine);
    EXPECT_EQ(r.position, (std::vector<double>{-2.5, 0, 11}));
    EXPECT_EQ(r.plannerBlocksFree, 15);
    EXPECT_EQ(r.rxBytesFree, 128);
    EXPECT_EQ(r.lineNumber, 99999);
    EXPECT_EQ(r.feedPerMin, 1500.5);
    EXPECT_EQ(r.spindleRpm, 8000.0);
    EXPECT_TRUE(r.pinTriggered('X'));
    EXPECT_TRUE(r.pinTriggered('P'));
    EXPECT_FALSE(r.pinTriggered('Y'));
    ASSERT_TRUE(r.overridesPercent);
    EXPECT_EQ((*r.overridesPercent)[0], 120);
    EXPECT_EQ((*r.overridesPercent)[1], 50);
    EXPECT_EQ(r.accessories, std::string("SFM"));
    ASSERT_TRUE(r.workOffset);
    EXPECT_EQ((*r.workOffset)[2], 5.664);
}

TEST(GrblStatus, SubStatesOfEveryState)
{
    EXPECT_EQ(parsed("<Door:1|MPos:0,0,0|FS:0,0>").subState, 1);
    EXPECT_EQ(parsed("<Door:3|MPos:0,0,0|FS:0,0>").state, MachineState::Door);
    EXPECT_EQ(parsed("<Hold:0|MPos:0,0,0|FS:0,0>").subState, 0);
    EXPECT_EQ(parsed("<Jog|MPos:0,0,0|FS:600,0>").state, MachineState::Jog);
    EXPECT_EQ(parsed("<Home|MPos:0,0,0|FS:0,0>").state, MachineState::Home);
    EXPECT_EQ(parsed("<Check|MPos:0,0,0|FS:0,0>").state, MachineState::Check);
    EXPECT_EQ(parsed("<Sleep|MPos:0,0,0|FS:0,0>").state, MachineState::Sleep);
    // grblHAL: Run:1 (hold pending), Alarm:N with its code, Tool.
    EXPECT_EQ(parsed("<Run:1|MPos:0,0,0|FS:0,0>").subState, 1);
    const StatusReport a = parsed("<Alarm:3|MPos:0,0,0|FS:0,0>");
    EXPECT_EQ(a.state, MachineState::Alarm);
    EXPECT_EQ(a.subState, 3);
    EXPECT_EQ(parsed("<Tool|MPos:0,0,0|FS:0,0>").state, MachineState::Tool);
}

TEST(GrblStatus, GrblHalFieldsAreKeptAsUnknownAndIgnored)
{
    const StatusReport r = parsed("<Idle|MPos:10.000,20.000,-1.000|Bf:35,1023|FS:0,0,0|Pn:PXY|WCO:0.000,0.000,0.000|"
                                  "WCS:G54|Ov:100,100,100|A:|H:1,7|FW:grblHAL>");
    EXPECT_EQ(r.plannerBlocksFree, 35);
    EXPECT_EQ(r.rxBytesFree, 1023);
    EXPECT_EQ(r.accessories, std::string());
    ASSERT_EQ(r.unknownFields.size(), 3u);
    EXPECT_EQ(r.unknownFields[0].first, "WCS");
    EXPECT_EQ(r.unknownFields[1].first, "H");
    EXPECT_EQ(r.unknownFields[1].second, "1,7");
    EXPECT_EQ(r.unknownFields[2].second, "grblHAL");
}

TEST(GrblStatus, ThreeToSixAxes)
{
    EXPECT_EQ(parsed("<Idle|MPos:1,2,3,4|F:0>").position.size(), 4u);
    EXPECT_EQ(parsed("<Idle|MPos:1,2,3,4,5,6|F:0>").position.size(), 6u);
    EXPECT_FALSE(parseStatusReport("Idle|MPos:1,2|F:0").report);
    EXPECT_FALSE(parseStatusReport("Idle|MPos:1,2,3,4,5,6,7|F:0").report);
}

TEST(GrblStatus, BrokenReportsAreRefusedWithAReason)
{
    for (const char* bad : {"", "Idle", "Idle|FS:0,0", "Walking|MPos:0,0,0", "Idle|MPos:0,0,x", "Idle|MPos:0,0,0|MPos:0,0,0",
                            "Hold:x|MPos:0,0,0", "Idle|MPos:0,0,0|Bf:15", "Idle|MPos:0,0,0|Ov:100,100", "Idle|MPos:0,0,0|Pn:1",
                            "Idle|MPos:0,0,0|WCO:1,2", "Idle|MPos:1e5,0,0", "Idle|MPos:nan,0,0"}) {
        const StatusParse p = parseStatusReport(bad);
        EXPECT_FALSE(p.report) << bad;
        EXPECT_EQ(p.problem.id, "grbl.status.malformed") << bad;
        EXPECT_FALSE(p.problem.text("reason").empty()) << bad;
    }
}

// Found by libFuzzer (tests/fuzz/corpus/grbl_lines/regress-override-beyond-int, replayed by
// fuzz_files): an override of 1.4e21 % was cast to int — undefined behaviour, a crash
// under UBSan. Overrides past 1000 % (GRBL's reach 200) are a damaged report.
TEST(GrblStatus, OverridesBeyondAnyControllersRangeAreRefused)
{
    for (const char* bad : {"Hold:1|WPos:-2.500,0.000,11.000|Ov:1444444444444444444420,50,100", "Idle|MPos:0,0,0|Ov:100,-5,100",
                            "Idle|MPos:0,0,0|Ov:100,100,1001", "Idle|MPos:0,0,0|Ov:nan,100,100"}) {
        const StatusParse p = parseStatusReport(bad);
        EXPECT_FALSE(p.report) << bad;
        EXPECT_EQ(p.problem.id, "grbl.status.malformed") << bad;
    }
    const StatusReport r = parsed("<Idle|MPos:0,0,0|Ov:200,25,10>");
    ASSERT_TRUE(r.overridesPercent);
    EXPECT_EQ(*r.overridesPercent, (std::array<int, 3>{200, 25, 10}));
}

TEST(GrblStatus, WorkPositionComesFromARememberedOffset)
{
    StatusTracker t;
    // First report after a reset carries WCO; later ones do not.
    EXPECT_TRUE(t.update(parsed("<Idle|MPos:10.000,20.000,-5.000|FS:0,0|WCO:1.000,2.000,-3.000>")));
    EXPECT_EQ(t.workMm(), (std::vector<double>{9, 18, -2}));
    EXPECT_TRUE(t.update(parsed("<Run|MPos:11.000,20.000,-5.000|FS:600,0>")));
    EXPECT_EQ(t.machineMm()[0], 11.0);
    EXPECT_EQ(t.workMm()[0], 10.0);  // WPos = MPos − WCO, with the WCO of two reports ago
    EXPECT_EQ(t.feedMmMin(), 600.0);
    // $10=0: WPos is sent; MPos = WPos + WCO.
    EXPECT_TRUE(t.update(parsed("<Idle|WPos:0.000,0.000,0.000|FS:0,0>")));
    EXPECT_EQ(t.machineMm(), (std::vector<double>{1, 2, -3}));
}

TEST(GrblStatus, WithoutAnOffsetTheOtherVectorIsUnknownNotGuessed)
{
    StatusTracker t;
    EXPECT_TRUE(t.update(parsed("<Idle|WPos:5.000,0.000,0.000|FS:0,0>")));
    EXPECT_FALSE(t.haveWorkOffset());
    EXPECT_EQ(t.workMm()[0], 5.0);
    EXPECT_TRUE(t.machineMm().empty());
}

TEST(GrblStatus, InchReportsBecomeMillimetres)
{
    StatusTracker t;
    t.setReportInches(true);  // $13=1
    EXPECT_TRUE(t.update(parsed("<Jog|MPos:1.0000,-0.5000,0.0000|FS:10,0|WCO:0.1000,0.0000,0.0000>")));
    EXPECT_NEAR(t.machineMm()[0], 25.4, 1e-9);
    EXPECT_NEAR(t.machineMm()[1], -12.7, 1e-9);
    EXPECT_NEAR(t.workMm()[0], 22.86, 1e-9);
    EXPECT_NEAR(*t.feedMmMin(), 254.0, 1e-9);
}

TEST(GrblStatus, OverridesAndAccessoriesTravelTogether)
{
    StatusTracker t;
    t.update(parsed("<Idle|MPos:0,0,0|FS:0,0|WCO:0,0,0>"));
    t.update(parsed("<Idle|MPos:0,0,0|FS:0,0|Ov:100,100,100|A:F>"));
    EXPECT_EQ(t.accessories(), "F");  // flood coolant on (M8)
    t.update(parsed("<Idle|MPos:0,0,0|FS:0,0>"));
    EXPECT_EQ(t.accessories(), "F");  // no Ov this time: nothing new about the accessories
    t.update(parsed("<Idle|MPos:0,0,0|FS:0,0|Ov:100,100,100>"));
    EXPECT_EQ(t.accessories(), "");   // Ov without A: everything off (M9)
}

TEST(GrblStatus, AResetForgetsTheOffsetAndADifferentAxisCountIsNotMixed)
{
    StatusTracker t;
    t.update(parsed("<Idle|MPos:1,2,3|FS:0,0|WCO:1,1,1>"));
    t.reset();
    EXPECT_FALSE(t.haveWorkOffset());
    t.update(parsed("<Idle|MPos:1,2,3|FS:0,0|WCO:1,1,1>"));
    EXPECT_TRUE(t.update(parsed("<Idle|MPos:1,2,3,4|FS:0,0>")));  // another board: 4 axes
    EXPECT_FALSE(t.haveWorkOffset());
    EXPECT_FALSE(t.update(parsed("<Idle|MPos:1,2,3,4|FS:0,0|WCO:1,1,1>")));
}

} // namespace
