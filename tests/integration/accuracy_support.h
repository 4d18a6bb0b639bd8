#pragma once
// What the accuracy runner tests share: the simulated stage homed with its clock sped
// up, a small ISO 230-2 test, and waits.
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/gauge_source.h"
#include "device/jobs/accuracy/readback_source.h"
#include "device/link/simulated_gauge.h"
#include "sim_session.h"

#include <QTemporaryDir>

#include <sstream>

namespace itest {

/// The simulated stage, connected, homed, its clock `timeScale` times the wall's.
struct AccuracyStage {
    AccuracyStage() : session(dev::proto::DeviceKind::Stage, kUnpaced) {}
    bool ready(double timeScale = 25)
    {
        if (!session.connect() || !session.homeAll())
            return false;
        session.link.host().setTimeScale(timeScale);
        return true;
    }
    SimSession session;
    QTemporaryDir dir;
};

/// X at 20, 40 and 60 mm, two cycles both ways: twelve readings, a few device seconds each.
inline dev::files::accuracy::AccuracyTest smallTest(std::vector<double> targets = {20, 40, 60}, int cycles = 2)
{
    motion::metrology::AxisTest t;
    t.name = "small";
    t.axis = "X";
    t.targetsMm = std::move(targets);
    t.cycles = cycles;
    t.feedMmS = 10;
    t.overrunMm = 0.5;
    t.dwellS = 0.05;
    t.settle = {1.0, 0.05, 2.0};
    return t;
}

inline bool waitRunner(dev::jobs::AccuracyRunner& r, dev::jobs::AccuracyRunner::State s, int ms = 60000)
{
    return waitFor([&] { return r.state() == s; }, ms);
}

inline std::string describe(const motion::msg::Problems& problems)
{
    std::ostringstream o;
    for (const auto& p : problems)
        o << p.path << ": " << motion::msg::debugString(p.message) << "\n";
    return o.str();
}

/// From now on the first MotionDone of `axis` is lost on the line; `dropped` counts it.
inline void loseFirstMotionDone(SimSession& s, int axis, int& dropped)
{
    s.tap.dropReceived = [axis, &dropped](const dev::proto::Frame& f) {
        if (dropped > 0 || f.type != static_cast<std::uint8_t>(dev::proto::MsgType::Event))
            return false;
        const auto e = dev::proto::decodeEvent(f.payload);
        if (!e || e->kind != dev::proto::EventKind::MotionDone || e->axis != axis)
            return false;
        ++dropped;
        return true;
    };
}

inline bool openSource(dev::jobs::ReadingSource& source)
{
    bool done = false;
    motion::msg::Message problem;
    source.open([&](const motion::msg::Message& p) {
        problem = p;
        done = true;
    });
    waitFor([&] { return done; }, 3000);
    return done && problem.empty();
}

} // namespace itest
