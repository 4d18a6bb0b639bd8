// Bad lines and bad devices, through the client and the in-process simulator:
// garbage, corrupted and lost frames, a silent device, a pulled cable, a port
// that does not exist. What the operator must see: errors that say what
// happened, a link that recovers by itself where it can, and a machine that
// never does a request twice.
#include "device/link/loopback.h"
#include "device/link/serial_transport.h"
#include "sim_session.h"

#include <QElapsedTimer>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <thread>

using namespace itest;
using K = dev::proto::EventKind;
using dev::LinkFaults;
using dev::LinkState;
using dev::LoopbackPair;
using dev::RequestError;
using BenchPilotClientLimits = dev::BenchPilotClient;

namespace {

std::string text(const QStringList& l) { return l.join(QStringLiteral(" | ")).toStdString(); }

QByteArray randomBytes(std::mt19937& rng, int n)
{
    QByteArray b(n, '\0');
    std::uniform_int_distribution<int> byte(0, 255);
    for (auto& c : b)
        c = static_cast<char>(byte(rng));
    return b;
}

qint64 nonZero(const QByteArray& b) { return b.size() - b.count('\0'); }

LinkFaults corruptEveryByte()
{
    LinkFaults f;
    f.corruptByteProbability = 1.0;
    f.seed = 7;
    return f;
}

LinkFaults dropEverything()
{
    LinkFaults f;
    f.dropChunkProbability = 1.0;
    f.seed = 11;
    return f;
}

} // namespace

