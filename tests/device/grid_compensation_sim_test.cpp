// The simulated stage's error model (benchpilot-sim --stage-errors) and its 2D
// compensation table (docs/protocol.md, "2D compensation"): the built-in errors are
// the ones the stage always had, a file's straightness and squareness move the
// work point where the model says, and a table fitted from a map of the stage's
// true positions, uploaded and enabled, cuts the same map's error more than
// five-fold. Enabling never moves the axes; a reconnect keeps the table, a power
// cycle only when it was saved.
#include "device/protocol/messages_compensation_2d.h"
#include "device/sim/sim_compensation_2d.h"
#include "motion/metrology/grid/compensation_table_2d.h"
#include "motion/metrology/grid/grid_map.h"
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace simtest;
using motion::metrology::StageErrors;

constexpr std::uint8_t kXy = 0x03;

/// The stage-error file's example (docs/accuracy.md).
StageErrors exampleErrors()
{
    StageErrors e;
    e.x.pitchPolyUm = {0, 0.5, -0.004};
    e.x.straightnessPolyUm = {0, 0, 0.002};
    e.y.pitchPolyUm = {0, 0.3};
    e.y.straightnessPolyUm = {0, 0, -0.003};
    e.squarenessUrad = 40;
    e.backlashXUm = 1.5;
    e.backlashYUm = 2.0;
    return e;
}

dev::sim::MachineConfig stageWithExampleErrors()
{
    auto c = dev::sim::stageConfig();
    dev::sim::applyStageErrors(c, exampleErrors());
    return c;
}

using ExampleStage = HomedMachine<stageWithExampleErrors>;
using BuiltInStage = HomedMachine<dev::sim::stageConfig>;

void moveXy(dev::sim::SimMachine& m, Runner& r, double x, double y)
{
    ASSERT_FALSE(m.move(absMove(kXy, {x, y})));
    ASSERT_TRUE(r.runUntilIdle(30));
    r.run(0.05);
}

const std::vector<double> kNodesMm = {20, 30, 40, 50, 60, 70, 80};

/// The map a camera on a grid plate would give: the work point's true place at every
/// node, the stage sent there through its (compensated or not) targets.
motion::metrology::GridMapInput mapByMoving(dev::sim::SimMachine& m, Runner& r)
{
    motion::metrology::GridMapInput in;
    in.xMm = kNodesMm;
    in.yMm = kNodesMm;
    for (double y : kNodesMm)
        for (double x : kNodesMm) {
            moveXy(m, r, x, y);
            const auto w = m.trueWorkPoint();
            in.exUm.push_back((w.xMm - x) * 1e3);
            in.eyUm.push_back((w.yMm - y) * 1e3);
        }
    return in;
}

void upload(dev::sim::SimMachine& m, const motion::metrology::CompensationTable2D& t)
{
    dev::proto::Comp2dUploadRequest h;
    h.columns = static_cast<std::uint8_t>(t.columns);
    h.rows = static_cast<std::uint8_t>(t.rows);
    h.originX = nm(t.originXMm);
    h.originY = nm(t.originYMm);
    h.pitchX = nm(t.pitchXMm);
    h.pitchY = nm(t.pitchYMm);
    const std::size_t n = t.correctionXUm.size();
    for (std::size_t first = 0; first < n; first += dev::proto::kMaxComp2dNodesPerFrame) {
        dev::proto::Comp2dUploadRequest part = h;
        part.first = static_cast<std::uint16_t>(first);
        for (std::size_t k = first; k < std::min(n, first + dev::proto::kMaxComp2dNodesPerFrame); ++k)
            part.nodes.push_back({static_cast<std::int32_t>(std::lround(t.correctionXUm[k] * 1e3)),
                                  static_cast<std::int32_t>(std::lround(t.correctionYUm[k] * 1e3))});
        // Through the codec, as the device receives it.
        const auto decoded = dev::proto::decodeComp2dUploadRequest(dev::proto::encode(part));
        ASSERT_TRUE(decoded);
        dev::proto::Comp2dUploadReply reply;
        ASSERT_FALSE(m.compensation2d().upload(*decoded, reply));
        EXPECT_EQ(reply.installed, first + dev::proto::kMaxComp2dNodesPerFrame >= n ? 1 : 0);
    }
}

dev::proto::Comp2dEnableReply enable2d(dev::sim::SimMachine& m, std::uint8_t flags)
{
    dev::proto::Comp2dEnableReply out;
    EXPECT_FALSE(m.compensation2d().enable({flags}, out));
    return out;
}

