// The real serial path: benchpilot-sim serves the reference firmware on a
// pseudo-terminal, and benchpilot-cli or a SerialTransport opens it like any
// serial port. The simulator runs at --time-scale 4 to keep homing short.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/serial_transport.h"
#include "programs.h"
#include "pty_simulator.h"
#include "wait.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <csignal>

using namespace itest;
using dev::LinkState;

namespace {

using CliRun = ProgramRun;

CliRun runCli(const QStringList& args, int timeoutMs = 60000) { return runProgram(binary("benchpilot-cli"), args, timeoutMs); }

} // namespace

TEST(PtySimulator, PrintsWhereItServesAndRemovesTheSymlinkOnSigint)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("analyzer"))) << sim.error().toStdString();
    EXPECT_TRUE(sim.line().startsWith(sim.link() + QStringLiteral(" -> /dev/pts/"))) << sim.line().toStdString();
    const QFileInfo link(sim.link());
    ASSERT_TRUE(link.isSymLink());
    EXPECT_TRUE(link.symLinkTarget().startsWith(QStringLiteral("/dev/pts/"))) << link.symLinkTarget().toStdString();

    ::kill(static_cast<pid_t>(sim.process().processId()), SIGINT);
    ASSERT_TRUE(sim.process().waitForFinished(5000));
    EXPECT_EQ(sim.process().exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(sim.process().exitCode(), 0);
    EXPECT_FALSE(QFileInfo(sim.link()).isSymLink()) << "the symlink outlived the simulator";
}

TEST(PtyCli, StatusHomeMoveAndStatusAgainAsJson)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"))) << sim.error().toStdString();
    const QStringList port{QStringLiteral("--port"), sim.link()};

    CliRun r = runCli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")});
    ASSERT_TRUE(r.finished);
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    QJsonObject axes = lastJson(r.out).value(QStringLiteral("axes")).toObject();
    ASSERT_EQ(axes.keys(), (QStringList{QStringLiteral("X"), QStringLiteral("Y")})) << r.describe();
    for (const QString& a : axes.keys()) {
        const QJsonObject o = axes.value(a).toObject();
        for (const char* key : {"position", "measured"})
            EXPECT_TRUE(o.value(QLatin1String(key)).isDouble()) << a.toStdString() << "." << key << ": " << r.describe();
        for (const char* key : {"homed", "moving"})
            EXPECT_TRUE(o.value(QLatin1String(key)).isBool()) << a.toStdString() << "." << key << ": " << r.describe();
        EXPECT_FALSE(o.value(QStringLiteral("homed")).toBool());
    }

    r = runCli(port + QStringList{QStringLiteral("--json"), QStringLiteral("home")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    axes = lastJson(r.out).value(QStringLiteral("axes")).toObject();
    EXPECT_TRUE(axes.value(QStringLiteral("X")).toObject().value(QStringLiteral("homed")).toBool()) << r.describe();
    EXPECT_TRUE(axes.value(QStringLiteral("Y")).toObject().value(QStringLiteral("homed")).toBool()) << r.describe();

    r = runCli(port + QStringList{QStringLiteral("move"), QStringLiteral("X=12.5"), QStringLiteral("Y=30")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();

    // A separate run, as a script would do it: the device's state as it is now.
    r = runCli(port + QStringList{QStringLiteral("status"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    axes = lastJson(r.out).value(QStringLiteral("axes")).toObject();
    const QJsonObject x = axes.value(QStringLiteral("X")).toObject(), y = axes.value(QStringLiteral("Y")).toObject();
    EXPECT_NEAR(x.value(QStringLiteral("position")).toDouble(-1), 12.5, 1e-6) << r.describe();
    EXPECT_NEAR(y.value(QStringLiteral("position")).toDouble(-1), 30.0, 1e-6) << r.describe();
    EXPECT_NEAR(x.value(QStringLiteral("measured")).toDouble(-1), 12.5, 0.002) << r.describe();
    EXPECT_NEAR(y.value(QStringLiteral("measured")).toDouble(-1), 30.0, 0.002) << r.describe();
    EXPECT_TRUE(x.value(QStringLiteral("homed")).toBool());
    EXPECT_FALSE(x.value(QStringLiteral("moving")).toBool(true));
    EXPECT_FALSE(y.value(QStringLiteral("moving")).toBool(true));
}

TEST(PtyCli, JogRunsForItsSecondsThenStopsAndWaits)
{
    // Real time: at --time-scale K the CLI's 50 ms refreshes are 50·K ms apart on
    // the device's clock, and from K = 4 on they no longer beat its 200 ms watchdog.
    // On a machine loaded by the rest of the suite a process can be held off the CPU for
    // 200 ms: the device then stops the jog as it must, and says so. That case (and only
    // that one) gets a second try, on a fresh simulator.
    CliRun r;
    for (int attempt = 0; attempt < 2; ++attempt) {
        PtySimulator sim;
        ASSERT_TRUE(sim.start(QStringLiteral("stage"), 1)) << sim.error().toStdString();
        r = runCli({QStringLiteral("--port"), sim.link(), QStringLiteral("--json"), QStringLiteral("jog"), QStringLiteral("X"),
                    QStringLiteral("4"), QStringLiteral("1")});
        ASSERT_TRUE(r.finished);
        if (r.exitCode == 0 || !r.err.contains(QLatin1String("heard no jog")))
            break;
        std::printf("the device's jog watchdog stopped the jog (the machine is busy): trying once more\n%s\n", qPrintable(r.err));
    }
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject x = lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject();
    // 1 s at 4 mm/s, give or take the start-up and the ramps.
    EXPECT_GT(x.value(QStringLiteral("position")).toDouble(), 2.5) << r.describe();
    EXPECT_LT(x.value(QStringLiteral("position")).toDouble(), 6.0) << r.describe();
    EXPECT_FALSE(x.value(QStringLiteral("moving")).toBool(true)) << r.describe();
}

TEST(PtyCli, AbsoluteMoveBeforeHomingExitsTwoWithTheReason)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"))) << sim.error().toStdString();
    const CliRun r = runCli({QStringLiteral("--port"), sim.link(), QStringLiteral("move"), QStringLiteral("X=5")});
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(r.exitCode, 2) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("axis X"))) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("not homed"))) << r.describe();
}

TEST(PtyCli, MissingPortExitsThreeWithTheReason)
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("ttyBP_missing"));
    QElapsedTimer wall;
    wall.start();
    const CliRun r = runCli({QStringLiteral("--port"), missing, QStringLiteral("status")}, 20000);
    ASSERT_TRUE(r.finished) << "benchpilot-cli hung on a missing port";
    EXPECT_EQ(r.exitCode, 3) << r.describe();
    EXPECT_TRUE(r.err.contains(missing)) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("no such port"))) << r.describe();
    EXPECT_TRUE(r.out.isEmpty()) << r.describe();
    EXPECT_LT(wall.elapsed(), 10000) << "a missing port must not wait for a timeout";
}

