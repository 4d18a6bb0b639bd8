// benchpilot: the operator and test-bench GUI.
//   benchpilot [--lang system|en|zh_CN] [--screenshot FILE --screen NAME [--sim analyzer|stage] [--settle-ms N] [--home-first] [--exercise] [--tune] [--recipe FILE]]
#include "main_window.h"
#include "screenshot.h"

#include "widgets/wording/translators.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>

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
    QCommandLineOption lang(QStringLiteral("lang"),
                            QApplication::translate("main", "language of the screens: system, en or zh_CN (default: the Language menu's choice)"),
                            QStringLiteral("language"));
    p.addOptions({shot, screen, sim, settle, script, exercise, tune, recipe, lang});
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
    // Before any window exists, so the first texts are already in the language.
    words::Translators translators;
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
        return app::takeScreenshot(r);
    }
    app::MainWindowOptions options;
    options.translators = &translators;
    app::MainWindow w(options);
    w.show();
    return app.exec();
}
