// benchpilot: the operator and test-bench GUI.
//   benchpilot [--api-socket PATH | --no-api] [--api-websocket PORT [--api-token-file FILE] [--api-allow-origin URL]...]
//   benchpilot --screenshot FILE --screen NAME [--sim analyzer|stage] [--settle-ms N] [--home-first] [--exercise] [--tune] [--recipe FILE]
#include "main_window.h"
#include "screenshot.h"
#include "app/cli/command.h"

#include <QApplication>
#include <QCommandLineParser>

#include <cstdio>

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
    QCommandLineOption sim(QStringLiteral("sim"), QApplication::translate("main", "instrument to show: analyzer or stage"),
                           QStringLiteral("kind"), QStringLiteral("analyzer"));
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
                                 QApplication::translate("main", "where the scripting API listens (default: %1)").arg(cli::defaultApiSocketPath()),
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
    p.addOptions({shot, screen, sim, settle, script, exercise, tune, recipe, apiSocket, noApi, apiWebSocket, apiToken, apiOrigin});
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
            std::printf("benchpilot %s\n", BP_VERSION);
            return 0;
        }
    }

    QApplication app(argc, argv);
    // Settings stay where earlier versions kept them.
    QApplication::setApplicationName(QStringLiteral("BenchPilot"));
    p.process(app);  // prints a wrong option and exits 1
    if (!p.positionalArguments().isEmpty()) {
        std::fprintf(stderr, "benchpilot: unexpected argument '%s'\ntry 'benchpilot --help'\n", qPrintable(p.positionalArguments().first()));
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
        return app::takeScreenshot(r);
    }
    app::MainWindowOptions options;
    if (!p.isSet(noApi)) {
        options.api.socketPath = p.isSet(apiSocket) ? p.value(apiSocket) : cli::defaultApiSocketPath();
        if (p.isSet(apiWebSocket)) {
            bool ok = false;
            const uint port = p.value(apiWebSocket).toUInt(&ok);
            if (!ok || port == 0 || port > 65535) {
                std::fprintf(stderr, "benchpilot: --api-websocket needs a port (1-65535), got '%s'\n", qPrintable(p.value(apiWebSocket)));
                return 1;
            }
            options.api.webSocketPort = static_cast<quint16>(port);
        }
        options.api.tokenFile = p.value(apiToken);
        options.api.allowedOrigins = p.values(apiOrigin);
    }
    app::MainWindow w(options);
    w.show();
    return app.exec();
}