TEST(LinkFaults, GarbageFromTheDeviceIsCountedAndSkippedWithoutReconnecting)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    QSignalSpy states(&s.client, &dev::BenchPilotClient::stateChanged);
    const dev::LinkStats before = s.client.stats();

    std::mt19937 rng(20240601);
    qint64 injected = 0;
    for (int burst = 0; burst < 6; ++burst) {
        const QByteArray junk = randomBytes(rng, 200 + 100 * burst);
        injected += nonZero(junk);
        s.link.pair().inject(LoopbackPair::B, junk);
        spin(30);
    }
    // A run longer than any frame may be (the cap is 1024 bytes) is dropped as oversize.
    const QByteArray longRun(3000, '\x55');
    injected += longRun.size();
    s.link.pair().inject(LoopbackPair::B, longRun);
    // About 6 kB at 11.5 kB/s behind whatever the device had queued.
    EXPECT_TRUE(waitFor([&] { return s.client.stats().droppedBytes - before.droppedBytes >= quint64(injected); }, 5000));
    spin(100);

    const dev::LinkStats after = s.client.stats();
    // Garbage is appended between whole frames, so every non-delimiter byte of it
    // and nothing else is dropped; no good frame was damaged.
    EXPECT_EQ(after.droppedBytes - before.droppedBytes, quint64(injected));
    EXPECT_GT(after.malformed + after.crcErrors - before.malformed - before.crcErrors, 0u);
    EXPECT_GE(after.oversize - before.oversize, 1u);
    EXPECT_GT(after.framesIn, before.framesIn) << "good frames keep arriving around the garbage";

    EXPECT_EQ(states.count(), 0) << "the link must ride through garbage without leaving Ready";
    EXPECT_EQ(s.client.state(), LinkState::Ready);
    EXPECT_TRUE(s.linkErrors.isEmpty()) << text(s.linkErrors);

    const int x = s.axis('X');
    const double start = s.link.machine().commandedLogical(x);
    const std::size_t mark = s.events.size();
    const auto err = s.call([&](auto cb) { s.client.move({{x, 1.5}}, true, 0, cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    EXPECT_NEAR(s.link.machine().commandedLogical(x), start + 1.5, 1e-6);
}

TEST(LinkFaults, GarbageToTheDeviceIsCountedThereAndRequestsStillWork)
{
    SimSession s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const dev::proto::DecoderStats before = s.link.host().firmware().decoderStats();
    const auto executedBefore = s.link.host().firmware().executedRequests();

    std::mt19937 rng(99);
    qint64 injected = 0;
    for (int burst = 0; burst < 5; ++burst) {
        const QByteArray junk = randomBytes(rng, 150);
        injected += nonZero(junk);
        s.link.pair().inject(LoopbackPair::A, junk);
        spin(20);
    }
    EXPECT_TRUE(waitFor([&] { return s.link.host().firmware().decoderStats().droppedBytes - before.droppedBytes >= std::uint64_t(injected); }, 5000));
    spin(100);
    const dev::proto::DecoderStats after = s.link.host().firmware().decoderStats();
    EXPECT_EQ(after.droppedBytes - before.droppedBytes, std::uint64_t(injected));
    EXPECT_GT(after.malformed + after.crcErrors - before.malformed - before.crcErrors, 0u);
    EXPECT_GT(s.link.host().firmware().executedRequests(), executedBefore) << "status polls kept being served";
    EXPECT_EQ(s.client.state(), LinkState::Ready);

    const int y = s.axis('Y');
    const double start = s.link.machine().commandedLogical(y);
    const std::size_t mark = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.jogStep(y, 0.25, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, y, mark));
    EXPECT_NEAR(s.link.machine().commandedLogical(y), start + 0.25, 1e-6);
}

TEST(LinkFaults, CorruptedRequestIsNeverExecutedAndItsRetransmissionRunsOnce)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    auto& fw = s.link.host().firmware();

    // Every byte of the first MOVE the client writes gets a bit flipped on the wire;
    // the line is clean again for everything after it, retransmissions included.
    int moveWrites = 0;
    s.tap.beforeWrite = [&](const QByteArray& bytes) {
        if (containsFrame(bytes, dev::proto::MsgType::Move) && moveWrites++ == 0)
            s.link.pair().setFaults(LoopbackPair::A, corruptEveryByte());
    };
    s.tap.afterWrite = [&](const QByteArray&) { s.link.pair().setFaults(LoopbackPair::A, LinkFaults{}); };

    const double start = s.link.machine().commandedLogical(x);
    const auto crcBefore = fw.decoderStats().crcErrors + fw.decoderStats().malformed;
    const auto dupBefore = fw.duplicateRequests();
    const auto retransmitsBefore = s.client.stats().retransmits;
    const std::size_t mark = s.events.size();

    const auto err = s.call([&](auto cb) { s.client.move({{x, 5.0}}, true, 0, cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    EXPECT_GE(moveWrites, 2) << "the client must have sent the move again";
    EXPECT_GE(s.client.stats().retransmits - retransmitsBefore, 1u);
    EXPECT_GT(fw.decoderStats().crcErrors + fw.decoderStats().malformed, crcBefore) << "the device saw the damaged frame";
    EXPECT_EQ(fw.duplicateRequests(), dupBefore) << "the damaged frame was never taken for the request";

    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    ASSERT_TRUE(s.waitStill());
    // Once: +5 mm, not +10 mm.
    EXPECT_NEAR(s.link.machine().commandedLogical(x) - start, 5.0, 1e-6);
    EXPECT_EQ(s.countEvents(K::MotionDone, x, mark), 1);
    EXPECT_EQ(s.client.state(), LinkState::Ready);
}

TEST(LinkFaults, RequestWhoseReplyIsLostIsRetransmittedAndExecutedOnce)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    auto& fw = s.link.host().firmware();

    // From the moment the first MOVE goes out until the device has acted on it,
    // everything the device sends is lost: its reply never reaches the client.
    bool armed = true, replyDropped = false;
    s.tap.beforeWrite = [&](const QByteArray& bytes) {
        if (armed && containsFrame(bytes, dev::proto::MsgType::Move)) {
            armed = false;
            s.link.pair().setFaults(LoopbackPair::B, dropEverything());
        }
    };
    dev::proto::FrameDecoder deviceSide;
    QObject::connect(s.link.pair().end(LoopbackPair::B), &dev::Transport::bytesReceived, &s.client,
                     [&](const QByteArray& bytes) {
                         // Runs after the simulator has read these bytes and written its answer.
                         std::vector<dev::proto::Frame> frames;
                         deviceSide.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                         static_cast<std::size_t>(bytes.size()), frames);
                         for (const auto& f : frames)
                             if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Move) && !replyDropped) {
                                 replyDropped = true;
                                 s.link.pair().setFaults(LoopbackPair::B, LinkFaults{});
                             }
                     });

    const double start = s.link.machine().commandedLogical(x);
    const auto executedBefore = fw.executedRequests();
    const auto dupBefore = fw.duplicateRequests();
    const auto retransmitsBefore = s.client.stats().retransmits;
    const std::size_t mark = s.events.size();

    const auto err = s.call([&](auto cb) { s.client.move({{x, 5.0}}, true, 0, cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    EXPECT_TRUE(replyDropped);
    EXPECT_GE(s.client.stats().retransmits - retransmitsBefore, 1u);
    EXPECT_GE(fw.duplicateRequests() - dupBefore, 1u) << "the device recognised the repeat";
    EXPECT_GE(fw.executedRequests(), executedBefore + 1);

    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    ASSERT_TRUE(s.waitStill());
    EXPECT_NEAR(s.link.machine().commandedLogical(x) - start, 5.0, 1e-6) << "executed once: +5 mm, not +10 mm";
    EXPECT_EQ(s.countEvents(K::MotionDone, x, mark), 1);
    EXPECT_EQ(s.client.state(), LinkState::Ready);
}

TEST(LinkFaults, DeviceThatNeverAnswersGivesALinkErrorAfterTwoSecondsOfSilence)
{
    LoopbackPair pair(itest::kLinkBaud);
    pair.end(LoopbackPair::B)->open();  // a device is there, powered, and mute
    dev::BenchPilotClient client;
    QStringList errors;
    QObject::connect(&client, &dev::BenchPilotClient::linkError, &client, [&](const motion::msg::Message& m) { errors << QString::fromStdString(motion::msg::debugString(m)); });
    client.setTransport(pair.end(LoopbackPair::A));

    QElapsedTimer wall;
    wall.start();
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return !errors.isEmpty(); }, 5000)) << "no error at all";
    const qint64 ms = wall.elapsed();
    std::printf("[ info ] silent device reported after %lld ms\n", static_cast<long long>(ms));
    // docs/protocol.md, "Retries and silence": 2 s of silence, checked every 20 ms.
    EXPECT_GE(ms, BenchPilotClientLimits::kSilenceLimitMs);
    EXPECT_LT(ms, BenchPilotClientLimits::kSilenceLimitMs + 600);
    EXPECT_NE(client.state(), LinkState::Ready);
    EXPECT_TRUE(waitFor([&] { return client.state() == LinkState::Disconnected; }, 1000));
    EXPECT_TRUE(errors.first().startsWith(QStringLiteral("link.no_answer{"))) << errors.first().toStdString();
    client.setTransport(nullptr);
}

