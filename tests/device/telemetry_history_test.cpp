// The telemetry hub's flight recorder: every instrument's
// positions and following errors from connection on, whether or not anyone wants
// them, in a fixed memory budget (docs/telemetry.md, "History"). The recorder on
// its own (bounded ring, order, thinning), the hub fed by hand (multi-instrument,
// reconnect gap, clock restart, CSV export) and the hub on the simulator (what is
// subscribed when nobody wants anything).
#include "qt_event_loop.h"
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/history_recorder.h"
#include "device/telemetry/telemetry_hub.h"

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
using dev::tele::HistoryBudget;
using dev::tele::HistoryRecorder;
using dev::tele::TelemetryHub;

using devtest::ensureApp;
using devtest::waitFor;

ChannelRef href(int axis, ChannelKind k) { return ChannelRef{static_cast<std::uint8_t>(axis), k}; }

/// `n` samples of `channels` from sample index `first`; value = sample index × 10 + channel.
dev::proto::TelemetryBatch historyBatch(std::uint32_t first, std::uint64_t t0Us, std::uint32_t periodUs,
                                   const std::vector<ChannelRef>& channels, int n)
{
    dev::proto::TelemetryBatch b;
    b.firstSampleIndex = first;
    b.firstSampleTimeUs = t0Us;
    b.periodUs = periodUs;
    b.channels = channels;
    b.sampleCount = static_cast<std::uint16_t>(n);
    for (int k = 0; k < n; ++k)
        for (std::size_t c = 0; c < channels.size(); ++c)
            b.values.push_back(static_cast<std::int32_t>((first + std::uint32_t(k)) * 10 + c));
    return b;
}

/// Feeds `values` (n at 100 Hz from t0S, sample index from first) into one channel.
void recordRamp(HistoryRecorder& r, const ChannelRef& ref, std::uint32_t first, double t0S, std::size_t n, double periodS = 0.01)
{
    std::vector<float> v(n);
    for (std::size_t k = 0; k < n; ++k)
        v[k] = static_cast<float>(first + k);
    r.record(1, ref, first, t0S, periodS, v.data(), n);
}

class TelemetryHistoryTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { ensureApp(); }
};

// ---- the recorder on its own ----------------------------------------------------------

TEST_F(TelemetryHistoryTest, RingKeepsTheNewestSamplesInOrderAndItsMemoryStaysWhereTheBudgetSays)
{
    const HistoryBudget budget{10, 100};
    ASSERT_EQ(budget.capacity(), 1000u) << "seconds × rate";
    HistoryRecorder r(budget);
    const ChannelRef x = href(0, ChannelKind::Measured);
    // Exactly the capacity: nothing dropped yet.
    for (std::uint32_t b = 0; b < 10; ++b)
        recordRamp(r, x, b * 100, b * 1.0, 100);
    const dev::tele::ChannelStore* s = r.store(1, x);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->size(), 1000u);
    const std::size_t full = r.memoryBytes();
    // Two and a half times the capacity: the oldest go first, the newest stay, in order.
    for (std::uint32_t b = 10; b < 25; ++b)
        recordRamp(r, x, b * 100, b * 1.0, 100);
    EXPECT_EQ(s->size(), 1000u);
    EXPECT_EQ(s->capacity(), 1000u);
    EXPECT_EQ(s->at(0).value, 1500.0f) << "the oldest kept is the 1501st sample";
    EXPECT_NEAR(s->at(0).tS, 15.0, 1e-9);
    EXPECT_EQ(s->at(999).value, 2499.0f);
    EXPECT_NEAR(s->at(999).tS, 24.99, 1e-9);
    for (std::size_t i = 1; i < s->size(); ++i) {
        ASSERT_EQ(s->at(i).value, s->at(i - 1).value + 1.0f) << i;
        ASSERT_GT(s->at(i).tS, s->at(i - 1).tS) << i;
    }
    EXPECT_EQ(r.memoryBytes(), full) << "feeding more than the capacity takes no more memory";
    // The stated bound: 4.53 bytes a slot (value and pyramid) plus a few runs and the object.
    EXPECT_LE(double(r.memoryBytes()), 4.6 * double(budget.capacity()) + 1024);
    EXPECT_NEAR(r.spanS(1), 9.99, 1e-9);
}

