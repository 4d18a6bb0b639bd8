// "Set home here" on a GRBL controller without homing, across connections: kept when the
// controller provably did not restart since (no start-up banner as the port opened, the same G54
// offset and machine position), dropped when it did — a board that restarts as its port opens,
// one that restarted while nothing was connected, one that reset by itself while connected.
// In-process over the loopback pair, and with two benchpilot-cli runs on benchpilot-sim's pty.
#include "device/backends/grbl/grbl_home_memory.h"
#include "grbl_session.h"
#include "pty_simulator.h"

#include <gtest/gtest.h>

#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include <cmath>

using itest::GrblSession;
using itest::waitFor;

namespace {

/// A session on a controller without homing switches, remembering homes in a file of its own.
struct HomeRig {
    QTemporaryDir dir;
    GrblSession s;
    QString file = dir.filePath(QStringLiteral("grbl-homes.json"));

    explicit HomeRig(bool restartsOnOpen)
    {
        s.firmware().setRestartsOnPortOpen(restartsOnOpen);
        s.firmware().settings().write(22, 0);
        s.firmware().restart();  // powered up without homing: Idle
        s.client.rememberHomesIn(file, QStringLiteral("/dev/ttyACM0"));
    }
    bool reconnect()
    {
        s.client.disconnectLink();
        return s.connect();
    }
    bool noted(const std::string& id) const
    {
        for (const auto& n : s.notes)
            if (n.id == id)
                return true;
        return false;
    }
    std::optional<dev::RequestError> moveTo(double x)
    {
        const std::size_t from = s.events.size();
        auto e = s.call([&](auto cb) { s.client.move({{0, x}}, false, 10, cb); });
        if (!e && !s.waitEvent(dev::proto::EventKind::MotionDone, 0, from))
            ADD_FAILURE() << "no MotionDone";
        return e;
    }
    /// Moves X by `dx` relative (allowed unestablished), then sets home here on X and Y.
    void setHomeAfter(double dx)
    {
        if (dx != 0) {
            const std::size_t from = s.events.size();
            ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, dx}}, true, 10, cb); }));
            ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, from));
            ASSERT_TRUE(s.waitStill());
        }
        ASSERT_FALSE(s.call([&](auto cb) { s.client.setZero(0, cb); }));
        ASSERT_TRUE(s.readout('X').homed);
        ASSERT_TRUE(dev::GrblHomeMemory(file).recall(remembered()).has_value()) << "set home here was not remembered";
    }
    std::string remembered() const
    {
        const auto all = dev::GrblHomeMemory::parse([this] {
            QFile f(file);
            f.open(QIODevice::ReadOnly);
            return f.readAll().toStdString();
        }());
        return all.empty() ? std::string() : all.front().controller;
    }
};

} // namespace

TEST(GrblHomeKept, ABoardThatDoesNotRestartKeepsTheHomeSetHereAcrossConnections)
{
    HomeRig r(false);
    ASSERT_TRUE(r.s.connect());
    EXPECT_FALSE(r.s.readout('X').homed);  // nothing remembered yet: unestablished, as always
    r.setHomeAfter(2);
    ASSERT_FALSE(r.moveTo(3));

    ASSERT_TRUE(r.reconnect());
    EXPECT_TRUE(r.s.readout('X').homed);
    EXPECT_TRUE(r.s.readout('Y').homed);
    EXPECT_TRUE(r.noted("grbl.home_kept"));
    EXPECT_NEAR(r.s.readout('X').commanded, 3, 1e-3);
    // An absolute move goes where it would have gone in the first connection.
    ASSERT_FALSE(r.moveTo(1)) << "an absolute move after reconnecting was refused";
    EXPECT_NEAR(r.s.firmware().machinePositionMm()[0] - r.s.firmware().workOffsetMm()[0], 1, 1e-6);
    // And a third connection still keeps it (the machine position seen last is the one compared).
    ASSERT_TRUE(r.reconnect());
    EXPECT_TRUE(r.s.readout('X').homed);
}

