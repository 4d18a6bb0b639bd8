// Google Benchmark program for device/telemetry and the telemetry link (docs/telemetry.md).
// Targets: ingest ≤ 50 ns per sample per channel; memory bounded by the window (a
// one-hour run at full rate grows nothing); decimation cost follows the columns,
// not the samples; ≥ 85 % of the wire's bytes are sample payload at 115200 baud;
// zero lost samples over a 10-minute simulated stream.
//
// Counters (derived figures, names say what they are):
//   ns_per_sample_channel   ingest cost: one value of one channel into its store
//   bytes_after_window, bytes_after_1h, growth_bytes   heap in use (malloc) during a 1 h run
//   ns_per_column           decimation of a 6 M-point channel to 1600 columns
//   payload_share           sample payload bytes / wire bytes device→host (0–1)
//   rate_hz                 the rate the device accepted (the highest the link carries)
//   lost_samples, samples_received, samples_expected   10-minute stream
//   wire_utilisation        wire bytes / what the baud rate carries in that time
//
// BP_BENCH_SHORT=1 (CTest) shrinks sizes and durations to prove the program works;
// each benchmark's label says what it ran. Full numbers come from a run by hand.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "device/protocol/frame_codec.h"
#include "device/telemetry/channel_store.h"
#include "device/telemetry/telemetry_hub.h"

#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <malloc.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

bool shortMode()
{
    static const bool s = std::getenv("BP_BENCH_SHORT") != nullptr;
    return s;
}

/// Heap bytes in use: small chunks in the arenas plus large mmapped ones (the rings).
double heapInUse()
{
    const struct mallinfo2 m = mallinfo2();
    return static_cast<double>(m.uordblks + m.hblkhd);
}

bool waitFor(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    return true;
}

