// Google Benchmark program for the scripting API (docs/api.md).
//
// BM_StatusRoundTrip: device.status over the Unix socket, from a client's send to the
//   answer's last byte read: the server and both simulated instruments run on a thread
//   of their own (as on the GUI's thread), the client blocks on a plain socket.
//   Target: p99 ≤ 2 ms. Counters: p50_us, p99_us, max_us.
//
// BM_PlotRedrawWithClients/N: the live plots' redraw (the Plots screen's stack, 8
//   channels, as bench_plots' BM_RedrawLive) on the thread that also serves the API,
//   while N clients, each on its own thread, are subscribed to the stage's positions at
//   50 Hz and the stage jogs back and forth. N = 0 is the baseline: p95 must not move
//   beyond noise with N = 10. Each client checks every message: the sequence gap to the
//   previous one minus one must equal its `coalesced` ("misses no more than its
//   coalescing says"). Counters: p50_ms, p95_ms (redraw wall time), frame_cpu_ms_mean
//   (this thread's CPU per redraw: what the frame costs when others share the machine),
//   serve_cpu_share (this thread's CPU outside the frames, per second of run: the
//   server's and the simulators' work), msgs_per_client_s, coalesced_per_client,
//   unexplained_gaps (must be 0), dropped_total, run_s.
//   The full run lasts 60 s (3600 frames at 60 Hz); BP_BENCH_SHORT=1 runs 1 s.
#include "app/api/api_server.h"
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/client/instrument_proxy.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/telemetry_hub.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_source.h"
#include "widgets/plot_stack.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <poll.h>
#include <time.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace {

bool shortMode() { return qEnvironmentVariableIntValue("BP_BENCH_SHORT") == 1; }

/// CPU time of this thread (ms): on a shared machine, wall time also counts others' work.
double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

/// The GUI's side: both simulated instruments behind proxies, the hub, the API server.
struct Bench {
    explicit Bench(const QString& socketPath)
        : analyzerLink(dev::proto::DeviceKind::Analyzer, 115200), stageLink(dev::proto::DeviceKind::Stage, 115200)
    {
        analyzer = new dev::BenchPilotClient;
        analyzerProxy.setBackend(analyzer);
        analyzer->setTransport(analyzerLink.hostEnd());
        stage = new dev::BenchPilotClient;
        stageProxy.setBackend(stage);
        stage->setTransport(stageLink.hostEnd());
        hub.addInstrument(0, QStringLiteral("Analyzer"), &analyzerProxy);
        hub.addInstrument(1, QStringLiteral("Stage"), &stageProxy);
        server = std::make_unique<app::api::ApiServer>(
            QVector<app::api::ServedInstrument>{{QStringLiteral("analyzer"), &analyzerProxy, 0, {}}, {QStringLiteral("stage"), &stageProxy, 1, {}}}, &hub);
        QString error;
        if (!server->listen(socketPath, &error))
            qFatal("bench_api: %s", qPrintable(error));
        analyzerProxy.connectLink();
        stageProxy.connectLink();
        QElapsedTimer t;
        t.start();
        while (!(analyzerProxy.isReady() && stageProxy.isReady()) && t.elapsed() < 10000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    ~Bench()
    {
        server.reset();
        analyzer->setTransport(nullptr);
        stage->setTransport(nullptr);
    }
    dev::SimulatedLink analyzerLink, stageLink;
    dev::InstrumentProxy analyzerProxy, stageProxy;
    dev::BenchPilotClient* analyzer;
    dev::BenchPilotClient* stage;
    dev::tele::TelemetryHub hub;
    std::unique_ptr<app::api::ApiServer> server;
};

/// A client on a plain Unix socket (no Qt): what a script's process does.
class RawClient {
public:
    explicit RawClient(const std::string& path)
    {
        m_fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        std::snprintf(a.sun_path, sizeof(a.sun_path), "%s", path.c_str());
        if (::connect(m_fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) != 0)
            qFatal("bench_api: cannot connect to %s", path.c_str());
    }
    ~RawClient() { ::close(m_fd); }
    void send(const std::string& line)
    {
        std::size_t off = 0;
        while (off < line.size()) {
            const ssize_t n = ::write(m_fd, line.data() + off, line.size() - off);
            if (n <= 0)
                return;
            off += static_cast<std::size_t>(n);
        }
    }
    /// The next line, waiting at most `timeoutMs`; false on timeout or close.
    bool readLine(std::string& line, int timeoutMs)
    {
        for (;;) {
            const auto nl = m_buffer.find('\n');
            if (nl != std::string::npos) {
                line = m_buffer.substr(0, nl);
                m_buffer.erase(0, nl + 1);
                return true;
            }
            pollfd p{m_fd, POLLIN, 0};
            if (::poll(&p, 1, timeoutMs) <= 0)
                return false;
            char chunk[65536];
            const ssize_t n = ::read(m_fd, chunk, sizeof(chunk));
            if (n <= 0)
                return false;
            m_buffer.append(chunk, static_cast<std::size_t>(n));
        }
    }

private:
    int m_fd = -1;
    std::string m_buffer;
};

void percentiles(benchmark::State& state, std::vector<double> v, const char* unit, double scale, const std::vector<double>& ps)
{
    if (v.empty())
        return;
    std::sort(v.begin(), v.end());
    auto pct = [&](double p) { return v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(p * double(v.size())) - 1))]; };
    for (double p : ps)
        state.counters[std::string("p") + std::to_string(int(std::round(p * 100))) + "_" + unit] = pct(p) * scale;
    state.counters[std::string("max_") + unit] = v.back() * scale;
}

