// Patience on a noisy line (docs/protocol.md "Retries and silence"): at 1 %
// of bytes damaged the handshake and every request get through by retrying with the
// same sequence number, each executed once; duplicated device frames are one event;
// a lost MotionDone does not stall a scan; a stopped pattern says how long it ran.
// Judged on the simulator's own record, not on what the client believes.
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/jobs/scan_runner.h"
#include "motion/plans/pattern.h"
#include "sim_session.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>

#include <gtest/gtest.h>

#include <algorithm>

using namespace itest;
using dev::LinkFaults;
using dev::LinkState;
using dev::LoopbackPair;
using K = dev::proto::EventKind;

namespace {

std::string text(const QStringList& l) { return l.join(QStringLiteral(" | ")).toStdString(); }

/// Removes every EVENT frame from what the device writes (frames are whole in a write).
QByteArray withoutEvents(const QByteArray& bytes)
{
    QByteArray out;
    int start = 0;
    for (int i = 0; i < bytes.size(); ++i) {
        if (bytes[i] != '\0')
            continue;
        const QByteArray frame = bytes.mid(start, i - start + 1);
        start = i + 1;
        const auto fs = framesIn(frame);
        if (fs.size() == 1 && fs.front().type == static_cast<std::uint8_t>(dev::proto::MsgType::Event))
            continue;
        out += frame;
    }
    out += bytes.mid(start);
    return out;
}

bool machineMoving(const dev::sim::SimMachine& m)
{
    for (const auto& a : m.status().axes)
        if (a.flags & dev::proto::AxisMoving)
            return true;
    return false;
}

} // namespace

// Found by the hostile pty campaign (seed 17 at 1 %, reproduced by hand every time): the
// device answered each of 43 HELLOs in 4.4 s and every reply arrived damaged, then the
// HELLO request gave up at its 5 s like any request, though the handshake is documented
// to keep trying for 10 s while damaged frames show a device answering.
TEST(LinkPatience, AHandshakeKeepsTryingPastFiveSecondsWhileDamagedRepliesShowTheDeviceAnswering)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    s.link.pair().setFaults(LoopbackPair::B, LinkFaults::bytes(0.05, 17));  // a HELLO reply never arrives whole
    QTimer::singleShot(6000, Qt::PreciseTimer, &s.client, [&] { s.link.pair().setFaults(LoopbackPair::B, LinkFaults{}); });
    QElapsedTimer took;
    took.start();
    ASSERT_TRUE(s.connect(dev::BenchPilotClient::kConnectGiveUpMs + 3000)) << text(s.linkErrors);
    // Past a request's 5 s give-up (a coarse timer may clear the faults a little early).
    EXPECT_GT(took.elapsed(), dev::BenchPilotClient::kRequestGiveUpMs) << "the replies were damaged until about 6 s";
    EXPECT_TRUE(s.linkErrors.isEmpty()) << text(s.linkErrors);
}

// A connect that fails says what the line carried: "no answer … check power" had been
// the message for a line whose every answer arrived damaged too, which sent the operator
// to the power switch instead of the cable (the hostile campaign's dead-line hunt).
TEST(LinkPatience, AConnectWhoseEveryAnswerArrivesDamagedSaysSoWhenItGivesUp)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    s.link.pair().setFaults(LoopbackPair::B, LinkFaults::bytes(0.05, 17));  // a HELLO reply never arrives whole
    ASSERT_FALSE(s.connect(dev::BenchPilotClient::kConnectGiveUpMs + 3000));
    ASSERT_EQ(s.linkErrors.size(), 1) << text(s.linkErrors);
    EXPECT_TRUE(s.linkErrors.first().startsWith(QStringLiteral("link.only_damaged{"))) << text(s.linkErrors);
    EXPECT_FALSE(s.linkErrors.first().contains(QStringLiteral("damaged=0"))) << text(s.linkErrors);
}

TEST(LinkPatience, ADeviceThatGoesSilentMidConnectIsToldFromOneThatNeverAnswered)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    s.link.pair().setFaults(LoopbackPair::B, LinkFaults::bytes(0.05, 17));
    QTimer::singleShot(1000, &s.client, [&] {
        LinkFaults mute;
        mute.filter = [](const QByteArray&) { return QByteArray(); };
        s.link.pair().setFaults(LoopbackPair::B, mute);
    });
    QElapsedTimer took;
    took.start();
    ASSERT_FALSE(s.connect(dev::BenchPilotClient::kConnectGiveUpMs + 3000));
    // 2 s of silence after the last damaged frame, not the handshake's 10 s.
    EXPECT_LT(took.elapsed(), dev::BenchPilotClient::kConnectGiveUpMs);
    ASSERT_EQ(s.linkErrors.size(), 1) << text(s.linkErrors);
    EXPECT_TRUE(s.linkErrors.first().startsWith(QStringLiteral("link.went_silent{"))) << text(s.linkErrors);
}

