#pragma once
// benchpilot-cli's commands: what each one is (name, one-line summary, usage,
// options) and what it gets when it runs (the parsed options, its arguments,
// the output streams, and the instrument when it needs one). See README.md here
// for how to add a command.
#include "motion/metrology/grid/stage_errors.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QTextStream>
#include <QVector>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace app::cli {

/// Exit codes: 0 ok, 1 usage, 2 refused by the device or failed motion, 3 link trouble.
enum ExitCode { Ok = 0, Usage = 1, Refused = 2, LinkTrouble = 3 };

/// How to reach the instrument: the global options every command accepts.
struct LinkOptions {
    QString sim;           ///< "analyzer" or "stage" when simulated in-process
    QString port;          ///< serial port path otherwise
    QString instrument;    ///< with --port: "analyzer" or "stage" (else from HELLO, the profile, or the analyzer)
    QString profile;       ///< with --port: a machine profile file (docs/grbl.md)
    qint32 baud = 115200;
    bool json = false;
    double timeoutS = 120; ///< longest wait for motion to finish
    /// --stage-errors: the simulated stage's errors (a benchpilot.stage-errors file), read and checked.
    std::optional<motion::metrology::StageErrors> stageErrors;
    // Inside the GUI (the scripting API, --attach) `sim` names which of the GUI's
    // instruments, whatever it is connected to; empty leaves it to the GUI.
};

class CliSession;
class Invocation;

/// How a command appears in the scripting API (docs/api.md, app/api/): the method
/// name, what it needs, and the JSON parameters its words are made from. Options not
/// listed in `params` are offered as they are: a flag as a boolean, an option with a
/// value as a string (a number or an array of numbers is accepted and written the way
/// the command line would spell it). See README.md, "The scripting API".
enum class Access {
    Compute,  ///< no instrument: plans, profiles, validation
    Read,     ///< reads an instrument, changes nothing: info, status
    Control,  ///< moves, pumps, changes gains or starts a job: needs the control lease
    Safety,   ///< makes the machine safer (stop, E-stop): anyone, lease or not, never gated
};

enum class ParamType {
    Text,       ///< a string (a number is written as the CLI would read it)
    Number,
    Integer,
    Boolean,    ///< a flag: true sets it
    Numbers,    ///< an array of numbers, written "a,b,c"
    Axis,       ///< one axis letter: "X"
    Axes,       ///< axis letters: "XY" or ["X","Y"]
    AxisValues, ///< {"X": 10, "Y": [1,2,3]}: words X=10 Y=1,2,3
    AxisRanges, ///< {"X": [min, max]}: words X=min:max
    File,       ///< a path; a relative one is taken from the client's working directory
};

struct ApiParam {
    QString name;         ///< the JSON name ("targets"); options default to their name with '-' as '_'
    ParamType type = ParamType::Text;
    QString description;  ///< one line; an option's own description when empty
    bool required = false;
    /// The option this parameter fills ("speed"); empty: a positional word, in the order listed.
    QString option;
    QStringList choices;  ///< the allowed values of a Text parameter, when there is a fixed set
};

/// A typed parameter for option `option` ("pixel-um"), named as JSON names it ("pixel_um").
ApiParam optionParam(const char* option, ParamType type, bool required = false);

struct ApiSpec {
    QString method;                 ///< "device.move"; empty: the command's words joined by '.', '-' as '_'
    Access access = Access::Control;  ///< the safe default for a command that does not say
    /// Control only when given positional words (`limits`, `gains`: without them they show).
    bool readsWithoutArguments = false;
    /// A Compute command that still reads which instrument is meant (pattern plan's timing).
    bool instrumentParam = false;
    QList<ApiParam> params;         ///< positional words in order, and options given a type
    QJsonObject example;            ///< params of the example in docs/api.md (checked by a test)
    bool offered = true;            ///< false: not a method (`completion`)
    /// Options the API does not offer: they act on benchpilot-cli's own process
    /// (`time-scale` speeds up its own simulator), not on the GUI's instruments.
    QStringList cliOnly;
};

struct Command {
    QString name;                 ///< "profile", or "validate" under "recipe"
    QString summary;              ///< one line for the command list
    QString arguments;            ///< usage after the name and options: "AXIS=VALUE..."
    QString description;          ///< more for --help; may be empty
    QList<QCommandLineOption> options;
    /// Runs the command; returns the exit code. Unset for a command that only groups subcommands.
    std::function<int(Invocation&)> run;
    std::vector<Command> subcommands;  ///< "recipe validate|plan|run"
    ApiSpec api = {};                  ///< how the scripting API offers it (docs/api.md)
};

/// Every command, in the order the help lists them.
const std::vector<Command>& commands();