// ---- device.status round trip -----------------------------------------------------------

void BM_StatusRoundTrip(benchmark::State& state)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("api.sock"));
    // The server's thread: it is the GUI's thread here, busy with nothing else.
    std::atomic<bool> ready{false};
    QThread* serverThread = QThread::create([&] {
        Bench bench(path);
        ready = true;
        QEventLoop loop;
        QObject::connect(QThread::currentThread(), &QThread::finished, &loop, &QEventLoop::quit);
        QTimer quit;
        QObject::connect(&quit, &QTimer::timeout, &loop, [&] {
            if (QThread::currentThread()->isInterruptionRequested())
                loop.quit();
        });
        quit.start(50);
        loop.exec();
    });
    serverThread->start();
    while (!ready)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    RawClient c(path.toStdString());
    std::string line;
    std::vector<double> us;
    int id = 0;
    for (auto _ : state) {
        const std::string request = "{\"jsonrpc\":\"2.0\",\"id\":" + std::to_string(++id)
            + ",\"method\":\"device.status\",\"params\":{\"instrument\":\"stage\"}}\n";
        QElapsedTimer t;
        t.start();
        c.send(request);
        if (!c.readLine(line, 5000))
            state.SkipWithError("no answer");
        const double s = double(t.nsecsElapsed()) * 1e-9;
        us.push_back(s);
        state.SetIterationTime(s);
    }
    percentiles(state, us, "us", 1e6, {0.5, 0.99});
    serverThread->requestInterruption();
    serverThread->wait();
    delete serverThread;
}
BENCHMARK(BM_StatusRoundTrip)->UseManualTime()->Unit(benchmark::kMicrosecond)->Iterations(shortMode() ? 100 : 5000);

// ---- plot redraw while clients subscribe --------------------------------------------------

constexpr double kRateHz = 10000;
constexpr int kChannels = 8;

/// The Plots screen's stack over 8 stores of a 10 s window at 10 kHz (as bench_plots, short).
struct Plots {
    std::vector<std::unique_ptr<dev::tele::ChannelStore>> stores;
    ui::StorePlotSource source;
    std::unique_ptr<ui::PlotStack> stack;
    double nowS = 0;

    Plots()
    {
        const double windowS = 10, period = 1.0 / kRateHz;
        const auto n = static_cast<std::size_t>(windowS * kRateHz);
        const dev::proto::ChannelKind kinds[4] = {dev::proto::ChannelKind::Commanded, dev::proto::ChannelKind::Measured,
                                             dev::proto::ChannelKind::FollowingError, dev::proto::ChannelKind::ControllerOutput};
        std::mt19937 rng(4242);
        std::normal_distribution<float> noise(0.f, 1.f);
        std::vector<float> values(n);
        for (int c = 0; c < kChannels; ++c) {
            auto store = std::make_unique<dev::tele::ChannelStore>(2 * n);
            for (std::size_t i = 0; i < n; ++i)
                values[i] = float(40 * std::sin(double(i) * period * 0.7 * (c + 1)) + noise(rng));
            store->appendRun(0, period, values.data(), n);
            const dev::tele::ChannelKey key{1, dev::proto::ChannelRef{std::uint8_t(c % 2), kinds[c / 2]}};
            source.add(key, store.get(), QStringLiteral("Stage %1").arg(c), QStringLiteral("mm"));
            stores.push_back(std::move(store));
        }
        nowS = stores.front()->lastTime();
        stack = std::make_unique<ui::PlotStack>(&source);
        for (int p = 1; p < kChannels / 2; ++p)
            stack->addPanel();
        for (int c = 0; c < kChannels; ++c)
            stack->addChannel(c / 2, dev::tele::ChannelKey{1, dev::proto::ChannelRef{std::uint8_t(c % 2), kinds[c / 2]}});
        stack->resize(1600, 900);
        stack->show();
        QApplication::processEvents();
    }

