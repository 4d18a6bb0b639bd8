// benchpilot-cli's command line: global options, command and subcommand
// dispatch, --help at every level, --version. Options are parsed by
// QCommandLineParser, so '--opt value' and '--opt=value' both work.
#include "cli_session.h"
#include "command.h"

#include "app/common/version_text.h"
#include "device/files/accuracy/grid/stage_errors_file.h"
#include "device/files/machine_profile_file.h"
#include "device/files/shipped_data.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

const QCommandLineOption& helpOption()
{
    static const QCommandLineOption o(QStringList{QStringLiteral("h"), QStringLiteral("help")}, tr("show this help"));
    return o;
}

const QCommandLineOption& versionOption()
{
    static const QCommandLineOption o(QStringLiteral("version"), tr("show the program's version"));
    return o;
}

QString optionNames(const QCommandLineOption& o)
{
    QStringList names;
    for (const QString& n : o.names())
        names << (n.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + n;
    QString s = names.join(QStringLiteral(", "));
    if (!o.valueName().isEmpty())
        s += QLatin1Char(' ') + o.valueName();
    return s;
}

QString optionTable(const QList<QCommandLineOption>& options)
{
    int width = 0;
    for (const auto& o : options)
        width = std::max(width, int(optionNames(o).size()));
    QString s;
    for (const auto& o : options) {
        QString line = QStringLiteral("  %1  %2").arg(optionNames(o), -width).arg(o.description());
        if (!o.defaultValues().isEmpty())
            line += tr(" (default: %1)").arg(o.defaultValues().join(QLatin1Char(',')));
        s += line + QLatin1Char('\n');
    }
    return s;
}

QString commandTable(const std::vector<Command>& list)
{
    int width = 0;
    for (const auto& c : list)
        width = std::max(width, int(c.name.size()));
    QString s;
    for (const auto& c : list)
        s += QStringLiteral("  %1  %2\n").arg(c.name, -width).arg(c.summary);
    return s;
}

const Command* find(const std::vector<Command>& list, const QString& name)
{
    for (const auto& c : list)
        if (c.name == name)
            return &c;
    return nullptr;
}

QStringList names(const std::vector<Command>& list)
{
    QStringList n;
    for (const auto& c : list)
        n << c.name;
    return n;
}

/// Reads the global options a parser saw into `link`; false after a usage message.
bool readLinkOptions(const QCommandLineParser& p, LinkOptions& link, QTextStream& err, const QString& who)
{
    auto fail = [&](const QString& m) {
        err << who << ": " << m << "\n";
        err.flush();
        return false;
    };
    if (p.isSet(QStringLiteral("json")))
        link.json = true;
    if (p.isSet(QStringLiteral("sim"))) {
        const QString v = p.value(QStringLiteral("sim"));
        if (v != QLatin1String("analyzer") && v != QLatin1String("stage"))
            return fail(tr("--sim needs 'analyzer' or 'stage' (got '%1')").arg(v));
        link.sim = v;
    }
    if (p.isSet(QStringLiteral("stage-errors"))) {
        if (link.sim != QLatin1String("stage"))
            return fail(tr("--stage-errors is for the simulated stage: give --sim stage"));
        const auto read = dev::files::accuracy::loadStageErrorsFile(unmarkNegative(p.value(QStringLiteral("stage-errors"))));
        if (!read.ok())
            return fail(tr("--stage-errors: %1").arg(ui::words::problems(read.problems()).join(QLatin1Char('\n'))));
        link.stageErrors = *read;
    }
    if (p.isSet(QStringLiteral("port"))) {
        link.port = unmarkNegative(p.value(QStringLiteral("port")));
        if (link.port.isEmpty())
            return fail(tr("--port needs a path"));
    }
    if (p.isSet(QStringLiteral("instrument"))) {
        const QString v = p.value(QStringLiteral("instrument"));
        if (v != QLatin1String("analyzer") && v != QLatin1String("stage"))
            return fail(tr("--instrument needs 'analyzer' or 'stage' (got '%1')").arg(v));
        link.instrument = v;
    }
    if (p.isSet(QStringLiteral("profile"))) {
        link.profile = dev::files::resolveMachineProfile(unmarkNegative(p.value(QStringLiteral("profile"))));
        dev::files::MachineProfile profile;
        dev::files::json::Problems problems;
        if (link.profile.isEmpty())
            return fail(tr("--profile needs a machine profile file"));
        if (!dev::files::loadMachineProfileFile(link.profile, &profile, &problems))
            return fail(tr("--profile: %1").arg(ui::words::fileProblems(problems, QFileInfo(link.profile).fileName()).join(QLatin1Char('\n'))));
    }
    if (p.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        link.baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || link.baud < 1200)
            return fail(tr("--baud needs a rate of at least 1200 (got '%1')").arg(unmarkNegative(p.value(QStringLiteral("baud")))));
    }
    if (p.isSet(QStringLiteral("timeout"))) {
        bool ok = false;
        link.timeoutS = unmarkNegative(p.value(QStringLiteral("timeout"))).toDouble(&ok);
        if (!ok || !(link.timeoutS > 0))
            return fail(tr("--timeout needs a positive number of seconds (got '%1')").arg(unmarkNegative(p.value(QStringLiteral("timeout")))));
    }
    return true;
}