/// Where a command runs: benchpilot-cli's own process (it opens its own link,
/// Ctrl+C interrupts it) or the GUI's scripting API (app/api/: the GUI's instruments,
/// a cancelled call interrupts it, the JSON objects go back to a client). A command
/// is written once against Invocation and never asks which.
class InvocationHost {
public:
    virtual ~InvocationHost() = default;
    /// The session for the instrument the invocation names; nullptr after reporting why.
    virtual std::unique_ptr<CliSession> openSession(Invocation& inv) = 0;
    /// Each JSON object the command printed (Invocation::printJson), in order.
    virtual void printedJson(const QJsonObject& object) { (void)object; }
    /// How far a long job has come, for a caller that shows it beside the output: the
    /// API puts it on the job board (the `jobs` topic) and sends it as call.progress.
    /// The CLI's output does not change: it prints its own progress for a person.
    virtual void progressed(const QJsonObject& progress) { (void)progress; }
    /// Each message the command reported (Invocation::report), in order.
    virtual void reported(const QString& message) { (void)message; }
    /// Arranges for `interrupt` to run when the run is interrupted (Ctrl+C or SIGTERM in
    /// the CLI; a cancelled call in the API) for as long as the returned guard lives.
    virtual std::shared_ptr<void> onInterrupt(std::function<void()> interrupt) = 0;
    /// A path as the person who typed it meant it (the API resolves a relative one
    /// against its client's working directory).
    virtual QString resolvePath(const QString& path) const { return path; }
    /// Arranges for `abort` to run when someone asks the job to stop without ending the
    /// program (the API's call.cancel, the operator's Abort in the GUI's API panel) for as
    /// long as the guard lives. The CLI has none (Ctrl+C is onInterrupt): nullptr.
    virtual std::shared_ptr<void> onAbort(std::function<void()> abort)
    {
        (void)abort;
        return nullptr;
    }
    /// Arranges for `lost` to run when the caller loses control of the instrument (the
    /// API's lease ends: taken back, connection closed, heartbeats stopped) for as long
    /// as the guard lives: velocity motion stops then, as when a jog key is released.
    /// The CLI has no lease: nullptr.
    virtual std::shared_ptr<void> onLostControl(std::function<void()> lost)
    {
        (void)lost;
        return nullptr;
    }
    /// Whether this caller can hold a velocity jog open-ended (the API's device.jog without
    /// seconds: it runs until device.stop or until the caller loses control).
    virtual bool canHoldJog() const { return false; }
    /// Starts that jog; it is stopped when the caller loses control.
    virtual void holdJog(CliSession& session, int axis, double velocity)
    {
        (void)session, (void)axis, (void)velocity;
    }
    /// True inside the GUI: no tricks on the simulator's clock, no process signals.
    virtual bool insideGui() const { return false; }
    /// The sessions a command that only makes machines safer (stop, estop) acts on: the
    /// one openSession() gives, unless the host holds several instruments and the words
    /// name none. Then it is every connected one, as the GUI's E-stop button halts them
    /// all: a halt is never refused because the caller did not say which. Empty after
    /// reporting why.
    virtual std::vector<std::unique_ptr<CliSession>> openHaltSessions(Invocation& inv);
};

/// benchpilot-cli's own host: a link of its own per command, signals for Ctrl+C.
std::unique_ptr<InvocationHost> makeLocalHost();

/// One run of a command: parsed options and arguments, output, and the errors
/// it reports ("benchpilot-cli profile: --vmax '-3' must be > 0").
class Invocation {
public:
    Invocation(QString path, QCommandLineParser& parser, LinkOptions link, QTextStream& out, QTextStream& err,
               InvocationHost& host);
    ~Invocation();

    const QString& path() const { return m_path; }  ///< "profile", "recipe validate"
    QTextStream& out() { return m_out; }
    QTextStream& err() { return m_err; }
    const LinkOptions& link() const { return m_link; }
    /// Before session(): the in-process simulator's link is not paced like a UART.
    /// Commands that speed the simulator's clock up ask for this so nothing waits on
    /// the wire (a paced wire is sped up with the clock, LoopbackPair::setTimeScale).
    void unpaceSimulatedLink() { m_link.baud = m_link.sim.isEmpty() ? m_link.baud : 0; }
    bool json() const { return m_link.json; }
    InvocationHost& host() { return m_host; }

    bool isSet(const QString& option) const;
    /// isSet for an option the command may not define (no warning when it does not).
    bool given(const QString& option) const;
    QString value(const QString& option) const;        ///< "" when absent
    QStringList values(const QString& option) const;  ///< in the order given
    QStringList arguments() const;                     ///< the words that are not options
    /// A path option or argument as its user meant it (see InvocationHost::resolvePath).
    QString path(const QString& fileOrFolder) const { return m_host.resolvePath(fileOrFolder); }

    /// Reads a number option; `fallback` when absent and not required. Reports the
    /// option and its text on error ("--vmax 'fast' is not a number") and returns false.
    bool number(const QString& option, double& value, std::optional<double> fallback = std::nullopt);
    /// Comma-separated numbers ("30,40"), exactly `count` of them when count > 0.
    bool numbers(const QString& option, QVector<double>& values, int count = 0);

    /// Prints one result object as a compact line on stdout (the --json output) and
    /// hands it to the host: the API's result is exactly this object.
    void printJson(const QJsonObject& object);
    /// Hands the host the object behind text the command printed in a format of its own
    /// (scan plan prints the plan file itself), without printing it again.
    void offerJson(const QJsonObject& object)
    {
        m_out.flush();
        m_host.printedJson(object);
    }

