// dev::tele::TelemetryHub: what the plots and the recorder get from the instruments.
// Against the in-process simulator on a manual clock (deterministic, fast): batches
// land in the stores at the device's times and in the units the axes show, a rate
// the link cannot carry falls back to the capacity the device states, the union of
// every consumer's wants is what is subscribed, again after a reconnect. With
// hand-made batches: losses, the window, pause, recording to CSV.
#include "qt_event_loop.h"
#include "device/english_words.h"
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/telemetry_hub.h"

#include <QRegularExpression>

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <cmath>
#include <functional>
#include <vector>

namespace {

using dev::proto::ChannelKind;
using dev::proto::ChannelRef;
using dev::tele::ChannelKey;
using dev::tele::TelemetryHub;

using devtest::ensureApp;
using devtest::waitFor;

void spin(int ms) { waitFor([] { return false; }, ms); }

ChannelRef ref(int axis, ChannelKind k) { return ChannelRef{static_cast<std::uint8_t>(axis), k}; }

/// A client on the simulator over an unpaced loopback; the device's clock moves only in run().
struct SimRig {
    explicit SimRig(dev::proto::DeviceKind kind, std::uint32_t deviceBaud = 921600, int instrument = 1,
                    const QString& name = QStringLiteral("Stage"))
        : link(kind, 0), index(instrument)
    {
        link.host().setManualClock(true);
        link.host().firmware().setLinkBaud(deviceBaud);
        client.setTransport(link.hostEnd());
        QObject::connect(&client, &dev::BenchPilotClient::telemetryReceived, &client,
                         [this](const dev::proto::TelemetryBatch& b) { batches.push_back(b); });
        QObject::connect(&client, &dev::BenchPilotClient::requestFailed, &client,
                         [this](const dev::RequestError& e) { failures.push_back(e); });
        QObject::connect(&hub, &TelemetryHub::subscriptionChanged, &hub, [this](int i, int rate, const motion::msg::Message& message) {
            const QString note = QString::fromStdString(message.empty() ? std::string() : motion::msg::debugString(message));
            changes.push_back({i, rate, note, message});
        });
        QObject::connect(&hub, &TelemetryHub::problem, &hub, [this](const motion::msg::Message& m) { problems << QString::fromStdString(motion::msg::debugString(m)); });
        hub.addInstrument(index, name, &client);
    }
    ~SimRig() { client.setTransport(nullptr); }

    bool connect()
    {
        client.connectLink();
        return waitFor([this] { return client.isReady(); });
    }
    /// Moves the device clock by `seconds` in 10 ms steps, delivering what it sends.
    void run(double seconds)
    {
        const int steps = static_cast<int>(std::lround(seconds / 0.01));
        for (int k = 0; k < steps; ++k) {
            link.host().advance(0.01);
            QCoreApplication::processEvents();
        }
        spin(20);
    }
    ChannelKey key(int axis, ChannelKind k) const { return ChannelKey{index, ref(axis, k)}; }
    bool waitRate(int minRate = 1)
    {
        return waitFor([&] { return !changes.empty() && changes.back().rate >= minRate; });
    }