TEST(PtyCli, BusyPortExitsThreeSayingItIsBusy)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"))) << sim.error().toStdString();
    // Another program (here: this one) has the port open.
    dev::SerialTransport holder(sim.link(), 115200);
    bool opened = false;
    QObject::connect(&holder, &dev::Transport::opened, &holder, [&] { opened = true; });
    holder.open();
    ASSERT_TRUE(waitFor([&] { return opened; }, 3000));

    const CliRun r = runCli({QStringLiteral("--port"), sim.link(), QStringLiteral("status")}, 20000);
    ASSERT_TRUE(r.finished) << "benchpilot-cli hung on a busy port";
    EXPECT_EQ(r.exitCode, 3) << r.describe();
    EXPECT_TRUE(r.err.contains(sim.link())) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("another program has it open"))) << r.describe();  // busy, not a permission question
    holder.close();
}

TEST(PtyCli, FrozenDeviceExitsThreeWithNoAnswerInsteadOfHanging)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("analyzer"))) << sim.error().toStdString();
    const auto pid = static_cast<pid_t>(sim.process().processId());
    ::kill(pid, SIGSTOP);  // powered, port open, firmware hung
    QElapsedTimer wall;
    wall.start();
    const CliRun r = runCli({QStringLiteral("--port"), sim.link(), QStringLiteral("status")}, 20000);
    const qint64 ms = wall.elapsed();
    ::kill(pid, SIGCONT);
    ASSERT_TRUE(r.finished) << "benchpilot-cli hung on a silent device";
    EXPECT_EQ(r.exitCode, 3) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("no answer"))) << r.describe();
    EXPECT_LT(ms, 10000) << "the CLI must give up after the client's reply timeouts";
}

TEST(PtySerial, SimulatorTerminatedDuringMoveIsLinkLostAndItsSymlinkIsGone)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"))) << sim.error().toStdString();
    dev::SerialTransport port(sim.link(), 115200);
    dev::BenchPilotClient client;
    QStringList errors;
    QObject::connect(&client, &dev::BenchPilotClient::linkError, &client, [&](const motion::msg::Message& m) { errors << QString::fromStdString(motion::msg::debugString(m)); });
    client.setTransport(&port);
    client.connectLink();
    ASSERT_TRUE(waitFor([&] { return client.state() == LinkState::Ready || client.state() == LinkState::Disconnected; }, 5000));
    ASSERT_EQ(client.state(), LinkState::Ready) << errors.join(QStringLiteral(" | ")).toStdString();
    EXPECT_EQ(client.identity().kind, dev::proto::DeviceKind::Stage);

    bool accepted = false;
    client.move({{0, 30.0}}, true, 0, [&](const auto& e) {
        EXPECT_FALSE(e) << motion::msg::debugString(e->message);
        accepted = true;
    });
    ASSERT_TRUE(waitFor([&] { return accepted && client.status().axes[0].moving; }, 5000));

    QElapsedTimer wall;
    wall.start();
    sim.process().terminate();  // SIGTERM
    ASSERT_TRUE(waitFor([&] { return client.state() == LinkState::Lost; }, 5000)) << "the client never noticed";
    EXPECT_LT(wall.elapsed(), 2000);
    ASSERT_FALSE(errors.isEmpty());
    EXPECT_TRUE(errors.last().startsWith(QStringLiteral("link.lost{"))) << errors.last().toStdString();

    // The event loop above may already have seen it exit.
    ASSERT_TRUE(sim.process().state() == QProcess::NotRunning || sim.process().waitForFinished(5000));
    EXPECT_EQ(sim.process().exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(sim.process().exitCode(), 0);
    EXPECT_FALSE(QFileInfo(sim.link()).isSymLink()) << "SIGTERM must remove the symlink";
    EXPECT_FALSE(QFileInfo::exists(sim.link()));
    client.setTransport(nullptr);
}
