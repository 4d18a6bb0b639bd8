// The plan's move times are the simulated firmware's: the deck file describes
// the analyzer's axes as dev::sim::analyzerConfig() builds them, and a move planned
// by move_time.h takes as long on the simulator as the plan says.
#include "device/files/plates/deck_file.h"
#include "device/sim/machine_config.h"
#include "device/sim/sim_machine.h"
#include "motion/plans/recipes/move_time.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

/// Seconds from a MOVE until every axis in it reported MotionDone, on the simulator.
double simulatedSeconds(dev::sim::SimMachine& m, const dev::proto::MoveRequest& r)
{
    m.takeEvents();
    const double t0 = m.timeS();
    EXPECT_FALSE(m.move(r).has_value());
    int pending = dev::proto::popcount8(r.axisMask);
    for (int tick = 0; tick < 200000 && pending > 0; ++tick) {
        m.tick();
        for (const auto& e : m.takeEvents())
            if (e.kind == dev::proto::EventKind::MotionDone)
                --pending;
    }
    EXPECT_EQ(pending, 0);
    return m.timeS() - t0;
}

void homeAll(dev::sim::SimMachine& m)
{
    ASSERT_FALSE(m.home(0).has_value());
    for (int tick = 0; tick < 3000000; ++tick) {
        m.tick();
        bool all = true;
        for (int i = 0; i < m.axisCount(); ++i)
            all = all && m.homed(i);
        if (all)
            break;
    }
    for (int tick = 0; tick < 1000; ++tick)
        m.tick();
    m.takeEvents();
}

} // namespace

TEST(PlateMoveTime, TheDeckFileDescribesTheSimulatedAnalyzer)
{
    const motion::plates::Deck d = dev::files::plates::builtinDeck();
    const dev::sim::MachineConfig c = dev::sim::analyzerConfig();
    const motion::plates::AxisMotion* axes[] = {&d.x, &d.y, &d.z, &d.p};
    ASSERT_EQ(c.axes.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(c.axes[i].letter);
        EXPECT_DOUBLE_EQ(axes[i]->maxSpeed, c.axes[i].maxSpeed);
        EXPECT_DOUBLE_EQ(axes[i]->defaultSpeed, c.axes[i].defaultSpeed);
        EXPECT_DOUBLE_EQ(axes[i]->accelTimeS, c.axes[i].accelTimeS);
        EXPECT_DOUBLE_EQ(axes[i]->maxAccel, c.axes[i].maxAccel);
    }
    EXPECT_DOUBLE_EQ(d.travelXMm, c.axes[0].travel);
    EXPECT_DOUBLE_EQ(d.travelYMm, c.axes[1].travel);
    EXPECT_DOUBLE_EQ(d.travelZMm, c.axes[2].travel);
    EXPECT_DOUBLE_EQ(d.syringeUl, c.axes[3].travel);
}

TEST(PlateMoveTime, PlannedTimesMatchTheSimulatedFirmware)
{
    const motion::plates::Deck d = dev::files::plates::builtinDeck();
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    homeAll(m);
    struct Case {
        std::uint8_t mask;
        std::vector<double> targets;  ///< mm or µL, absolute
        double speed;                 ///< 0 = default
        std::vector<std::pair<const motion::plates::AxisMotion*, int>> axes;
    };
    const std::vector<Case> cases = {
        {0b0011, {22.38, 19.24}, 0, {{&d.x, 0}, {&d.y, 1}}},       // to A1 of slot 1
        {0b0011, {31.38, 19.24}, 0, {{&d.x, 0}, {&d.y, 1}}},       // one pitch along the row
        {0b0011, {150.0, 180.0}, 100, {{&d.x, 0}, {&d.y, 1}}},     // long diagonal at full speed
        {0b0100, {70.0}, 0, {{&d.z, 2}}},                          // down into the well
        {0b0100, {55.0}, 0, {{&d.z, 2}}},                          // up to the safe height
        {0b1000, {10.0}, 0, {{&d.p, 3}}},                          // a 10 µL aspirate
        {0b1000, {400.0}, 250, {{&d.p, 3}}},                       // a fast 390 µL stroke
    };
    std::vector<double> at(4, 0.0);
    for (int i = 0; i < 4; ++i)
        at[static_cast<std::size_t>(i)] = m.commandedLogical(i);
    for (const Case& c : cases) {
        dev::proto::MoveRequest r;
        r.axisMask = c.mask;
        r.speed = static_cast<std::uint32_t>(std::lround(c.speed * (c.mask == 0b1000 ? 1e3 : 1e6)));
        std::vector<motion::plates::AxisDelta> deltas;
        for (std::size_t k = 0; k < c.targets.size(); ++k) {
            const int axis = c.axes[k].second;
            r.targets.push_back(static_cast<std::int32_t>(std::lround(c.targets[k] * (axis == 3 ? 1e3 : 1e6))));
            deltas.push_back({c.axes[k].first, c.targets[k] - at[static_cast<std::size_t>(axis)]});
            at[static_cast<std::size_t>(axis)] = c.targets[k];
        }
        const double planned = motion::plates::moveTimeS(deltas, c.speed);
        const double simulated = simulatedSeconds(m, r);
        // The firmware ends a segment on the first 100 µs tick at or past its duration.
        EXPECT_NEAR(simulated, planned, 2 * dev::sim::SimMachine::kTickS) << "mask " << int(c.mask) << " to " << c.targets[0];
    }
}