    struct Change {
        int instrument, rate;
        QString note;
        motion::msg::Message message;
    };
    dev::SimulatedLink link;
    dev::BenchPilotClient client;
    TelemetryHub hub;
    int index;
    std::vector<dev::proto::TelemetryBatch> batches;
    std::vector<dev::RequestError> failures;
    std::vector<Change> changes;
    QStringList problems;
};

/// A hub fed by hand: batches emitted as if a client had decoded them.
struct FakeRig {
    FakeRig()
    {
        hub.addInstrument(0, QStringLiteral("Analyzer"), &analyzer);
        hub.addInstrument(1, QStringLiteral("Stage"), &stage);
        QObject::connect(&hub, &TelemetryHub::dataArrived, &hub, [this](int i) { arrived.push_back(i); });
        QObject::connect(&hub, &TelemetryHub::problem, &hub, [this](const motion::msg::Message& m) { problems << QString::fromStdString(motion::msg::debugString(m)); });
    }
    /// n samples of `channels` from sample index `first`, value = f(sample index, channel).
    static dev::proto::TelemetryBatch batch(std::uint32_t first, std::uint64_t t0Us, std::uint32_t periodUs,
                                       const std::vector<ChannelRef>& channels, int n,
                                       const std::function<std::int32_t(std::uint32_t, std::size_t)>& f)
    {
        dev::proto::TelemetryBatch b;
        b.firstSampleIndex = first;
        b.firstSampleTimeUs = t0Us;
        b.periodUs = periodUs;
        b.channels = channels;
        b.sampleCount = static_cast<std::uint16_t>(n);
        for (int k = 0; k < n; ++k)
            for (std::size_t c = 0; c < channels.size(); ++c)
                b.values.push_back(f(first + static_cast<std::uint32_t>(k), c));
        return b;
    }
    /// `seconds` of 1 kHz stage telemetry (X measured) from device time `fromS`, in 100-sample batches.
    void feedStage(double fromS, double seconds)
    {
        const auto startUs = static_cast<std::uint64_t>(std::llround(fromS * 1e6));
        const int batches = static_cast<int>(std::lround(seconds * 10));
        for (int b = 0; b < batches; ++b) {
            emit stage.telemetryReceived(batch(nextIndex, startUs + std::uint64_t(b) * 100000, 1000,
                                               {ref(0, ChannelKind::Measured)}, 100,
                                               [](std::uint32_t i, std::size_t) { return std::int32_t(i); }));
            nextIndex += 100;
        }
    }
    dev::BenchPilotClient analyzer, stage;
    TelemetryHub hub;
    std::uint32_t nextIndex = 0;
    std::vector<int> arrived;
    QStringList problems;
    const ChannelKey stageX{1, ref(0, ChannelKind::Measured)};
};

class TelemetryHubTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { ensureApp(); }
};

/// Every CSV line split at commas (the recorder quotes nothing in these tests).
std::vector<QList<QByteArray>> readCsv(const QString& path)
{
    QFile f(path);
    std::vector<QList<QByteArray>> rows;
    if (!f.open(QIODevice::ReadOnly))
        return rows;
    while (!f.atEnd()) {
        QByteArray line = f.readLine();
        if (line.endsWith('\n'))
            line.chop(1);
        rows.push_back(line.split(','));
    }
    return rows;
}

// ---- against the simulator ----------------------------------------------------------

