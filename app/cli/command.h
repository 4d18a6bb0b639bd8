#pragma once
// benchpilot-cli's commands: what each one is (name, one-line summary, usage,
// options) and what it gets when it runs (the parsed options, its arguments,
// the output streams, and the instrument when it needs one). See README.md here
// for how to add a command.
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>
#include <QTextStream>
#include <QVector>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace cli {

/// Exit codes: 0 ok, 1 usage, 2 refused by the device or failed motion, 3 link trouble.
enum ExitCode { Ok = 0, Usage = 1, Refused = 2, LinkTrouble = 3 };

/// How to reach the instrument: the global options every command accepts.
struct LinkOptions {
    QString sim;           ///< "analyzer" or "stage" when simulated in-process
    QString port;          ///< serial port path otherwise
    qint32 baud = 115200;
    bool json = false;
    double timeoutS = 120; ///< longest wait for motion to finish
};

class CliSession;
class Invocation;

struct Command {
    QString name;                 ///< "profile", or "validate" under "recipe"
    QString summary;              ///< one line for the command list
    QString arguments;            ///< usage after the name and options: "AXIS=VALUE..."
    QString description;          ///< more for --help; may be empty
    QList<QCommandLineOption> options;
    /// Runs the command; returns the exit code. Unset for a command that only groups subcommands.
    std::function<int(Invocation&)> run;
    std::vector<Command> subcommands;  ///< "recipe validate|plan|run"
};

/// Every command, in the order the help lists them.
const std::vector<Command>& commands();

/// One run of a command: parsed options and arguments, output, and the errors
/// it reports ("benchpilot-cli profile: --vmax '-3' must be > 0").
class Invocation {
public:
    Invocation(QString path, QCommandLineParser& parser, LinkOptions link, QTextStream& out, QTextStream& err);
    ~Invocation();

    const QString& path() const { return m_path; }  ///< "profile", "recipe validate"
    QTextStream& out() { return m_out; }
    QTextStream& err() { return m_err; }
    const LinkOptions& link() const { return m_link; }
    /// Before session(): the in-process simulator's link is not paced like a UART. A
    /// simulator clock sped up over a paced link sends more than the wire carries in
    /// wall time (SimulatorHost::setTimeScale); commands that speed it up ask for this.
    void unpaceSimulatedLink() { m_link.baud = m_link.sim.isEmpty() ? m_link.baud : 0; }
    bool json() const { return m_link.json; }

    bool isSet(const QString& option) const;
    QString value(const QString& option) const;        ///< "" when absent
    QStringList values(const QString& option) const;  ///< in the order given
    QStringList arguments() const;                     ///< the words that are not options

    /// Reads a number option; `fallback` when absent and not required. Reports the
    /// option and its text on error ("--vmax 'fast' is not a number") and returns false.
    bool number(const QString& option, double& value, std::optional<double> fallback = std::nullopt);
    /// Comma-separated numbers ("30,40"), exactly `count` of them when count > 0.
    bool numbers(const QString& option, QVector<double>& values, int count = 0);

    int usage(const QString& message);        ///< prints it, returns Usage
    int refused(const QString& message);      ///< prints it, returns Refused
    int linkTrouble(const QString& message);  ///< prints it, returns LinkTrouble
    /// Prints "benchpilot-cli PATH: message" on stderr.
    void report(const QString& message);

    /// Connects to the instrument the global options name (the analyzer simulator
    /// when none): nullptr after reporting why (exit with LinkTrouble then).
    CliSession* session();

private:
    QString m_path;
    QCommandLineParser& m_parser;
    LinkOptions m_link;
    QTextStream& m_out;
    QTextStream& m_err;
    std::unique_ptr<CliSession> m_session;
};

/// Options with a value take the next word even when it starts with '-', and a
/// negative number is an argument, not an option ("jog X -5 2"): the parser
/// sees it marked, the command sees it plain.
QString markNegative(const QString& word);
QString unmarkNegative(const QString& word);

/// The whole command line (without the program name): dispatch, --help, --version,
/// completion. Returns the exit code.
int runCli(const QStringList& args, QTextStream& out, QTextStream& err);

/// An option for a command's list: no `valueName` makes a flag, `fallback` is its
/// default; the description is translated in the "cli" context.
QCommandLineOption option(const char* name, const char* description, const char* valueName = nullptr,
                          const char* fallback = nullptr);

/// Registration lists, one per area (commands.cpp calls each in order).
void addDeviceCommands(std::vector<Command>& list);
void addMotionCommands(std::vector<Command>& list);
void addTuningCommands(std::vector<Command>& list);
void addPatternCommands(std::vector<Command>& list);
void addRecipeCommands(std::vector<Command>& list);
void addScanCommands(std::vector<Command>& list);
void addAccuracyCommands(std::vector<Command>& list);
void addCompensationCommands(std::vector<Command>& list);
void addCompletionCommand(std::vector<Command>& list);

/// The help texts, also used by the completion script.
QString topHelp();
QString commandHelp(const QString& path, const Command& c);
/// The options every command accepts (--sim, --port, --baud, --json, --timeout).
QList<QCommandLineOption> globalOptions();

} // namespace cli