TEST_F(BuiltInStage, KeepsTheErrorsItAlwaysHadAsTheStageErrorDefaults)
{
    ASSERT_TRUE(m.config().stageErrors);
    const auto builtIn = motion::metrology::builtInStageErrors();
    EXPECT_EQ(m.config().axes[0].abbeErrorPolyUm, builtIn.x.pitchPolyUm);
    EXPECT_EQ(m.config().axes[1].abbeErrorPolyUm, builtIn.y.pitchPolyUm);
    moveXy(m, r, 70, 30);
    // Each axis' work point is its carriage plus its own Abbe curve alone, as before.
    EXPECT_NEAR(m.trueWorkPoint().xMm, m.axis(0).workPoint() - (m.axis(0).measured() - measuredMm(m, 0)), 1e-9);
    EXPECT_NEAR(m.trueWorkPoint().yMm, m.axis(1).workPoint() - (m.axis(1).measured() - measuredMm(m, 1)), 1e-9);
}

TEST_F(ExampleStage, PutsTheWorkPointWhereTheFilesFormulaSays)
{
    moveXy(m, r, 40, 10);
    const auto low = m.trueWorkPoint();
    moveXy(m, r, 40, 60);
    const auto high = m.trueWorkPoint();
    // X stands still while Y travels 50 mm up: X's work point leans by the squareness
    // (40 µrad · 50 mm = 2 µm) and Y's straightness (−0.003 · (60² − 10²) = −10.5 µm).
    EXPECT_NEAR((high.xMm - low.xMm) * 1e3, 2.0 - 10.5, 0.6);
    // The function of a grating reading says the same where the stage stands.
    const auto at = m.trueWorkPointAt(m.axis(0).measured() - m.logicalOffset(0), m.axis(1).measured() - m.logicalOffset(1));
    EXPECT_NEAR(at.xMm, high.xMm, 0.5e-3);
    EXPECT_NEAR(at.yMm, high.yMm, 0.5e-3);
    // Half the backlash against the approach: the same place reached from above.
    moveXy(m, r, 50, 70);
    moveXy(m, r, 40, 60);
    const auto fromAbove = m.trueWorkPoint();
    EXPECT_NEAR((fromAbove.xMm - high.xMm) * 1e3, 1.5, 0.6);
    EXPECT_NEAR((fromAbove.yMm - high.yMm) * 1e3, 2.0, 0.6);
}

TEST_F(ExampleStage, ATableFittedFromItsMapCutsTheSameMapsErrorFiveFold)
{
    const auto before = motion::metrology::analyseGridMap(mapByMoving(m, r));
    ASSERT_TRUE(before);
    const auto table = motion::metrology::compensationFromMap(*before);
    ASSERT_TRUE(table);
    upload(m, *table);
    EXPECT_FALSE(m.compensation2d().enabled()) << "installed disabled";
    const auto held = m.trueWorkPoint();
    const auto on = enable2d(m, dev::proto::Comp2dEnableOn);
    EXPECT_EQ(on.state & (dev::proto::Comp2dInstalled | dev::proto::Comp2dEnabled | dev::proto::Comp2dApplied),
              dev::proto::Comp2dInstalled | dev::proto::Comp2dEnabled | dev::proto::Comp2dApplied);
    EXPECT_EQ(on.columns, 7);
    r.run(0.2);
    EXPECT_NEAR(m.trueWorkPoint().xMm, held.xMm, 1e-6) << "enabling never moves the axes";
    EXPECT_NEAR(m.trueWorkPoint().yMm, held.yMm, 1e-6);
    const auto after = motion::metrology::analyseGridMap(mapByMoving(m, r));
    ASSERT_TRUE(after);
    RecordProperty("rms_before_um", std::to_string(before->figures.rmsErrorUm));
    RecordProperty("rms_after_um", std::to_string(after->figures.rmsErrorUm));
    EXPECT_GT(before->figures.rmsErrorUm, 5.0);
    EXPECT_LT(after->figures.rmsErrorUm * 5, before->figures.rmsErrorUm)
        << "before " << before->figures.rmsErrorUm << " µm, after " << after->figures.rmsErrorUm << " µm";
    // Disabled, the map is what it was.
    enable2d(m, 0);
    const auto off = motion::metrology::analyseGridMap(mapByMoving(m, r));
    ASSERT_TRUE(off);
    EXPECT_NEAR(off->figures.rmsErrorUm, before->figures.rmsErrorUm, 0.5);
}

