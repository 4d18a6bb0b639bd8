// The scan planner's stage model is the simulated stage's own numbers, so estimates
// and exports match the firmware.
#include "device/sim/machine_config.h"
#include "motion/plans/scan/scan_plan.h"

#include <gtest/gtest.h>

TEST(ScanStageModel, MatchesTheSimulatedStage)
{
    const dev::sim::MachineConfig stage = dev::sim::stageConfig();
    const motion::scan::StageModel model;
    ASSERT_EQ(stage.axes.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const auto& a = stage.axes[static_cast<std::size_t>(i)];
        EXPECT_EQ(model.maxSpeedMmS[i], a.maxSpeed);
        EXPECT_EQ(model.maxAccelMmS2[i], a.maxAccel);
        EXPECT_EQ(model.maxJerkMmS3[i], a.maxJerk);
    }
    EXPECT_EQ(model.travel.widthMm(), stage.axes[0].travel);
    EXPECT_EQ(model.travel.heightMm(), stage.axes[1].travel);
    // The simulated stage's work point follows seed 002's curves; the plan carries none of
    // its own (the device's compensation corrects the work point).
    EXPECT_EQ(stage.axes[0].abbeErrorPolyUm, (std::vector<double>{1.563, 0.9473, -0.0006}));
    EXPECT_EQ(stage.axes[1].abbeErrorPolyUm, (std::vector<double>{1.021, 0.6397, 0.0168}));
}