TEST_F(TelemetryHistoryTest, AFasterStreamIsThinnedSoTheRingStillSpansTheBudgetsSeconds)
{
    HistoryRecorder r(HistoryBudget{10, 100});
    EXPECT_EQ(r.strideFor(0.01), 1u);
    EXPECT_EQ(r.strideFor(0.005), 2u);
    EXPECT_EQ(r.strideFor(0.001), 10u);
    EXPECT_EQ(r.strideFor(1.0 / 588), 6u) << "never kept faster than 100 Hz: the span never falls short";
    EXPECT_EQ(r.strideFor(0.1), 1u);
    const ChannelRef fe = href(1, ChannelKind::FollowingError);
    // 30 s at 1 kHz in batches of 37 (not a multiple of the stride): every 10th sample by index.
    std::uint32_t index = 0;
    while (index < 30000) {
        const std::size_t n = std::min<std::size_t>(37, 30000 - index);
        recordRamp(r, fe, index, index * 0.001, n, 0.001);
        index += static_cast<std::uint32_t>(n);
    }
    const dev::tele::ChannelStore* s = r.store(1, fe);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->size(), 1000u);
    EXPECT_NEAR(r.spanS(1), 9.99, 1e-6);
    for (std::size_t i = 0; i < s->size(); ++i) {
        ASSERT_EQ(std::fmod(s->at(i).value, 10.0f), 0.0f) << "index " << i;
        ASSERT_NEAR(s->at(i).tS, s->at(i).value * 0.001, 1e-6);
    }
    EXPECT_EQ(s->at(999).value, 29990.0f);
    EXPECT_LE(double(r.memoryBytes()), 4.6 * 1000 + 1024) << "one periodic run, not one per batch";
}

// ---- the hub, fed by hand -----------------------------------------------------------------

struct HistoryRig {
    HistoryRig()
    {
        hub.enableHistory(HistoryBudget{20, 100});
        hub.addInstrument(0, QStringLiteral("Analyzer"), &analyzer);
        hub.addInstrument(1, QStringLiteral("Stage"), &stage);
        QObject::connect(&hub, &TelemetryHub::problem, &hub, [this](const motion::msg::Message& m) { problems << QString::fromStdString(m.id); });
    }
    /// `seconds` at 100 Hz from device time `fromS` in 10-sample batches of X and Y commanded,
    /// measured, following error and velocity (velocity is not a recorded kind).
    void feed(dev::BenchPilotClient& who, std::uint32_t& index, double fromS, double seconds, int axes = 2)
    {
        std::vector<ChannelRef> channels;
        for (int a = 0; a < axes; ++a)
            for (ChannelKind k : {ChannelKind::Commanded, ChannelKind::Measured, ChannelKind::FollowingError, ChannelKind::Velocity})
                channels.push_back(href(a, k));
        const auto startUs = static_cast<std::uint64_t>(std::llround(fromS * 1e6));
        const int batches = static_cast<int>(std::lround(seconds * 10));
        for (int b = 0; b < batches; ++b) {
            emit who.telemetryReceived(historyBatch(index, startUs + std::uint64_t(b) * 100000, 10000, channels, 10));
            index += 10;
        }
    }
    dev::BenchPilotClient analyzer, stage;
    TelemetryHub hub;
    std::uint32_t analyzerIndex = 0, stageIndex = 0;
    QStringList problems;
};