TEST_F(TelemetryHubTest, StoresHoldTheDevicesSamplesAtItsTimesInAxisUnits)
{
    SimRig s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect());
    const int x = s.client.identity().axisIndex(QLatin1Char('X'));
    const ChannelKey measured = s.key(x, ChannelKind::Measured), error = s.key(x, ChannelKind::FollowingError);
    const ChannelKey contour{s.index, ref(dev::proto::kNoAxis, ChannelKind::ContourError)};
    EXPECT_EQ(s.hub.channelName(measured), QStringLiteral("Stage X measured"));
    EXPECT_EQ(s.hub.channelUnit(measured), QStringLiteral("mm"));
    EXPECT_EQ(s.hub.channelUnit(error), QStringLiteral("µm"));
    EXPECT_EQ(s.hub.channelUnit(s.key(x, ChannelKind::Velocity)), QStringLiteral("mm/s"));
    EXPECT_EQ(s.hub.channelUnit(s.key(x, ChannelKind::ControllerOutput)), QStringLiteral("steps/s"));
    EXPECT_EQ(s.hub.channelName(contour), QStringLiteral("Stage contour error"));
    EXPECT_EQ(s.hub.channelUnit(contour), QStringLiteral("µm"));
    const auto available = s.hub.availableChannels(s.index);
    EXPECT_EQ(available.size(), 2 * 7 + 1);  // X and Y with PID output and controller output u, plus contour error
    EXPECT_TRUE(available.contains(contour));

    s.hub.setWanted(QStringLiteral("plot"), {measured, error, contour}, 1000);
    ASSERT_TRUE(s.waitRate());
    EXPECT_EQ(s.changes.back().rate, 1000);
    EXPECT_TRUE(s.changes.back().note.isEmpty()) << s.changes.back().note.toStdString();
    EXPECT_EQ(s.client.subscribedRateHz(), 1000);
    EXPECT_EQ(s.client.subscribedChannels().size(), 3);
    s.batches.clear();
    s.client.jogStep(x, 2.0, 20.0);  // something worth plotting: a 2 mm step
    s.run(0.5);

    std::size_t checked = 0;
    for (const auto& b : s.batches) {
        ASSERT_EQ(b.channels.size(), 3u);
        for (std::size_t c = 0; c < 3; ++c) {
            const ChannelKey key{s.index, b.channels[c]};
            const dev::tele::ChannelStore* store = s.hub.store(key);
            ASSERT_NE(store, nullptr);
            const double factor = key == measured ? 1.0 : 1000.0;  // mm; µm
            for (std::size_t k = 0; k < b.sampleCount; ++k) {
                const double t = double(b.firstSampleTimeUs + k * b.periodUs) * 1e-6;
                const std::size_t i = store->lowerBound(t - 1e-7);
                ASSERT_LT(i, store->size());
                EXPECT_NEAR(store->at(i).tS, t, 1e-9);
                EXPECT_EQ(store->at(i).value,
                          static_cast<float>(s.client.toAxisUnits(b.channels[c], b.values[k * 3 + c]) * factor));
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 3u * 450);
    const dev::tele::ChannelStore* m = s.hub.store(measured);
    EXPECT_GT(m->at(m->size() - 1).value - m->at(0).value, 1.0f) << "the jog step shows in the measured position";
    const auto& last = s.batches.back();
    EXPECT_DOUBLE_EQ(s.hub.latestTimeS(s.index), double(last.firstSampleTimeUs + (last.sampleCount - 1u) * last.periodUs) * 1e-6);
    EXPECT_EQ(s.hub.lostSamples(s.index), 0u);
    EXPECT_GE(s.hub.samplesReceived(s.index), 450u);
    EXPECT_EQ(s.hub.store(s.key(x, ChannelKind::Velocity)), nullptr) << "nobody wants it";
}

TEST_F(TelemetryHubTest, AnalyzerOffersNoPidChannelsAndPumpUnits)
{
    SimRig s(dev::proto::DeviceKind::Analyzer, 921600, 0, QStringLiteral("Analyzer"));
    ASSERT_TRUE(s.connect());
    const auto available = s.hub.availableChannels(0);
    EXPECT_EQ(available.size(), 4 * 5);
    for (const auto& k : available) {
        EXPECT_NE(k.ref.kind, ChannelKind::ControllerOutput);
        EXPECT_NE(k.ref.kind, ChannelKind::ContourError);
    }
    const int p = s.client.identity().axisIndex(QLatin1Char('P'));
    ASSERT_GE(p, 0);
    EXPECT_EQ(s.hub.channelName(s.key(p, ChannelKind::Commanded)), QStringLiteral("Analyzer P commanded"));
    EXPECT_EQ(s.hub.channelUnit(s.key(p, ChannelKind::Commanded)), QStringLiteral("µL"));
    EXPECT_EQ(s.hub.channelUnit(s.key(p, ChannelKind::FollowingError)), QStringLiteral("nL"));
}

TEST_F(TelemetryHubTest, RateAboveTheLinksCapacityFallsBackToTheCapacityTheDeviceStates)
{
    SimRig s(dev::proto::DeviceKind::Stage, 115200);
    ASSERT_TRUE(s.connect());
    const QVector<ChannelKey> xy{s.key(0, ChannelKind::Commanded), s.key(0, ChannelKind::Measured),
                                 s.key(1, ChannelKind::Commanded), s.key(1, ChannelKind::Measured)};
    s.hub.setWanted(QStringLiteral("plot"), xy, 10000);
    ASSERT_TRUE(s.waitRate());
    const int rate = s.changes.back().rate;
    EXPECT_LT(rate, 10000);
    EXPECT_GT(rate, 100);
    EXPECT_EQ(s.client.subscribedRateHz(), rate);
    EXPECT_EQ(s.hub.subscribedRateHz(s.index), rate);
    // The device refused with its capacity, and the hub says so.
    // The client leaves the refusal to the hub (no error banner for a handled
    // fallback); the hub's note carries the capacity the device stated.
    int stated = 0;
    for (const auto& f : s.failures)
        EXPECT_NE(f.code, dev::proto::ErrorCode::OverCapacity) << "a handled fallback was reported as a failure";
    const motion::msg::Message& why = s.changes.back().message;
    EXPECT_EQ(why.id, "telemetry.rate_link_limited") << s.changes.back().note.toStdString();
    stated = static_cast<int>(why.number("max"));
    ASSERT_GT(stated, 0) << "the device refused 10 kHz and stated its capacity";
    // The fastest rate the link carries, not one sample-clock tick slower.
    // (the device states whole Hz rounded up, 589 for its 588.2 Hz period).
    EXPECT_GE(rate, stated - 1);
    EXPECT_LE(rate, stated + 1);
    EXPECT_EQ(why.number("baud"), 115200);
    EXPECT_EQ(why.number("rate"), rate);

    // What the device then sends fits the wire and nothing is lost.
    const qint64 before = s.link.pair().bytesCarried(dev::LoopbackPair::B);
    const quint64 received0 = s.hub.samplesReceived(s.index);
    s.run(2.0);
    const double bytesPerS = double(s.link.pair().bytesCarried(dev::LoopbackPair::B) - before) / 2.0;
    EXPECT_LE(bytesPerS, 115200 / 10.0);
    EXPECT_NEAR(double(s.hub.samplesReceived(s.index) - received0), 2.0 * rate, rate * 0.1 + 64);
    EXPECT_EQ(s.hub.lostSamples(s.index), 0u);
}

TEST_F(TelemetryHubTest, SubscribesTheUnionOfAllConsumersAtTheHighestRate)
{
    SimRig s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect());
    // Nobody wants anything yet: the hub switched the client's default stream off.
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 0; }));
    s.hub.setWanted(QStringLiteral("jog strip"), {s.key(0, ChannelKind::Measured)}, 0);  // default rate
    s.hub.setWanted(QStringLiteral("plot"), {s.key(1, ChannelKind::Measured), s.key(0, ChannelKind::Measured)}, 500);
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 500; }));
    EXPECT_EQ(s.client.subscribedChannels(),
              (QVector<ChannelRef>{ref(0, ChannelKind::Measured), ref(1, ChannelKind::Measured)}));
    s.run(0.1);
    EXPECT_NE(s.hub.store(s.key(1, ChannelKind::Measured)), nullptr);

    s.hub.setWanted(QStringLiteral("plot"), {}, 0);  // the plot goes away: back to the strip's wish
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == TelemetryHub::kDefaultRateHz; }));
    EXPECT_EQ(s.client.subscribedChannels(), (QVector<ChannelRef>{ref(0, ChannelKind::Measured)}));
    EXPECT_EQ(s.hub.store(s.key(1, ChannelKind::Measured)), nullptr);
    EXPECT_NE(s.hub.store(s.key(0, ChannelKind::Measured)), nullptr);
    s.hub.setWanted(QStringLiteral("jog strip"), {}, 0);
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 0; }));
    EXPECT_EQ(s.changes.back().rate, 0);
}

