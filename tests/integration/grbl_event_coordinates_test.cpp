// A GRBL event that says where an axis is says it in both coordinate systems: the screens show
// work coordinates (G54), GRBL homes in machine coordinates, and with a work offset the two
// differ — "home done at -41.712 mm" beside a screen showing 0 was two systems and a stale report.
#include "grbl_session.h"

#include <gtest/gtest.h>

#include <cmath>

using itest::GrblSession;
using itest::waitFor;

TEST(GrblEventCoordinates, HomeDoneSaysWhereHomingLeftTheAxisInWorkAndMachineCoordinates)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    // A work offset: home set 5 mm into the travel, then a move to work X = 3 (machine X = 8).
    std::size_t from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 5}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, from));
    ASSERT_TRUE(s.waitStill());
    ASSERT_FALSE(s.call([&](auto cb) { s.client.setZero(1u << 0, cb); }));
    from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 3}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, from));
    const dev::DeviceEvent moved = s.events[static_cast<std::size_t>(s.findEvent(dev::proto::EventKind::MotionDone, 0, from))];
    EXPECT_NEAR(moved.position, 3, 1e-3);
    ASSERT_EQ(moved.detail.id, "grbl.event.position") << moved.detail;
    EXPECT_NEAR(moved.detail.number("work"), 3, 1e-3);
    EXPECT_NEAR(moved.detail.number("machine"), 8, 1e-3);
    ASSERT_TRUE(s.waitStill());

    // Homing takes X back to machine 0, which is work -5: the event says so, not the 3 it left.
    from = s.events.size();
    ASSERT_TRUE(s.homeAll());
    const int at = s.findEvent(dev::proto::EventKind::HomeDone, 0, from);
    ASSERT_GE(at, 0);
    const dev::DeviceEvent homed = s.events[static_cast<std::size_t>(at)];
    EXPECT_NEAR(homed.position, -5, 1e-3);
    EXPECT_NEAR(homed.position, s.readout('X').commanded, 1e-3);  // what the screen shows
    ASSERT_EQ(homed.detail.id, "grbl.event.position") << homed.detail;
    EXPECT_NEAR(homed.detail.number("work"), -5, 1e-3);
    EXPECT_NEAR(homed.detail.number("machine"), 0, 1e-3);
}
