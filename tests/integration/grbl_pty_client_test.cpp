// The GRBL backend over a real pseudo-terminal (QSerialPort), against benchpilot-sim --protocol
// grbl and grblhal in its own process: the port's protocol is detected, the controller identified,
// homed, moved, a 10 mm circle streamed — and the simulator's own receive-buffer accounting,
// printed when it stops, shows that no byte was ever dropped. Then the CLI, on the same kind of
// port: info says which firmware, status, move, jog, pattern run, estop, reset and unlock, with
// the exit codes and JSON shapes of the BenchPilot protocol.
#include "device/backends/grbl/client/grbl_client.h"
#include "device/backends/protocol_probe.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/link/serial_transport.h"
#include "motion/plans/pattern.h"
#include "pty_simulator.h"
#include "wait.h"

#include <QJsonArray>
#include <QRegularExpression>

#include <gtest/gtest.h>

using itest::waitFor;

namespace {

/// benchpilot-sim's last words: "receive buffer: N bytes lost, at most M of R bytes held".
struct BufferAccounting {
    long lost = -1, most = -1, size = -1;
};
BufferAccounting stopAndReadAccounting(itest::PtySimulator& sim)
{
    sim.process().terminate();
    sim.process().waitForFinished(10000);
    const QString out = QString::fromUtf8(sim.process().readAllStandardOutput());
    const auto m = QRegularExpression(QStringLiteral("receive buffer: (\\d+) bytes lost, at most (\\d+) of (\\d+) bytes held")).match(out);
    BufferAccounting b;
    if (m.hasMatch())
        b = {m.captured(1).toLong(), m.captured(2).toLong(), m.captured(3).toLong()};
    return b;
}

struct CliRun {
    int code = -1;
    QString out, err;
};
CliRun cli(const QStringList& args, int timeoutMs = 60000)
{
    QProcess p;
    p.start(itest::binary("benchpilot-cli"), args);
    CliRun r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished(5000);
        r.err = QStringLiteral("benchpilot-cli did not finish");
        return r;
    }
    r.code = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace

TEST(GrblPtyClient, DetectsIdentifiesHomesMovesAndStreamsACircleOverARealPort)
{
    for (const char* dialect : {"grbl", "grblhal"}) {
        SCOPED_TRACE(dialect);
        itest::PtySimulator sim;
        ASSERT_TRUE(sim.start(QStringLiteral("stage"), 8, {QStringLiteral("--protocol"), QString::fromLatin1(dialect)})) << qPrintable(sim.error());
        dev::SerialTransport port(sim.link(), 115200);
        dev::ProtocolProbe probe(&port);
        probe.start();
        ASSERT_TRUE(waitFor([&] { return probe.done(); }, 8000));
        ASSERT_EQ(probe.result().protocol, dev::ProbeResult::Protocol::Grbl) << motion::msg::debugString(probe.result().error);

        dev::GrblClient client(dev::files::defaultProfile(dev::proto::DeviceKind::Stage), true);
        client.setTransport(&port);  // the probe left it open
        client.connectLink();
        ASSERT_TRUE(waitFor([&] { return client.isReady() || client.state() == dev::LinkState::Disconnected; }, 10000));
        ASSERT_TRUE(client.isReady());
        EXPECT_EQ(client.identity().family, QString::fromLatin1(std::string(dialect) == "grbl" ? "Grbl 1.1h" : "grblHAL 1.1f"));
        bool homed = false;
        client.home(0, [&](const auto& e) { homed = !e; });
        ASSERT_TRUE(waitFor([&] { return homed && client.status().axes[0].homed && !client.status().anyMoving(); }, 30000));

        dev::jobs::PatternRunner runner(&client);
        QObject::connect(&client, &dev::Instrument::telemetryReceived, &runner,
                         [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, client, b); });
        client.subscribe(dev::jobs::patternChannels(), 250);
        motion::plans::Pattern circle;
        circle.shape = motion::plans::PatternShape::Circle;  // 10 mm at 2 mm/s
        ASSERT_TRUE(runner.start(motion::plans::plan(circle), {}));
        ASSERT_TRUE(waitFor([&] { return !runner.busy(); }, 60000));
        EXPECT_EQ(runner.state(), dev::jobs::PatternRunner::State::Done);
        EXPECT_LT(runner.summary().maxContourMm, 0.005);
        client.disconnectLink();
        const BufferAccounting b = stopAndReadAccounting(sim);
        EXPECT_EQ(b.lost, 0);
        EXPECT_GT(b.most, 0);
        EXPECT_LT(b.most, b.size);
    }
}

