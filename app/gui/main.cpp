// benchpilot: the operator and test-bench GUI.
//   benchpilot [--lang system|en|zh_CN] [--sim analyzer|stage [--stage-errors FILE] [--specimen NAME]] [--port PATH [--instrument analyzer|stage] [--profile FILE] [--baud N]]
//   benchpilot [--api-socket PATH | --no-api] [--api-websocket PORT [--api-token-file FILE] [--api-allow-origin URL]...]
//   benchpilot [--lang …] --screenshot FILE --screen NAME [--size WxH] [--sim analyzer|stage] [--settle-ms N] [--home-first] [--exercise] [--tune] [--recipe FILE]
#include "main_window.h"
#include "screenshot.h"
#include "app/cli/command.h"

#include "device/backends/protocol_probe.h"
#include "device/camera/specimen.h"
#include "app/common/version_text.h"
#include "device/files/accuracy/grid/stage_errors_file.h"
#include "device/files/machine_profile_file.h"
#include "device/files/shipped_data.h"
#include "device/link/serial_transport.h"

#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include <QApplication>
#include <QIcon>
#include <QCommandLineParser>
#include <QEventLoop>
#include <QFileInfo>
#include <QSettings>
#include <QTimer>

#include <cstdio>

namespace {

/// Which instrument a port is, when nobody said: a BenchPilot device tells in its HELLO; a GRBL
/// controller does not (the analyzer then, as the CLI takes it). Errors are the connection's to
/// tell later; here they only leave the analyzer.
dev::proto::DeviceKind detectInstrument(const QString& port, qint32 baud)
{
    dev::SerialTransport transport(port, baud);
    dev::ProtocolProbe probe(&transport);
    QEventLoop loop;
    QObject::connect(&probe, &dev::ProtocolProbe::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(dev::ProtocolProbe::kLongestMs + 2000, &loop, &QEventLoop::quit);
    probe.start();
    if (!probe.done())
        loop.exec();
    transport.close();
    const dev::ProbeResult& r = probe.result();
    if (r.protocol == dev::ProbeResult::Protocol::None)
        std::fprintf(stderr, "benchpilot: %s\n", qPrintable(ui::words::text(r.error)));
    return r.kindKnown ? r.kind : dev::proto::DeviceKind::Analyzer;
}

int kindIndex(dev::proto::DeviceKind k) { return k == dev::proto::DeviceKind::Stage ? 1 : 0; }

} // namespace

int main(int argc, char** argv)
{
    QStringList args;
    for (int i = 0; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    QCommandLineParser p;
    p.setApplicationDescription(QApplication::translate("main", "BenchPilot operator and test-bench application."));
    p.addHelpOption();
    p.addVersionOption();
    QCommandLineOption shot(QStringLiteral("screenshot"), QApplication::translate("main", "render a screen to a PNG and exit"),
                            QStringLiteral("file"));
    QCommandLineOption screen(QStringLiteral("screen"), QApplication::translate("main", "screen to show: jog, plots, profiles, …"),
                              QStringLiteral("name"), QStringLiteral("jog"));
    QCommandLineOption sim(QStringLiteral("sim"),
                           QApplication::translate("main", "connect this instrument to its in-process simulator and show it "
                                                           "(analyzer or stage; also the instrument a screenshot shows)"),
                           QStringLiteral("kind"), QStringLiteral("analyzer"));
    QCommandLineOption stageErrors(QStringLiteral("stage-errors"),
                                   QApplication::translate("main", "with --sim stage: the simulated stage's errors from a "
                                                                   "benchpilot.stage-errors file"),
                                   QStringLiteral("file"));
    QCommandLineOption specimen(QStringLiteral("specimen"),
                                QApplication::translate("main", "with --sim stage: what the simulated camera sees on the stage: slide, "
                                                                "grid-plate or line-scales"),
                                QStringLiteral("name"), QStringLiteral("slide"));
    QCommandLineOption port(QStringLiteral("port"),
                            QApplication::translate("main", "connect to this serial port or path (e.g. benchpilot-sim's pty); the "
                                                            "protocol is detected: BenchPilot or GRBL"),
                            QStringLiteral("path"));
    QCommandLineOption instrument(QStringLiteral("instrument"),
                                  QApplication::translate("main", "with --port: which instrument it is, analyzer or stage (default: what "
                                                                  "the device says; a GRBL controller: the profile's, else the analyzer)"),
                                  QStringLiteral("kind"));
    QCommandLineOption profile(QStringLiteral("profile"),
                               QApplication::translate("main", "with --port: the machine profile of a GRBL controller, a file or the name of one BenchPilot ships (stage-grbl-uno; docs/grbl.md)"),
                               QStringLiteral("file"));
    QCommandLineOption baud(QStringLiteral("baud"), QApplication::translate("main", "with --port: the link speed"), QStringLiteral("N"),
                            QStringLiteral("115200"));
    QCommandLineOption size(QStringLiteral("size"),
                            QApplication::translate("main", "screenshot: the window's size, e.g. 1366x768 (a window that cannot "
                                                            "shrink to it shows as a larger picture)"),
                            QStringLiteral("WxH"), QStringLiteral("1600x1000"));
    QCommandLineOption settle(QStringLiteral("settle-ms"),
                              QApplication::translate("main", "screenshot: how long the simulators run first"),
                              QStringLiteral("ms"), QStringLiteral("1500"));
    QCommandLineOption script(QStringLiteral("home-first"),
                              QApplication::translate("main", "screenshot: home the shown instrument and move it before the picture"));
    QCommandLineOption exercise(QStringLiteral("exercise"),
                                QApplication::translate("main", "screenshot: jog and move the shown instrument so live plots show motion"));
    QCommandLineOption tune(QStringLiteral("tune"),
                            QApplication::translate("main", "screenshot: tune the stage's X axis (relay, then a step test) on the tuning screen"));
    QCommandLineOption recipe(QStringLiteral("recipe"),
                              QApplication::translate("main", "screenshot: open this recipe on the Plates screen, home the analyzer and run it"),
                              QStringLiteral("file"));
    QCommandLineOption apiSocket(QStringLiteral("api-socket"),
                                 QApplication::translate("main", "where the scripting API listens (default: %1)").arg(app::cli::defaultApiSocketPath()),
                                 QStringLiteral("path"));
    QCommandLineOption noApi(QStringLiteral("no-api"), QApplication::translate("main", "do not start the scripting API"));
    QCommandLineOption apiWebSocket(QStringLiteral("api-websocket"),
                                    QApplication::translate("main", "also serve the API as a WebSocket on 127.0.0.1:port (off by default)"),
                                    QStringLiteral("port"));
    QCommandLineOption apiToken(QStringLiteral("api-token-file"),
                                QApplication::translate("main", "the WebSocket's token file, 0600 (default: api.token beside the socket)"),
                                QStringLiteral("file"));
    QCommandLineOption apiOrigin(QStringLiteral("api-allow-origin"),
                                 QApplication::translate("main", "a browser Origin the WebSocket accepts (repeat for more; none by default)"),
                                 QStringLiteral("url"));
    QCommandLineOption lang(QStringLiteral("lang"),
                            QApplication::translate("main", "language of the screens: system, en or zh_CN (default: the Language menu's choice)"),
                            QStringLiteral("language"));
    p.addOptions({sim, stageErrors, specimen, port, instrument, profile, baud, shot, screen, size, settle, script, exercise, tune, recipe, lang,
                  apiSocket, noApi, apiWebSocket, apiToken, apiOrigin});
    QCoreApplication::setOrganizationName(QStringLiteral("BenchPilot"));
    QCoreApplication::setApplicationName(QStringLiteral("benchpilot"));
    QCoreApplication::setApplicationVersion(QStringLiteral(BP_VERSION));
    // Help and version answer before QApplication exists, so they work on a machine
    // without a display (over ssh, in a build script). Everything else is parsed
    // after QApplication has taken its own options (-platform, -style, …) out.
    for (const QString& a : args.mid(1)) {
        if (a == QLatin1String("--"))
            break;
        if (a == QLatin1String("-h") || a == QLatin1String("--help") || a == QLatin1String("-?")) {
            std::fputs(qPrintable(p.helpText().replace(QLatin1String("<executable_name>"), QLatin1String("benchpilot"))), stdout);
            return 0;
        }
        if (a == QLatin1String("-v") || a == QLatin1String("--version")) {
            std::fputs(app::versionText("benchpilot").c_str(), stdout);
            return 0;
        }
    }

    QApplication app(argc, argv);
    // Settings stay where earlier versions kept them.
    QApplication::setApplicationName(QStringLiteral("BenchPilot"));
    // The icon the installed desktop entry names (the theme's when installed, else the
    // one built in), and the entry itself, so a Wayland shell groups the window with it.
    Q_INIT_RESOURCE(resources);  // resources.qrc is in gui_lib, a static library
    QIcon builtIn;
    for (int px : {16, 32, 48, 64, 128, 256})
        builtIn.addFile(QStringLiteral(":/icons/hicolor/%1x%1/benchpilot.png").arg(px), QSize(px, px));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("io.github.benchpilot.BenchPilot"), builtIn));
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.benchpilot.BenchPilot"));
    p.process(app);  // prints a wrong option and exits 1
    if (!p.positionalArguments().isEmpty()) {
        std::fprintf(stderr, "benchpilot: unexpected argument '%s'\ntry 'benchpilot --help'\n", qPrintable(p.positionalArguments().first()));
        return 1;
    }
    // Before any window exists, so the first texts are already in the language.
    ui::words::Translators translators;
    const QString language = p.isSet(lang) ? p.value(lang) : QSettings().value(QStringLiteral("language"), QStringLiteral("system")).toString();
    if (!translators.setLanguage(language) && p.isSet(lang)) {
        std::fprintf(stderr, "benchpilot: --lang '%s': no such language (system, en, zh_CN)\n", qPrintable(language));
        return 1;
    }
    if (p.isSet(shot)) {
        app::ScreenshotRequest r;
        r.file = p.value(shot);
        r.screen = p.value(screen);
        r.instrument = p.value(sim);
        r.settleMs = p.value(settle).toInt();
        r.homeFirst = p.isSet(script);
        r.exercise = p.isSet(exercise);
        r.tune = p.isSet(tune);
        r.recipe = p.value(recipe);
        const QStringList wh = p.value(size).split(QLatin1Char('x'));
        bool okW = false, okH = false;
        if (wh.size() == 2)
            r.size = QSize(wh[0].toInt(&okW), wh[1].toInt(&okH));
        if (!okW || !okH || r.size.width() < 200 || r.size.height() < 150) {
            std::fprintf(stderr, "benchpilot: --size needs WIDTHxHEIGHT, e.g. 1366x768 (got '%s')\n", qPrintable(p.value(size)));
            return 1;
        }
        return app::takeScreenshot(r);
    }
    // --sim and --port say what to connect this time (over what was remembered).
    app::MainWindowOptions options;
    options.translators = &translators;
    auto fail = [](const QString& m) {
        std::fprintf(stderr, "benchpilot: %s\ntry 'benchpilot --help'\n", qPrintable(m));
        return 1;
    };
    auto kindOf = [](const QString& v) -> std::optional<dev::proto::DeviceKind> {
        if (v == QLatin1String("analyzer"))
            return dev::proto::DeviceKind::Analyzer;
        if (v == QLatin1String("stage"))
            return dev::proto::DeviceKind::Stage;
        return std::nullopt;
    };
    if ((p.isSet(instrument) || p.isSet(profile)) && !p.isSet(port))
        return fail(QApplication::translate("main", "--instrument and --profile go with --port"));
    if (p.isSet(sim)) {
        const auto k = kindOf(p.value(sim));
        if (!k)
            return fail(QApplication::translate("main", "--sim needs 'analyzer' or 'stage' (got '%1')").arg(p.value(sim)));
        ui::ConnectionChoice c;
        if (p.isSet(stageErrors)) {
            if (*k != dev::proto::DeviceKind::Stage)
                return fail(QApplication::translate("main", "--stage-errors is for the simulated stage: give --sim stage"));
            const auto read = dev::files::accuracy::loadStageErrorsFile(p.value(stageErrors));
            if (!read.ok())
                return fail(QApplication::translate("main", "--stage-errors: %1").arg(ui::words::problems(read.problems()).join(QLatin1Char('\n'))));
            c.stageErrors = *read;
        }
        options.connection[kindIndex(*k)] = c;
        options.showInstrument = kindIndex(*k);
    } else if (p.isSet(stageErrors)) {
        return fail(QApplication::translate("main", "--stage-errors is for the simulated stage: give --sim stage"));
    }
    if (p.isSet(specimen)) {
        const auto kind = dev::camera::specimenFromName(p.value(specimen).toStdString());
        if (!kind)
            return fail(QApplication::translate("main", "--specimen must be slide, grid-plate or line-scales (got '%1')").arg(p.value(specimen)));
        options.specimen = *kind;
    }
    if (p.isSet(port)) {
        bool ok = false;
        const qint32 rate = p.value(baud).toInt(&ok);
        if (!ok || rate < 1200)
            return fail(QApplication::translate("main", "--baud needs a rate of at least 1200 (got '%1')").arg(p.value(baud)));
        std::optional<dev::proto::DeviceKind> k;
        if (p.isSet(instrument) && !(k = kindOf(p.value(instrument))))
            return fail(QApplication::translate("main", "--instrument needs 'analyzer' or 'stage' (got '%1')").arg(p.value(instrument)));
        const QString profileFile = p.isSet(profile) ? dev::files::resolveMachineProfile(p.value(profile)) : QString();
        if (p.isSet(profile)) {
            dev::files::MachineProfile mp;
            dev::files::json::Problems problems;
            if (!dev::files::loadMachineProfileFile(profileFile, &mp, &problems))
                return fail(QApplication::translate("main", "--profile: %1")
                                .arg(ui::words::fileProblems(problems, QFileInfo(profileFile).fileName()).join(QLatin1Char('\n'))));
            if (k && *k != mp.instrument)
                return fail(QApplication::translate("main", "--profile is for the other instrument than --instrument names"));
            k = mp.instrument;
        }
        if (!k)
            k = detectInstrument(p.value(port), rate);
        if (options.connection[kindIndex(*k)] && p.isSet(sim))
            return fail(QApplication::translate("main", "--sim and --port name the same instrument"));
        ui::ConnectionChoice c;
        c.simulator = false;
        c.port = p.value(port);
        c.baud = rate;
        c.profile = profileFile;
        options.connection[kindIndex(*k)] = c;
        options.showInstrument = kindIndex(*k);
    }
    if (!p.isSet(noApi)) {
        options.api.socketPath = p.isSet(apiSocket) ? p.value(apiSocket) : app::cli::defaultApiSocketPath();
        if (p.isSet(apiWebSocket)) {
            bool ok = false;
            const uint wsPort = p.value(apiWebSocket).toUInt(&ok);
            if (!ok || wsPort == 0 || wsPort > 65535) {
                std::fprintf(stderr, "benchpilot: --api-websocket needs a port (1-65535), got '%s'\n", qPrintable(p.value(apiWebSocket)));
                return 1;
            }
            options.api.webSocketPort = static_cast<quint16>(wsPort);
        }
        options.api.tokenFile = p.value(apiToken);
        options.api.allowedOrigins = p.values(apiOrigin);
    }
    app::MainWindow w(options);
    w.show();
    return app.exec();
}