/// QCommandLineParser's "Unknown option 'x'." said as this CLI says things, with the choices.
QString parseError(const QCommandLineParser& p, const QList<QCommandLineOption>& known)
{
    const QStringList unknown = p.unknownOptionNames();
    if (unknown.isEmpty())
        return p.errorText();
    QStringList shown, choices;
    for (const QString& n : unknown)
        shown << (n.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + n;
    for (const auto& o : known)
        choices << QStringLiteral("--") + o.names().constLast();
    return tr("unknown option %1 (options: %2)").arg(QLatin1Char('\'') + shown.join(QStringLiteral("', '")) + QLatin1Char('\''),
                                                   choices.join(QLatin1Char(' ')));
}

} // namespace

QList<QCommandLineOption> globalOptions()
{
    return {QCommandLineOption(QStringLiteral("sim"),
                               tr("the in-process simulator: analyzer or stage (default: analyzer); with --attach, the older "
                                  "spelling of --instrument"),
                               QStringLiteral("KIND")),
            QCommandLineOption(QStringLiteral("stage-errors"),
                               tr("with --sim stage: the simulated stage's errors from a benchpilot.stage-errors file"),
                               QStringLiteral("FILE")),
            QCommandLineOption(QStringLiteral("port"), tr("a serial port, or the pty of benchpilot-sim"), QStringLiteral("PATH")),
            QCommandLineOption(QStringLiteral("baud"), tr("link speed (default: 115200)"), QStringLiteral("N")),
            QCommandLineOption(QStringLiteral("instrument"),
                               tr("with --port: which instrument it is, analyzer or stage (default: what the device says; "
                                  "a GRBL controller: the profile's, else the analyzer); with --attach: which of the GUI's "
                                  "instruments, whatever it is connected to (may be left out when only one is; stop and estop "
                                  "without it halt every one)"),
                               QStringLiteral("KIND")),
            QCommandLineOption(QStringLiteral("profile"),
                               tr("with --port: the machine profile of a GRBL controller, a file or the name of one BenchPilot ships (stage-grbl-uno; docs/grbl.md)"), QStringLiteral("FILE")),
            QCommandLineOption(QStringLiteral("json"), tr("print JSON instead of text")),
            QCommandLineOption(QStringLiteral("timeout"), tr("longest wait for motion to finish, s (default: 120)"), QStringLiteral("S")),
            QCommandLineOption(QStringLiteral("attach"), tr("run the command through the running BenchPilot GUI (its instruments, its control lease)")),
            QCommandLineOption(QStringLiteral("api-socket"),
                               tr("with --attach: the GUI's API socket (default: %1; $XDG_RUNTIME_DIR/benchpilot/api.sock, or "
                                  "/tmp/benchpilot-UID/api.sock without XDG_RUNTIME_DIR)")
                                   .arg(defaultApiSocketPath()),
                               QStringLiteral("PATH")),
            QCommandLineOption(QStringLiteral("lang"), tr("language of the text for people: en (default), zh_CN, or system (follows LANG); --json never changes"),
                               QStringLiteral("LANG"))};
}

QString topHelp()
{
    QList<QCommandLineOption> global = globalOptions();
    global << helpOption() << versionOption();
    return tr("usage: benchpilot-cli [GLOBAL OPTIONS] COMMAND [OPTIONS] [ARGUMENTS]\n\n"
              "Scripts BenchPilot's instruments (the in-process simulators, benchpilot-sim's pty, or a\n"
              "serial port: BenchPilot firmware, or a GRBL 1.1 / grblHAL controller) and its motion library.\n\n"
              "Commands:\n")
        + commandTable(commands())
        + tr("\nGlobal options (before or after the command):\n") + optionTable(global)
        + tr("\n'benchpilot-cli COMMAND --help' shows a command's options. Options take their value as\n"
             "'--opt value' or '--opt=value'.\n"
             "Exit codes: 0 ok, 1 usage, 2 refused or motion failed, 3 link trouble.\n"
             "Bash completion: source <(benchpilot-cli completion bash)\n");
}

