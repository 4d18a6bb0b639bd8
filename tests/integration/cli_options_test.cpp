// The command line behaves as users expect: --help and -h on every
// command and subcommand, --opt=value beside --opt value, negative numbers as
// values and arguments, --version on all programs, bash completion.
#include "app/cli/command.h"
#include "programs.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

namespace {

struct CliRun {
    int code = -1;
    QString out, err;
};

CliRun runCli(const QStringList& args)
{
    CliRun r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::cli::runCli(args, out, err);
    out.flush();
    err.flush();
    return r;
}

QStringList words(const char* text) { return QString::fromUtf8(text).split(QLatin1Char(' '), Qt::SkipEmptyParts); }

/// Every command path ("move", "recipe validate", …) with its command.
void allPaths(const std::vector<app::cli::Command>& list, const QStringList& prefix, std::vector<std::pair<QStringList, const app::cli::Command*>>& out)
{
    for (const auto& c : list) {
        out.push_back({prefix + QStringList{c.name}, &c});
        allPaths(c.subcommands, prefix + QStringList{c.name}, out);
    }
}

} // namespace

TEST(CliOptions, TopHelpListsEveryCommandWithOneLine)
{
    const CliRun r = runCli({QStringLiteral("--help")});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.err.isEmpty());
    for (const auto& c : app::cli::commands()) {
        ASSERT_FALSE(c.summary.isEmpty()) << c.name.toStdString();
        EXPECT_FALSE(c.summary.contains(QLatin1Char('\n'))) << c.name.toStdString();
        EXPECT_TRUE(r.out.contains(QStringLiteral("  %1  ").arg(c.name))) << c.name.toStdString();
        EXPECT_TRUE(r.out.contains(c.summary)) << c.name.toStdString();
    }
    EXPECT_EQ(runCli({QStringLiteral("-h")}).out, r.out);
}

TEST(CliOptions, EveryCommandAndSubcommandPrintsItsUsageWithHelp)
{
    std::vector<std::pair<QStringList, const app::cli::Command*>> paths;
    allPaths(app::cli::commands(), {}, paths);
    ASSERT_GE(paths.size(), 15u);
    for (const auto& [path, command] : paths) {
        for (const char* flag : {"--help", "-h"}) {
            const CliRun r = runCli(path + QStringList{QString::fromLatin1(flag)});
            EXPECT_EQ(r.code, 0) << path.join(QLatin1Char(' ')).toStdString() << " " << flag << ": " << r.err.toStdString();
            EXPECT_TRUE(r.out.startsWith(QStringLiteral("usage: benchpilot-cli ") + path.join(QLatin1Char(' '))))
                << r.out.toStdString();
            for (const auto& o : command->options)
                EXPECT_TRUE(r.out.contains(QStringLiteral("--") + o.names().constLast())) << o.names().constLast().toStdString();
        }
        // "benchpilot-cli --help move" is the same as "benchpilot-cli move --help".
        EXPECT_EQ(runCli(QStringList{QStringLiteral("--help")} + path).out, runCli(path + QStringList{QStringLiteral("--help")}).out);
    }
}

TEST(CliOptions, OptionValuesMayBeJoinedWithEquals)
{
    const CliRun spaced = runCli(words("interpolate --shape line --to 1,2 --step 0.5"));
    const CliRun joined = runCli(words("interpolate --shape=line --to=1,2 --step=0.5"));
    ASSERT_EQ(spaced.code, 0) << spaced.err.toStdString();
    EXPECT_EQ(joined.code, 0) << joined.err.toStdString();
    EXPECT_EQ(joined.out, spaced.out);
    const CliRun mixed = runCli(words("profile --kind=trapezoid --distance 10 --vmax=20 --amax 200 --dt=0.5"));
    EXPECT_EQ(mixed.code, 0) << mixed.err.toStdString();
}

