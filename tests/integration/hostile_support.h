#pragma once
// Jobs on a hostile line (docs/testing.md): each runs one job — recipe, scan, pattern, tuning,
// joystick — on the in-process simulator over a loopback whose bytes are dropped,
// corrupted, duplicated and delayed (dev::LinkFaults, seeded), with unplugs where the
// job has a way back, and judges the invariants a lab relies on by the SIMULATOR's own
// record (dev::sim::Firmware::journal(), the machine's state), not by what the client says.
// The quick set (integration) and the campaign (tests/hostile/, label hostile) share it.
#include "device/client/joystick_driver.h"
#include "device/client/tuning_client.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/jobs/scan_runner.h"
#include "device/jobs/tuning/instrument_target.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "device/sim/sim_tuning.h"
#include "hostile_outcome.h"
#include "motion/plans/pattern.h"
#include "plates_run_support.h"
#include "sim_session.h"

#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace hostile {

/// The line both ways: `rate` of the bytes damaged (a third corrupted, a third dropped,
/// a third doubled), and up to 3 ms of jitter per write.
inline void spoil(itest::SimSession& s, double rate, std::uint64_t seed)
{
    auto a = dev::LinkFaults::bytes(rate, seed * 2 + 1);
    auto b = dev::LinkFaults::bytes(rate, seed * 2 + 2);
    a.jitterMs = b.jitterMs = 3;
    s.link.pair().setFaults(dev::LoopbackPair::A, a);
    s.link.pair().setFaults(dev::LoopbackPair::B, b);
}

inline void tally(itest::SimSession& s, Outcome& o)
{
    o.retransmits = s.client.stats().retransmits;
    o.crcErrors = s.client.stats().crcErrors + s.link.host().firmware().decoderStats().crcErrors;
    o.duplicatesAnswered = s.link.host().firmware().duplicateRequests();
    for (auto side : {dev::LoopbackPair::A, dev::LoopbackPair::B}) {
        const auto& c = s.link.pair().faultCounts(side);
        o.damagedBytes += c.corruptedBytes + c.droppedBytes + c.duplicatedBytes;
    }
}

/// Connects, retrying like an operator would (a connect can still fail on a bad line:
/// that counts as a stop).
inline bool connect(itest::SimSession& s, Outcome& o, int tries = 5)
{
    for (int i = 0; i < tries; ++i) {
        if (s.client.state() == dev::LinkState::Ready || s.connect(8000))
            return true;
        ++o.stops;
        o.why += (o.why.empty() ? "" : ",") + std::string("connect:") + (s.linkMessages.empty() ? "?" : s.linkMessages.back().id);
        itest::spin(100);
    }
    return false;
}

inline bool homeAll(itest::SimSession& s, Outcome& o)
{
    for (int i = 0; i < 3; ++i) {
        if (!connect(s, o))
            return false;
        if (s.homeAll())
            return true;
        ++o.stops;
        o.why += (o.why.empty() ? "" : ",") + std::string("home:") + (s.linkMessages.empty() ? "?" : s.linkMessages.back().id);
    }
    return false;
}

// ---- recipe: every well once, never twice; the plunger's volume accounted for ----------