// Found under Xvfb: a scan's cable pulled, put back 10 s later, Connect pressed; the GUI
// said "connecting" for 12 s on a line that carried the device's answer at once. The
// first timeout check of the new connect took the time since the old link's last check
// for the host's own event loop held up, and put the HELLO's retry off by all of it: a
// first reply lost or damaged then cost as long as the cable had been out.
TEST(LinkPatience, AReconnectRetriesAtOnceHoweverLongTheLinkWasDown)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    s.client.disconnectLink();
    QElapsedTimer down;
    down.start();
    waitFor([] { return false; }, 3000);  // the cable out for 3 s
    ASSERT_GE(down.elapsed(), 2500);  // a coarse timer may end the wait a little early
    bool lostOne = false;  // the first HELLO reply of the reconnect does not arrive
    LinkFaults f;
    f.filter = [&lostOne](const QByteArray& bytes) {
        if (!lostOne) {
            for (const auto& fr : framesIn(bytes))
                if (fr.type == dev::proto::replyTypeOf(dev::proto::MsgType::Hello)) {
                    lostOne = true;
                    return QByteArray();
                }
        }
        return bytes;
    };
    s.link.pair().setFaults(LoopbackPair::B, f);
    QElapsedTimer took;
    took.start();
    ASSERT_TRUE(s.connect(dev::BenchPilotClient::kConnectGiveUpMs)) << text(s.linkErrors);
    EXPECT_TRUE(lostOne) << "no reply was lost: no test";
    EXPECT_LT(took.elapsed(), 1500) << "the lost reply's retry waited for the time the link was down";
}

TEST(LinkPatience, HandshakeAndRequestsRideThroughOnePercentByteFaults)
{
    // The test waits as long as the client itself would before it gives up; the client's
    // patience, not the test's, is what is measured.
    constexpr int kPatientConnectMs = dev::BenchPilotClient::kConnectGiveUpMs + 3000;
    // Before: 3 attempts of 300 ms, and a HELLO reply of ~150 bytes arrives whole at
    // 1 % only one time in four to seven, so connects failed with link.no_answer.
    for (std::uint64_t seed : {1u, 2u}) {
        SCOPED_TRACE(seed);
        SimSession s(dev::proto::DeviceKind::Analyzer);
        s.link.pair().setFaults(LoopbackPair::A, LinkFaults::bytes(0.01, seed));
        s.link.pair().setFaults(LoopbackPair::B, LinkFaults::bytes(0.01, seed + 100));
        for (int attempt = 0; attempt < 3; ++attempt) {
            QElapsedTimer took;
            took.start();
            ASSERT_TRUE(s.connect(kPatientConnectMs)) << "connect " << attempt << ": " << text(s.linkErrors);
            std::printf("[ info ] seed %llu: connect %d took %lld ms\n", static_cast<unsigned long long>(seed), attempt,
                        static_cast<long long>(took.elapsed()));
            if (attempt < 2)
                s.client.disconnectLink();
        }
        const int x = s.axis('X');
        const double start = s.link.machine().commandedLogical(x);
        for (int i = 0; i < 4; ++i) {
            const auto err = s.call([&](auto cb) { s.client.jogStep(x, 0.5, 0, cb); }, 8000);
            ASSERT_FALSE(err) << i << ": " << motion::msg::debugString(err->message);
            ASSERT_TRUE(waitFor([&] { return !machineMoving(s.link.machine()); }, 5000));
        }
        // The simulator's record: four steps of 0.5 mm, each executed once.
        EXPECT_NEAR(s.link.machine().commandedLogical(x) - start, 2.0, 1e-6);
        EXPECT_EQ(s.client.state(), LinkState::Ready) << text(s.linkErrors);
        EXPECT_TRUE(s.linkErrors.isEmpty()) << text(s.linkErrors);
        const auto& counts = s.link.pair().faultCounts(LoopbackPair::B);
        EXPECT_GT(counts.corruptedBytes + counts.droppedBytes + counts.duplicatedBytes, 0) << "the line was clean: no test";
        std::printf("[ info ] seed %llu: %llu retransmits, %llu CRC errors, %llu duplicates answered from the cache\n",
                    static_cast<unsigned long long>(seed), static_cast<unsigned long long>(s.client.stats().retransmits),
                    static_cast<unsigned long long>(s.client.stats().crcErrors),
                    static_cast<unsigned long long>(s.link.host().firmware().duplicateRequests()));
    }
}

