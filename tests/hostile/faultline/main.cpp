// bp-faultline: a bad cable between a host and benchpilot-sim, on real pseudo-terminals.
//
//   benchpilot-sim --pty /tmp/sim ...   bp-faultline --device /tmp/sim --listen /tmp/bad ...
//   benchpilot-cli --port /tmp/bad ...
//
// It opens the simulator's pty as a client, serves a pty of its own to the host (a
// symlink at --listen, as benchpilot-sim does), and forwards bytes both ways through
// the same seeded fault model as the in-process loopback (dev::FaultyLine over
// dev::LinkFaults): the loopback tests stop at the transport, this reaches QSerialPort,
// the kernel's tty layer and a host process that can be killed.
//
//   --seed N            the line's seed (each direction draws from its own generator)
//   --rate R            R/3 of the bytes corrupted, R/3 dropped, R/3 doubled (each way)
//   --drop P --corrupt P --dup P   per-byte probabilities, instead of or on top of --rate
//   --delay-ms A..B     every write arrives A ms late, plus up to B-A ms of jitter (order kept)
//   --hang-every S --hang-ms M     the line goes silent both ways for M ms every S s
//   --unplug-every S --unplug-ms M the cable is pulled every S s: the host's pty is closed
//                       and its symlink removed (a USB adapter vanishing), then after M ms a
//                       new pty appears at the same path (replugged)
//   SIGUSR1             pull the cable now (back after --unplug-ms); SIGUSR2: hang now
//   --json              a JSON line when listening and one with the counts at exit
// SIGTERM/SIGINT end it; the fault counts are printed then. Test tool: no tr().
#include "app/sim/pty_transport.h"
#include "device/link/link_faults.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSocketNotifier>
#include <QTimer>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <memory>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace {

int g_signalPipe[2] = {-1, -1};
void onSignal(int sig)
{
    const char c = static_cast<char>(sig);
    [[maybe_unused]] const auto n = ::write(g_signalPipe[1], &c, 1);
}

int fail(const QString& message)
{
    std::fprintf(stderr, "bp-faultline: %s\n", qPrintable(message));
    return 2;
}

/// One direction of the cable: the fault model, then a queue that releases each write
/// when its delay is up, never before the write ahead of it (a UART does not reorder).
struct Direction {
    dev::FaultyLine line;
    struct Pending {
        qint64 dueNs;
        QByteArray bytes;
    };
    std::deque<Pending> queue;
    qint64 lastDueNs = 0;
    qint64 carried = 0, lost = 0;  ///< bytes forwarded; bytes thrown away by a hang or an unplug
};