TEST_F(TelemetryHubTest, ResubscribesAfterTheLinkComesBack)
{
    SimRig s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect());
    s.hub.setWanted(QStringLiteral("plot"), {s.key(0, ChannelKind::Measured), s.key(0, ChannelKind::FollowingError)}, 2000);
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 2000; }));
    s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return s.client.state() == dev::LinkState::Lost; }));
    EXPECT_EQ(s.hub.subscribedRateHz(s.index), 0);
    EXPECT_EQ(s.changes.back().rate, 0);
    s.link.pair().replug();
    s.link.pair().end(dev::LoopbackPair::B)->open();
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 2000; }));
    EXPECT_EQ(s.client.subscribedChannels(),
              (QVector<ChannelRef>{ref(0, ChannelKind::Measured), ref(0, ChannelKind::FollowingError)}));
    s.run(0.2);
    EXPECT_EQ(s.hub.lostSamples(s.index), 0u);
    EXPECT_GE(s.hub.store(s.key(0, ChannelKind::Measured))->size(), 300u);
}

TEST_F(TelemetryHubTest, RecordsTheDevicesSamplesToCsvAndReadsBack)
{
    SimRig s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("x.csv"));
    const QVector<ChannelKey> columns{s.key(0, ChannelKind::Measured), s.key(0, ChannelKind::FollowingError),
                                      s.key(0, ChannelKind::Switches)};
    motion::msg::Message error;
    ASSERT_TRUE(s.hub.startRecording(path, columns, &error)) << error;
    EXPECT_TRUE(s.hub.recording());
    EXPECT_EQ(s.hub.recordingPath(), path);
    // Recording alone collects its channels, at the default rate.
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == TelemetryHub::kDefaultRateHz; }));
    s.batches.clear();
    s.client.jogStep(0, 1.0, 10.0);
    s.run(1.0);
    s.hub.stopRecording();
    EXPECT_FALSE(s.hub.recording());

    const auto rows = readCsv(path);
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows[0], (QList<QByteArray>{"time_s", "instrument", "Stage X measured [mm]",
                                          QStringLiteral("Stage X following error [µm]").toUtf8(), "Stage X switches"}));
    std::size_t expected = 0;
    for (const auto& b : s.batches)
        expected += b.sampleCount;
    ASSERT_EQ(rows.size(), expected + 1);
    std::size_t r = 1;
    for (const auto& b : s.batches) {
        for (std::size_t k = 0; k < b.sampleCount; ++k, ++r) {
            const auto& row = rows[r];
            ASSERT_EQ(row.size(), 5);
            EXPECT_DOUBLE_EQ(row[0].toDouble(), double(b.firstSampleTimeUs + k * b.periodUs) * 1e-6);
            EXPECT_EQ(row[1], "Stage");
            for (std::size_t c = 0; c < 3; ++c) {
                const double factor = c == 1 ? 1000.0 : 1.0;
                EXPECT_EQ(row[int(c) + 2].toDouble(), s.client.toAxisUnits(b.channels[c], b.values[k * 3 + c]) * factor)
                    << "row " << r << " column " << c;
            }
        }
    }
    ASSERT_TRUE(waitFor([&] { return s.client.subscribedRateHz() == 0; })) << "recording over: nobody wants the channels";
}