TEST(LinkPatience, TheReplyTimeoutFollowsTheMeasuredRoundTrip)
{
    SimSession s(dev::proto::DeviceKind::Stage);
    EXPECT_EQ(s.client.replyTimeoutMs(), dev::BenchPilotClient::kInitialReplyTimeoutMs);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    spin(300);
    const int fast = s.client.replyTimeoutMs();
    EXPECT_GE(fast, dev::BenchPilotClient::kMinReplyTimeoutMs);
    // 150 ms more each way: the timeout grows past the round trip instead of
    // retrying every request before its answer can come.
    LinkFaults slow;
    slow.extraDelayMs = 150;
    s.link.pair().setFaults(LoopbackPair::B, slow);
    spin(3000);
    EXPECT_GT(s.client.replyTimeoutMs(), 150) << "was " << fast;
    EXPECT_LE(s.client.replyTimeoutMs(), dev::BenchPilotClient::kMaxReplyTimeoutMs);
    EXPECT_EQ(s.client.state(), LinkState::Ready) << text(s.linkErrors);
}

TEST(LinkPatience, ADuplicatedEventIsOneEvent)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    LinkFaults twice;
    twice.duplicateChunkProbability = 1.0;  // every write of the device arrives twice
    s.link.pair().setFaults(LoopbackPair::B, twice);
    const int x = s.axis('X');
    const std::size_t mark = s.events.size();
    const double start = s.link.machine().commandedLogical(x);
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 1.0}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    spin(300);
    EXPECT_EQ(s.countEvents(K::MotionDone, x, mark), 1);
    EXPECT_GT(s.client.duplicateFrames(), 0u);
    EXPECT_EQ(s.client.stats().lostSamples, 0u) << "a repeated telemetry batch is not a gap either";
    EXPECT_NEAR(s.link.machine().commandedLogical(x) - start, 1.0, 1e-6);
}

TEST(LinkPatience, AScanWhoseMotionDoneEventsAreAllLostStillTakesEveryTile)
{
    SimSession s(dev::proto::DeviceKind::Stage, kUnpaced);
    ASSERT_TRUE(s.connect() && s.homeAll()) << text(s.linkErrors);
    s.link.host().setTimeScale(10);
    LinkFaults noEvents;
    noEvents.filter = withoutEvents;
    s.link.pair().setFaults(LoopbackPair::B, noEvents);

    motion::scan::ScanPlan p;
    p.name = "no-events";
    p.region.cornerA = {40, 60};
    p.region.cornerB = {41.8, 61.8};
    p.camera.source = motion::scan::FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.0;
    p.camera.samplePixelUm = 0.5;
    p.overlapX = p.overlapY = 0.1;
    p.speedMmS = 10;
    p.settleS = 0.03;
    p.exposureS = 0.02;
    QTemporaryDir dir;
    dev::jobs::ScanRunner runner(&s.client);
    std::vector<int> triggered;
    QObject::connect(&runner, &dev::jobs::ScanRunner::triggered, &runner, [&](int tile, quint64) { triggered.push_back(tile); });
    motion::msg::Message error;
    ASSERT_TRUE(runner.prepare(p, dir.path(), false, &error)) << error;
    ASSERT_TRUE(runner.start(&error)) << error;
    ASSERT_TRUE(waitFor([&] { return !runner.isActive(); }, 30000));
    EXPECT_EQ(runner.state(), dev::jobs::ScanRunner::State::Finished);
    for (const auto& rec : runner.records())
        EXPECT_TRUE(rec.measured()) << rec.label;
    EXPECT_EQ(s.countEvents(K::MotionDone, SimSession::kAnyAxis), 0) << "the filter let events through: no test";
    std::vector<int> sorted = triggered;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a tile taken twice";
    EXPECT_EQ(static_cast<int>(sorted.size()), runner.totalTiles());
    EXPECT_GT(s.link.pair().faultCounts(LoopbackPair::B).filteredWrites, 0);
}

TEST(LinkPatience, AStoppedPatternRunReportsHowLongItRan)
{
    SimSession s(dev::proto::DeviceKind::Stage, kUnpaced);
    dev::jobs::PatternRunner runner(&s.client);
    QObject::connect(&s.client, &dev::BenchPilotClient::telemetryReceived, &runner,
                     [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, s.client, b); });
    ASSERT_TRUE(s.connect() && s.homeAll()) << text(s.linkErrors);
    s.link.host().setTimeScale(4);
    bool limits = false;
    s.client.paths()->refreshLimits([&](const auto&) { limits = true; });
    ASSERT_TRUE(waitFor([&] { return limits; }, 3000));
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Spiral;
    pat.feedMmS = 4;
    ASSERT_TRUE(runner.start(motion::plans::plan(pat), {}));
    ASSERT_TRUE(waitFor([&] { return runner.state() == dev::jobs::PatternRunner::State::Running && runner.segmentsDone() >= 3; }, 20000));
    const double runningFromS = s.link.machine().timeS();
    spin(300);
    s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return runner.state() == dev::jobs::PatternRunner::State::Interrupted; }, 5000));
    const auto sum = runner.summary();
    EXPECT_FALSE(sum.complete);
    // It ran at least from three segments in to the cable pull (300 ms of wall time at 4×).
    EXPECT_GT(sum.durationS, 0.5) << "a stopped run reported " << sum.durationS << " s";
    EXPECT_LT(sum.durationS, s.link.machine().timeS() - runningFromS + 60);
}