TEST(LinkFaults, DeviceThatFallsSilentWhileReadyIsReportedLostAfterTwoSeconds)
{
    SimSession s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const auto timeoutsBefore = s.client.stats().timeouts;
    QElapsedTimer wall;
    wall.start();
    s.link.pair().setFaults(LoopbackPair::B, dropEverything());
    ASSERT_TRUE(waitFor([&] { return s.client.state() == LinkState::Lost; }, 5000));
    const qint64 ms = wall.elapsed();
    std::printf("[ info ] device silent while Ready: link lost after %lld ms\n", static_cast<long long>(ms));
    // Silent for more than 2 s while a request waits (the request in flight may have
    // gone out up to a status period after the line went quiet).
    EXPECT_GE(ms, BenchPilotClientLimits::kSilenceLimitMs);
    EXPECT_LT(ms, BenchPilotClientLimits::kSilenceLimitMs + 600);
    EXPECT_GT(s.client.stats().retransmits, 0u) << "the waiting request was retried meanwhile";
    EXPECT_EQ(s.client.stats().timeouts - timeoutsBefore, 1u);
    ASSERT_FALSE(s.linkErrors.isEmpty());
    EXPECT_EQ(s.linkMessages.back().id, "link.lost") << text(s.linkErrors);
    EXPECT_EQ(motion::msg::nested(s.linkMessages.back(), "cause").id, "link.stopped_answering") << text(s.linkErrors);

    // The line comes back: reconnecting works without restarting anything.
    s.link.pair().setFaults(LoopbackPair::B, LinkFaults{});
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
}

