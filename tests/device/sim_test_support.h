#pragma once
// What the simulator tests share: readouts in host units, a runner that ticks
// the machine and keeps its events, and move requests in millimetres.
#include "device/sim/sim_machine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace simtest {

constexpr double kNmPerMm = 1e6;

inline dev::proto::WireUnits nm(double mm) { return static_cast<dev::proto::WireUnits>(std::lround(mm * kNmPerMm)); }
constexpr std::uint8_t bit(int i) { return static_cast<std::uint8_t>(1u << i); }

/// Logical positions the host sees, in mm.
inline double measuredMm(const dev::sim::SimMachine& m, int i) { return m.status().axes[static_cast<std::size_t>(i)].measured / 1e6; }
inline double commandedMm(const dev::sim::SimMachine& m, int i) { return m.status().axes[static_cast<std::size_t>(i)].commanded / 1e6; }
inline bool moving(const dev::sim::SimMachine& m, int i) { return m.status().axes[static_cast<std::size_t>(i)].flags & dev::proto::AxisMoving; }
inline bool anyMoving(const dev::sim::SimMachine& m)
{
    for (const auto& a : m.status().axes)
        if (a.flags & dev::proto::AxisMoving)
            return true;
    return false;
}

/// Collects every event the machine emits while the test runs it.
struct Runner {
    dev::sim::SimMachine& m;
    std::vector<dev::proto::EventMsg> events;

    void run(double seconds, const std::function<void()>& eachTick = {})
    {
        const auto ticks = static_cast<long>(std::lround(seconds / dev::sim::SimMachine::kTickS));
        for (long k = 0; k < ticks; ++k) {
            m.tick();
            if (eachTick)
                eachTick();
            take();
        }
    }
    /// Runs until nothing moves; false if that takes longer than `timeoutS`.
    bool runUntilIdle(double timeoutS, const std::function<void()>& eachTick = {})
    {
        const auto ticks = static_cast<long>(std::lround(timeoutS / dev::sim::SimMachine::kTickS));
        for (long k = 0; k < ticks; ++k) {
            m.tick();
            if (eachTick)
                eachTick();
            take();
            if (k % 10 == 0 && !anyMoving(m))
                return true;
        }
        return !anyMoving(m);
    }
    void take()
    {
        auto e = m.takeEvents();
        events.insert(events.end(), e.begin(), e.end());
    }
    const dev::proto::EventMsg* find(dev::proto::EventKind kind, int axis) const
    {
        for (const auto& e : events)
            if (e.kind == kind && (axis < 0 || e.axis == axis))
                return &e;
        return nullptr;
    }
    int count(dev::proto::EventKind kind, int axis = -1) const
    {
        return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const dev::proto::EventMsg& e) {
            return e.kind == kind && (axis < 0 || e.axis == axis);
        }));
    }
};

inline dev::proto::MoveRequest absMove(std::uint8_t mask, std::vector<double> targetsMm, double speedMmS = 0)
{
    dev::proto::MoveRequest r;
    r.relative = false;
    r.axisMask = mask;
    r.speed = static_cast<std::uint32_t>(std::lround(speedMmS * kNmPerMm));
    for (double t : targetsMm)
        r.targets.push_back(nm(t));
    return r;
}
inline dev::proto::MoveRequest relMove(std::uint8_t mask, std::vector<double> deltasMm, double speedMmS = 0)
{
    auto r = absMove(mask, std::move(deltasMm), speedMmS);
    r.relative = true;
    return r;
}

/// A machine homed on every axis, its events discarded: where most tests start.
template <dev::sim::MachineConfig (*Config)()>
struct HomedMachine : ::testing::Test {
    dev::sim::SimMachine m{Config()};
    Runner r{m, {}};
    void SetUp() override
    {
        ASSERT_FALSE(m.home(0));
        ASSERT_TRUE(r.runUntilIdle(60));
        for (int i = 0; i < m.axisCount(); ++i)
            ASSERT_TRUE(m.homed(i)) << "axis " << i;
        r.events.clear();
    }
};

} // namespace simtest