class Faultline : public QObject {
public:
    Faultline(QString devicePath, QString listenPath) : m_devicePath(std::move(devicePath)), m_listenPath(std::move(listenPath))
    {
        m_clock.start();
        m_timer.setSingleShot(true);
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, &Faultline::deliverDue);
    }
    ~Faultline() override
    {
        unplugHost();
        if (m_device >= 0)
            ::close(m_device);
    }

    void setFaults(const dev::LinkFaults& toDevice, const dev::LinkFaults& toHost)
    {
        m_dir[kToDevice].line.setFaults(toDevice);
        m_dir[kToHost].line.setFaults(toHost);
    }
    void setUnplugMs(int ms) { m_unplugMs = ms; }
    void setHangMs(int ms) { m_hangMs = ms; }

    QString openDevice()
    {
        m_device = ::open(qPrintable(m_devicePath), O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (m_device < 0)
            return QStringLiteral("cannot open %1: %2").arg(m_devicePath, QString::fromLocal8Bit(std::strerror(errno)));
        termios t{};
        if (::tcgetattr(m_device, &t) == 0) {
            ::cfmakeraw(&t);
            ::tcsetattr(m_device, TCSANOW, &t);
        }
        m_deviceRead = new QSocketNotifier(m_device, QSocketNotifier::Read, this);
        connect(m_deviceRead, &QSocketNotifier::activated, this, [this] {
            char buf[4096];
            for (;;) {
                const ssize_t n = ::read(m_device, buf, sizeof buf);
                if (n == 0 || (n < 0 && errno == EIO)) {
                    // The simulator closed its end: nothing will come again. Reading on would
                    // spin the notifier at full speed and load the very machine being measured.
                    m_deviceRead->setEnabled(false);
                    std::fprintf(stderr, "bp-faultline: the device closed its end\n");
                    QCoreApplication::quit();
                    return;
                }
                if (n < 0)
                    break;
                send(kToHost, QByteArray(buf, static_cast<qsizetype>(n)));
            }
        });
        m_deviceWrite = new QSocketNotifier(m_device, QSocketNotifier::Write, this);
        m_deviceWrite->setEnabled(false);
        connect(m_deviceWrite, &QSocketNotifier::activated, this, &Faultline::flushDevice);
        return {};
    }

    /// A fresh pty for the host at --listen: at start and at every replug.
    QString plugHost()
    {
        const QFileInfo existing(m_listenPath);
        if (existing.exists() || existing.isSymLink()) {
            if (!existing.isSymLink())
                return QStringLiteral("%1 exists and is not a symlink: refusing to replace it").arg(m_listenPath);
            ::unlink(qPrintable(m_listenPath));
        }
        auto pty = std::make_unique<app::sim::PtyTransport>();
        if (!pty->create())
            return pty->error();
        connect(pty.get(), &dev::Transport::bytesReceived, this, [this](const QByteArray& b) { send(kToDevice, b); });
        if (::symlink(qPrintable(pty->slavePath()), qPrintable(m_listenPath)) != 0)
            return QStringLiteral("cannot create symlink %1: %2").arg(m_listenPath, QString::fromLocal8Bit(std::strerror(errno)));
        m_host = std::move(pty);
        return {};
    }

    /// The cable out: the host's pty goes away (its reads and writes fail, as on a vanished
    /// USB adapter) and nothing in flight arrives.
    void unplugHost()
    {
        if (!m_host)
            return;
        ::unlink(qPrintable(m_listenPath));
        m_host->close();
        m_host.reset();
        for (auto& d : m_dir) {
            for (const auto& p : d.queue)
                d.lost += p.bytes.size();
            d.queue.clear();
        }
    }

    void unplugFor()
    {
        if (!m_host)
            return;
        ++m_unplugs;
        unplugHost();
        QTimer::singleShot(m_unplugMs, this, [this] {
            if (const QString why = plugHost(); !why.isEmpty())
                std::fprintf(stderr, "bp-faultline: replug failed: %s\n", qPrintable(why));
        });
    }

    void hang()
    {
        ++m_hangs;
        m_hungUntilNs = std::max(m_hungUntilNs, m_clock.nsecsElapsed() + qint64(m_hangMs) * 1000000);
    }

    QString hostPtyPath() const { return m_host ? m_host->slavePath() : QString(); }

    QJsonObject counts() const
    {
        auto one = [](const Direction& d) {
            const dev::LinkFaultCounts& c = d.line.counts();
            return QJsonObject{{QStringLiteral("corrupted_bytes"), c.corruptedBytes},
                               {QStringLiteral("dropped_bytes"), c.droppedBytes},
                               {QStringLiteral("duplicated_bytes"), c.duplicatedBytes},
                               {QStringLiteral("dropped_writes"), c.droppedChunks},
                               {QStringLiteral("duplicated_writes"), c.duplicatedChunks},
                               {QStringLiteral("carried_bytes"), d.carried},
                               {QStringLiteral("lost_bytes"), d.lost}};
        };
        return QJsonObject{{QStringLiteral("event"), QStringLiteral("faults")},
                           {QStringLiteral("to_device"), one(m_dir[kToDevice])},
                           {QStringLiteral("to_host"), one(m_dir[kToHost])},
                           {QStringLiteral("damaged_bytes"), m_dir[0].line.counts().damagedBytes() + m_dir[1].line.counts().damagedBytes()},
                           {QStringLiteral("unplugs"), m_unplugs},
                           {QStringLiteral("hangs"), m_hangs}};
    }

private:
    enum { kToDevice = 0, kToHost = 1 };

    void send(int to, const QByteArray& bytes)
    {
        Direction& d = m_dir[to];
        if (m_hungUntilNs > m_clock.nsecsElapsed() || !m_host) {
            d.lost += bytes.size();
            return;
        }
        std::int64_t delayNs = 0;
        QByteArray spoilt = d.line.spoil(bytes, &delayNs);
        if (spoilt.isEmpty())
            return;
        const qint64 due = std::max(m_clock.nsecsElapsed() + delayNs, d.lastDueNs);
        d.lastDueNs = due;
        d.queue.push_back({due, std::move(spoilt)});
        schedule();
    }

    void schedule()
    {
        qint64 next = -1;
        for (const auto& d : m_dir)
            if (!d.queue.empty() && (next < 0 || d.queue.front().dueNs < next))
                next = d.queue.front().dueNs;
        if (next < 0)
            return;
        const qint64 waitNs = next - m_clock.nsecsElapsed();
        const int ms = waitNs <= 0 ? 0 : static_cast<int>((waitNs + 999999) / 1000000);
        if (!m_timer.isActive() || m_timer.remainingTime() > ms)
            m_timer.start(ms);
    }

    void deliverDue()
    {
        const qint64 now = m_clock.nsecsElapsed();
        for (int to = 0; to < 2; ++to) {
            Direction& d = m_dir[to];
            QByteArray out;
            while (!d.queue.empty() && d.queue.front().dueNs <= now) {
                out += d.queue.front().bytes;
                d.queue.pop_front();
            }
            if (out.isEmpty())
                continue;
            d.carried += out.size();
            if (to == kToHost) {
                if (m_host)
                    m_host->write(out);
            } else {
                m_toDevice += out;
                flushDevice();
            }
        }
        schedule();
    }

    void flushDevice()
    {
        while (!m_toDevice.isEmpty()) {
            const ssize_t n = ::write(m_device, m_toDevice.constData(), static_cast<size_t>(m_toDevice.size()));
            if (n <= 0)
                break;
            m_toDevice.remove(0, static_cast<qsizetype>(n));
        }
        m_deviceWrite->setEnabled(!m_toDevice.isEmpty());
    }

    QString m_devicePath, m_listenPath;
    int m_device = -1;
    QSocketNotifier* m_deviceRead = nullptr;
    QSocketNotifier* m_deviceWrite = nullptr;
    QByteArray m_toDevice;  ///< what the simulator's pty could not take yet
    std::unique_ptr<app::sim::PtyTransport> m_host;
    Direction m_dir[2];
    QElapsedTimer m_clock;
    QTimer m_timer;
    qint64 m_hungUntilNs = 0;
    int m_unplugMs = 300, m_hangMs = 500;
    int m_unplugs = 0, m_hangs = 0;
};

