// The ISO 230-4 circular test on the simulated stage (its clock stepped by hand): both
// directions run as queued arcs with lead-in and lead-out, the evaluated revolution
// sampled without a gap, G per direction, G(b) and H evaluated; `accuracy circle`
// refuses a circle outside the travel before anything moves.
#include "accuracy_support.h"
#include "cli_in_process.h"

#include "device/jobs/accuracy/circle_runner.h"
#include "device/jobs/accuracy/circle_telemetry.h"


#include <gtest/gtest.h>

using namespace itest;

namespace {

TEST(AccuracyCircle, BothDirectionsAreSampledAndEvaluated)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready(1));
    motion::metrology::CircularTest t;
    t.centreMm = {50, 50};
    t.radiusMm = 10;
    t.feedMmS = 10;
    t.leadArcDeg = 30;
    t.samplesPerRevolution = 90;
    dev::jobs::CircleRunner r(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r.prepare(t, &problems)) << describe(problems);
    std::vector<motion::msg::Message> said;
    QObject::connect(&r, &dev::jobs::CircleRunner::problem, [&](const motion::msg::Message& m) { said.push_back(m); });
    int samples = 0;
    QObject::connect(&r, &dev::jobs::CircleRunner::sampled, [&] { ++samples; });
    // Fed no telemetry, the runner samples the path by polling status on the host's clock, so a sped-up
    // device clock on a loaded machine leaves gaps. The device's clock is stepped by hand
    // instead: 50 ms of device time (0.5 mm, under 3° of this circle) at a time, each step
    // waiting for the runner's next sample while the path runs.
    s.session.link.host().setManualClock(true);
    ASSERT_TRUE(r.start());
    auto over = [&] { return r.state() == dev::jobs::CircleRunner::State::Finished || r.state() == dev::jobs::CircleRunner::State::Stopped; };
    for (int step = 0; step < 5000 && !over(); ++step) {
        const int before = samples;
        s.session.link.host().advance(0.05);
        waitFor([&] { return samples > before || over(); }, 15);
    }
    s.session.link.host().setManualClock(false);
    ASSERT_EQ(r.state(), dev::jobs::CircleRunner::State::Finished) << (said.empty() ? "" : motion::msg::debugString(said.back()));
    ASSERT_EQ(r.runs().size(), 2u);
    for (const auto& run : r.runs())
        EXPECT_GE(run.samplesMm.size(), 24u) << "one sample per 4° bin at most, enough to leave no 30° gap";
    const auto e = r.evaluation();
    ASSERT_TRUE(e.ok()) << describe(e.problems);
    ASSERT_TRUE(e.hysteresisMm);
    for (const auto& run : e.runs) {
        EXPECT_LT(run.circularDeviationMm, 0.01) << "a grating loop contours within micrometres";
        EXPECT_NEAR(run.lsq.radiusMm, 10, 0.01);
    }
}

TEST(AccuracyCircle, TelemetrySamplesEveryDegreeOfTheRevolutionOnASpedUpClock)
{
    // Status polls come on the host's clock: at 10x one lands every ~60 ms of device time,
    // about a hundred a revolution here. The device's telemetry comes on its own clock,
    // 250 a second of it: every 1° bin of both revolutions gets its sample.
    AccuracyStage s;
    ASSERT_TRUE(s.ready(10));
    motion::metrology::CircularTest t;
    t.centreMm = {50, 50};
    t.radiusMm = 10;
    t.feedMmS = 10;
    t.samplesPerRevolution = 360;
    dev::jobs::CircleRunner r(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r.prepare(t, &problems)) << describe(problems);
    QObject::connect(&s.session.client, &dev::Instrument::telemetryReceived, &r,
                     [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedCircleBatch(r, s.session.client, b); });
    ASSERT_FALSE(s.session.call([&](auto cb) { s.session.client.subscribe(dev::jobs::circleChannels(r), 250, [cb](const auto& e, const auto&) { cb(e); }); }));
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitFor([&] { return !r.isActive(); }, 30000));
    ASSERT_EQ(r.state(), dev::jobs::CircleRunner::State::Finished);
    ASSERT_EQ(r.runs().size(), 2u);
    for (const auto& run : r.runs())
        EXPECT_EQ(run.samplesMm.size(), 360u) << "a sample in every degree";
    const auto e = r.evaluation();
    ASSERT_TRUE(e.ok()) << describe(e.problems);
    for (const auto& run : e.runs)
        EXPECT_NEAR(run.lsq.radiusMm, 10, 0.01);
}

TEST(AccuracyCircle, AMotionDoneLostOnTheWayToTheStartIsMadeGoodByTheStatus)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready(5));
    motion::metrology::CircularTest t;
    t.centreMm = {50, 50};
    t.radiusMm = 10;
    t.feedMmS = 10;
    dev::jobs::CircleRunner r(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r.prepare(t, &problems)) << describe(problems);
    int samples = 0;
    QObject::connect(&r, &dev::jobs::CircleRunner::sampled, [&] { ++samples; });
    int dropped = 0;
    loseFirstMotionDone(s.session, s.session.axis('Y'), dropped);
    ASSERT_TRUE(r.start());
    EXPECT_TRUE(waitFor([&] { return samples > 0; }, 20000)) << "the circle never began";
    EXPECT_EQ(dropped, 1);
    r.abort();
}

TEST(AccuracyCircle, TheCommandRefusesACircleOutsideTheTravel)
{
    // (A whole run through the command is not tested here: the runner samples by polling
    // status on the host's clock, and the command cannot step the device's clock by hand,
    // so on a loaded machine a sped-up run leaves gaps.)
    // Outside the travel: refused naming the limit, nothing moves.
    const auto out = runCliInProcess(splitWords("--sim stage accuracy circle --home --time-scale 25 --radius 20 --centre 10,50"));
    EXPECT_EQ(out.code, 1);
    EXPECT_TRUE(out.err.contains(QStringLiteral("below the soft limit"))) << out.err.toStdString();
}

} // namespace