// ---- with hand-made batches ---------------------------------------------------------------

TEST_F(TelemetryHubTest, GapsInTheSampleCounterAreCountedAsLost)
{
    FakeRig f;
    f.hub.setWanted(QStringLiteral("plot"), {f.stageX}, 1000);
    auto value = [](std::uint32_t i, std::size_t) { return std::int32_t(i); };
    const std::vector<ChannelRef> x{ref(0, ChannelKind::Measured)};
    emit f.stage.telemetryReceived(FakeRig::batch(0, 1'000'000, 1000, x, 10, value));
    emit f.stage.telemetryReceived(FakeRig::batch(10, 1'010'000, 1000, x, 10, value));
    emit f.stage.telemetryReceived(FakeRig::batch(25, 1'025'000, 1000, x, 10, value));  // 5 never arrived
    emit f.stage.telemetryReceived(FakeRig::batch(35, 1'035'000, 1000, x, 10, value));
    EXPECT_EQ(f.hub.lostSamples(1), 5u);
    EXPECT_EQ(f.hub.samplesReceived(1), 40u);
    EXPECT_EQ(f.hub.lostSamples(0), 0u);
    const dev::tele::ChannelStore* st = f.hub.store(f.stageX);
    ASSERT_NE(st, nullptr);
    EXPECT_EQ(st->size(), 40u);
    // The hole stays a hole: nothing is invented between 1.019 s and 1.025 s.
    EXPECT_EQ(st->lowerBound(1.0195), 20u);
    EXPECT_DOUBLE_EQ(st->at(20).tS, 1.025);
    EXPECT_EQ(st->at(20).value, 25.0f);  // no identity: wire units pass through
}

