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

dev::DeviceIdentity stage(double accel, double jerk, proto::MotionProfile profile)
{
    dev::DeviceIdentity id;
    id.kind = proto::DeviceKind::Stage;
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
    const auto m = jobs::stageModelOf(stage(50, 700, proto::MotionProfile::JerkLimited), {});
    EXPECT_DOUBLE_EQ(m.maxSpeedMmS[0], 25);
    EXPECT_DOUBLE_EQ(m.maxAccelMmS2[1], 50);
    EXPECT_DOUBLE_EQ(m.maxJerkMmS3[0], 700);
    // …and a move takes longer on it than on the reference stage.
    const motion::scan::StageModel reference;
    EXPECT_GT(motion::scan::moveTimeS({0, 0}, {2, 0}, 10, m), 1.5 * motion::scan::moveTimeS({0, 0}, {2, 0}, 10, reference));
}

TEST(IfaceMachineModel, ADeviceThatReportedNothingIsTheReferenceStage)
{
    const auto m = jobs::stageModelOf(stage(0, 0, proto::MotionProfile::Unstated), {{10, 90}, {5, 95}});
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
    const auto m = jobs::stageModelOf(stage(200, 0, proto::MotionProfile::Trapezoid), {});
    EXPECT_DOUBLE_EQ(m.maxJerkMmS3[0], jobs::kUnlimitedJerkMmS3);
    // 10 mm at 20 mm/s and 200 mm/s²: 0.1 s up, 0.4 s cruise, 0.1 s down.
    EXPECT_NEAR(motion::scan::moveTimeS({0, 0}, {10, 0}, 20, m), 0.6, 1e-3);
}

TEST(IfaceMachineModel, TheDeckTakesTheAnalyzersReportedMotion)
{
    const plates::Deck file = platefiles::builtinDeck();
    dev::DeviceIdentity id;
    id.motionProfile = proto::MotionProfile::SeedSCurve;
    for (char c : {'X', 'Y', 'Z', 'P'}) {
        dev::AxisDescriptor a;
        a.letter = QLatin1Char(c);
        a.maxSpeed = 80;
        a.maxAccel = 400;
        a.defaultSpeed = 30;
        a.minAccelTimeS = 0.2;
        id.axes.push_back(a);
    }
    const plates::Deck d = jobs::deckWithDeviceMotion(file, id);
    EXPECT_DOUBLE_EQ(d.x.maxSpeed, 80);
    EXPECT_DOUBLE_EQ(d.y.maxAccel, 400);
    EXPECT_DOUBLE_EQ(d.z.defaultSpeed, 30);
    EXPECT_DOUBLE_EQ(d.p.accelTimeS, 0.2);
    EXPECT_EQ(d.plateSlots.size(), file.plateSlots.size());  // the rest is the file's
    EXPECT_GT(plates::moveTimeS({{&d.x, 50}}, 0), plates::moveTimeS({{&file.x, 50}}, 0));

    // Not connected (no axes): the file as it is.
    const plates::Deck same = jobs::deckWithDeviceMotion(file, {});
    EXPECT_DOUBLE_EQ(same.x.maxAccel, file.x.maxAccel);
    // Reported axes but no planner limits (protocol 1.0): only the top speed is the device's.
    id.motionProfile = proto::MotionProfile::Unstated;
    const plates::Deck old = jobs::deckWithDeviceMotion(file, id);
    EXPECT_DOUBLE_EQ(old.x.maxSpeed, 80);
    EXPECT_DOUBLE_EQ(old.x.maxAccel, file.x.maxAccel);
    EXPECT_DOUBLE_EQ(old.x.accelTimeS, file.x.accelTimeS);
}
