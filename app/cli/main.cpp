// benchpilot-cli: scripts the instruments and the motion library.
#include "cli_session.h"
#include "motion_commands.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

namespace {
const char* kHelp =
    "usage: benchpilot-cli [--sim analyzer|stage | --port PATH [--baud N]] [--json] [--timeout S] COMMAND [ARGS]\n"
    "\n"
    "Instrument commands (default: --sim analyzer):\n"
    "  info                         device identity, axes, travel, resolution\n"
    "  status                       positions (commanded and measured), homed, moving, switches\n"
    "  home [AXES]                  home the axes (all when none given), wait until done\n"
    "  move AXIS=VALUE... [--relative] [--speed V]   move and wait until done (mm, µL for P)\n"
    "  jog AXIS VELOCITY SECONDS    velocity jog refreshed for SECONDS, then stop and wait until still\n"
    "  stop | estop | reset         decelerate all axes | halt at once | clear the E-stop latch\n"
    "  zero AXES                    make the current position zero\n"
    "  limits [AXIS=MIN:MAX...]     show or set soft limits\n"
    "Motion library commands (no instrument needed):\n"
    "  profile, interpolate, steptable, blocks   (see docs/motion.md)\n"
    "\n"
    "Exit codes: 0 ok, 1 usage, 2 refused or motion failed, 3 link trouble.\n";
}

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("benchpilot-cli"));
    QTextStream out(stdout), err(stderr);
    cli::LinkOptions opt;
    QString command;
    QStringList rest;
    const QStringList args = app.arguments().mid(1);
    auto usage = [&](const QString& m) {
        err << "benchpilot-cli: " << m << "\n" << kHelp;
        err.flush();
        return int(cli::Usage);
    };
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (!command.isEmpty()) {
            if (a == QLatin1String("--json"))
                opt.json = true;
            else
                rest << a;
            continue;
        }
        auto value = [&](QString* v) {
            if (i + 1 >= args.size())
                return false;
            *v = args[++i];
            return true;
        };
        QString v;
        if (a == QLatin1String("-h") || a == QLatin1String("--help")) {
            out << kHelp;
            return 0;
        } else if (a == QLatin1String("--json")) {
            opt.json = true;
        } else if (a == QLatin1String("--sim")) {
            if (!value(&v) || (v != QLatin1String("analyzer") && v != QLatin1String("stage")))
                return usage(QStringLiteral("--sim needs 'analyzer' or 'stage'"));
            opt.sim = v;
        } else if (a == QLatin1String("--port")) {
            if (!value(&v) || v.isEmpty())
                return usage(QStringLiteral("--port needs a path"));
            opt.port = v;
        } else if (a == QLatin1String("--baud")) {
            bool ok = false;
            if (!value(&v) || (opt.baud = v.toInt(&ok), !ok) || opt.baud < 1200)
                return usage(QStringLiteral("--baud needs a rate of at least 1200"));
        } else if (a == QLatin1String("--timeout")) {
            bool ok = false;
            if (!value(&v) || (opt.timeoutS = v.toDouble(&ok), !ok) || opt.timeoutS <= 0)
                return usage(QStringLiteral("--timeout needs a positive number of seconds"));
        } else if (a.startsWith(QLatin1String("--"))) {
            return usage(QStringLiteral("unknown option '%1'").arg(a));
        } else {
            command = a;
        }
    }
    if (command.isEmpty())
        return usage(QStringLiteral("no command given"));
    if (auto rc = cli::runMotionCommand(command, rest, out, err))
        return *rc;
    if (!opt.sim.isEmpty() && !opt.port.isEmpty())
        return usage(QStringLiteral("give either --sim or --port, not both"));
    if (opt.sim.isEmpty() && opt.port.isEmpty())
        opt.sim = QStringLiteral("analyzer");
    cli::CliSession session(opt, out, err);
    return session.run(command, rest);
}
