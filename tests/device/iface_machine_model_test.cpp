// What plans assume about the machine comes from what the device reported
// (device/jobs/machine_model.h): a stage that reports other limits is modelled with
// them, one that reports none (protocol 1.0) as the reference stage, a planner without
// a jerk limit as a trapezoid; the deck takes the analyzer's reported motion.
#include "device/files/plates/deck_file.h"
#include "device/jobs/machine_model.h"
#include "motion/plans/recipes/move_time.h"
#include "motion/plans/scan/scan_estimate.h"

#include <gtest/gtest.h>

namespace {

dev::DeviceIdentity stage(double accel, double jerk, dev::proto::MotionProfile profile)
{
    dev::DeviceIdentity id;
    id.kind = dev::proto::DeviceKind::Stage;
    id.motionProfile = profile;
    for (char c : {'X', 'Y'}) {
        dev::AxisDescriptor a;
        a.letter = QLatin1Char(c);
        a.travelMax = 100;
        a.maxSpeed = 25;
        a.maxAccel = accel;
        a.maxJerk = jerk;
        id.axes.push_back(a);
    }
    return id;
}

} // namespace

TEST(IfaceMachineModel, TheStageModelIsTheOneTheDeviceReported)
{
    const auto m = dev::jobs::stageModelOf(stage(50, 700, dev::proto::MotionProfile::JerkLimited), {});
    EXPECT_DOUBLE_EQ(m.maxSpeedMmS[0], 25);
    EXPECT_DOUBLE_EQ(m.maxAccelMmS2[1], 50);
    EXPECT_DOUBLE_EQ(m.maxJerkMmS3[0], 700);
    // …and a move takes longer on it than on the reference stage.
    const motion::scan::StageModel reference;
    EXPECT_GT(motion::scan::moveTimeS({0, 0}, {2, 0}, 10, m), 1.5 * motion::scan::moveTimeS({0, 0}, {2, 0}, 10, reference));
}

TEST(IfaceMachineModel, ADeviceThatReportedNothingIsTheReferenceStage)
{
    const auto m = dev::jobs::stageModelOf(stage(0, 0, dev::proto::MotionProfile::Unstated), {{10, 90}, {5, 95}});
    const motion::scan::StageModel reference;
    EXPECT_DOUBLE_EQ(m.maxAccelMmS2[0], reference.maxAccelMmS2[0]);
    EXPECT_DOUBLE_EQ(m.maxJerkMmS3[1], reference.maxJerkMmS3[1]);
    EXPECT_DOUBLE_EQ(m.maxSpeedMmS[0], 25);  // protocol 1.0 did carry the top speed
    // The soft limits narrow the travel.
    EXPECT_DOUBLE_EQ(m.travel.x0Mm, 10);
    EXPECT_DOUBLE_EQ(m.travel.y1Mm, 95);
}

TEST(IfaceMachineModel, APlannerWithoutAJerkLimitIsTimedAsATrapezoid)
{
    const auto m = dev::jobs::stageModelOf(stage(200, 0, dev::proto::MotionProfile::Trapezoid), {});
    EXPECT_DOUBLE_EQ(m.maxJerkMmS3[0], dev::jobs::kUnlimitedJerkMmS3);
    // 10 mm at 20 mm/s and 200 mm/s²: 0.1 s up, 0.4 s cruise, 0.1 s down.
    EXPECT_NEAR(motion::scan::moveTimeS({0, 0}, {10, 0}, 20, m), 0.6, 1e-3);
}

TEST(IfaceMachineModel, TheDeckTakesTheAnalyzersReportedMotion)
{
    const motion::plates::Deck file = dev::files::plates::builtinDeck();
    dev::DeviceIdentity id;
    id.motionProfile = dev::proto::MotionProfile::SeedSCurve;
    for (char c : {'X', 'Y', 'Z', 'P'}) {
        dev::AxisDescriptor a;
        a.letter = QLatin1Char(c);
        a.maxSpeed = 80;
        a.maxAccel = 400;
        a.defaultSpeed = 30;
        a.minAccelTimeS = 0.2;
        id.axes.push_back(a);
    }
    const motion::plates::Deck d = dev::jobs::deckWithDeviceMotion(file, id);
    EXPECT_DOUBLE_EQ(d.x.maxSpeed, 80);
    EXPECT_DOUBLE_EQ(d.y.maxAccel, 400);
    EXPECT_DOUBLE_EQ(d.z.defaultSpeed, 30);
    EXPECT_DOUBLE_EQ(d.p.accelTimeS, 0.2);
    EXPECT_EQ(d.plateSlots.size(), file.plateSlots.size());  // the rest is the file's
    EXPECT_GT(motion::plates::moveTimeS({{&d.x, 50}}, 0), motion::plates::moveTimeS({{&file.x, 50}}, 0));

    // Not connected (no axes): the file as it is.
    const motion::plates::Deck same = dev::jobs::deckWithDeviceMotion(file, {});
    EXPECT_DOUBLE_EQ(same.x.maxAccel, file.x.maxAccel);
    // Reported axes but no planner limits (protocol 1.0): only the top speed is the device's.
    id.motionProfile = dev::proto::MotionProfile::Unstated;
    const motion::plates::Deck old = dev::jobs::deckWithDeviceMotion(file, id);
    EXPECT_DOUBLE_EQ(old.x.maxSpeed, 80);
    EXPECT_DOUBLE_EQ(old.x.maxAccel, file.x.maxAccel);
    EXPECT_DOUBLE_EQ(old.x.accelTimeS, file.x.accelTimeS);
}
