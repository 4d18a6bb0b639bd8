// The accuracy runner on the simulated stage, on the simulator's clock sped up: a
// run goes through ISO 230-2's standard linear cycle and writes its readings and
// result; an abort or a pulled cable stops it and it continues at the next reading,
// never reading a stop twice; a gauge that answers garbage stops it with the port and
// what was sent; a test outside the soft limits is refused before anything moves.
#include "accuracy_support.h"

#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/readings_csv.h"
#include "device/files/text_file.h"

#include <QDir>

#include <gtest/gtest.h>

using namespace itest;
using dev::jobs::AccuracyRunner;

namespace {

TEST(AccuracyRunner, RunsTheStandardLinearCycleAndWritesItsResults)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready());
    dev::jobs::ReadbackSource source(&s.session.client);
    AccuracyRunner r(&s.session.client);
    motion::msg::Problems problems;
    const auto test = smallTest();
    ASSERT_TRUE(r.prepare(test, &source, s.dir.path(), false, &problems)) << describe(problems);
    EXPECT_EQ(r.totalReadings(), 3 * 2 * 2);
    std::vector<int> order;
    QObject::connect(&r, &AccuracyRunner::readingTaken, [&](int k) { order.push_back(k); });
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitRunner(r, AccuracyRunner::State::Finished)) << AccuracyRunner::stateName(r.state());
    ASSERT_EQ(order.size(), 12u);
    for (std::size_t k = 0; k < order.size(); ++k)
        EXPECT_EQ(order[k], static_cast<int>(k));
    // ↑ then ↓ in every cycle: 20, 40, 60 then 60, 40, 20.
    const auto& e = r.entries();
    EXPECT_EQ(e[0].targetMm[0], 20);
    EXPECT_EQ(e[2].targetMm[0], 60);
    EXPECT_EQ(e[3].direction, motion::metrology::Direction::Down);
    EXPECT_EQ(e[3].targetMm[0], 60);
    EXPECT_EQ(e[6].cycle, 2);
    const auto eval = r.evaluation();
    ASSERT_TRUE(eval.ok());
    EXPECT_TRUE(eval.bidirectional);
    EXPECT_LT(*eval.figures.aMm, 0.003) << "the grating reads the loop's own target";
    // The results beside the log, readable by the file readers.
    ASSERT_TRUE(QFileInfo::exists(r.basePath() + QStringLiteral(".readings.csv")));
    const auto back = dev::files::accuracy::loadReadingsCsv(r.basePath() + QStringLiteral(".readings.csv"));
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.readings.size(), 12u);
    const auto result = dev::files::accuracy::loadAccuracyResultFile(r.basePath() + QStringLiteral(".accuracy-result.json"));
    ASSERT_TRUE(result.result) << motion::msg::debugFormat(result.problems);
    EXPECT_EQ(result.result->reference, "readback");
}

TEST(AccuracyRunner, AnAbortAndAPulledCableContinueAtTheNextReadingNeverReadingAStopTwice)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready());
    dev::jobs::ReadbackSource source(&s.session.client);
    auto r = std::make_unique<AccuracyRunner>(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r->prepare(smallTest(), &source, s.dir.path(), false, &problems)) << describe(problems);
    ASSERT_TRUE(r->start());
    ASSERT_TRUE(waitFor([&] { return r->readingsTaken() >= 3; }, 30000));
    r->abort();
    EXPECT_EQ(r->state(), AccuracyRunner::State::Stopped);
    const int afterAbort = r->readingsTaken();
    ASSERT_TRUE(s.session.waitStill());
    ASSERT_TRUE(r->start());
    ASSERT_TRUE(waitFor([&] { return r->readingsTaken() >= afterAbort + 2; }, 30000));
    // The cable comes out with a MOVE on the wire.
    bool pulled = false;
    s.session.tap.afterWrite = [&](const QByteArray& bytes) {
        if (!pulled && containsFrame(bytes, dev::proto::MsgType::Move)) {
            pulled = true;
            QTimer::singleShot(0, [&] { s.session.link.pair().unplug(); });
        }
    };
    ASSERT_TRUE(waitRunner(*r, AccuracyRunner::State::Stopped, 10000));
    s.session.tap.afterWrite = nullptr;
    EXPECT_TRUE(pulled);
    s.session.link.pair().replug();
    ASSERT_TRUE(s.session.connect());
    ASSERT_TRUE(s.session.waitStill());
    // A new runner (a new program) on the same folder continues from the log.
    r = std::make_unique<AccuracyRunner>(&s.session.client);
    ASSERT_TRUE(r->prepare(smallTest(), &source, s.dir.path(), false, &problems)) << describe(problems);
    EXPECT_GE(r->readingsTaken(), afterAbort + 2);
    ASSERT_TRUE(r->start());
    ASSERT_TRUE(waitRunner(*r, AccuracyRunner::State::Finished));
    // The log has each stop once, in order: the parser refuses anything else.
    std::string text;
    QString error;
    ASSERT_TRUE(dev::files::readText(r->logPath(), &text, &error));
    const auto log = dev::files::accuracy::parseRunLog(text);
    ASSERT_TRUE(log.log);
    EXPECT_EQ(log.log->entries.size(), 12u);
    EXPECT_TRUE(r->evaluation().ok()) << "every target and direction read exactly once per cycle";
}