TEST_F(TelemetryHubTest, DataArrivedOncePerEventLoopTurn)
{
    FakeRig f;
    f.hub.setWanted(QStringLiteral("plot"), {f.stageX}, 1000);
    f.feedStage(0, 0.5);  // five batches in one turn
    EXPECT_TRUE(f.arrived.empty()) << "never from inside the batch handler";
    spin(10);
    EXPECT_EQ(f.arrived, std::vector<int>{1});
}

TEST_F(TelemetryHubTest, WindowKeepsTheNewestWindowOnly)
{
    FakeRig f;
    f.hub.setWindowS(1.0);
    f.hub.setWanted(QStringLiteral("plot"), {f.stageX}, 1000);
    f.feedStage(10, 3.0);
    const dev::tele::ChannelStore* st = f.hub.store(f.stageX);
    ASSERT_NE(st, nullptr);
    EXPECT_DOUBLE_EQ(f.hub.latestTimeS(1), 12.999);
    EXPECT_NEAR(st->firstTime(), 11.999, 1e-9);
    EXPECT_DOUBLE_EQ(st->lastTime(), 12.999);
    EXPECT_EQ(st->size(), 1001u);
    EXPECT_LE(st->capacity(), std::size_t(2 * 1000 + 1024 + 1));

    f.hub.setWindowS(0.01);
    EXPECT_EQ(f.hub.windowS(), TelemetryHub::kMinWindowS);
    f.hub.setWindowS(1e6);
    EXPECT_EQ(f.hub.windowS(), TelemetryHub::kMaxWindowS);
    f.hub.setWindowS(2.0);
    f.feedStage(13, 3.0);
    st = f.hub.store(f.stageX);  // may be a new store after the window changed
    EXPECT_NEAR(st->firstTime(), 15.999 - 2.0, 1e-9);
    EXPECT_EQ(st->size(), 2001u);
}

