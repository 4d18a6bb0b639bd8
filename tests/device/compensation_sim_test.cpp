// The simulator's axis error compensation (docs/protocol.md, "Compensation"): an
// uploaded curve puts the stage's work point on its targets once enabled and homed,
// enabling never moves the axis, a table with backlash serves the open-loop analyzer
// from both sides, a bad or out-of-order upload is refused without changing what the
// axis had, and only a saved compensation survives a power cycle.
#include "device/protocol/messages_compensation.h"
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace simtest;
using dev::proto::CompKind;

constexpr int kX = 0, kY = 1;

dev::proto::CompUploadRequest polynomial(int axis, std::vector<double> coefficientsUm, double backlashUm = 0)
{
    dev::proto::CompUploadRequest r;
    r.axis = static_cast<std::uint8_t>(axis);
    r.kind = CompKind::Polynomial;
    r.backlash = static_cast<std::int32_t>(std::lround(backlashUm * 1e3));
    r.total = static_cast<std::uint16_t>(coefficientsUm.size());
    r.validFrom = 0;
    r.validTo = nm(100);
    r.coefficients = std::move(coefficientsUm);
    return r;
}

dev::proto::CompEnableRequest enableAxis(int axis, bool on, bool save = false)
{
    return {bit(axis), static_cast<std::uint8_t>((on ? dev::proto::CompEnableOn : 0) | (save ? dev::proto::CompEnableSave : 0))};
}

using StageHomed = HomedMachine<dev::sim::stageConfig>;
using AnalyzerHomed = HomedMachine<dev::sim::analyzerConfig>;

double gaugeErrorUm(dev::sim::SimMachine& m, Runner& r, int axis, double target)
{
    EXPECT_FALSE(m.move(absMove(bit(axis), {target})));
    EXPECT_TRUE(r.runUntilIdle(30));
    r.run(0.05);
    return (m.workPointLogical(axis) - target) * 1e3;
}

TEST_F(StageHomed, SeedTwosCurveUploadedAndEnabledPutsTheWorkPointOnTheTarget)
{
    const double before = gaugeErrorUm(m, r, kY, 60);
    EXPECT_GT(before, 60) << "seed 002's Y curve at 60 mm";
    dev::proto::CompUploadReply reply;
    ASSERT_FALSE(m.compensation().upload(polynomial(kY, {1.021, 0.6397, 0.0168}), reply));
    EXPECT_EQ(reply.installed, 1);
    EXPECT_FALSE(m.compensation().enabled(kY)) << "installed disabled";
    EXPECT_NEAR(gaugeErrorUm(m, r, kY, 60), before, 1.0) << "not applied until enabled";
    ASSERT_FALSE(m.compensation().enable(enableAxis(kY, true)));
    r.run(0.01);
    EXPECT_TRUE(m.compensation().applied(kY));
    for (double target : {20.0, 60.0, 95.0}) {
        EXPECT_LT(std::fabs(gaugeErrorUm(m, r, kY, target)), 1.5) << "at " << target;
        EXPECT_NEAR(measuredMm(m, kY), target, 0.0006) << "the readback is reported at the nominal target";
    }
    EXPECT_NE(r.find(dev::proto::kEvCompChanged, kY), nullptr);
}

TEST_F(StageHomed, EnablingAndDisablingNeverMoveTheAxis)
{
    ASSERT_FALSE(m.move(absMove(bit(kX), {70})));
    ASSERT_TRUE(r.runUntilIdle(30));
    dev::proto::CompUploadReply reply;
    ASSERT_FALSE(m.compensation().upload(polynomial(kX, {1.563, 0.9473, -0.0006}), reply));
    const double carriage = m.axis(kX).carriage();
    ASSERT_FALSE(m.compensation().enable(enableAxis(kX, true)));
    r.run(0.2);
    EXPECT_NEAR(m.axis(kX).carriage(), carriage, 0.0006) << "within a grating count";
    // The correction at 70 mm is −64.9 µm (seed 002's X curve solved for the command).
    EXPECT_NEAR(commandedMm(m, kX), 70 + 0.0649, 0.002) << "the readout shifts by the correction instead";
    ASSERT_FALSE(m.compensation().enable(enableAxis(kX, false)));
    r.run(0.2);
    EXPECT_NEAR(m.axis(kX).carriage(), carriage, 0.0006);
    EXPECT_NEAR(commandedMm(m, kX), 70, 1e-6);
}

TEST_F(AnalyzerHomed, APolynomialWithBacklashLandsTheOpenLoopAxisFromBothSides)
{
    // X: 150 µm/m of lead error and 20 µm of play.
    auto side = [&](double target, double from) {
        EXPECT_FALSE(m.move(absMove(bit(kX), {from})));
        EXPECT_TRUE(r.runUntilIdle(30));
        return gaugeErrorUm(m, r, kX, target);
    };
    // Measured as an accuracy test would, at two targets from both sides.
    const double up20 = side(20, 10), down20 = side(20, 30), up150 = side(150, 140), down150 = side(150, 160);
    EXPECT_GT(std::fabs(up150 - down150), 15) << "the play shows as reversal";
    EXPECT_GT(std::fabs(up150 + down150) / 2, 15) << "the lead error shows at 150 mm";
    // The mean error as a line through both targets, the backlash b = −B̄ = x̄↓ − x̄↑.
    const double e20 = (up20 + down20) / 2, e150 = (up150 + down150) / 2;
    const double slope = (e150 - e20) / 130;
    const double backlash = ((down20 - up20) + (down150 - up150)) / 2;
    auto req = polynomial(kX, {e20 - slope * 20, slope}, backlash);
    req.validTo = nm(200);
    dev::proto::CompUploadReply reply;
    ASSERT_FALSE(m.compensation().upload(req, reply));
    ASSERT_FALSE(m.compensation().enable(enableAxis(kX, true)));
    const double up = side(150, 140), down = side(150, 160);
    EXPECT_LT(std::fabs(up), 4) << "within an encoder count and the play's own scatter";
    EXPECT_LT(std::fabs(down), 4);
}

