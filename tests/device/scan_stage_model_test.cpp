// The scan planner's stage model and compensation defaults are the simulated
// stage's (seed 002's) own numbers, so estimates and exports match the firmware.
#include "device/sim/machine_config.h"
#include "motion/plans/scan/scan_plan.h"

#include <gtest/gtest.h>

TEST(ScanStageModel, MatchesTheSimulatedStage)
{
    const sim::MachineConfig stage = sim::stageConfig();
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
    // The simulated stage's work point follows the same seed 002 curves the plan compensates.
    const motion::scan::Compensation c;
    EXPECT_EQ(c.xPolyUm, stage.axes[0].abbeErrorPolyUm);
    EXPECT_EQ(c.yPolyUm, stage.axes[1].abbeErrorPolyUm);
}