TEST_F(TelemetryHistoryTest, EveryInstrumentsPositionsAndErrorsAreKeptThoughNobodyWantsThem)
{
    HistoryRig rig;
    rig.feed(rig.analyzer, rig.analyzerIndex, 50.0, 3.0, 3);
    rig.feed(rig.stage, rig.stageIndex, 7.0, 2.0, 2);
    const ChannelKey stageYError{1, href(1, ChannelKind::FollowingError)};
    const ChannelKey analyzerZ{0, href(2, ChannelKind::Measured)};
    EXPECT_EQ(rig.hub.store(stageYError), nullptr) << "no screen wants it: no live store";
    const dev::tele::ChannelStore* y = rig.hub.historyStore(stageYError);
    ASSERT_NE(y, nullptr);
    EXPECT_EQ(y->size(), 200u);
    EXPECT_DOUBLE_EQ(y->firstTime(), 7.0);
    EXPECT_EQ(y->at(0).value, 6.0f * 1000) << "following error in µm, like the live stores (Y's is the batch's 7th channel)";
    EXPECT_EQ(rig.hub.viewStore(stageYError), y) << "a plot of it shows the history";
    const dev::tele::ChannelStore* z = rig.hub.historyStore(analyzerZ);
    ASSERT_NE(z, nullptr);
    EXPECT_EQ(z->size(), 300u);
    EXPECT_DOUBLE_EQ(z->lastTime(), 52.99);
    EXPECT_EQ(rig.hub.historyStore(ChannelKey{1, href(0, ChannelKind::Velocity)}), nullptr) << "not a recorded kind";
    EXPECT_EQ(rig.hub.historyChannels().size(), 3 * 3 + 2 * 3);
    EXPECT_NEAR(rig.hub.historySpanS(0), 2.99, 1e-9);
    EXPECT_NEAR(rig.hub.historySpanS(1), 1.99, 1e-9);
}

TEST_F(TelemetryHistoryTest, PlotsGetTheLiveStoreOnceItCoversTheWindowAndTheHistoryBefore)
{
    HistoryRig rig;
    rig.hub.setWindowS(2.0);
    rig.feed(rig.stage, rig.stageIndex, 0.0, 5.0);
    const ChannelKey x{1, href(0, ChannelKind::Measured)};
    rig.hub.setWanted(QStringLiteral("plot"), {x}, 100);  // ticked after five seconds of motion
    rig.feed(rig.stage, rig.stageIndex, 5.0, 0.5);
    ASSERT_NE(rig.hub.store(x), nullptr);
    EXPECT_EQ(rig.hub.viewStore(x), rig.hub.historyStore(x)) << "the live store holds 0.5 s of a 2 s window";
    EXPECT_DOUBLE_EQ(rig.hub.viewStore(x)->firstTime(), 0.0) << "the earlier samples show";
    rig.feed(rig.stage, rig.stageIndex, 5.5, 2.0);
    EXPECT_EQ(rig.hub.viewStore(x), rig.hub.store(x)) << "a full window live: the rate the plot asked for";
}

TEST_F(TelemetryHistoryTest, AReconnectLeavesAGapAndKeepsEverythingBeforeIt)
{
    HistoryRig rig;
    rig.feed(rig.stage, rig.stageIndex, 10.0, 1.0);
    emit rig.stage.stateChanged(dev::LinkState::Lost);
    emit rig.stage.stateChanged(dev::LinkState::Ready);
    rig.stageIndex = 0;  // a new subscription counts from zero
    rig.feed(rig.stage, rig.stageIndex, 14.0, 1.0);  // the device's clock ran on meanwhile
    const dev::tele::ChannelStore* s = rig.hub.historyStore(ChannelKey{1, href(0, ChannelKind::Commanded)});
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->size(), 200u) << "nothing wiped";
    EXPECT_DOUBLE_EQ(s->firstTime(), 10.0);
    EXPECT_DOUBLE_EQ(s->lastTime(), 14.99);
    EXPECT_EQ(s->lowerBound(11.0), 100u);
    EXPECT_DOUBLE_EQ(s->at(100).tS, 14.0) << "nothing invented in the gap";
    // Drawn, the gap is empty columns.
    std::vector<dev::tele::MinMax> columns(50);
    s->decimate(10.0, 15.0, 50, columns.data());
    EXPECT_FALSE(columns[5].empty());
    for (int c = 11; c < 39; ++c)
        EXPECT_TRUE(columns[std::size_t(c)].empty()) << c;
    EXPECT_FALSE(columns[45].empty());
}