bool parseRange(const QString& text, int* lo, int* hi)
{
    const QStringList parts = text.split(QStringLiteral(".."));
    bool ok1 = false, ok2 = true;
    *lo = parts.value(0).toInt(&ok1);
    *hi = parts.size() > 1 ? parts.value(1).toInt(&ok2) : *lo;
    return ok1 && ok2 && parts.size() <= 2 && *lo >= 0 && *hi >= *lo;
}

} // namespace

int main(int argc, char** argv)
{
    // A test tool: when the campaign that started it dies, so does it, instead of holding
    // a simulator's pty for the rest of the session.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    QCoreApplication app(argc, argv);
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral("A fault-injecting pty proxy between a host and benchpilot-sim."));
    p.addHelpOption();
    auto opt = [&](const char* name, const char* help, const char* value = nullptr, const char* def = nullptr) {
        QCommandLineOption o(QString::fromLatin1(name), QString::fromLatin1(help));
        if (value)
            o.setValueName(QString::fromLatin1(value));
        if (def)
            o.setDefaultValue(QString::fromLatin1(def));
        p.addOption(o);
        return o;
    };
    const auto device = opt("device", "the simulator's pty (benchpilot-sim --pty PATH)", "path");
    const auto listen = opt("listen", "symlink to create for the host's pty", "path");
    const auto seed = opt("seed", "the line's seed", "n", "1");
    const auto rate = opt("rate", "bytes damaged, a third each corrupted, dropped and doubled", "p", "0");
    const auto drop = opt("drop", "probability each byte is dropped", "p", "0");
    const auto corrupt = opt("corrupt", "probability each byte has a bit flipped", "p", "0");
    const auto dup = opt("dup", "probability each byte arrives twice", "p", "0");
    const auto delay = opt("delay-ms", "latency of every write, A or A..B (B-A: jitter)", "A..B", "0");
    const auto hangEvery = opt("hang-every", "seconds between hangs (0: none)", "s", "0");
    const auto hangMs = opt("hang-ms", "how long a hang lasts", "ms", "500");
    const auto unplugEvery = opt("unplug-every", "seconds between unplugs (0: none)", "s", "0");
    const auto unplugMs = opt("unplug-ms", "how long the cable stays out", "ms", "300");
    const auto json = opt("json", "print JSON lines (listening, and the counts at exit)");
    p.process(app);

    if (p.value(device).isEmpty() || p.value(listen).isEmpty())
        return fail(QStringLiteral("--device PATH and --listen PATH are required"));
    bool ok = true;
    auto number = [&](const QCommandLineOption& o, double lo, double hi) {
        bool good = false;
        const double v = p.value(o).toDouble(&good);
        if (!good || v < lo || v > hi) {
            fail(QStringLiteral("--%1 must be a number in [%2, %3] (got '%4')").arg(o.names().first()).arg(lo).arg(hi).arg(p.value(o)));
            ok = false;
        }
        return v;
    };
    const auto seedValue = static_cast<std::uint64_t>(number(seed, 0, 1e15));
    dev::LinkFaults f = dev::LinkFaults::bytes(number(rate, 0, 0.5), 0);
    f.dropByteProbability += number(drop, 0, 0.5);
    f.corruptByteProbability += number(corrupt, 0, 0.5);
    f.duplicateByteProbability += number(dup, 0, 0.5);
    int delayLo = 0, delayHi = 0;
    if (!parseRange(p.value(delay), &delayLo, &delayHi))
        return fail(QStringLiteral("--delay-ms must be A or A..B with 0 <= A <= B (got '%1')").arg(p.value(delay)));
    f.extraDelayMs = delayLo;
    f.jitterMs = delayHi - delayLo;
    const double hangS = number(hangEvery, 0, 86400), unplugS = number(unplugEvery, 0, 86400);
    const int hangLength = static_cast<int>(number(hangMs, 1, 600000)), unplugLength = static_cast<int>(number(unplugMs, 1, 600000));
    if (!ok)
        return 2;
    // The same seeds per direction as the in-process campaign (hostile::spoil).
    dev::LinkFaults toDevice = f, toHost = f;
    toDevice.seed = seedValue * 2 + 1;
    toHost.seed = seedValue * 2 + 2;

    Faultline line(p.value(device), p.value(listen));
    line.setFaults(toDevice, toHost);
    line.setHangMs(hangLength);
    line.setUnplugMs(unplugLength);
    if (const QString why = line.openDevice(); !why.isEmpty())
        return fail(why);
    if (const QString why = line.plugHost(); !why.isEmpty())
        return fail(why);

    QTimer hangTimer, unplugTimer;
    if (hangS > 0) {
        QObject::connect(&hangTimer, &QTimer::timeout, &line, [&] { line.hang(); });
        hangTimer.start(static_cast<int>(hangS * 1000));
    }
    if (unplugS > 0) {
        QObject::connect(&unplugTimer, &QTimer::timeout, &line, [&] { line.unplugFor(); });
        unplugTimer.start(static_cast<int>(unplugS * 1000));
    }

    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalPipe) != 0)
        return fail(QStringLiteral("socketpair failed"));
    QSocketNotifier sn(g_signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&sn, &QSocketNotifier::activated, &app, [&] {
        char c = 0;
        if (::read(g_signalPipe[0], &c, 1) != 1)
            return;
        if (c == SIGUSR1)
            line.unplugFor();
        else if (c == SIGUSR2)
            line.hang();
        else
            app.quit();
    });
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGUSR1, onSignal);
    std::signal(SIGUSR2, onSignal);

    if (p.isSet(json))
        std::printf("%s\n", QJsonDocument(QJsonObject{{QStringLiteral("event"), QStringLiteral("listening")},
                                                      {QStringLiteral("listen"), p.value(listen)},
                                                      {QStringLiteral("pty"), line.hostPtyPath()},
                                                      {QStringLiteral("device"), p.value(device)}})
                                .toJson(QJsonDocument::Compact)
                                .constData());
    else
        std::printf("%s -> %s, forwarding to %s (seed %llu)\n", qPrintable(p.value(listen)), qPrintable(line.hostPtyPath()),
                    qPrintable(p.value(device)), static_cast<unsigned long long>(seedValue));
    std::fflush(stdout);
    const int rc = app.exec();
    const QJsonObject c = line.counts();
    if (p.isSet(json)) {
        std::printf("%s\n", QJsonDocument(c).toJson(QJsonDocument::Compact).constData());
    } else {
        for (const char* dir : {"to_device", "to_host"}) {
            const QJsonObject d = c.value(QLatin1String(dir)).toObject();
            std::printf("%s: %lld corrupted, %lld dropped, %lld doubled bytes; %lld carried, %lld lost to hangs and unplugs\n", dir,
                        static_cast<long long>(d.value(QStringLiteral("corrupted_bytes")).toDouble()),
                        static_cast<long long>(d.value(QStringLiteral("dropped_bytes")).toDouble()),
                        static_cast<long long>(d.value(QStringLiteral("duplicated_bytes")).toDouble()),
                        static_cast<long long>(d.value(QStringLiteral("carried_bytes")).toDouble()),
                        static_cast<long long>(d.value(QStringLiteral("lost_bytes")).toDouble()));
        }
        std::printf("%d unplugs, %d hangs\n", c.value(QStringLiteral("unplugs")).toInt(), c.value(QStringLiteral("hangs")).toInt());
    }
    std::fflush(stdout);
    line.unplugHost();
    return rc;
}
