// A grating counter holds whole counts: after homing, every reading the host
// sees is a multiple of 0.5 µm, at rest and on the move.
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using simtest::anyMoving;
using simtest::bit;


TEST(SimGratingCounts, HomedReadingsAreWholeCounts)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    ASSERT_FALSE(m.home(0).has_value());
    for (long k = 0; k < 600000 && (k < 10 || anyMoving(m)); ++k)
        m.tick();
    ASSERT_FALSE(anyMoving(m));
    dev::proto::MoveRequest r;
    r.axisMask = 0b11;
    r.targets = {12'345'600, 7'000'250};
    ASSERT_FALSE(m.move(r).has_value());
    constexpr int kCountNm = 500;
    for (long k = 0; k < 100000; ++k) {
        m.tick();
        if (k % 97 != 0)
            continue;
        for (const auto& a : m.status().axes)
            ASSERT_EQ(a.measured % kCountNm, 0) << "reading " << a.measured << " nm at tick " << k;
    }
}

} // namespace