TEST_F(TelemetryHubTest, PauseFreezesTheViewWhileCollectionAndRecordingGoOn)
{
    FakeRig f;
    QTemporaryDir dir;
    motion::msg::Message error;
    ASSERT_TRUE(f.hub.startRecording(dir.filePath(QStringLiteral("p.csv")), {f.stageX}, &error)) << error;
    f.hub.setWindowS(1.0);
    f.hub.setWanted(QStringLiteral("plot"), {f.stageX}, 1000);
    f.feedStage(0, 2.0);
    f.hub.setPaused(true);
    EXPECT_TRUE(f.hub.paused());
    const double pausedAt = f.hub.pausedAtS(1);
    EXPECT_DOUBLE_EQ(pausedAt, 1.999);
    auto frozenSamples = [&] {
        const dev::tele::ChannelStore* st = f.hub.store(f.stageX);
        return st->lowerBound(pausedAt + 1e-9) - st->lowerBound(pausedAt - 1.0 - 1e-9);
    };
    EXPECT_EQ(frozenSamples(), 1001u);

    // Less than a window later: everything is still there, old and new.
    f.feedStage(2.0, 0.8);
    EXPECT_DOUBLE_EQ(f.hub.latestTimeS(1), 2.799);
    EXPECT_DOUBLE_EQ(f.hub.pausedAtS(1), pausedAt);
    EXPECT_EQ(frozenSamples(), 1001u);
    EXPECT_DOUBLE_EQ(f.hub.store(f.stageX)->lastTime(), 2.799);
    EXPECT_EQ(f.hub.heldBackSamples(1), 0u);

    // Much longer: the frozen range is untouched, memory stays bounded, the rest is held back.
    f.feedStage(2.8, 10.0);
    const dev::tele::ChannelStore* st = f.hub.store(f.stageX);
    EXPECT_EQ(frozenSamples(), 1001u);
    EXPECT_NEAR(st->firstTime(), pausedAt - 1.0, 1e-9);
    EXPECT_EQ(st->size(), st->capacity());
    EXPECT_GT(f.hub.heldBackSamples(1), 5000u);
    EXPECT_DOUBLE_EQ(f.hub.latestTimeS(1), 12.799);
    EXPECT_EQ(f.hub.recordedRows(), 12'800u) << "the recording got every sample";

    // A wider window while paused gives room; narrowing it again must not throw the
    // frozen range (the oldest part) away to keep newer samples.
    f.hub.setWindowS(5.0);
    f.feedStage(12.8, 6.0);
    EXPECT_EQ(frozenSamples(), 1001u);
    f.hub.setWindowS(1.0);
    EXPECT_EQ(frozenSamples(), 1001u);
    EXPECT_DOUBLE_EQ(f.hub.store(f.stageX)->lastTime(), 18.799);

    f.hub.setPaused(false);
    EXPECT_TRUE(std::isnan(f.hub.pausedAtS(1)));
    f.feedStage(18.8, 0.5);
    st = f.hub.store(f.stageX);
    EXPECT_NEAR(st->firstTime(), 19.299 - 1.0, 1e-9) << "back to the live window";
    EXPECT_DOUBLE_EQ(st->lastTime(), 19.299);
    EXPECT_LE(st->capacity(), std::size_t(2 * 1000 + 1024 + 1)) << "and its memory";
    f.hub.stopRecording();
}

TEST_F(TelemetryHubTest, ADeviceClockThatStartsAgainContinuesThatInstrumentsTimeLine)
{
    FakeRig f;
    f.hub.setWanted(QStringLiteral("plot"), {f.stageX}, 1000);
    f.feedStage(100, 1.0);
    ASSERT_EQ(f.hub.store(f.stageX)->size(), 1000u);
    f.nextIndex = 0;
    f.feedStage(0.5, 0.2);  // power-cycled device: its clock is back near zero
    // Nothing before the restart is thrown away (the history must tell what happened): the new samples
    // follow the old ones after the gap the host saw.
    const dev::tele::ChannelStore* st = f.hub.store(f.stageX);
    EXPECT_EQ(st->size(), 1200u);
    EXPECT_DOUBLE_EQ(st->at(999).tS, 100.999);
    EXPECT_GT(st->at(1000).tS, 100.999);
    EXPECT_EQ(st->at(1000).value, 0.0f) << "the new stream's first sample";
    EXPECT_NEAR(f.hub.latestTimeS(1) - st->at(1000).tS, 0.199, 1e-9);
    ASSERT_EQ(f.problems.size(), 1);
    EXPECT_TRUE(f.problems[0].contains(QStringLiteral("clock"))) << f.problems[0].toStdString();
}

TEST_F(TelemetryHubTest, RecordingSpansInstrumentsWithOneRowPerDeviceSample)
{
    FakeRig f;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("both.csv"));
    const ChannelKey analyzerZ{0, ref(2, ChannelKind::Commanded)};
    motion::msg::Message error;
    ASSERT_TRUE(f.hub.startRecording(path, {f.stageX, analyzerZ}, &error)) << error;
    const std::vector<ChannelRef> z{ref(2, ChannelKind::Commanded)};
    emit f.analyzer.telemetryReceived(FakeRig::batch(0, 5'000'000, 10'000, z, 2, [](std::uint32_t i, std::size_t) {
        return std::int32_t(-7 - i);
    }));
    f.feedStage(1.0, 0.1);
    f.hub.stopRecording();
    const auto rows = readCsv(path);
    ASSERT_EQ(rows.size(), 1u + 2 + 100);
    EXPECT_EQ(rows[0], (QList<QByteArray>{"time_s", "instrument", "Stage 0 measured [mm]", "Analyzer 2 commanded [mm]"}));
    EXPECT_EQ(rows[1], (QList<QByteArray>{"5.000000", "Analyzer", "", "-7"}));
    EXPECT_EQ(rows[2], (QList<QByteArray>{"5.010000", "Analyzer", "", "-8"}));
    EXPECT_EQ(rows[3], (QList<QByteArray>{"1.000000", "Stage", "0", ""}));
    EXPECT_EQ(rows[102], (QList<QByteArray>{"1.099000", "Stage", "99", ""}));
}