TEST(AccuracyRunner, AMotionDoneLostOnTheLineIsMadeGoodByTheStatus)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready());
    dev::jobs::ReadbackSource source(&s.session.client);
    AccuracyRunner r(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r.prepare(smallTest({20, 40}, 2), &source, s.dir.path(), false, &problems)) << describe(problems);
    int dropped = 0;
    loseFirstMotionDone(s.session, s.session.axis('X'), dropped);
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitRunner(r, AccuracyRunner::State::Finished, 30000)) << AccuracyRunner::stateName(r.state());
    EXPECT_EQ(dropped, 1);
    EXPECT_EQ(r.readingsTaken(), 8);
}

TEST(AccuracyRunner, AGaugeThatAnswersGarbageStopsTheRunNamingItsPortAndWhatItSent)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready());
    dev::SimulatedGauge gauge(s.session.link.machine(), 0);
    dev::jobs::GaugeSource source(gauge.hostEnd(), QStringLiteral("simulated gauge"));
    source.link().setTimeoutMs(200);
    ASSERT_TRUE(openSource(source));
    AccuracyRunner r(&s.session.client);
    motion::msg::Problems problems;
    ASSERT_TRUE(r.prepare(smallTest(), &source, s.dir.path(), false, &problems)) << describe(problems);
    std::vector<motion::msg::Message> said;
    QObject::connect(&r, &AccuracyRunner::problem, [&](const motion::msg::Message& m) { said.push_back(m); });
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitFor([&] { return r.readingsTaken() >= 2; }, 30000));
    gauge.gauge().setFault(dev::sim::SimGauge::Fault::Garbage);
    ASSERT_TRUE(waitRunner(r, AccuracyRunner::State::Stopped, 30000));
    ASSERT_FALSE(said.empty());
    EXPECT_EQ(said.back().id, "gauge.not_a_reading");
    EXPECT_EQ(said.back().text("port"), "simulated gauge");
    EXPECT_EQ(said.back().text("text"), "Err 7");
    const int taken = r.readingsTaken();
    // Nothing was logged for the stop the gauge garbled; once it answers, the same stop is read.
    gauge.gauge().setFault(dev::sim::SimGauge::Fault::Silent);
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitRunner(r, AccuracyRunner::State::Stopped, 30000));
    EXPECT_EQ(said.back().id, "gauge.no_answer");
    EXPECT_EQ(r.readingsTaken(), taken);
    gauge.gauge().setFault(dev::sim::SimGauge::Fault::None);
    ASSERT_TRUE(r.start());
    ASSERT_TRUE(waitRunner(r, AccuracyRunner::State::Finished));
    EXPECT_EQ(r.readingsTaken(), 12);
}

TEST(AccuracyRunner, TargetsOutsideTheSoftLimitsAreRefusedBeforeAnythingMoves)
{
    AccuracyStage s;
    ASSERT_TRUE(s.ready());
    dev::jobs::ReadbackSource source(&s.session.client);
    AccuracyRunner r(&s.session.client);
    auto test = smallTest();
    auto firstError = [](const motion::msg::Problems& ps) {
        for (const auto& p : ps)
            if (p.isError())
                return p;
        return motion::msg::Problem{};
    };
    std::get<motion::metrology::AxisTest>(test).targetsMm = {20, 60, 99.8};  // the overrun goes to 100.3
    motion::msg::Problems problems;
    EXPECT_FALSE(r.prepare(test, &source, s.dir.path(), false, &problems));
    EXPECT_EQ(firstError(problems).message.id, "accuracy.overrun_above_limit") << describe(problems);
    EXPECT_EQ(firstError(problems).path, "overrun_mm");
    std::get<motion::metrology::AxisTest>(test).targetsMm = {20, 60, 40};
    EXPECT_FALSE(r.prepare(test, &source, s.dir.path(), false, &problems));
    EXPECT_EQ(firstError(problems).message.id, "accuracy.targets_not_increasing") << describe(problems);
    EXPECT_FALSE(QFileInfo::exists(QDir(s.dir.path()).filePath(QStringLiteral("accuracy-run.jsonl")))) << "nothing written";
}

} // namespace