QString commandHelp(const QString& path, const Command& c)
{
    QString s;
    if (!c.subcommands.empty()) {
        s = tr("usage: benchpilot-cli %1 SUBCOMMAND [OPTIONS] [ARGUMENTS]\n\n%2\n\nSubcommands:\n").arg(path, c.summary)
            + commandTable(c.subcommands);
        if (!c.description.isEmpty())
            s += QLatin1Char('\n') + c.description + QLatin1Char('\n');
        return s + tr("\n'benchpilot-cli %1 SUBCOMMAND --help' shows a subcommand's options.\n").arg(path);
    }
    s = tr("usage: benchpilot-cli %1%2%3\n\n%4\n")
            .arg(path, c.options.isEmpty() ? QString() : tr(" [OPTIONS]"),
                 c.arguments.isEmpty() ? QString() : QLatin1Char(' ') + c.arguments, c.summary);
    if (!c.description.isEmpty())
        s += QLatin1Char('\n') + c.description + QLatin1Char('\n');
    if (!c.options.isEmpty())
        s += tr("\nOptions:\n") + optionTable(c.options);
    return s + tr("\nGlobal options: --sim KIND, --port PATH, --baud N, --instrument KIND, --profile FILE, --json, --timeout S (see "
                  "benchpilot-cli --help).\n");
}

namespace {

/// The command the positional words name, walking down subcommands; `rest` keeps the
/// words after it. Returns nullptr with `level`/`parent` saying where the walk stopped.
struct Walk {
    const Command* cmd = nullptr;      ///< the last command the words named
    const std::vector<Command>* level = nullptr;
    QString path;
    QString stopWord;                  ///< the word that named nothing (when the walk stopped early)
    bool complete = false;             ///< cmd is a leaf (runnable) command
};

Walk walk(QStringList& rest)
{
    Walk w;
    w.level = &commands();
    for (;;) {
        const QString word = rest.isEmpty() ? QString() : rest.takeFirst();
        const Command* next = find(*w.level, word);
        if (!next) {
            w.stopWord = word;
            return w;
        }
        w.cmd = next;
        w.path = w.path.isEmpty() ? next->name : w.path + QLatin1Char(' ') + next->name;
        if (next->subcommands.empty()) {
            w.complete = true;
            return w;
        }
        w.level = &next->subcommands;
    }
}

} // namespace

const Command* findCommand(const QStringList& rawArgs, QString* path)
{
    QStringList args{QStringLiteral("benchpilot-cli")};
    for (const QString& a : rawArgs)
        args << markNegative(a);
    QCommandLineParser top;
    top.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsPositionalArguments);
    top.addOptions(globalOptions());
    top.addOption(helpOption());
    top.addOption(versionOption());
    if (!top.parse(args))
        return nullptr;
    QStringList rest = top.positionalArguments();
    const Walk w = walk(rest);
    if (!w.complete)
        return nullptr;
    if (path)
        *path = w.path;
    return w.cmd;
}

QString methodName(const QString& path, const Command& c)
{
    if (!c.api.method.isEmpty())
        return c.api.method;
    QString m = path;
    m.replace(QLatin1Char(' '), QLatin1Char('.'));
    m.replace(QLatin1Char('-'), QLatin1Char('_'));
    return m;
}

int runCli(const QStringList& rawArgs, QTextStream& out, QTextStream& err)
{
    // The language first, wherever it stands, so that every later word (usage
    // errors included) is in it. English unless asked: scripts parse this output.
    ui::words::Translators translators;
    for (int i = 0; i < rawArgs.size(); ++i) {
        const QString& a = rawArgs[i];
        QString language;
        if (a == QLatin1String("--lang") && i + 1 < rawArgs.size())
            language = rawArgs[i + 1];
        else if (a.startsWith(QLatin1String("--lang=")))
            language = a.mid(7);
        else
            continue;
        if (!translators.setLanguage(language)) {
            err << "benchpilot-cli: " << tr("--lang needs en, zh_CN or system (got '%1')").arg(language) << "\n";
            err.flush();
            return Usage;
        }
    }
    // --attach [--api-socket PATH], before or after the command: the same commandWords go to
    // the running GUI, which runs them and sends back the output and the exit code.
    QStringList commandWords;
    bool attach = false;
    QString socketPath;
    for (int i = 0; i < rawArgs.size(); ++i) {
        const QString& a = rawArgs[i];
        if (a == QLatin1String("--")) {
            commandWords += rawArgs.mid(i);
            break;
        }
        if (a == QLatin1String("--attach")) {
            attach = true;
        } else if (a == QLatin1String("--api-socket") && i + 1 < rawArgs.size()) {
            socketPath = rawArgs[++i];
        } else if (a.startsWith(QLatin1String("--api-socket="))) {
            socketPath = a.mid(13);
        } else {
            commandWords << a;
        }
    }
    if (!socketPath.isEmpty() && !attach) {
        err << "benchpilot-cli: " << tr("--api-socket goes with --attach") << "\n";
        err.flush();
        return Usage;
    }
    if (attach)
        return runAttached(commandWords, socketPath, out, err);
    const std::unique_ptr<InvocationHost> host = makeLocalHost();
    return runCommandLine(commandWords, out, err, *host);
}