TEST_F(TelemetryHubTest, RecordingRefusesWhatItCannotDoWithAReason)
{
    FakeRig f;
    motion::msg::Message error;
    EXPECT_FALSE(f.hub.startRecording(QStringLiteral("/nonexistent-dir/x.csv"), {f.stageX}, &error));
    EXPECT_TRUE(QString::fromStdString(i18ntest::english(error)).contains(QStringLiteral("/nonexistent-dir/x.csv"))) << error;
    EXPECT_FALSE(f.hub.recording());
    EXPECT_FALSE(f.hub.startRecording(QStringLiteral("/tmp/never.csv"), {}, &error));
    EXPECT_TRUE(QString::fromStdString(i18ntest::english(error)).contains(QStringLiteral("nothing to record"))) << error;
    QTemporaryDir dir;
    ASSERT_TRUE(f.hub.startRecording(dir.filePath(QStringLiteral("a.csv")), {f.stageX}, &error));
    EXPECT_FALSE(f.hub.startRecording(dir.filePath(QStringLiteral("b.csv")), {f.stageX}, &error));
    EXPECT_TRUE(QString::fromStdString(i18ntest::english(error)).contains(QStringLiteral("already recording"))) << error;
}

} // namespace

// Found in the Xvfb session: Disconnect, a few seconds, Connect on the simulator that
// outlives its link, and the status bar said "786 samples lost". Nothing was lost on the
// wire: the link was down while the device's counter ran on, and batches it numbered
// before the reconnect still came in after it (here, the paced wire's queue).
TEST_F(TelemetryHubTest, SamplesTheDeviceTookWhileDisconnectedAreNotCountedAsLost)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Stage, 115200);  // paced, as the GUI's simulator
    dev::BenchPilotClient client;
    client.setTransport(link.hostEnd());
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return client.isReady(); }));
    bool subscribed = false;
    client.subscribe({ref(0, ChannelKind::Measured)}, 500, [&](const auto& e, const auto&) { subscribed = !e; });
    ASSERT_TRUE(waitFor([&] { return subscribed; }));
    spin(300);
    ASSERT_GT(client.stats().telemetrySamples, 50u);
    client.disconnectLink();
    spin(800);
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return client.isReady(); }));
    const quint64 before = client.stats().telemetrySamples;
    spin(300);
    ASSERT_GT(client.stats().telemetrySamples, before) << "no sample came after the reconnect: no test";
    EXPECT_EQ(client.stats().lostSamples, 0u);
    client.setTransport(nullptr);
}
