// benchpilot: the operator and test-bench GUI.
//   benchpilot [--screenshot FILE --screen NAME [--sim analyzer|stage] [--settle-ms N] [--home-first] [--exercise]]
#include "main_window.h"
#include "screenshot.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("BenchPilot"));
    QApplication::setApplicationName(QStringLiteral("BenchPilot"));
    QCommandLineParser p;
    p.setApplicationDescription(QApplication::translate("main", "BenchPilot operator and test-bench application."));
    p.addHelpOption();
    QCommandLineOption shot(QStringLiteral("screenshot"), QApplication::translate("main", "render a screen to a PNG and exit"),
                            QStringLiteral("file"));
    QCommandLineOption screen(QStringLiteral("screen"), QApplication::translate("main", "screen to show: jog, profiles, …"),
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
    p.addOptions({shot, screen, sim, settle, script, exercise});
    p.process(app);

    if (p.isSet(shot)) {
        app::ScreenshotRequest r;
        r.file = p.value(shot);
        r.screen = p.value(screen);
        r.instrument = p.value(sim);
        r.settleMs = p.value(settle).toInt();
        r.homeFirst = p.isSet(script);
        r.exercise = p.isSet(exercise);
        return app::takeScreenshot(r);
    }
    app::MainWindow w;
    w.show();
    return app.exec();
}