TEST(GrblHomeKept, ABoardThatRestartsAsItsPortOpensStartsUnestablished)
{
    HomeRig r(true);
    ASSERT_TRUE(r.s.connect());
    r.setHomeAfter(2);
    const int restarts = r.s.firmware().restarts();
    ASSERT_TRUE(r.reconnect());
    EXPECT_GT(r.s.firmware().restarts(), restarts);
    EXPECT_FALSE(r.s.readout('X').homed);
    EXPECT_TRUE(r.noted("grbl.home_lost_restart"));
    const auto refused = r.moveTo(1);
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->message.id, "grbl.move_not_established");
    EXPECT_TRUE(r.remembered().empty());  // dropped: no later connection takes it up again
}

TEST(GrblHomeKept, ARestartWhileNothingWasConnectedIsToldByTheMachinePosition)
{
    HomeRig r(false);
    ASSERT_TRUE(r.s.connect());
    r.setHomeAfter(2);
    r.s.client.disconnectLink();
    r.s.firmware().restart();  // its banner goes to a closed port: nobody hears it
    itest::spin(100);
    ASSERT_TRUE(r.s.connect());
    EXPECT_FALSE(r.s.readout('X').homed);  // G54 is as it was (EEPROM), the machine position is not
    EXPECT_TRUE(r.noted("grbl.home_lost_changed"));
}

TEST(GrblHomeKept, AResetByItselfWhileConnectedDropsTheHomeEvenWhereThePositionsStillAgree)
{
    HomeRig r(false);
    ASSERT_TRUE(r.s.connect());
    r.setHomeAfter(0);  // at machine position 0: a restart leaves the position reading the same
    r.s.firmware().restart();
    ASSERT_TRUE(waitFor([&] { return !r.s.readout('X').homed; }, 5000));
    EXPECT_TRUE(r.remembered().empty());
    ASSERT_TRUE(r.reconnect());
    EXPECT_FALSE(r.s.readout('X').homed);
}

TEST(GrblHomeKept, TheCliZeroThenAnAbsoluteMoveWorksOnABoardThatDoesNotRestart)
{
    // Two benchpilot-cli runs on one port, as a shell script drives the board.
    itest::PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 8, {QStringLiteral("--protocol"), QStringLiteral("grblhal"), QStringLiteral("--no-homing")}))
        << qPrintable(sim.error());
    QTemporaryDir state;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_DATA_HOME"), state.path());
    auto cli = [&](const QStringList& command, QString* out) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(itest::binary("benchpilot-cli"),
                QStringList{QStringLiteral("--port"), sim.link(), QStringLiteral("--instrument"), QStringLiteral("stage")} + command);
        if (!p.waitForFinished(60000)) {
            p.kill();
            p.waitForFinished(5000);
            return -1;
        }
        *out = QString::fromUtf8(p.readAllStandardError()) + QString::fromUtf8(p.readAllStandardOutput());
        return p.exitCode();
    };
    QString out;
    // Before any home is set, an absolute move is refused, as it must be.
    EXPECT_NE(cli({QStringLiteral("move"), QStringLiteral("X=10")}, &out), 0) << out.toStdString();
    EXPECT_TRUE(out.contains(QStringLiteral("no established position"))) << out.toStdString();
    ASSERT_EQ(cli({QStringLiteral("zero"), QStringLiteral("XY")}, &out), 0) << out.toStdString();
    EXPECT_EQ(cli({QStringLiteral("move"), QStringLiteral("X=10")}, &out), 0) << out.toStdString();
    EXPECT_TRUE(out.contains(QStringLiteral("10.0000"))) << out.toStdString();
    EXPECT_EQ(cli({QStringLiteral("move"), QStringLiteral("X=4")}, &out), 0) << out.toStdString();
}
