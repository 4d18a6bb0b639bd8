// benchpilot-cli: scripts the instruments and the motion library. The commands
// are in this folder, one area a file; cli.cpp parses the command line.
#include "command.h"

#include <QCoreApplication>
#include <QTextStream>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("benchpilot-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(BP_VERSION));
    QTextStream out(stdout), err(stderr);
    return cli::runCli(app.arguments().mid(1), out, err);
}