TEST_F(StageHomed, APartOutOfOrderOrAModelADeviceCannotApplyIsRefusedAndChangesNothing)
{
    dev::proto::CompUploadReply reply;
    ASSERT_FALSE(m.compensation().upload(polynomial(kX, {1.563, 0.9473, -0.0006}), reply));
    ASSERT_FALSE(m.compensation().enable(enableAxis(kX, true)));
    // A table of five points sent in parts, the second starting at the wrong entry.
    dev::proto::CompUploadRequest part;
    part.axis = kX;
    part.kind = CompKind::Table;
    part.total = 5;
    part.points = {{0, 0, 0}, {nm(10), -1000, -1000}, {nm(20), -2000, -2000}};
    ASSERT_FALSE(m.compensation().upload(part, reply));
    EXPECT_EQ(reply.received, 3);
    EXPECT_EQ(reply.installed, 0);
    part.first = 2;
    auto e = m.compensation().upload(part, reply);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::kErrCompSequence);
    EXPECT_EQ(e->value, 3) << "the entry the device expects";
    // Too steep: 200 µm/mm is not a positioning error.
    e = m.compensation().upload(polynomial(kX, {0, 200}), reply);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::kErrCompInvalid);
    // 300 points is more than a device keeps.
    part.first = 0;
    part.total = 300;
    e = m.compensation().upload(part, reply);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::kErrCompInvalid);
    // The polynomial uploaded first is still there, enabled.
    ASSERT_TRUE(m.compensation().model(kX));
    EXPECT_EQ(m.compensation().model(kX)->kind, motion::metrology::CompensationModel::Kind::Polynomial);
    EXPECT_TRUE(m.compensation().enabled(kX));
}

TEST_F(StageHomed, NothingChangesUnderAMovingAxisAndNothingIsEnabledThatIsNotThere)
{
    auto e = m.compensation().enable(enableAxis(kY, true));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::kErrCompMissing);
    ASSERT_FALSE(m.move(absMove(bit(kX), {90})));
    r.run(0.05);
    dev::proto::CompUploadReply reply;
    e = m.compensation().upload(polynomial(kX, {1, 1}), reply);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::Busy);
}

TEST(CompensationSim, OnlyASavedCompensationSurvivesAPowerCycle)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    dev::proto::CompUploadReply reply;
    ASSERT_FALSE(m.compensation().upload(polynomial(kX, {1.563, 0.9473, -0.0006}), reply));
    ASSERT_FALSE(m.compensation().upload(polynomial(kY, {1.021, 0.6397, 0.0168}), reply));
    ASSERT_FALSE(m.compensation().enable(enableAxis(kX, true, true)));
    ASSERT_FALSE(m.compensation().enable(enableAxis(kY, true)));
    EXPECT_FALSE(m.compensation().applied(kX)) << "positions are home coordinates: nothing applies before homing";

    dev::sim::SimMachine after(dev::sim::stageConfig(), m.compensation().flash());
    ASSERT_TRUE(after.compensation().model(kX));
    EXPECT_TRUE(after.compensation().enabled(kX));
    EXPECT_FALSE(after.compensation().model(kY)) << "Y was never saved";
    dev::proto::CompGetReply got;
    ASSERT_FALSE(after.compensation().get({kX, 0, 80}, got));
    EXPECT_EQ(got.kind, CompKind::Polynomial);
    EXPECT_EQ(got.coefficients, (std::vector<double>{1.563, 0.9473, -0.0006}));
    EXPECT_EQ(got.flags & dev::proto::CompSaved, dev::proto::CompSaved);
    EXPECT_EQ(got.flags & dev::proto::CompApplied, 0);
}

TEST(CompensationSim, ATableIsReadBackInFramesOfEightyPoints)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    std::vector<dev::proto::CompPoint> points;
    for (int k = 0; k < 200; ++k)
        points.push_back({nm(0.5 * k), -10 * k, -10 * k - 4});
    dev::proto::CompUploadReply reply;
    for (std::size_t first = 0; first < points.size(); first += 80) {
        dev::proto::CompUploadRequest part;
        part.axis = kY;
        part.kind = CompKind::TablePerDirection;
        part.total = 200;
        part.first = static_cast<std::uint16_t>(first);
        part.points.assign(points.begin() + static_cast<long>(first), points.begin() + static_cast<long>(std::min<std::size_t>(first + 80, 200)));
        ASSERT_FALSE(m.compensation().upload(part, reply)) << first;
    }
    EXPECT_EQ(reply.installed, 1);
    std::vector<dev::proto::CompPoint> back;
    for (std::uint16_t first = 0; first < 200;) {
        dev::proto::CompGetReply got;
        ASSERT_FALSE(m.compensation().get({kY, first, 80}, got));
        EXPECT_EQ(got.kind, CompKind::TablePerDirection);
        EXPECT_EQ(got.total, 200);
        ASSERT_FALSE(got.points.empty());
        back.insert(back.end(), got.points.begin(), got.points.end());
        first = static_cast<std::uint16_t>(first + got.points.size());
    }
    EXPECT_EQ(back, points);
}

} // namespace