TEST(CliOptions, NegativeNumbersAreValuesNotOptions)
{
    const CliRun r = runCli(words("profile --distance -30 --vmax 10 --amax 100 --jmax -1000"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--jmax"))) << r.err.toStdString();  // refused as a limit, not as an unknown option
    EXPECT_FALSE(r.err.contains(QStringLiteral("unknown option"))) << r.err.toStdString();
    const CliRun ok = runCli(words("profile --distance=-30 --vmax 10 --amax 100 --jmax 1000 --dt 1"));
    ASSERT_EQ(ok.code, 0) << ok.err.toStdString();
    EXPECT_EQ(QJsonDocument::fromJson(ok.out.toUtf8()).object()[QStringLiteral("distance")].toDouble(), -30);
}

TEST(CliOptions, NegativeJogVelocityIsAnArgument)
{
    const CliRun r = runCli(words("--sim stage --json jog X -2 0.3"));
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    const auto x = QJsonDocument::fromJson(r.out.toUtf8()).object()[QStringLiteral("axes")].toObject()[QStringLiteral("X")].toObject();
    EXPECT_LT(x[QStringLiteral("position")].toDouble(), 41.7 - 0.3);  // the stage starts at X 41.7 mm and went the negative way
}

TEST(CliOptions, MistakesNameTheCommandAndTheWayOut)
{
    CliRun r = runCli(words("profile --speed 3"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("benchpilot-cli profile: unknown option '--speed' (options: --kind"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("try 'benchpilot-cli profile --help'")));
    r = runCli(words("frobnicate"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("unknown command 'frobnicate' (commands: info, status,"))) << r.err.toStdString();
    r = runCli({});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no command given")));
    r = runCli(words("profile --vmax"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--vmax"))) << r.err.toStdString();
    r = runCli(words("--sim stage --port /dev/null status"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("either --sim or --port"))) << r.err.toStdString();
    r = runCli(words("--sim robot status"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--sim needs 'analyzer' or 'stage' (got 'robot')"))) << r.err.toStdString();
    r = runCli(words("move X=abc"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("benchpilot-cli move: "))) << r.err.toStdString();
    r = runCli(words("status extra"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("takes no arguments (got 'extra')"))) << r.err.toStdString();
}

TEST(CliOptions, GlobalOptionsMayFollowTheCommand)
{
    const CliRun before = runCli(words("--sim stage --json status"));
    const CliRun after = runCli(words("status --sim=stage --json"));
    ASSERT_EQ(before.code, 0) << before.err.toStdString();
    ASSERT_EQ(after.code, 0) << after.err.toStdString();
    EXPECT_EQ(QJsonDocument::fromJson(after.out.toUtf8()).object()[QStringLiteral("instrument")],
              QJsonDocument::fromJson(before.out.toUtf8()).object()[QStringLiteral("instrument")]);
}

TEST(CliOptions, VersionOnAllThreePrograms)
{
    const CliRun r = runCli({QStringLiteral("--version")});
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out.section(QLatin1Char('\n'), 0, 0), QStringLiteral("benchpilot-cli " BP_VERSION));
    const ProgramRun c = runProgram(binary("benchpilot-cli"), {QStringLiteral("--version")});
    EXPECT_EQ(c.exitCode, 0) << c.describe();
    EXPECT_EQ(c.out.section(QLatin1Char('\n'), 0, 0), QStringLiteral("benchpilot-cli " BP_VERSION));
    const ProgramRun s = runProgram(binary("benchpilot-sim"), {QStringLiteral("--version")});
    EXPECT_EQ(s.exitCode, 0) << s.describe();
    EXPECT_EQ(s.out.section(QLatin1Char('\n'), 0, 0), QStringLiteral("benchpilot-sim " BP_VERSION));
    // The licence the programs are distributed under, as GNU programs say it (and help2man reads it).
    for (const QString& out : {r.out, c.out, s.out}) {
        EXPECT_TRUE(out.contains(QStringLiteral("License GPL-3.0-or-later"))) << out.toStdString();
        EXPECT_TRUE(out.contains(QStringLiteral("NO WARRANTY"))) << out.toStdString();
    }
}

TEST(CliOptions, SimulatorHelpAndJoinedValues)
{
    const ProgramRun help = runProgram(binary("benchpilot-sim"), {QStringLiteral("--help")});
    EXPECT_EQ(help.exitCode, 0) << help.describe();
    for (const char* o : {"--instrument", "--pty", "--time-scale", "--baud", "--version"})
        EXPECT_TRUE(help.out.contains(QLatin1String(o))) << o;
    // --opt=value reaches the option: a bad joined value is refused by name.
    const ProgramRun bad = runProgram(binary("benchpilot-sim"), {QStringLiteral("--instrument=robot"), QStringLiteral("--pty=/tmp/x")});
    EXPECT_EQ(bad.exitCode, 2) << bad.describe();
    EXPECT_TRUE(bad.err.contains(QStringLiteral("--instrument must be analyzer or stage (got 'robot')"))) << bad.describe();
}

TEST(CliOptions, BashCompletionCompletesCommandsSubcommandsAndOptions)
{
    const CliRun script = runCli(words("completion bash"));
    ASSERT_EQ(script.code, 0) << script.err.toStdString();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("benchpilot-cli.bash"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(script.out.toUtf8());
    f.close();
    auto complete = [&](const QString& line) {
        // COMP_WORDS as bash splits the line; the last word is being completed.
        QStringList w = line.split(QLatin1Char(' '));
        QString words = QStringLiteral("(");
        for (const QString& x : w)
            words += QStringLiteral("\"%1\" ").arg(x);
        words += QLatin1Char(')');
        const QString prog = QStringLiteral("source %1; COMP_WORDS=%2; COMP_CWORD=%3; _benchpilot_cli; echo \"${COMPREPLY[*]}\"")
                                 .arg(path, words)
                                 .arg(w.size() - 1);
        const ProgramRun r = runProgram(QStringLiteral("bash"), {QStringLiteral("-c"), prog});
        EXPECT_EQ(r.exitCode, 0) << r.describe();
        return r.out.trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    };
    EXPECT_EQ(complete(QStringLiteral("benchpilot-cli prof")), QStringList{QStringLiteral("profile")});
    EXPECT_TRUE(complete(QStringLiteral("benchpilot-cli profile --v")).contains(QStringLiteral("--vmax")));
    EXPECT_TRUE(complete(QStringLiteral("benchpilot-cli --sim stage move --")).contains(QStringLiteral("--relative")));
    EXPECT_EQ(complete(QStringLiteral("benchpilot-cli --sim st")), QStringList{QStringLiteral("stage")});
    for (const auto& c : app::cli::commands())
        EXPECT_TRUE(complete(QStringLiteral("benchpilot-cli ")).contains(c.name)) << c.name.toStdString();
}