TEST_F(TelemetryHistoryTest, ADeviceClockThatStartsAgainContinuesTheTimeLineAfterAGap)
{
    HistoryRig rig;
    const ChannelKey x{1, href(0, ChannelKind::Measured)};
    rig.hub.setWanted(QStringLiteral("plot"), {x}, 100);
    rig.feed(rig.stage, rig.stageIndex, 100.0, 1.0);
    rig.stageIndex = 0;
    rig.feed(rig.stage, rig.stageIndex, 0.5, 0.5);  // power-cycled: its clock is back near zero
    ASSERT_EQ(rig.problems, QStringList{QStringLiteral("telemetry.clock_restarted")});
    for (const dev::tele::ChannelStore* s : {rig.hub.historyStore(x), rig.hub.store(x)}) {
        ASSERT_NE(s, nullptr);
        EXPECT_EQ(s->size(), 150u) << "what came before the restart is kept";
        EXPECT_DOUBLE_EQ(s->at(99).tS, 100.99);
        EXPECT_GT(s->at(100).tS, 100.99) << "the new samples follow the old ones";
        EXPECT_EQ(s->at(100).value, 0.0f + 1.0f) << "the first of the new stream (index 0, channel 1)";
        for (std::size_t i = 1; i < s->size(); ++i)
            ASSERT_GT(s->at(i).tS, s->at(i - 1).tS);
    }
    EXPECT_DOUBLE_EQ(rig.hub.latestTimeS(1), rig.hub.store(x)->lastTime());
}

/// Every CSV line split at commas.
std::vector<QList<QByteArray>> historyCsv(const QString& path)
{
    QFile f(path);
    std::vector<QList<QByteArray>> rows;
    if (!f.open(QIODevice::ReadOnly))
        return rows;
    while (!f.atEnd()) {
        QByteArray line = f.readLine();
        line.chop(line.endsWith('\n') ? 1 : 0);
        rows.push_back(line.split(','));
    }
    return rows;
}

TEST_F(TelemetryHistoryTest, ExportHoldsEveryRecordedChannelWithDataForTheChosenSpan)
{
    HistoryRig rig;
    QTemporaryDir dir;
    motion::msg::Message error;
    EXPECT_FALSE(rig.hub.exportHistory(dir.filePath(QStringLiteral("none.csv")), 0, &error));
    EXPECT_EQ(error.id, "telemetry.history_empty");

    rig.feed(rig.analyzer, rig.analyzerIndex, 50.0, 3.0, 1);
    rig.feed(rig.stage, rig.stageIndex, 7.0, 4.0, 2);
    const QString path = dir.filePath(QStringLiteral("history.csv"));
    quint64 rows = 0;
    ASSERT_TRUE(rig.hub.exportHistory(path, 1.0, &error, &rows)) << motion::msg::debugString(error);
    const auto csv = historyCsv(path);
    ASSERT_FALSE(csv.empty());
    EXPECT_EQ(csv[0], (QList<QByteArray>{"time_s", "instrument", "Analyzer 0 commanded [mm]", "Analyzer 0 measured [mm]",
                                         QStringLiteral("Analyzer 0 following error [µm]").toUtf8(),
                                         "Stage 0 commanded [mm]", "Stage 0 measured [mm]",
                                         QStringLiteral("Stage 0 following error [µm]").toUtf8(), "Stage 1 commanded [mm]",
                                         "Stage 1 measured [mm]", QStringLiteral("Stage 1 following error [µm]").toUtf8()}));
    // The last second of each instrument: [latest − 1 s, latest] holds 101 samples at 100 Hz.
    EXPECT_EQ(rows, 101u + 101u);
    ASSERT_EQ(csv.size(), 1 + rows);
    EXPECT_EQ(csv[1][0], "51.990000");
    EXPECT_EQ(csv[1][1], "Analyzer");
    EXPECT_EQ(csv[101][0], "52.990000");
    EXPECT_EQ(csv[102][0], "9.990000");
    EXPECT_EQ(csv[102][1], "Stage");
    for (std::size_t r = 1; r < csv.size(); ++r) {
        ASSERT_EQ(csv[r].size(), 11) << r;
        const bool analyzer = csv[r][1] == "Analyzer";
        for (int c = 2; c < 11; ++c)
            EXPECT_EQ(csv[r][c].isEmpty(), analyzer != (c < 5)) << "row " << r << " column " << c;
    }
    // Values: sample index × 10 + the channel's place in its batch (commanded 0, measured 1, error 2 × 1000).
    EXPECT_EQ(csv[102][3 + 3].toDouble(), (299 * 10 + 1));
    EXPECT_EQ(csv[102][3 + 4].toDouble(), (299 * 10 + 2) * 1000.0);

    ASSERT_TRUE(rig.hub.exportHistory(path, 0, &error, &rows)) << motion::msg::debugString(error);
    EXPECT_EQ(rows, 300u + 400u) << "0: everything recorded";
}