int runCommandLine(const QStringList& rawArgs, QTextStream& out, QTextStream& err, InvocationHost& host, const Command** ran)
{
    if (ran)
        *ran = nullptr;
    QStringList args{QStringLiteral("benchpilot-cli")};  // QCommandLineParser skips the program name
    for (const QString& a : rawArgs)
        args << markNegative(a);

    auto fail = [&](const QString& who, const QString& message, const QString& helpHint) {
        err << who << ": " << message << "\n" << helpHint;
        err.flush();
        return int(Usage);
    };

    QCommandLineParser top;
    top.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsPositionalArguments);
    top.addOptions(globalOptions());
    top.addOption(helpOption());
    top.addOption(versionOption());
    if (!top.parse(args))
        return fail(QStringLiteral("benchpilot-cli"), parseError(top, globalOptions()), tr("try 'benchpilot-cli --help'\n"));
    if (top.isSet(versionOption())) {
        out << QString::fromStdString(app::versionText("benchpilot-cli"));
        out.flush();
        return Ok;
    }
    QStringList rest = top.positionalArguments();
    if (rest.isEmpty()) {
        if (top.isSet(helpOption())) {
            out << topHelp();
            out.flush();
            return Ok;
        }
        return fail(QStringLiteral("benchpilot-cli"), tr("no command given"), topHelp());
    }
    if (top.isSet(helpOption())) {  // "benchpilot-cli --help move" means "move --help"
        rest.append(QStringLiteral("--help"));  // after any subcommand: "--help recipe run" is "recipe run --help"
    }
    LinkOptions link;
    if (!readLinkOptions(top, link, err, QStringLiteral("benchpilot-cli")))
        return Usage;

    // Walk down to the command (or subcommand) the words name.
    const Walk w = walk(rest);
    if (!w.complete) {
        const QString& word = w.stopWord;
        if (!w.cmd)
            return fail(QStringLiteral("benchpilot-cli"),
                        tr("unknown command '%1' (commands: %2)").arg(word, names(*w.level).join(QStringLiteral(", "))),
                        tr("try 'benchpilot-cli --help'\n"));
        if (word == QLatin1String("-h") || word == QLatin1String("--help")) {
            out << commandHelp(w.path, *w.cmd);
            out.flush();
            return Ok;
        }
        return fail(QStringLiteral("benchpilot-cli ") + w.path,
                    word.isEmpty() ? tr("which one? (%1)").arg(names(*w.level).join(QStringLiteral(", ")))
                                   : tr("unknown subcommand '%1' (%2)").arg(word, names(*w.level).join(QStringLiteral(", "))),
                    commandHelp(w.path, *w.cmd));
    }
    const Command* cmd = w.cmd;
    const QString& path = w.path;

    QCommandLineParser p;
    p.addOptions(globalOptions());
    p.addOption(helpOption());
    p.addOptions(cmd->options);
    const QString who = QStringLiteral("benchpilot-cli ") + path;
    if (!p.parse(QStringList{args.first()} + rest))
        return fail(who, parseError(p, cmd->options + globalOptions()), tr("try 'benchpilot-cli %1 --help'\n").arg(path));
    if (p.isSet(helpOption())) {
        out << commandHelp(path, *cmd);
        out.flush();
        return Ok;
    }
    if (!readLinkOptions(p, link, err, who))
        return Usage;
    if (top.isSet(QStringLiteral("attach")) || p.isSet(QStringLiteral("attach")))
        return fail(who, tr("--attach is already in effect here"), QString());
    if (host.insideGui() && link.port.isEmpty() && !link.instrument.isEmpty()) {
        // Inside the GUI (--attach, the API) --instrument names which of its instruments,
        // whatever it is connected to; --sim is the older spelling of the same.
        if (!link.sim.isEmpty() && link.sim != link.instrument)
            return fail(who, tr("--instrument %1 and --sim %2 name different instruments").arg(link.instrument, link.sim), QString());
        link.sim = link.instrument;
        link.instrument.clear();
    }
    if (!link.sim.isEmpty() && !link.port.isEmpty())
        return fail(who, tr("give either --sim or --port, not both"), QString());
    if (link.port.isEmpty() && !link.instrument.isEmpty())
        return fail(who, tr("--instrument goes with --port, or with --attach to name the GUI's instrument (--sim names its simulator itself)"),
                    QString());
    if (link.port.isEmpty() && !link.profile.isEmpty())
        return fail(who, tr("--profile goes with --port"), QString());
    if (ran)
        *ran = cmd;
    Invocation inv(path, p, link, out, err, host);
    return cmd->run(inv);
}

} // namespace app::cli