void spin(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

using dev::proto::ChannelKind;
using dev::proto::ChannelRef;
using dev::tele::ChannelKey;

/// The XY plot's channels: commanded and measured of both stage axes.
const std::vector<ChannelRef> kXy{{0, ChannelKind::Commanded}, {0, ChannelKind::Measured},
                                  {1, ChannelKind::Commanded}, {1, ChannelKind::Measured}};

QVector<ChannelKey> keys(int instrument, const std::vector<ChannelRef>& refs)
{
    QVector<ChannelKey> out;
    for (const auto& r : refs)
        out.push_back(ChannelKey{instrument, r});
    return out;
}

/// Simulated stage + client + hub. paced: the loopback delivers at the baud rate in
/// wall time (the simulator then runs in real time); unpaced: bytes arrive at once and
/// the device's clock moves only by advance(), so minutes take seconds.
struct Rig {
    Rig(qint32 baud, bool paced) : link(dev::proto::DeviceKind::Stage, paced ? baud : 0)
    {
        link.host().firmware().setLinkBaud(static_cast<std::uint32_t>(baud));
        if (!paced)
            link.host().setManualClock(true);
        client.setTransport(link.hostEnd());
        hub.addInstrument(1, QStringLiteral("Stage"), &client);
        QObject::connect(&hub, &dev::tele::TelemetryHub::subscriptionChanged, &hub,
                         [this](int, int rate, const motion::msg::Message& n) {
                             rateHz = rate;
                             note = QString::fromStdString(motion::msg::debugString(n));
                         });
    }
    ~Rig() { client.setTransport(nullptr); }
    bool connect()
    {
        client.connectLink();
        return waitFor([this] { return client.isReady(); }, 10000);
    }
    /// Wants `refs` at `wantHz`; returns once the device streams at some rate.
    bool subscribe(const std::vector<ChannelRef>& refs, int wantHz)
    {
        hub.setWanted(QStringLiteral("bench"), keys(1, refs), wantHz);
        return waitFor([this] { return rateHz > 0; }, 10000);
    }
    dev::SimulatedLink link;
    dev::BenchPilotClient client;
    dev::tele::TelemetryHub hub;
    int rateHz = 0;
    QString note;
};

/// One batch like the device's: 4 channels, 124 samples (what fits 1 KiB frames).
struct BatchMaker {
    explicit BatchMaker(const std::vector<ChannelRef>& refs, std::uint32_t periodUs = 100, std::uint16_t n = 124)
    {
        b.channels = refs;
        b.periodUs = periodUs;
        b.sampleCount = n;
        b.values.resize(std::size_t(n) * refs.size());
        std::mt19937 rng(7);
        std::uniform_int_distribution<std::int32_t> d(-50'000'000, 50'000'000);
        for (auto& v : b.values)
            v = d(rng);
    }
    const dev::proto::TelemetryBatch& next()
    {
        b.firstSampleIndex = index;
        b.firstSampleTimeUs = timeUs;
        index += b.sampleCount;
        timeUs += std::uint64_t(b.sampleCount) * b.periodUs;
        return b;
    }
    std::size_t valuesPerBatch() const { return b.values.size(); }
    dev::proto::TelemetryBatch b;
    std::uint32_t index = 0;
    std::uint64_t timeUs = 1'000'000;
};

// ---- ingest ---------------------------------------------------------------------

/// The store alone: one channel of a 4-channel sample-major batch (stride 4).
void BM_StoreIngest(benchmark::State& state)
{
    const std::size_t capacity = shortMode() ? 200'000 : 12'000'000;
    dev::tele::ChannelStore store(capacity);
    std::vector<float> batch(124 * 4);
    for (std::size_t i = 0; i < batch.size(); ++i)
        batch[i] = std::sin(float(i) * 0.01f);
    double t = 0;
    std::size_t values = 0;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        for (std::size_t c = 0; c < 4; ++c)
            store.appendRun(t, 1e-4, batch.data() + c, 124, 4);  // same channel four times: 4 batches' worth
        t += 4 * 124e-4;
        values += 4 * 124;
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(store.size());
    state.counters["ns_per_sample_channel"] = ns / double(values);
    state.SetItemsProcessed(static_cast<std::int64_t>(values));
    state.SetLabel("capacity " + std::to_string(capacity));
}
BENCHMARK(BM_StoreIngest);

/// The whole path a batch takes from the client's signal: sample counter, unit
/// conversion (toAxisUnits), trimming to the window, the four stores.
void BM_HubIngest(benchmark::State& state)
{
    Rig rig(921600, false);
    if (!rig.connect()) {
        state.SkipWithError("simulator did not connect");
        return;
    }
    rig.hub.setWindowS(shortMode() ? 10 : 600);
    rig.hub.setWanted(QStringLiteral("bench"), keys(1, kXy), 100);
    spin(20);
    BatchMaker maker(kXy);
    std::size_t values = 0;
    int batches = 0;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        emit rig.client.telemetryReceived(maker.next());
        values += maker.valuesPerBatch();
        if (++batches % 16 == 0)
            QCoreApplication::processEvents();  // a GUI turn now and then, as in the app
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    state.counters["ns_per_sample_channel"] = ns / double(values);
    state.SetItemsProcessed(static_cast<std::int64_t>(values));
    state.SetLabel(shortMode() ? "10 s window" : "600 s window");
}
BENCHMARK(BM_HubIngest);

/// What the flight recorder (docs/telemetry.md, "History") costs per telemetry batch: the hub
/// ingesting 124-sample batches of the stage's X and Y commanded, measured and
/// following error (6 channels, all recorded kinds) that a plot wants, with the
/// history off (arg 0) and on (arg 1), at the 10 kHz sample clock (period 100 µs:
/// the history keeps every 100th sample) and at 100 Hz (10 000 µs: it keeps each).
/// ns_per_batch on minus off is the recording's cost; history_bytes is its heap.
void BM_HistoryRecording(benchmark::State& state)
{
    const bool history = state.range(0) != 0;
    const auto periodUs = static_cast<std::uint32_t>(state.range(1));
    Rig rig(921600, false);
    if (history)
        rig.hub.enableHistory();
    if (!rig.connect()) {
        state.SkipWithError("simulator did not connect");
        return;
    }
    const std::vector<ChannelRef> refs{{0, ChannelKind::Commanded}, {0, ChannelKind::Measured}, {0, ChannelKind::FollowingError},
                                       {1, ChannelKind::Commanded}, {1, ChannelKind::Measured}, {1, ChannelKind::FollowingError}};
    rig.hub.setWindowS(10);
    rig.hub.setWanted(QStringLiteral("bench"), keys(1, refs), 100);
    spin(20);
    rig.client.disconnectLink();  // only the hub from here on (the client keeps its units)
    spin(20);
    BatchMaker maker(refs, periodUs);
    long batches = 0;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        emit rig.client.telemetryReceived(maker.next());
        if (++batches % 16 == 0)
            QCoreApplication::processEvents();
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    state.counters["ns_per_batch"] = ns / double(std::max(1L, batches));
    state.counters["ns_per_sample_channel"] = ns / double(std::max(1L, batches)) / double(maker.valuesPerBatch());
    state.counters["history_bytes"] = rig.hub.history() ? double(rig.hub.history()->memoryBytes()) : 0.0;
    state.SetLabel(std::string(history ? "history on" : "history off") + (periodUs == 100 ? ", 10 kHz" : ", 100 Hz"));
}
BENCHMARK(BM_HistoryRecording)->Args({0, 100})->Args({1, 100})->Args({0, 10000})->Args({1, 10000});

// ---- memory ---------------------------------------------------------------------

/// One hour of device time at the full sample clock (10 kHz × 4 channels, more than
/// any link carries) through the hub with a 10-minute window; optionally recording
/// to /dev/null (formatting and buffering, no disk). Heap in use after the first
/// window vs after the hour: nothing may grow.
void BM_HubMemoryOneHour(benchmark::State& state)
{
    const bool record = state.range(0) != 0;
    const double windowS = shortMode() ? 10 : 600;
    const double runS = shortMode() ? 60 : 3600;
    double afterWindow = 0, afterRun = 0, storeBytes = 0;
    for (auto _ : state) {
        Rig rig(921600, false);
        if (!rig.connect()) {
            state.SkipWithError("simulator did not connect");
            return;
        }
        rig.hub.setWindowS(windowS);
        rig.hub.setWanted(QStringLiteral("bench"), keys(1, kXy), 100);
        if (record) {
            motion::msg::Message error;
            if (!rig.hub.startRecording(QStringLiteral("/dev/null"), keys(1, kXy), &error)) {
                state.SkipWithError(motion::msg::debugString(error).c_str());
                return;
            }
        }
        spin(20);
        // Only the hub from here on: the link's status polls and the loopback's queues
        // would add a few hundred bytes of noise to the heap figures. The client keeps
        // its identity (units) after disconnecting.
        rig.client.disconnectLink();
        spin(20);
        BatchMaker maker(kXy);
        const double batchS = 124 * 1e-4;
        const auto batches = static_cast<long>(runS / batchS);
        const auto windowBatches = static_cast<long>(2 * windowS / batchS) + 10;  // both halves of the ring written
        for (long k = 0; k < batches; ++k) {
            emit rig.client.telemetryReceived(maker.next());
            if (k % 16 == 0)
                QCoreApplication::processEvents();
            if (k == windowBatches) {
                QCoreApplication::processEvents();  // the same state as at the end: no event pending
                afterWindow = heapInUse();
            }
        }
        QCoreApplication::processEvents();
        afterRun = heapInUse();
        for (const auto& r : kXy)
            if (const auto* s = rig.hub.store(ChannelKey{1, r}))
                storeBytes += double(s->memoryBytes());
        if (rig.hub.lostSamples(1) != 0)
            state.SkipWithError("samples lost in a synthetic stream");
        rig.hub.stopRecording();
    }
    state.counters["bytes_after_window"] = afterWindow;
    state.counters["bytes_after_1h"] = afterRun;
    state.counters["growth_bytes"] = afterRun - afterWindow;
    state.counters["store_bytes"] = storeBytes;
    state.SetLabel(std::string(shortMode() ? "short: 60 s run, 10 s window" : "3600 s run, 600 s window")
                   + (record ? ", recording" : ""));
}
BENCHMARK(BM_HubMemoryOneHour)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kMillisecond);