inline Outcome recipe(double rate, std::uint64_t seed, const std::string& wells, int wellCount, double volumeUl = 10)
{
    using namespace platestest;
    Outcome o{"recipe", rate, seed};
    itest::SimSession s(dev::proto::DeviceKind::Analyzer, itest::kUnpaced);
    s.link.host().firmware().setJournal(true);
    spoil(s, rate, seed);
    if (!homeAll(s, o)) {
        o.end = "no-connection";
        o.fail("could not connect and home");
        tally(s, o);
        return o;
    }
    s.link.host().setTimeScale(kRunTimeScale);
    const int ix = s.axis('X'), iy = s.axis('Y'), iz = s.axis('Z'), ip = s.axis('P');
    const double p0 = s.link.machine().commandedLogical(ip);
    const std::size_t journalFrom = s.link.host().firmware().journal().size();

    QTemporaryDir dir;
    const QString log = dir.filePath(QStringLiteral("run.jsonl"));
    const motion::plates::Recipe r = samplingRecipe(wells, volumeUl);
    dev::jobs::RecipeRunner runner(&s.client);
    motion::msg::Message error;
    if (!runner.setPlan(planFor(r, s.client), QStringLiteral("hostile"), &error) || !runner.start(log, &error)) {
        o.end = "refused";
        o.fail("refused: " + motion::msg::debugString(error));
        tally(s, o);
        return o;
    }
    QObject::connect(&runner, &dev::jobs::RecipeRunner::message, &runner, [&](const motion::msg::Message& m, bool problem) {
        if (problem)
            o.why += (o.why.empty() ? "" : ",") + m.id;
    });
    int skipped = 0;
    for (int round = 0; round < 8; ++round) {
        waitSettled(runner, 300000);
        if (runner.state() != dev::jobs::RunState::Stopped)
            break;
        ++o.stops;
        if (!connect(s, o))
            break;
        itest::spin(200);
        // The operator's choice for a well cut in the middle: skip it (a well done
        // twice is what the lab must never see).
        runner.resume([&](const dev::jobs::InterruptedOp&) {
            ++skipped;
            return dev::jobs::InterruptedChoice::Skip;
        }, &error);
    }
    o.end = runner.state() == dev::jobs::RunState::Finished ? "finished" : "stopped";
    if (o.end != "finished")
        o.fail("the run did not finish");
    s.waitStill();

    // The device's own record: every plunger move it executed, and where X, Y stood.
    (void)iz;
    std::vector<double> wireScale;
    for (const auto& a : s.client.identity().axes)
        wireScale.push_back(a.wireScale());
    const PlungerTally t = plungerByWell(s.link.host().firmware().journal(), journalFrom, wireScale, ix, iy, ip);
    judgeWells(o, t, wellCount, volumeUl, skipped, s.link.machine().commandedLogical(ip) - p0);
    tally(s, o);
    return o;
}

// ---- scan: every tile once, each with a measured position --------------------------------

inline Outcome scan(double rate, std::uint64_t seed, double sideMm, bool unplugOnce)
{
    Outcome o{"scan", rate, seed};
    itest::SimSession s(dev::proto::DeviceKind::Stage, itest::kUnpaced);
    s.link.host().firmware().setJournal(true);
    spoil(s, rate, seed);
    if (!homeAll(s, o)) {
        o.end = "no-connection";
        o.fail("could not connect and home");
        tally(s, o);
        return o;
    }
    s.link.host().setTimeScale(10);
    motion::scan::ScanPlan p;
    p.name = "hostile";
    p.region.cornerA = {40, 60};
    p.region.cornerB = {40 + sideMm, 60 + sideMm};
    p.camera.source = motion::scan::FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.0;
    p.camera.samplePixelUm = 0.5;
    p.overlapX = p.overlapY = 0.1;
    p.speedMmS = 10;
    p.settleS = 0.03;
    p.exposureS = 0.02;
    QTemporaryDir dir;
    dev::jobs::ScanRunner runner(&s.client);
    std::map<int, int> triggers;
    QObject::connect(&runner, &dev::jobs::ScanRunner::triggered, &runner, [&](int tile, quint64) {
        ++triggers[tile];
    });
    // The cable is pulled once, right after the third tile is taken (on the way to the
    // fourth), and put back 300 ms later. A tile cut in the middle of its exposure is
    // taken again, and is no tile taken twice: it was never taken.
    bool pulled = false;
    QObject::connect(&runner, &dev::jobs::ScanRunner::tileTaken, &runner, [&](int) {
        if (!unplugOnce || pulled || runner.takenTiles() < 3)
            return;
        pulled = true;
        s.link.pair().unplug();
        QTimer::singleShot(300, &runner, [&] { s.link.pair().replug(); });
    });
    motion::msg::Message error;
    if (!runner.prepare(p, dir.path(), false, &error) || !runner.start(&error)) {
        o.end = "refused";
        o.fail("refused: " + motion::msg::debugString(error));
        tally(s, o);
        return o;
    }
    for (int round = 0; round < 8; ++round) {
        itest::waitFor([&] { return !runner.isActive(); }, 120000);
        if (runner.state() == dev::jobs::ScanRunner::State::Finished)
            break;
        ++o.stops;
        itest::spin(400);
        if (!connect(s, o))
            break;
        itest::spin(200);
        if (!runner.start(&error))
            break;
    }
    o.end = runner.state() == dev::jobs::ScanRunner::State::Finished ? "finished" : "stopped";
    if (o.end != "finished")
        o.fail("the scan did not finish");
    judgeTiles(o, runner.records(), runner.totalTiles(), triggers, p.toleranceUm, xyMovesUm(s.link.host().firmware().journal()));
    tally(s, o);
    return o;
}

