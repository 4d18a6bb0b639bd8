// benchpilot-cli: scripts the instruments and the motion library. The commands
// are in this folder, one area a file; cli.cpp parses the command line.
#include "command.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QTextStream>

#include <unistd.h>

int main(int argc, char** argv)
{
    // A Gui application, offscreen, so `accuracy run` can draw its PDF report without a
    // display; nothing is ever shown.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // The platform plugin wants a runtime directory and complains on stderr without one
    // (a script reading stderr would see it): give it a private one. --attach still looks
    // for the GUI where the user's own environment says (app::cli::defaultApiSocketPath).
    app::cli::noteUsersRuntimeDir();
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QString dir = QDir::tempPath() + QStringLiteral("/benchpilot-runtime-%1").arg(::getuid());
        QDir().mkpath(dir);
        QFile::setPermissions(dir, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        qputenv("XDG_RUNTIME_DIR", dir.toLocal8Bit());
    }
    QGuiApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("benchpilot-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(BP_VERSION));
    QTextStream out(stdout), err(stderr);
    return app::cli::runCli(app.arguments().mid(1), out, err);
}
