// benchpilot-sim --gauge serves a simulated length gauge on a pty of its own, reading
// the true position of one axis' work point: a serial host asks "?" + CR and gets a
// signed reading with its unit, as from a USB gauge.
#include "pty_simulator.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTemporaryDir>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace {

std::string askRaw(const QString& path, const std::string& request, int limitMs = 5000)
{
    const int fd = ::open(qPrintable(path), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0)
        return "(cannot open)";
    termios t{};
    ::tcgetattr(fd, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(fd, TCSANOW, &t);
    [[maybe_unused]] const auto n = ::write(fd, request.data(), request.size());
    std::string got;
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < limitMs && got.find('\n') == std::string::npos) {
        char buf[128];
        const ssize_t k = ::read(fd, buf, sizeof buf);
        if (k > 0)
            got.append(buf, static_cast<std::size_t>(k));
        else
            ::usleep(5000);
    }
    ::close(fd);
    return got;
}

TEST(AccuracyGaugePty, BenchpilotSimServesAGaugeThatReadsTheWorkPoint)
{
    QTemporaryDir dir;
    const QString gauge = dir.filePath(QStringLiteral("ttyGauge"));
    itest::PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 1,
                          {QStringLiteral("--gauge"), gauge, QStringLiteral("--gauge-axis"), QStringLiteral("X"),
                           QStringLiteral("--gauge-noise"), QStringLiteral("0")}))
        << qPrintable(sim.error());
    const std::string answer = askRaw(gauge, "?\r");
    ASSERT_EQ(answer.size(), std::string("+000.0398 mm\r\n").size()) << answer;
    EXPECT_EQ(answer.substr(9), " mm\r\n");
    // At power-up the readback reads 0 where the stage stands (41.7 mm from the machine's
    // zero); the work point there is off by seed 002's X curve (40.0 µm) less the
    // grating's 5 µm/m over those 41.7 mm.
    const double v = std::stod(answer.substr(0, 9));
    EXPECT_NEAR(v, 0.0398, 0.0003) << answer;
}

TEST(AccuracyGaugePty, AGaugeNeedsAnAxisTheInstrumentHas)
{
    QTemporaryDir dir;
    QProcess p;
    p.start(itest::binary("benchpilot-sim"), {QStringLiteral("--instrument"), QStringLiteral("stage"), QStringLiteral("--pty"),
                                                dir.filePath(QStringLiteral("tty")), QStringLiteral("--gauge"),
                                                dir.filePath(QStringLiteral("g")), QStringLiteral("--gauge-axis"), QStringLiteral("Z")});
    ASSERT_TRUE(p.waitForFinished(10000));
    EXPECT_EQ(p.exitCode(), 2);
    EXPECT_TRUE(p.readAllStandardError().contains("no axis 'Z'"));
}

} // namespace
