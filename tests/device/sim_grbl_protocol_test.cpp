// The simulator's GRBL personality, its conversation: banner, unlock, settings, $I, $G,
// homing, errors, outputs, driven with real command lines.
#include "device/backends/grbl/grbl_build_info.h"
#include "device/backends/grbl/grbl_settings.h"
#include "sim_grbl_support.h"

namespace {

using grbltest::Host;
using State = dev::sim::GrblFirmware::State;

TEST(SimGrblProtocol, PowerUpGreetsAndLocksUntilHomedOrUnlocked)
{
    Host h;
    ASSERT_GE(h.lines.size(), 3u);
    EXPECT_EQ(h.lines[0], "");  // GRBL starts its banner with a line end
    EXPECT_EQ(dev::grbl::classifyLine(h.lines[1]).kind, dev::grbl::LineKind::Banner);
    EXPECT_EQ(dev::grbl::parseBanner(h.lines[1])->firmware, dev::grbl::Firmware::Grbl);
    EXPECT_EQ(h.lines[2], "[MSG:'$H'|'$X' to unlock]");
    EXPECT_EQ(h.status().state, dev::grbl::MachineState::Alarm);
    EXPECT_EQ(h.command("G0 X1"), "error:9");  // G-code locked out in alarm
    EXPECT_EQ(h.command("$X"), "ok");
    EXPECT_TRUE(h.received("[MSG:Caution: Unlocked]"));
    EXPECT_EQ(h.status().state, dev::grbl::MachineState::Idle);
}

TEST(SimGrblProtocol, TheFirstReportAfterAResetCarriesTheOffsetAndTheSecondTheOverrides)
{
    Host h;
    const dev::grbl::StatusReport first = h.status();
    ASSERT_TRUE(first.workOffset);
    EXPECT_EQ(first.position.size(), 4u);  // the analyzer: X Y Z and the pump as A
    EXPECT_TRUE(first.positionIsMachine);
    const dev::grbl::StatusReport second = h.status();
    EXPECT_FALSE(second.workOffset);
    EXPECT_TRUE(second.overridesPercent);
}

TEST(SimGrblProtocol, SettingsReadBackAsTheMachinesLimits)
{
    Host h;
    EXPECT_EQ(h.command("$$"), "ok");
    dev::grbl::Settings s;
    for (const auto& l : h.lines)
        if (const auto sl = dev::grbl::parseSettingLine(l))
            s.add(*sl);
    const dev::grbl::LimitsRead r = dev::grbl::machineLimits(s, h.fw.axisLetters());
    ASSERT_TRUE(r.limits);
    const dev::sim::MachineConfig c = dev::sim::analyzerConfig();
    for (std::size_t i = 0; i < c.axes.size(); ++i) {
        EXPECT_NEAR(r.limits->axes[i].maxRateMmS, c.axes[i].maxSpeed, 1e-3) << i;
        EXPECT_NEAR(r.limits->axes[i].accelMmS2, c.axes[i].maxAccel, 1e-3) << i;
        EXPECT_NEAR(r.limits->axes[i].maxTravelMm, c.axes[i].travel, 1e-3) << i;
    }
    EXPECT_TRUE(r.limits->softLimits);
    EXPECT_TRUE(r.limits->hardLimits);
    EXPECT_TRUE(r.limits->homingEnabled);
}

TEST(SimGrblProtocol, SettingsChangesTakeEffect)
{
    Host h;
    EXPECT_EQ(h.command("$22=0"), "ok");
    EXPECT_EQ(h.command("$H"), "error:5");  // homing disabled
    EXPECT_EQ(h.command("$20=1"), "error:10");  // soft limits need homing
    EXPECT_EQ(h.command("$999=1"), "error:3");
    EXPECT_EQ(h.command("$110=abc"), "error:2");
    EXPECT_EQ(h.command("$X"), "ok");
    EXPECT_EQ(h.command("$10=2"), "ok");  // WPos and buffer fields
    const dev::grbl::StatusReport r = h.status();
    EXPECT_FALSE(r.positionIsMachine);
    ASSERT_TRUE(r.plannerBlocksFree);
    EXPECT_EQ(*r.plannerBlocksFree, 15);
    EXPECT_EQ(*r.rxBytesFree, 127);
    EXPECT_EQ(h.command("$13=1"), "ok");  // report inches
    EXPECT_EQ(h.command("G91 G1 X25.4 F1200"), "ok");
    h.run(2.0);
    const dev::grbl::StatusReport in = h.status();
    EXPECT_NEAR(in.position[0], 1.0, 1e-4);  // 25.4 mm reported as 1 inch
}

TEST(SimGrblProtocol, BuildInfoOfBothDialects)
{
    for (const auto d : {dev::sim::GrblFirmware::Dialect::Grbl, dev::sim::GrblFirmware::Dialect::GrblHal}) {
        Host h(dev::sim::stageConfig(), d);
        const bool hal = d == dev::sim::GrblFirmware::Dialect::GrblHal;
        EXPECT_EQ(dev::grbl::parseBanner(h.lines[1])->firmware, hal ? dev::grbl::Firmware::GrblHal : dev::grbl::Firmware::Grbl);
        h.fresh();
        EXPECT_EQ(h.command("$I"), "ok");
        dev::grbl::BuildInfo info;
        for (const auto& l : h.lines)
            dev::grbl::addBuildInfoLine(info, dev::grbl::classifyLine(l));
        EXPECT_EQ(info.plannerBlocks, hal ? 35 : 15);
        EXPECT_EQ(info.rxBufferBytes, hal ? 1024 : 128);
        EXPECT_TRUE(info.hasOption('Z'));
        if (hal) {
            EXPECT_EQ(info.firmware, dev::grbl::Firmware::GrblHal);
            EXPECT_EQ(info.axisLetters, "XYZ");  // the stage's XY and the Z every GRBL has
        }
    }
}

TEST(SimGrblProtocol, HomingAnswersWhenDoneAtMachineZero)
{
    Host h;
    EXPECT_EQ(h.command("$H"), "ok");
    const dev::grbl::StatusReport r = h.status();
    EXPECT_EQ(r.state, dev::grbl::MachineState::Idle);
    for (const double p : r.position)
        EXPECT_NEAR(p, 0, 1e-3);
    EXPECT_TRUE(h.fw.machine().homed(0));
}

TEST(SimGrblProtocol, GcodeErrorsHaveTheirDocumentedCodes)
{
    Host h;
    h.command("$X");
    EXPECT_EQ(h.command("G1 X10"), "error:22");  // no feed yet
    EXPECT_EQ(h.command("G5 X1"), "error:20");
    EXPECT_EQ(h.command("G0 G1 X1"), "error:21");
    EXPECT_EQ(h.command("G1 X1 X2 F10"), "error:25");
    EXPECT_EQ(h.command("G4"), "error:28");
    EXPECT_EQ(h.command("G2 X1 Y1 F100"), "error:35");
    EXPECT_EQ(h.command("G2 X10 Y0 I1 J0 F100"), "error:33");  // end far off the circle
    EXPECT_EQ(h.command("G0 X1 Q2"), "error:20");
    EXPECT_EQ(h.command("G0 X1 I2"), "error:36");
    EXPECT_EQ(h.command("X"), "error:2");
    EXPECT_EQ(h.command("1"), "error:1");
    EXPECT_EQ(h.command("M62 P0"), "error:20");  // stock GRBL has no digital outputs
    EXPECT_EQ(h.command("$Q"), "error:3");
    EXPECT_EQ(h.command("$J=G91 X1"), "error:22");  // a jog needs its own F
    EXPECT_EQ(h.command("$J=G91 M8 X1 F10"), "error:16");
    EXPECT_EQ(h.command(std::string(90, '0')), "error:11");
    EXPECT_EQ(h.command(""), "ok");
}

TEST(SimGrblProtocol, CrLfLineEndsCostAnExtraOk)
{
    Host h;
    h.fresh();
    h.write("$G\r\n");
    h.run(0.01);
    int oks = 0;
    for (const auto& l : h.fresh())
        oks += l == "ok";
    EXPECT_EQ(oks, 2);  // why the streamer ends lines with '\n' alone
}

TEST(SimGrblProtocol, CoolantSwitchesWhenTheMotionBeforeItIsDone)
{
    Host h;
    h.home();
    const double t0 = h.now();
    h.write("G1 X20 F1200\nM8\n");
    h.run(0.05);
    EXPECT_TRUE(h.fw.outputEvents().empty());  // M8 waits for the move (about 1 s)
    EXPECT_TRUE(h.runUntil([&] { return !h.fw.outputEvents().empty(); }, 3));
    EXPECT_GT(h.fw.outputEvents()[0].timeS - t0, 0.99);
    EXPECT_NEAR(h.fw.machinePositionMm()[0], 20, 1e-6);
    EXPECT_EQ(h.command("$G"), "ok");
    bool m8 = false;
    for (const auto& l : h.lines)
        m8 = m8 || (l.rfind("[GC:", 0) == 0 && l.find("M8") != std::string::npos);
    EXPECT_TRUE(m8);
    EXPECT_EQ(h.command("M9"), "ok");
    EXPECT_FALSE(h.fw.outputEvents().back().on);
}

TEST(SimGrblProtocol, GrblHalDigitalOutputsAtOnceOrWithTheMotion)
{
    Host h(dev::sim::stageConfig(), dev::sim::GrblFirmware::Dialect::GrblHal);
    h.home();
    EXPECT_EQ(h.command("M64 P1"), "ok");
    ASSERT_EQ(h.fw.outputEvents().size(), 1u);
    EXPECT_EQ(h.fw.outputEvents()[0].port, 1);
    EXPECT_TRUE(h.fw.outputEvents()[0].on);
    h.write("G1 X5 F600\n");  // 0.5 s
    h.write("M62 P2 G1 X10\n");  // switches as the second move begins
    h.run(0.2);
    EXPECT_EQ(h.fw.outputEvents().size(), 1u);
    ASSERT_TRUE(h.runUntil([&] { return h.fw.outputEvents().size() == 2; }, 2));
    EXPECT_EQ(h.fw.outputEvents()[1].port, 2);
    EXPECT_NEAR(h.fw.machinePositionMm()[0], 5, 0.05);  // at the junction, where the second move starts
}

TEST(SimGrblProtocol, DwellAnswersAfterTheWait)
{
    Host h;
    h.home();
    h.fresh();
    h.write("G1 X10 F1200\nG4 P0.5\n");
    const double t0 = h.now();
    std::size_t oks = 0;
    h.runUntil(
        [&] {
            for (const auto& l : h.fresh())
                oks += l == "ok";
            return oks == 2;
        },
        5);
    EXPECT_EQ(oks, 2u);
    EXPECT_GT(h.now() - t0, 0.5 + 0.5);  // the move (0.5 s at 20 mm/s) then the dwell
}

TEST(SimGrblProtocol, InchesWorkConsistently)
{
    Host h;
    h.home();
    EXPECT_EQ(h.command("G20 G91 G1 X1 F10"), "ok");  // 1 inch at 10 in/min = 254 mm/min
    h.run(7);
    EXPECT_NEAR(h.fw.machinePositionMm()[0], 25.4, 1e-6);
    EXPECT_EQ(h.command("G21"), "ok");
}

} // namespace