    /// 1/60 s of new samples, then one timed frame; returns its wall time (ms).
    double frame()
    {
        const double period = 1.0 / kRateHz;
        const std::size_t perFrame = static_cast<std::size_t>(kRateHz / 60);
        std::vector<float> values(perFrame);
        for (std::size_t c = 0; c < stores.size(); ++c) {
            for (std::size_t i = 0; i < perFrame; ++i)
                values[i] = float(std::sin((nowS + double(i) * period) * 3.0) * 10 + double(c));
            stores[c]->appendRun(nowS + period, period, values.data(), perFrame);
        }
        nowS += double(perFrame) * period;
        QElapsedTimer t;
        t.start();
        stack->setAnchors(std::nan(""), nowS);
        stack->setTimeRange(-10, 0);
        stack->redraw();
        stack->repaint();
        return double(t.nsecsElapsed()) * 1e-6;
    }
};

/// One subscribed client on its own thread: reads every message and checks its accounting.
struct Subscriber {
    std::thread thread;
    std::atomic<bool> stop{false};
    std::atomic<long> messages{0}, coalesced{0}, unexplained{0}, dropped{0};

    explicit Subscriber(const std::string& path)
    {
        thread = std::thread([this, path] {
            RawClient c(path);
            c.send("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"subscribe\",\"params\":{\"topics\":{\"positions\":"
                   "{\"instrument\":\"stage\",\"max_hz\":50}}}}\n");
            std::string line;
            long long lastSeq = -1;
            while (!stop) {
                if (!c.readLine(line, 100))
                    continue;
                const QJsonObject m = QJsonDocument::fromJson(QByteArray::fromStdString(line)).object();
                if (m.value(QStringLiteral("method")).toString() != QLatin1String("subscription"))
                    continue;
                const QJsonObject p = m.value(QStringLiteral("params")).toObject();
                const long long seq = p.value(QStringLiteral("seq")).toInteger();
                const long long folded = p.value(QStringLiteral("coalesced")).toInteger();
                if (lastSeq >= 0 && seq - lastSeq - 1 != folded)
                    ++unexplained;
                lastSeq = seq;
                ++messages;
                coalesced += folded;
                dropped = static_cast<long>(p.value(QStringLiteral("dropped_total")).toInteger());
            }
        });
    }
    ~Subscriber()
    {
        stop = true;
        thread.join();
    }
};

void BM_PlotRedrawWithClients(benchmark::State& state)
{
    const int clients = static_cast<int>(state.range(0));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("api.sock"));
    Bench bench(path);  // on this thread, as in the GUI
    Plots plots;
    // The stage jogs back and forth so the positions keep changing.
    QTimer mover;
    double direction = 1;
    QObject::connect(&mover, &QTimer::timeout, [&] {
        direction = -direction;
        bench.stageProxy.startJog(0, 2 * direction);
    });
    bench.stageProxy.startJog(0, 2);
    mover.start(2000);
    std::vector<std::unique_ptr<Subscriber>> subs;
    for (int i = 0; i < clients; ++i)
        subs.push_back(std::make_unique<Subscriber>(path.toStdString()));
    QElapsedTimer run;
    run.start();
    std::vector<double> ms;
    double frameCpu = 0, serveCpu = 0;
    for (auto _ : state) {
        // A frame interval of event loop (the server's work happens here), then the frame.
        const double cpu0 = threadCpuMs();
        QElapsedTimer gap;
        gap.start();
        while (gap.elapsed() < 16)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 2);
        const double cpu1 = threadCpuMs();
        const double f = plots.frame();
        frameCpu += threadCpuMs() - cpu1;
        serveCpu += cpu1 - cpu0;
        ms.push_back(f);
        state.SetIterationTime(f * 1e-3);
    }
    const double runS = double(run.elapsed()) * 1e-3;
    bench.stageProxy.stopJog(0);
    percentiles(state, ms, "ms", 1, {0.5, 0.95});
    long messages = 0, coalesced = 0, unexplained = 0, dropped = 0;
    for (auto& s : subs) {
        s->stop = true;
        messages += s->messages;
        coalesced += s->coalesced;
        unexplained += s->unexplained;
        dropped += s->dropped;
    }
    subs.clear();
    state.counters["run_s"] = runS;
    state.counters["frame_cpu_ms_mean"] = ms.empty() ? 0 : frameCpu / double(ms.size());
    state.counters["serve_cpu_share"] = serveCpu * 1e-3 / runS;
    if (clients > 0) {
        state.counters["msgs_per_client_s"] = double(messages) / clients / runS;
        state.counters["coalesced_per_client"] = double(coalesced) / clients;
        state.counters["unexplained_gaps"] = double(unexplained);
        state.counters["dropped_total"] = double(dropped);
    }
}

// 60 s of frames at 60 Hz in the full run; a second in CTest's short run.
const int kFrames = shortMode() ? 30 : 3600;

} // namespace

BENCHMARK(BM_PlotRedrawWithClients)->Arg(0)->Arg(10)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kFrames);

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
