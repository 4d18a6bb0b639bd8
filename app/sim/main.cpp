// benchpilot-sim: the reference firmware served on a pseudo-terminal.
//   benchpilot-sim --instrument analyzer|stage --pty PATH [--protocol benchpilot|grbl|grblhal]
//                  [--time-scale K] [--baud N]
// --protocol chooses what the firmware speaks over the same machine model: the BenchPilot
// protocol, or the GRBL 1.1 / grblHAL personality (docs/grbl.md).
#include "device/link/simulated_link.h"
#include "device/sim/grbl_firmware.h"
#include "pty_transport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QSocketNotifier>

#include <csignal>
#include <memory>
#include <cstdio>
#include <sys/socket.h>
#include <unistd.h>

namespace {
int g_signalPipe[2] = {-1, -1};
void onSignal(int)
{
    const char c = 1;
    [[maybe_unused]] const auto n = ::write(g_signalPipe[1], &c, 1);
}
int fail(const QString& message)
{
    std::fprintf(stderr, "benchpilot-sim: %s\n", qPrintable(message));
    return 2;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("benchpilot-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(BP_VERSION));
    QCommandLineParser p;
    p.setApplicationDescription(QCoreApplication::translate("sim", "BenchPilot simulated instrument on a pseudo-terminal."));
    p.addHelpOption();
    p.addVersionOption();
    QCommandLineOption instrument({QStringLiteral("i"), QStringLiteral("instrument")},
                                  QCoreApplication::translate("sim", "analyzer or stage"), QStringLiteral("kind"));
    QCommandLineOption ptyPath(QStringLiteral("pty"), QCoreApplication::translate("sim", "symlink to create for the pty"),
                               QStringLiteral("path"));
    QCommandLineOption timeScale(QStringLiteral("time-scale"),
                                 QCoreApplication::translate("sim", "virtual seconds per wall-clock second; above 3 a host refreshing jogs every 50 ms trips the 200 ms jog watchdog"),
                                 QStringLiteral("k"), QStringLiteral("1"));
    QCommandLineOption baud(QStringLiteral("baud"), QCoreApplication::translate("sim", "link speed the firmware assumes"),
                            QStringLiteral("n"), QStringLiteral("115200"));
    QCommandLineOption protocol(QStringLiteral("protocol"),
                                QCoreApplication::translate("sim", "benchpilot, grbl or grblhal"), QStringLiteral("name"),
                                QStringLiteral("benchpilot"));
    p.addOptions({instrument, ptyPath, protocol, timeScale, baud});
    p.process(app);

    const QString kind = p.value(instrument);
    if (kind != QLatin1String("analyzer") && kind != QLatin1String("stage"))
        return fail(QCoreApplication::translate("sim", "--instrument must be analyzer or stage (got '%1')").arg(kind));
    const QString proto = p.value(protocol);
    if (proto != QLatin1String("benchpilot") && proto != QLatin1String("grbl") && proto != QLatin1String("grblhal"))
        return fail(QCoreApplication::translate("sim", "--protocol must be benchpilot, grbl or grblhal (got '%1')").arg(proto));
    if (p.value(ptyPath).isEmpty())
        return fail(QCoreApplication::translate("sim", "--pty PATH is required"));
    bool ok = false;
    const double scale = p.value(timeScale).toDouble(&ok);
    if (!ok || scale <= 0 || scale > 1000)
        return fail(QCoreApplication::translate("sim", "--time-scale must be a number in (0, 1000] (got '%1')").arg(p.value(timeScale)));
    const int baudRate = p.value(baud).toInt(&ok);
    if (!ok || baudRate < 1200)
        return fail(QCoreApplication::translate("sim", "--baud must be at least 1200 (got '%1')").arg(p.value(baud)));

    const QString link = p.value(ptyPath);
    const QFileInfo existing(link);
    if (existing.exists() || existing.isSymLink()) {
        if (!existing.isSymLink())
            return fail(QCoreApplication::translate("sim", "%1 exists and is not a symlink: refusing to replace it").arg(link));
        ::unlink(qPrintable(link));
    }

    simapp::PtyTransport pty;
    if (!pty.create())
        return fail(pty.error());
    if (::symlink(qPrintable(pty.slavePath()), qPrintable(link)) != 0)
        return fail(QCoreApplication::translate("sim", "cannot create symlink %1: %2").arg(link, QString::fromLocal8Bit(strerror(errno))));

    const sim::MachineConfig machine = kind == QLatin1String("stage") ? sim::stageConfig() : sim::analyzerConfig();
    std::unique_ptr<dev::SimulatorHost> host;
    const sim::GrblFirmware* grbl = nullptr;
    if (proto == QLatin1String("benchpilot")) {
        host = std::make_unique<dev::SimulatorHost>(machine, baudRate, &pty);
    } else {
        auto fw = std::make_unique<sim::GrblFirmware>(machine, proto == QLatin1String("grbl") ? sim::GrblFirmware::Dialect::Grbl
                                                                                               : sim::GrblFirmware::Dialect::GrblHal);
        grbl = fw.get();
        host = std::make_unique<dev::SimulatorHost>(std::move(fw), &pty);
    }
    host->setTimeScale(scale);
    host->start();

    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalPipe) != 0)
        return fail(QStringLiteral("socketpair failed"));
    QSocketNotifier sn(g_signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&sn, &QSocketNotifier::activated, &app, [&] { app.quit(); });
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);

    std::printf("%s -> %s (%s, %s, %d baud, time scale %g)\n", qPrintable(link), qPrintable(pty.slavePath()), qPrintable(kind),
                qPrintable(proto), baudRate, scale);
    std::fflush(stdout);
    const int rc = app.exec();
    if (grbl) {
        // The receive buffer's accounting, for the host that streamed to it (and its tests): a host
        // that counts characters never has a byte dropped.
        std::printf("receive buffer: %llu bytes lost, at most %zu of %zu bytes held\n",
                    static_cast<unsigned long long>(grbl->lostRxBytes()), grbl->maxRxBytesQueued(), grbl->rxBufferBytes());
        std::fflush(stdout);
    }
    ::unlink(qPrintable(link));
    pty.close();
    return rc;
}