// ---- on the simulator ---------------------------------------------------------------------

TEST_F(TelemetryHistoryTest, AnInstrumentNobodyWatchesStreamsItsHistoryChannelsAtTheDefaultRate)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Analyzer, 0);
    link.host().setManualClock(true);
    link.host().firmware().setLinkBaud(921600);
    dev::BenchPilotClient client;
    client.setTransport(link.hostEnd());
    TelemetryHub hub;
    hub.enableHistory();
    hub.addInstrument(0, QStringLiteral("Analyzer"), &client);
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return client.isReady(); }));
    const int axes = client.identity().axes.size();
    ASSERT_EQ(axes, 4);
    ASSERT_TRUE(waitFor([&] { return client.subscribedChannels().size() == axes * 3; }));
    EXPECT_EQ(client.subscribedRateHz(), TelemetryHub::kDefaultRateHz);
    for (int k = 0; k < 100; ++k) {
        link.host().advance(0.01);
        QCoreApplication::processEvents();
    }
    waitFor([] { return false; }, 20);
    for (int a = 0; a < axes; ++a)
        for (ChannelKind kind : HistoryRecorder::recordedKinds()) {
            const ChannelKey key{0, href(a, kind)};
            EXPECT_EQ(hub.store(key), nullptr);
            ASSERT_NE(hub.historyStore(key), nullptr) << a;
            EXPECT_GE(hub.historyStore(key)->size(), 80u) << a;
        }
    EXPECT_LE(hub.history()->memoryBytes(), std::size_t(12 * (4.6 * 30000 + 1024)));
    client.setTransport(nullptr);
}

TEST_F(TelemetryHistoryTest, HistoryNeverCostsAScreenItsRateOnASlowLink)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Analyzer, 0);
    link.host().setManualClock(true);
    link.host().firmware().setLinkBaud(115200);
    dev::BenchPilotClient client;
    client.setTransport(link.hostEnd());
    TelemetryHub hub;
    hub.enableHistory();
    hub.addInstrument(0, QStringLiteral("Analyzer"), &client);
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return client.isReady(); }));
    // 3 channels at 500 Hz fit 115200 baud; 12 do not.
    const QVector<ChannelKey> wanted{ChannelKey{0, href(0, ChannelKind::Measured)}, ChannelKey{0, href(1, ChannelKind::Measured)},
                                     ChannelKey{0, href(2, ChannelKind::Measured)}};
    hub.setWanted(QStringLiteral("plot"), wanted, 500);
    ASSERT_TRUE(waitFor([&] { return client.subscribedRateHz() == 500; }));
    EXPECT_EQ(client.subscribedChannels().size(), 3) << "the history's other channels were left out";
    EXPECT_TRUE(hub.historyHeldBack(0));
    hub.setWanted(QStringLiteral("plot"), {}, 0);
    ASSERT_TRUE(waitFor([&] { return client.subscribedChannels().size() == 12; }));
    EXPECT_FALSE(hub.historyHeldBack(0));
    client.setTransport(nullptr);
}

} // namespace
