// benchpilot-sim: the reference firmware served on a pseudo-terminal.
//   benchpilot-sim --instrument analyzer|stage --pty PATH [--protocol benchpilot|grbl|grblhal]
//                  [--time-scale K] [--baud N]
//                  [--gauge PATH --gauge-axis X [--gauge-resolution MM] [--gauge-noise MM]]
//                  [--journal FILE] [--no-homing] [--stage-errors FILE]
//                  [--camera-socket PATH [--specimen NAME] [--camera-seed N]
//                                        [--camera-sensor W,H] [--camera-pixel-um UM]]
// --protocol chooses what the firmware speaks over the same machine model: the BenchPilot
// protocol, or the GRBL 1.1 / grblHAL personality (docs/grbl.md).
// The GRBL board runs on when a host opens the port, as most grblHAL boards do (a board that
// restarts then is played in-process: GrblFirmware::setRestartsOnPortOpen). --no-homing: a GRBL
// board without homing switches ($22=0), Idle at power-up.
// --gauge serves a simulated length gauge on a second pty: it answers "?" + CR with the
// true position of one axis' work point (docs/accuracy.md, "Gauge dialect"), which the
// instrument's own encoder or grating does not see.
// --stage-errors gives the stage the errors of a benchpilot.stage-errors file (pitch,
// straightness, squareness, lost motion at the work point; docs/accuracy.md).
// --camera-socket serves the simulated camera on a local socket beside the pty: it renders the
// specimen at the stage's TRUE work point, which only this process knows, for the camera
// sim:PATH of benchpilot-cli or the GUI (docs/camera.md). The socket is removed on exit.
#include "device/link/simulated_link.h"
#include "device/sim/grbl_firmware.h"
#include "app/common/version_text.h"
#include "device/files/accuracy/grid/stage_errors_file.h"
#include "device/camera/sim_camera_server.h"
#include "device/sim/sim_gauge.h"
#include "widgets/wording/wording.h"
#include "camera_options.h"
#include "journal_file.h"
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
    QCommandLineOption gaugePath(QStringLiteral("gauge"),
                                 QCoreApplication::translate("sim", "symlink to create for a simulated gauge's pty"),
                                 QStringLiteral("path"));
    QCommandLineOption gaugeAxis(QStringLiteral("gauge-axis"),
                                 QCoreApplication::translate("sim", "the axis whose work point the gauge reads"),
                                 QStringLiteral("letter"), QStringLiteral("X"));
    QCommandLineOption gaugeResolution(QStringLiteral("gauge-resolution"),
                                       QCoreApplication::translate("sim", "the gauge's last digit in mm"), QStringLiteral("mm"),
                                       QStringLiteral("0.0001"));
    QCommandLineOption gaugeNoise(QStringLiteral("gauge-noise"),
                                  QCoreApplication::translate("sim", "standard deviation of the gauge's noise in mm"),
                                  QStringLiteral("mm"), QStringLiteral("0.0001"));
    QCommandLineOption journal(QStringLiteral("journal"),
                               QCoreApplication::translate("sim", "write what the firmware executed to this file when stopped (benchpilot protocol only)"),
                               QStringLiteral("file"));
    QCommandLineOption noHoming(QStringLiteral("no-homing"),
                                QCoreApplication::translate("sim", "the GRBL board has no homing switches ($22=0)"));
    QCommandLineOption stageErrors(QStringLiteral("stage-errors"),
                                   QCoreApplication::translate("sim", "the stage's errors from a benchpilot.stage-errors file"),
                                   QStringLiteral("file"));
    p.addOptions({instrument, ptyPath, protocol, timeScale, baud, gaugePath, gaugeAxis, gaugeResolution, gaugeNoise, journal, noHoming,
                  stageErrors});
    const app::sim::CameraOptions cameraOptions;
    cameraOptions.addTo(p);
    // --version gives the licence too (app/common/version_text.h), not Qt's bare line.
    for (const QString& a : QCoreApplication::arguments().mid(1)) {
        if (a == QLatin1String("--"))
            break;
        if (a == QLatin1String("-v") || a == QLatin1String("--version")) {
            std::fputs(app::versionText("benchpilot-sim").c_str(), stdout);
            return 0;
        }
    }
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

    if (p.isSet(noHoming) && proto == QLatin1String("benchpilot"))
        return fail(QCoreApplication::translate("sim", "--no-homing is for the GRBL personality (--protocol grbl or grblhal)"));
    if (p.isSet(journal) && proto != QLatin1String("benchpilot"))
        return fail(QCoreApplication::translate("sim", "--journal records the benchpilot protocol's requests only"));

    dev::sim::MachineConfig machine = kind == QLatin1String("stage") ? dev::sim::stageConfig() : dev::sim::analyzerConfig();
    if (p.isSet(stageErrors)) {
        if (kind != QLatin1String("stage"))
            return fail(QCoreApplication::translate("sim", "--stage-errors is for the simulated stage (--instrument stage)"));
        const auto read = dev::files::accuracy::loadStageErrorsFile(p.value(stageErrors));
        if (!read.ok())
            return fail(ui::words::problems(read.problems()).join(QLatin1Char('\n')));
        dev::sim::applyStageErrors(machine, *read);
    }
    const QString gaugeLink = p.value(gaugePath);
    int gaugeAxisIndex = -1;
    dev::sim::GaugeConfig gaugeConfig;
    if (!gaugeLink.isEmpty()) {
        const QString letter = p.value(gaugeAxis).trimmed().toUpper();
        for (std::size_t i = 0; i < machine.axes.size(); ++i)
            if (letter.size() == 1 && machine.axes[i].letter == letter.at(0).toLatin1())
                gaugeAxisIndex = static_cast<int>(i);
        if (gaugeAxisIndex < 0)
            return fail(QCoreApplication::translate("sim", "--gauge-axis: the %1 has no axis '%2'").arg(kind, p.value(gaugeAxis)));
        gaugeConfig.resolutionMm = p.value(gaugeResolution).toDouble(&ok);
        if (!ok || !(gaugeConfig.resolutionMm >= 1e-6 && gaugeConfig.resolutionMm <= 0.1))
            return fail(QCoreApplication::translate("sim", "--gauge-resolution must be from 0.000001 to 0.1 mm (got '%1')")
                            .arg(p.value(gaugeResolution)));
        gaugeConfig.noiseMm = p.value(gaugeNoise).toDouble(&ok);
        if (!ok || !(gaugeConfig.noiseMm >= 0 && gaugeConfig.noiseMm <= 1))
            return fail(QCoreApplication::translate("sim", "--gauge-noise must be from 0 to 1 mm (got '%1')").arg(p.value(gaugeNoise)));
        if (gaugeLink == p.value(ptyPath))
            return fail(QCoreApplication::translate("sim", "--gauge needs a path of its own, not the instrument's"));
    }

    app::sim::CameraChoice camera;
    if (QString why; !cameraOptions.read(p, kind, {p.value(ptyPath), gaugeLink}, &camera, &why))
        return fail(why);

    auto claimLink = [](const QString& path) -> QString {
        const QFileInfo existing(path);
        if (existing.exists() || existing.isSymLink()) {
            if (!existing.isSymLink())
                return QCoreApplication::translate("sim", "%1 exists and is not a symlink: refusing to replace it").arg(path);
            ::unlink(qPrintable(path));
        }
        return {};
    };
    const QString link = p.value(ptyPath);
    if (const QString why = claimLink(link); !why.isEmpty())
        return fail(why);
    app::sim::PtyTransport pty;
    if (!pty.create())
        return fail(pty.error());
    if (::symlink(qPrintable(pty.slavePath()), qPrintable(link)) != 0)
        return fail(QCoreApplication::translate("sim", "cannot create symlink %1: %2").arg(link, QString::fromLocal8Bit(strerror(errno))));

    std::unique_ptr<dev::SimulatorHost> host;
    const dev::sim::GrblFirmware* grbl = nullptr;
    dev::sim::SimMachine* simMachine = nullptr;
    if (proto == QLatin1String("benchpilot")) {
        host = std::make_unique<dev::SimulatorHost>(machine, baudRate, &pty);
        simMachine = &host->firmware().machine();
    } else {
        auto fw = std::make_unique<dev::sim::GrblFirmware>(machine, proto == QLatin1String("grbl") ? dev::sim::GrblFirmware::Dialect::Grbl
                                                                                               : dev::sim::GrblFirmware::Dialect::GrblHal);
        if (p.isSet(noHoming)) {
            fw->settings().write(22, 0);
            fw->restart();  // powered up so: Idle, no homing lock
        }
        grbl = fw.get();
        simMachine = &fw->machine();
        host = std::make_unique<dev::SimulatorHost>(std::move(fw), &pty);
    }
    host->setTimeScale(scale);
    // The camera reads the machine on this thread, where the firmware runs, when a request arrives.
    std::unique_ptr<dev::camera::SimCameraServer> cameraServer;
    if (camera.serve) {
        cameraServer = std::make_unique<dev::camera::SimCameraServer>(
            [simMachine]() -> std::optional<dev::camera::WorkPoint> {
                const auto at = simMachine->trueWorkPoint();
                return dev::camera::WorkPoint{at.xMm, at.yMm, simMachine->timeUs()};
            },
            camera.settings);
        motion::msg::Message why;
        if (!cameraServer->listen(camera.path, &why)) {
            ::unlink(qPrintable(link));
            return fail(ui::words::text(why));
        }
    }
    if (p.isSet(journal))
        host->firmware().setJournal(true);
    host->start();

    // The gauge: a second pty whose device end answers from the same machine.
    app::sim::PtyTransport gaugePty;
    std::unique_ptr<dev::SimulatorHost> gaugeHost;
    if (!gaugeLink.isEmpty()) {
        if (const QString why = claimLink(gaugeLink); !why.isEmpty())
            return fail(why);
        if (!gaugePty.create())
            return fail(gaugePty.error());
        if (::symlink(qPrintable(gaugePty.slavePath()), qPrintable(gaugeLink)) != 0)
            return fail(QCoreApplication::translate("sim", "cannot create symlink %1: %2")
                            .arg(gaugeLink, QString::fromLocal8Bit(strerror(errno))));
        gaugeHost = std::make_unique<dev::SimulatorHost>(
            std::make_unique<dev::sim::SimGauge>([simMachine, gaugeAxisIndex] { return simMachine->workPointLogical(gaugeAxisIndex); },
                                            gaugeConfig),
            &gaugePty);
        gaugeHost->setManualClock(true);  // it answers when asked; nothing to run between requests
        gaugeHost->start();
    }

    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalPipe) != 0)
        return fail(QStringLiteral("socketpair failed"));
    QSocketNotifier sn(g_signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&sn, &QSocketNotifier::activated, &app, [&] { app.quit(); });
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);

    std::printf("%s -> %s (%s, %s, %d baud, time scale %g)\n", qPrintable(link), qPrintable(pty.slavePath()), qPrintable(kind),
                qPrintable(proto), baudRate, scale);
    if (gaugeHost)
        std::printf("gauge %s -> %s (axis %c, resolution %g mm, noise %g mm)\n", qPrintable(gaugeLink),
                    qPrintable(gaugePty.slavePath()), machine.axes[static_cast<std::size_t>(gaugeAxisIndex)].letter,
                    gaugeConfig.resolutionMm, gaugeConfig.noiseMm);
    if (cameraServer)
        std::printf("camera %s (%s, seed %llu)\n", qPrintable(camera.path), dev::camera::specimenName(camera.settings.specimen),
                    static_cast<unsigned long long>(camera.settings.seed));
    std::fflush(stdout);
    const int rc = app.exec();
    if (cameraServer)
        cameraServer->close();  // removes the socket, as the pty's symlink below
    if (grbl) {
        // The receive buffer's accounting, for the host that streamed to it (and its tests): a host
        // that counts characters never has a byte dropped.
        std::printf("receive buffer: %llu bytes lost, at most %zu of %zu bytes held\n",
                    static_cast<unsigned long long>(grbl->lostRxBytes()), grbl->maxRxBytesQueued(), grbl->rxBufferBytes());
        std::fflush(stdout);
    }
    if (p.isSet(journal)) {
        QString why;
        if (!app::sim::writeJournal(host->firmware(), p.value(journal), &why))
            std::fprintf(stderr, "benchpilot-sim: cannot write the journal %s: %s\n", qPrintable(p.value(journal)), qPrintable(why));
    }
    ::unlink(qPrintable(link));
    pty.close();
    if (gaugeHost) {
        ::unlink(qPrintable(gaugeLink));
        gaugePty.close();
    }
    return rc;
}