// ---- pattern: the whole path, once, on the path ------------------------------------------

inline Outcome pattern(double rate, std::uint64_t seed)
{
    Outcome o{"pattern", rate, seed};
    itest::SimSession s(dev::proto::DeviceKind::Stage, itest::kUnpaced);
    s.link.host().firmware().setJournal(true);
    spoil(s, rate, seed);
    dev::jobs::PatternRunner runner(&s.client);
    QObject::connect(&s.client, &dev::BenchPilotClient::telemetryReceived, &runner,
                     [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, s.client, b); });
    if (!homeAll(s, o)) {
        o.end = "no-connection";
        o.fail("could not connect and home");
        tally(s, o);
        return o;
    }
    s.link.host().setTimeScale(4);
    bool limits = false;
    s.client.paths()->refreshLimits([&](const auto&) { limits = true; });
    itest::waitFor([&] { return limits; }, 5000);
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Circle;
    pat.feedMmS = 5;
    const auto path = motion::plans::plan(pat);
    if (!runner.start(path, {})) {
        o.end = "refused";
        o.fail("refused");
        tally(s, o);
        return o;
    }
    for (int round = 0; round < 8; ++round) {
        itest::waitFor([&] { return !runner.busy(); }, 120000);
        if (runner.state() != dev::jobs::PatternRunner::State::Interrupted)
            break;
        ++o.stops;
        if (!connect(s, o))
            break;
        runner.resume();
        itest::waitFor([&] { return runner.state() != dev::jobs::PatternRunner::State::Interrupted; }, 5000);
    }
    o.end = runner.state() == dev::jobs::PatternRunner::State::Done ? "finished" : "stopped";
    if (o.end != "finished")
        o.fail("the pattern did not finish");
    if (runner.segmentsDone() != path.size())
        o.fail("segments done " + std::to_string(runner.segmentsDone()) + " of " + std::to_string(path.size()));
    // The device's record: it ends where the path ends, and it never went off the path.
    const double ex = s.link.machine().commandedLogical(0) - path.back().end.x;
    const double ey = s.link.machine().commandedLogical(1) - path.back().end.y;
    if (std::hypot(ex, ey) > 1e-3)
        o.fail("the stage does not stand at the path's end");
    if (runner.summary().maxContourMm > 0.005)
        o.fail("contour error " + std::to_string(runner.summary().maxContourMm * 1e3) + " um");
    if (o.end == "finished" && o.stops == 0 && runner.summary().durationS <= 0)
        o.fail("no duration");
    tally(s, o);
    return o;
}

// ---- tuning: a run cut in the middle leaves the gains the axis had ------------------------