TEST_F(ExampleStage, RefusesAPartOutOfOrderAndAnEnableWithoutATable)
{
    dev::proto::Comp2dEnableReply out;
    const auto missing = m.compensation2d().enable({dev::proto::Comp2dEnableOn}, out);
    ASSERT_TRUE(missing);
    EXPECT_EQ(missing->code, dev::proto::kErrCompMissing);
    dev::proto::Comp2dUploadRequest part;
    part.columns = 19;
    part.rows = 19;
    part.pitchX = part.pitchY = nm(5);
    part.first = 0;
    part.nodes.assign(96, {});
    dev::proto::Comp2dUploadReply reply;
    ASSERT_FALSE(m.compensation2d().upload(part, reply));
    EXPECT_EQ(reply.received, 96);
    part.first = 100;
    const auto seq = m.compensation2d().upload(part, reply);
    ASSERT_TRUE(seq);
    EXPECT_EQ(seq->code, dev::proto::kErrCompSequence);
    EXPECT_EQ(seq->value, 96);
    // A complete table the device cannot apply (a pitch of 10 nm) is refused whole.
    dev::proto::Comp2dUploadRequest bad;
    bad.columns = 2;
    bad.rows = 2;
    bad.pitchX = 10;
    bad.pitchY = nm(1);
    bad.nodes.assign(4, {});
    const auto invalid = m.compensation2d().upload(bad, reply);
    ASSERT_TRUE(invalid);
    EXPECT_EQ(invalid->code, dev::proto::kErrCompInvalid);
    EXPECT_FALSE(m.compensation2d().table());
}

TEST_F(ExampleStage, OnlyASavedTableSurvivesAPowerCycle)
{
    motion::metrology::CompensationTable2D t;
    t.columns = t.rows = 2;
    t.pitchXMm = t.pitchYMm = 100;
    t.correctionXUm = {1, 2, 3, 4};
    t.correctionYUm = {0, 0, 0, 0};
    upload(m, t);
    enable2d(m, dev::proto::Comp2dEnableOn);
    dev::sim::SimMachine unsaved(stageWithExampleErrors(), m.compensation().flash());
    EXPECT_FALSE(unsaved.compensation2d().table());
    const auto kept = enable2d(m, dev::proto::Comp2dEnableOn | dev::proto::Comp2dEnableSave);
    EXPECT_TRUE(kept.state & dev::proto::Comp2dSaved);
    dev::sim::SimMachine saved(stageWithExampleErrors(), m.compensation().flash());
    ASSERT_TRUE(saved.compensation2d().table());
    EXPECT_TRUE(saved.compensation2d().enabled());
    EXPECT_EQ(saved.compensation2d().table()->correctionXUm, t.correctionXUm);
}

TEST(Comp2dCodec, RoundTripsAndRefusesWhatDoesNotFit)
{
    dev::proto::Comp2dUploadRequest r;
    r.columns = 3;
    r.rows = 2;
    r.originX = -5;
    r.originY = 7;
    r.pitchX = nm(5);
    r.pitchY = nm(2.5);
    r.first = 4;
    r.nodes = {{1, -2}, {300000, -400000}};
    const auto bytes = dev::proto::encode(r);
    EXPECT_EQ(bytes.size(), 21u + 16u);
    const auto back = dev::proto::decodeComp2dUploadRequest(bytes);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->nodes, r.nodes);
    EXPECT_EQ(back->pitchY, r.pitchY);
    auto shortBytes = bytes;
    shortBytes.pop_back();
    EXPECT_FALSE(dev::proto::decodeComp2dUploadRequest(shortBytes));
    auto longBytes = bytes;
    longBytes.push_back(0);
    EXPECT_FALSE(dev::proto::decodeComp2dUploadRequest(longBytes));
    EXPECT_FALSE(dev::proto::decodeComp2dEnableRequest({0x08}));
    EXPECT_FALSE(dev::proto::decodeComp2dEnableRequest({}));
    EXPECT_TRUE(dev::proto::decodeComp2dEnableRequest({0x07}));
    EXPECT_FALSE(dev::proto::decodeComp2dEnableReply({0x10, 0, 0}));
    EXPECT_FALSE(dev::proto::decodeComp2dUploadReply({1, 0, 2}));
    EXPECT_STREQ(dev::proto::compensation2dTypeName(0x1E), "COMP2D_UPLOAD");
    EXPECT_EQ(dev::proto::compensation2dTypeName(0x1D), nullptr);
}

} // namespace