    int usage(const QString& message);        ///< prints it, returns Usage
    int refused(const QString& message);      ///< prints it, returns Refused
    int linkTrouble(const QString& message);  ///< prints it, returns LinkTrouble
    /// Prints "benchpilot-cli PATH: message" on stderr.
    void report(const QString& message);
    /// Everything report() said, in order (the API's error message and data).
    const QStringList& reports() const { return m_reports; }

    /// Connects to the instrument the global options name (the analyzer simulator
    /// when none): nullptr after reporting why (exit with LinkTrouble then).
    CliSession* session();
    /// The session if one was opened.
    CliSession* openedSession() const { return m_session.get(); }
    /// For stop and estop: every instrument they halt (InvocationHost::openHaltSessions),
    /// opened at once; empty after reporting why. One of them is also session().
    QVector<CliSession*> haltSessions();

private:
    QString m_path;
    QCommandLineParser& m_parser;
    LinkOptions m_link;
    QTextStream& m_out;
    QTextStream& m_err;
    InvocationHost& m_host;
    QStringList m_reports;
    std::unique_ptr<CliSession> m_session;
    std::vector<std::unique_ptr<CliSession>> m_moreSessions;  ///< haltSessions() beyond the first
};

/// Options with a value take the next word even when it starts with '-', and a
/// negative number is an argument, not an option ("jog X -5 2"): the parser
/// sees it marked, the command sees it plain.
QString markNegative(const QString& word);
QString unmarkNegative(const QString& word);

/// The whole command line (without the program name): dispatch, --help, --version,
/// completion, and `--attach` (the same command through the running GUI, attach.cpp).
/// Returns the exit code.
int runCli(const QStringList& args, QTextStream& out, QTextStream& err);
/// The command line run by `host` (no --attach): what runCli does in its own process
/// and what the API server does for a call. `ran` receives the command that ran (nullptr
/// when the words named none, or only asked for help).
int runCommandLine(const QStringList& args, QTextStream& out, QTextStream& err, InvocationHost& host,
                   const Command** ran = nullptr);

/// `--attach`: sends the words to the running GUI's API socket (`socketPath`, or the
/// default one) as a cli.run call and prints what comes back (attach.cpp).
int runAttached(const QStringList& args, const QString& socketPath, QTextStream& out, QTextStream& err);
/// Where the GUI listens, and benchpilot-cli --attach looks, unless told otherwise: the
/// one rule for both (clients/python/benchpilot.py's default_socket_path() spells it the
/// same way): $XDG_RUNTIME_DIR/benchpilot/api.sock, or /tmp/benchpilot-UID/api.sock when
/// XDG_RUNTIME_DIR is not set, as the user's environment gave it to the program.
QString defaultApiSocketPath();
/// The rule itself, for a given XDG_RUNTIME_DIR ("" = not set) and user id.
QString apiSocketPathFor(const QString& runtimeDir, uint uid);
/// Notes XDG_RUNTIME_DIR as the program was started with it. benchpilot-cli calls it
/// before it gives Qt a private runtime folder of its own when there is none, so that
/// --attach still looks where the GUI listens.
void noteUsersRuntimeDir();

/// The command the words name after the global options ("recipe", "run", …), with its
/// path ("recipe run"); nullptr when they name none. Global options are skipped.
const Command* findCommand(const QStringList& args, QString* path = nullptr);
/// The API method of a command at `path` ("recipe run" → "recipe.run").
QString methodName(const QString& path, const Command& c);

/// An option for a command's list: no `valueName` makes a flag, `fallback` is its
/// default; the description is translated in the "app::cli" context.
QCommandLineOption option(const char* name, const char* description, const char* valueName = nullptr,
                          const char* fallback = nullptr);

/// Registration lists, one per area (commands.cpp calls each in order).
void addDeviceCommands(std::vector<Command>& list);
void addMotionCommands(std::vector<Command>& list);
void addTuningCommands(std::vector<Command>& list);
void addPatternCommands(std::vector<Command>& list);
void addRecipeCommands(std::vector<Command>& list);
void addScanCommands(std::vector<Command>& list);
void addStitchCommands(std::vector<Command>& list);
void addCameraCommands(std::vector<Command>& list);
void addAccuracyCommands(std::vector<Command>& list);
/// grid-map run: the stage mapped by the camera on a grid plate.
void addGridMapCommands(std::vector<Command>& list);
void addCompensationCommands(std::vector<Command>& list);
/// compensation fit-2d | upload-2d | show-2d | enable-2d | disable-2d | export-2d.
void addCompensation2dSubcommands(Command& comp);
void addCompletionCommand(std::vector<Command>& list);

/// The help texts, also used by the completion script.
QString topHelp();
QString commandHelp(const QString& path, const Command& c);
/// The options every command accepts (--sim, --port, --baud, --instrument, --profile, --json, --timeout).
QList<QCommandLineOption> globalOptions();

} // namespace app::cli