inline Outcome tuningCut(double rate, std::uint64_t seed)
{
    Outcome o{"tuning", rate, seed};
    itest::SimSession s(dev::proto::DeviceKind::Stage, itest::kUnpaced);
    spoil(s, rate, seed);
    if (!homeAll(s, o)) {
        o.end = "no-connection";
        o.fail("could not connect and home");
        tally(s, o);
        return o;
    }
    const int x = s.axis('X');
    s.call([&](auto cb) { s.client.move({{x, 50.0}}, false, 0, cb); }, 10000);
    s.waitStill();
    const dev::sim::PidGains before = s.link.machine().tuning().gains(x);
    dev::InstrumentTarget target(s.client.tuning(), x, QStringLiteral("Stage"));
    dev::TuningRunner runner;
    dev::TuningRunner::ZnOptions opt;
    opt.method = motion::control::TuningMethod::Relay;
    opt.envelope = {0.05, 0.05, 20};
    opt.step = 0.02;
    opt.trialS = 0.3;
    opt.startKp = 0.25;
    opt.relayAmplitude = 0.02;
    opt.hysteresis = 0.001;
    opt.relayCycles = 2000;  // long enough to cut it in the middle
    opt.verifyRule = "zn-pid";
    opt.verifyStep = 0.02;
    if (!runner.startZn(&target, opt)) {
        o.end = "refused";
        o.fail("refused");
        tally(s, o);
        return o;
    }
    if (!itest::waitFor([&] { return s.link.machine().tuning().testRunning(x); }, 10000))
        o.fail("the test never started on the device");
    itest::spin(200);
    s.link.pair().unplug();  // the cut
    itest::waitFor([&] { return !s.link.machine().tuning().testRunning(x); }, 3000);
    itest::spin(300);
    o.end = s.link.machine().tuning().testRunning(x) ? "still-testing" : "cut";
    if (o.end != "cut")
        o.fail("the device went on testing after the cut");
    const dev::sim::PidGains after = s.link.machine().tuning().gains(x);
    if (after.kp != before.kp || after.ki != before.ki || after.kd != before.kd)
        o.fail("gains not back to what they were");
    if (s.link.machine().status().axes[static_cast<std::size_t>(x)].flags & dev::proto::AxisMoving)
        o.fail("the axis still moves after the cut");
    tally(s, o);
    return o;
}

// ---- joystick: nothing moves longer than the watchdog allows after the link dies ----------

inline Outcome joystick(double rate, std::uint64_t seed, int holdMs)
{
    Outcome o{"joystick", rate, seed};
    itest::SimSession s(dev::proto::DeviceKind::Stage, itest::kUnpaced);  // homing runs on a sped-up clock
    spoil(s, rate, seed);
    if (!homeAll(s, o)) {
        o.end = "no-connection";
        o.fail("could not connect and home");
        tally(s, o);
        return o;
    }
    s.link.host().firmware().setJournal(true);
    dev::JoystickDriver driver(&s.client);
    driver.setVelocities({{0, 5.0}, {1, -4.0}});
    itest::spin(holdMs);
    auto moving = [&] {
        const auto st = s.link.machine().status();
        return (st.axes[0].flags & dev::proto::AxisMoving) || (st.axes[1].flags & dev::proto::AxisMoving);
    };
    if (!moving())
        o.fail("the stick did not move the stage");
    // The link dies: one of the two ways, by seed.
    if (seed % 2)
        s.link.pair().unplug();
    else
        s.link.pair().hang(5000);
    o.end = seed % 2 ? "unplugged" : "hung";
    if (!itest::waitFor([&] { return !moving(); }, 3000))
        o.fail("still moving 3 s after the link died");
    // The device's record: the last velocity it executed (no later than the cut), and
    // the events that said each axis was at rest.
    judgeCoast(o, s.link.host().firmware().journal(), {0, 1}, s.client.identity().jogWatchdogMs / 1000.0);
    tally(s, o);
    return o;
}

} // namespace hostile