// ---- decimation -------------------------------------------------------------------

/// A 10-minute window at 10 kHz (6 M points; short mode 600 k) written past the
/// ring's end once, so the range crosses the seam like a live store's does.
const dev::tele::ChannelStore& bigStore()
{
    static const std::unique_ptr<dev::tele::ChannelStore> store = [] {
        const std::size_t n = shortMode() ? 600'000 : 6'000'000;
        auto s = std::make_unique<dev::tele::ChannelStore>(n);
        std::mt19937 rng(11);
        std::normal_distribution<float> noise(0, 0.002f);
        std::vector<float> batch(1000);
        double t = 0;
        std::size_t k = 0;
        for (std::size_t b = 0; b < (n + n / 3) / batch.size(); ++b) {
            for (auto& v : batch) {
                v = 20.0f * std::sin(float(k++) * 1e-4f) + noise(rng);
            }
            s->appendRun(t, 1e-4, batch.data(), batch.size());
            t += double(batch.size()) * 1e-4;
        }
        return s;
    }();
    return *store;
}

void BM_Decimate(benchmark::State& state)
{
    const dev::tele::ChannelStore& s = bigStore();
    const int columns = 1600;
    std::vector<dev::tele::MinMax> out(columns);
    const double first = s.firstTime(), last = s.lastTime();
    const bool zoom = state.range(0) != 0;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (auto _ : state) {
        double a = first, b = last;
        if (zoom) {  // a random 0.1 %–30 % of the window, as when zooming and panning
            const double span = (last - first) * (0.001 + 0.3 * u(rng));
            a = first + (last - first - span) * u(rng);
            b = a + span;
        }
        s.decimate(a, b, columns, out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["ns_per_column"] =
        benchmark::Counter(double(state.iterations()) * columns, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["points"] = double(s.size());
    state.SetLabel(std::string(zoom ? "random zoomed range" : "whole window") + ", " + std::to_string(s.size())
                   + " points to 1600 columns");
}
BENCHMARK(BM_Decimate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// ---- the link -------------------------------------------------------------------

/// Real-time stream on the loopback with baud emulation: the stage's XY channels
/// wanted at 10 kHz, the hub falls back to what the device says the link carries.
/// Payload share = sample bytes in the batches received / bytes the host received
/// (frames, CRC, COBS, delimiters, status replies: everything device→host).
void BM_LinkPayloadShare(benchmark::State& state)
{
    const auto baud = static_cast<qint32>(state.range(0));
    const int measureMs = shortMode() ? 1500 : 10000;
    double share = 0, rate = 0, utilisation = 0, carriedShare = 0;
    quint64 lost = 0;
    for (auto _ : state) {
        Rig rig(baud, true);
        if (!rig.connect() || !rig.subscribe(kXy, 10000)) {
            state.SkipWithError("no subscription");
            return;
        }
        spin(300);  // let the new stream settle
        qint64 wire = 0, payload = 0;
        QObject::connect(rig.link.hostEnd(), &dev::Transport::bytesReceived, &rig.hub,
                         [&wire](const QByteArray& b) { wire += b.size(); });
        QObject::connect(&rig.client, &dev::BenchPilotClient::telemetryReceived, &rig.hub,
                         [&payload](const dev::proto::TelemetryBatch& b) { payload += qint64(b.values.size()) * 4; });
        const qint64 carried0 = rig.link.pair().bytesCarried(dev::LoopbackPair::B);
        QElapsedTimer t;
        t.start();
        spin(measureMs);
        const double seconds = double(t.nsecsElapsed()) * 1e-9;
        const qint64 carried = rig.link.pair().bytesCarried(dev::LoopbackPair::B) - carried0;
        share = wire > 0 ? double(payload) / double(wire) : 0;
        carriedShare = carried > 0 ? double(payload) / double(carried) : 0;
        utilisation = double(wire) / (baud / 10.0 * seconds);
        rate = rig.rateHz;
        lost = rig.hub.lostSamples(1);
    }
    state.counters["payload_share"] = share;
    state.counters["payload_share_of_carried"] = carriedShare;
    state.counters["rate_hz"] = rate;
    state.counters["wire_utilisation"] = utilisation;
    state.counters["lost_samples"] = double(lost);
    state.SetLabel(std::to_string(baud) + " baud, 4 channels, " + std::to_string(measureMs / 1000.0).substr(0, 4)
                   + " s real time");
}
BENCHMARK(BM_LinkPayloadShare)->Arg(115200)->Arg(921600)->Iterations(1)->Unit(benchmark::kMillisecond);

/// Ten minutes of device time (short mode: 30 s) at the highest rate the link
/// carries, on a manual clock so it takes seconds: every sample the device sent
/// arrives (lost_samples = 0, received = expected), and the device never sent more
/// than the baud rate carries in that time (wire_utilisation ≤ 1).
void BM_LinkTenMinutesNoLoss(benchmark::State& state)
{
    const auto baud = static_cast<qint32>(state.range(0));
    const double durationS = shortMode() ? 30 : 600;
    double received = 0, expected = 0, lost = 0, utilisation = 0, rate = 0, clientLost = 0;
    for (auto _ : state) {
        Rig rig(baud, false);
        if (!rig.connect())
            return state.SkipWithError("simulator did not connect");
        rig.hub.setWindowS(60);
        rig.hub.setWanted(QStringLiteral("bench"), keys(1, kXy), 10000);
        if (!waitFor([&rig] { return rig.rateHz > 0; }, 10000))
            return state.SkipWithError("no subscription");
        rig.client.jogStep(0, 40.0, 5.0);  // something moving for the first 8 s
        spin(10);
        const quint64 received0 = rig.hub.samplesReceived(1);
        const qint64 carried0 = rig.link.pair().bytesCarried(dev::LoopbackPair::B);
        const double stepS = 0.01;
        const auto steps = static_cast<long>(std::lround(durationS / stepS));
        for (long k = 0; k < steps; ++k) {
            rig.link.host().advance(stepS);
            QCoreApplication::processEvents();
        }
        spin(50);
        rate = rig.rateHz;
        received = double(rig.hub.samplesReceived(1) - received0);
        // The reply's rate is rounded to whole Hz; the device samples at clock / ticks.
        const double clock = rig.client.identity().maxTelemetryRateHz;
        const double exactRate = clock > 0 ? clock / std::round(clock / rate) : rate;
        expected = std::floor(exactRate * durationS);
        // Whole batches only arrive: the last one is still being filled on the device.
        const double perBatch = std::ceil(rate * 0.1);
        lost = double(rig.hub.lostSamples(1));
        clientLost = double(rig.client.stats().lostSamples);
        utilisation = double(rig.link.pair().bytesCarried(dev::LoopbackPair::B) - carried0) / (baud / 10.0 * durationS);
        if (std::abs(received - expected) > std::max(perBatch, 250.0))
            state.SkipWithError("received count differs from rate × time by more than a batch");
    }
    state.counters["lost_samples"] = lost;
    state.counters["client_lost_samples"] = clientLost;
    state.counters["samples_received"] = received;
    state.counters["samples_expected"] = expected;
    state.counters["rate_hz"] = rate;
    state.counters["wire_utilisation"] = utilisation;
    state.SetLabel(std::to_string(baud) + " baud, 4 channels, "
                   + (shortMode() ? std::string("short: 30 s simulated, not 10 min") : std::string("600 s simulated")));
}
BENCHMARK(BM_LinkTenMinutesNoLoss)->Arg(115200)->Arg(921600)->Iterations(1)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
    int qtArgc = 1;
    char* qtArgv[] = {argv[0], nullptr};
    QCoreApplication app(qtArgc, qtArgv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