TEST(LinkFaults, OneUnansweredRequestFromADeviceThatIsStillTalkingIsNotLinkLoss)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    // One STATUS request vanishes on the way out, every attempt of it; telemetry
    // keeps arriving meanwhile, so after 5 s the request alone is given up and
    // later requests go through.
    int lostSeq = -1;
    s.tap.beforeWrite = [&](const QByteArray& bytes) {
        for (const auto& f : framesIn(bytes))
            if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Status) && (lostSeq < 0 || lostSeq == f.seq)) {
                lostSeq = f.seq;
                s.link.pair().setFaults(LoopbackPair::A, dropEverything());
            }
    };
    s.tap.afterWrite = [&](const QByteArray&) { s.link.pair().setFaults(LoopbackPair::A, LinkFaults{}); };
    const auto timeoutsBefore = s.client.stats().timeouts;
    ASSERT_TRUE(waitFor([&] { return s.client.stats().timeouts > timeoutsBefore; }, BenchPilotClientLimits::kRequestGiveUpMs + 3000));
    const int statusesAfterTimeout = s.statusCount;
    spin(1200);
    EXPECT_EQ(s.client.state(), dev::LinkState::Ready) << text(s.linkErrors);
    EXPECT_TRUE(s.linkErrors.isEmpty()) << text(s.linkErrors);
    EXPECT_GT(s.statusCount, statusesAfterTimeout) << "status polls resumed";
}

TEST(LinkFaults, UnplugDuringMoveIsLinkLostAndReplugReconnects)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    const double start = s.link.machine().commandedLogical(x);
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 40.0}}, true, 0, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.link.machine().commandedLogical(x) > start + 2.0; }, 5000));

    QSignalSpy states(&s.client, &dev::BenchPilotClient::stateChanged);
    s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return s.client.state() == LinkState::Lost; }, 2000));
    ASSERT_FALSE(s.linkErrors.isEmpty());
    EXPECT_EQ(s.linkMessages.back().id, "link.lost") << text(s.linkErrors);
    EXPECT_EQ(motion::msg::nested(s.linkMessages.back(), "cause").id, "link.cable_pulled") << text(s.linkErrors);
    // Requests while lost fail at once with a reason instead of hanging.
    const auto refused = s.call([&](auto cb) { s.client.move({{x, 1.0}}, true, 0, cb); }, 1000);
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->kind, RequestError::Kind::LinkDown);

    // Reconnecting with the cable still out fails cleanly.
    const int errorsBefore = s.linkErrors.size();
    s.client.connectLink();
    ASSERT_TRUE(waitFor([&] { return s.linkErrors.size() > errorsBefore; }, 2000));
    EXPECT_TRUE(waitFor([&] { return s.client.state() == LinkState::Disconnected; }, 1000));

    // Cable back in: the same client connects again and the machine answers.
    s.link.pair().replug();
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const double now = s.link.machine().commandedLogical(x);
    EXPECT_GT(now, start + 2.0);
    ASSERT_TRUE(waitFor([&] { return s.statusCount > 0 && std::abs(s.readout('X').commanded - s.link.machine().commandedLogical(x)) < 1.0; }, 3000));
    ASSERT_TRUE(s.waitStill());
    const std::size_t mark = s.events.size();
    const double before = s.link.machine().commandedLogical(x);
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 1.0}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    EXPECT_NEAR(s.link.machine().commandedLogical(x), before + 1.0, 1e-6);
}

