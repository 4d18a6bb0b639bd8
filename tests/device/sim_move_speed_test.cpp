// A MOVE carries one speed. It is in the unit of the first axis named, so a move
// of X together with the pump is not refused for asking the pump 50 000 µL/s.
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using simtest::anyMoving;
using simtest::bit;


void runUntilIdle(dev::sim::SimMachine& m, double timeoutS)
{
    const auto ticks = static_cast<long>(timeoutS / dev::sim::SimMachine::kTickS);
    for (long k = 0; k < ticks; ++k) {
        m.tick();
        if (k > 10 && !anyMoving(m))
            return;
    }
    FAIL() << "still moving after " << timeoutS << " s";
}

TEST(SimMoveSpeed, SpeedIsInTheFirstAxisUnitAndThePumpKeepsItsDefault)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    dev::proto::MoveRequest r;
    r.relative = true;
    r.speed = 50'000'000;  // 50 mm/s in nm/s
    r.axisMask = 0b1001;   // X and P
    r.targets = {10'000'000, 100'000};  // +10 mm, +100 µL
    const auto refused = m.move(r);
    ASSERT_FALSE(refused.has_value()) << refused->message;
    double xDoneS = -1, pDoneS = -1;
    for (long k = 0; k < 200000 && (xDoneS < 0 || pDoneS < 0); ++k) {
        m.tick();
        for (const auto& e : m.takeEvents()) {
            if (e.kind != dev::proto::EventKind::MotionDone)
                continue;
            (e.axis == 0 ? xDoneS : pDoneS) = m.timeS();
        }
    }
    ASSERT_GT(xDoneS, 0);
    ASSERT_GT(pDoneS, 0);
    // 10 mm at 50 mm/s with the seed's 0.1 s ramps: about 0.3 s, not the 0.2 s of 100 mm/s.
    EXPECT_NEAR(xDoneS, 0.3, 0.05);
    // 100 µL at the pump's 100 µL/s default: about 1 s plus its ramps.
    EXPECT_NEAR(pDoneS, 1.05, 0.1);
    runUntilIdle(m, 2);
    EXPECT_NEAR(m.status().axes[3].commanded / 1e3, 100.0, 1e-6);
}

TEST(SimMoveSpeed, SpeedAboveAnAxisMaximumIsRefusedNamingTheAxis)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    dev::proto::MoveRequest r;
    r.relative = true;
    r.speed = 80'000'000;  // 80 mm/s: fine for X (100), too fast for Z (50)
    r.axisMask = 0b0101;
    r.targets = {5'000'000, 5'000'000};
    const auto refused = m.move(r);
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->code, dev::proto::ErrorCode::OutOfRange);
    EXPECT_NE(refused->message.find("axis Z"), std::string::npos) << refused->message;
}

} // namespace