TEST(GrblPtyClient, TheCliDrivesAGrblControllerOnItsPort)
{
    itest::PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 8, {QStringLiteral("--protocol"), QStringLiteral("grbl")})) << qPrintable(sim.error());
    const QStringList port = {QStringLiteral("--port"), sim.link(), QStringLiteral("--instrument"), QStringLiteral("stage"),
                              QStringLiteral("--json")};

    // info: which firmware, and the BenchPilot protocol's JSON shape.
    CliRun r = cli(port + QStringList{QStringLiteral("info")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QJsonObject info = itest::lastJson(r.out);
    EXPECT_EQ(info.value(QStringLiteral("family")).toString(), QStringLiteral("Grbl 1.1h"));
    EXPECT_EQ(info.value(QStringLiteral("instrument")).toString(), QStringLiteral("stage"));
    EXPECT_EQ(info.value(QStringLiteral("motion_profile")).toString(), QStringLiteral("trapezoid"));
    for (const char* key : {"model", "firmware", "protocol", "capabilities", "features", "link_baud", "axes"})
        EXPECT_TRUE(info.contains(QLatin1String(key))) << key;
    EXPECT_FALSE(info.value(QStringLiteral("features")).toArray().contains(QStringLiteral("pid_gains")));

    // status before homing: in alarm; a move is refused (2).
    r = cli(port + QStringList{QStringLiteral("status")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_FALSE(itest::lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().value(QStringLiteral("homed")).toBool());
    r = cli(port + QStringList{QStringLiteral("move"), QStringLiteral("X=10")});
    EXPECT_EQ(r.code, 2) << r.err.toStdString();

    // home, move, a soft-limit refusal that says so, a jog.
    r = cli(port + QStringList{QStringLiteral("home")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    r = cli(port + QStringList{QStringLiteral("move"), QStringLiteral("X=30"), QStringLiteral("Y=40"), QStringLiteral("--speed"), QStringLiteral("20")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QJsonObject axes = itest::lastJson(r.out).value(QStringLiteral("axes")).toObject();
    EXPECT_NEAR(axes.value(QStringLiteral("X")).toObject().value(QStringLiteral("position")).toDouble(), 30, 1e-3);
    r = cli(port + QStringList{QStringLiteral("move"), QStringLiteral("X=150")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine travel"))) << r.err.toStdString();
    r = cli(port + QStringList{QStringLiteral("jog"), QStringLiteral("X"), QStringLiteral("5"), QStringLiteral("0.5")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_GT(itest::lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().value(QStringLiteral("position")).toDouble(), 30.5);

    // pattern run: the 10 mm circle, its contour error and the rate it was sampled at.
    r = cli(port + QStringList{QStringLiteral("pattern"), QStringLiteral("run"), QStringLiteral("--shape"), QStringLiteral("circle")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject run = itest::lastJson(r.out);
    EXPECT_TRUE(run.value(QStringLiteral("complete")).toBool());
    EXPECT_EQ(run.value(QStringLiteral("sample_rate_hz")).toInt(), 10);
    EXPECT_LT(run.value(QStringLiteral("max_contour_um")).toDouble(), 5.0);

    // estop: the position is lost (it was at rest: GRBL keeps it, so move first to be caught moving).
    r = cli(port + QStringList{QStringLiteral("estop")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(itest::lastJson(r.out).value(QStringLiteral("estop")).toBool());
    r = cli(port + QStringList{QStringLiteral("reset")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_FALSE(itest::lastJson(r.out).value(QStringLiteral("estop")).toBool());
    // limits cannot be set on GRBL: refused with the reason (2).
    r = cli(port + QStringList{QStringLiteral("limits"), QStringLiteral("X=0:50")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("$130"))) << r.err.toStdString();
    const BufferAccounting b = stopAndReadAccounting(sim);
    EXPECT_EQ(b.lost, 0);
}