TEST(LinkFaults, SerialPortThatDoesNotExistFailsAtOnceWithAClearMessage)
{
    dev::SerialTransport port(QStringLiteral("/dev/ttyBP_nonexistent"), 115200);
    dev::BenchPilotClient client;
    QStringList errors;
    QObject::connect(&client, &dev::BenchPilotClient::linkError, &client, [&](const motion::msg::Message& m) { errors << QString::fromStdString(motion::msg::debugString(m)); });
    QSignalSpy failed(&port, &dev::Transport::failed);
    client.setTransport(&port);

    QElapsedTimer wall;
    wall.start();
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return !errors.isEmpty(); }, 3000));
    EXPECT_LT(wall.elapsed(), 1000);
    EXPECT_EQ(failed.count(), 1);
    EXPECT_EQ(client.state(), LinkState::Disconnected);
    EXPECT_TRUE(errors.first().contains(QStringLiteral("/dev/ttyBP_nonexistent"))) << errors.first().toStdString();
    EXPECT_TRUE(errors.first().startsWith(QStringLiteral("link.no_such_port{"))) << errors.first().toStdString();
    EXPECT_FALSE(port.isOpen());
    client.setTransport(nullptr);
}

TEST(LinkFaults, ASecondSessionSeesTheDeviceAsItIsNotAsTheLastSessionLeftIt)
{
    // Two sessions one after the other on the same device (a CLI run, then the
    // GUI): the second's first status must show where the machine is now.
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    const double start = s.readout('X').commanded;
    const std::size_t mark = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 3.0}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    s.client.disconnectLink();

    dev::BenchPilotClient second;
    second.setTransport(&s.tap);
    second.connectLink();
    ASSERT_TRUE(waitFor([&] { return second.state() == LinkState::Ready; }, 5000));
    EXPECT_NEAR(second.status().axes[x].commanded, start + 3.0, 1e-6)
        << "the first status of a new session came from an old one";
    second.setTransport(nullptr);
}

// A busy GUI thread holds up the event loop with a request on the wire: its answer (and
// the in-process simulator itself) waits in the queue behind the client's timeout check.
// Before, the check resent the request after a short hold-up and, after one longer than
// the silence limit, declared a device that had answered all along silent.
TEST(LinkFaults, AnEventLoopHeldUpResendsNothingAndKeepsTheLink)
{
    // Unpaced: on a paced loopback the in-process device, held up with the host, sends the
    // telemetry of the held-up time only afterwards and its reply queues behind it, where
    // a real device's would have been in the port's buffer already.
    SimSession s(dev::proto::DeviceKind::Analyzer, kUnpaced);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    waitFor([] { return false; }, 300);  // the round trip measured, the timeout near its floor
    const auto before = s.client.stats();
    for (int heldMs : {300, 2500}) {
        // The status request written just before the hold-up, and any write of it again
        // (a retransmission keeps its sequence number).
        std::optional<std::uint16_t> heldSeq;
        int again = 0;
        s.tap.afterWrite = [&](const QByteArray& bytes) {
            for (const auto& f : framesIn(bytes)) {
                if (f.type != static_cast<std::uint8_t>(dev::proto::MsgType::Status))
                    continue;
                if (!heldSeq) {
                    heldSeq = f.seq;
                    std::this_thread::sleep_for(std::chrono::milliseconds(heldMs));
                } else if (f.seq == *heldSeq) {
                    ++again;
                }
            }
        };
        ASSERT_TRUE(waitFor([&] { return heldSeq.has_value(); }, 2000));
        waitFor([] { return false; }, 200);
        s.tap.afterWrite = nullptr;
        EXPECT_EQ(again, 0) << heldMs << " ms: the request answered during the hold-up was sent again";
        EXPECT_EQ(s.client.state(), LinkState::Ready) << heldMs << " ms: " << text(s.linkErrors);
    }
    EXPECT_EQ(s.client.stats().timeouts, before.timeouts);
    EXPECT_GE(s.client.stats().stalls, before.stalls + 2) << "both hold-ups were seen";
}
