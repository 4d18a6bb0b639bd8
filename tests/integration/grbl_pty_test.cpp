// benchpilot-sim --protocol grbl on a real pseudo-terminal: the GRBL personality answers a
// serial host the way a GRBL board on a USB serial port does.
#include "pty_simulator.h"

#include "device/backends/grbl/grbl_build_info.h"
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_status.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace {

/// The pty opened raw, as a serial host opens a port.
class RawPort {
public:
    explicit RawPort(const QString& path) : m_fd(::open(qPrintable(path), O_RDWR | O_NOCTTY | O_NONBLOCK))
    {
        if (m_fd >= 0) {
            termios t{};
            ::tcgetattr(m_fd, &t);
            ::cfmakeraw(&t);
            ::tcsetattr(m_fd, TCSANOW, &t);
        }
    }
    ~RawPort()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    bool ok() const { return m_fd >= 0; }
    void write(const std::string& s) { ASSERT_EQ(::write(m_fd, s.data(), s.size()), static_cast<ssize_t>(s.size())); }
    /// Lines until one equals `last` (or starts with it, with `prefix`), included, or `limitMs` passes.
    std::vector<std::string> readUntil(const std::string& last, int limitMs = 5000, bool prefix = false)
    {
        std::vector<dev::grbl::LineReader::Line> got;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < limitMs) {
            char buf[256];
            const ssize_t n = ::read(m_fd, buf, sizeof buf);
            if (n > 0)
                m_reader.feed(std::string_view(buf, static_cast<std::size_t>(n)), got);
            else
                ::usleep(5000);
            for (const auto& l : got)
                if (prefix ? l.text.rfind(last, 0) == 0 : l.text == last) {
                    std::vector<std::string> out;
                    for (const auto& g : got)
                        out.push_back(g.text);
                    return out;
                }
        }
        ADD_FAILURE() << "no '" << last << "' within " << limitMs << " ms";
        return {};
    }

private:
    int m_fd;
    dev::grbl::LineReader m_reader;
};

TEST(GrblPty, BenchpilotSimSpeaksGrblOnAPty)
{
    itest::PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 1, {QStringLiteral("--protocol"), QStringLiteral("grbl")})) << qPrintable(sim.error());
    EXPECT_TRUE(sim.line().contains(QStringLiteral("grbl"))) << qPrintable(sim.line());
    RawPort port(sim.link());
    ASSERT_TRUE(port.ok());
    port.write("\x18");  // the banner came before we listened: a reset says it again
    const auto hello = port.readUntil("[MSG:'$H'|'$X' to unlock]");
    ASSERT_GE(hello.size(), 2u);
    EXPECT_EQ(dev::grbl::parseBanner(hello[hello.size() - 2])->firmware, dev::grbl::Firmware::Grbl);
    port.write("$I\n");
    dev::grbl::BuildInfo info;
    for (const auto& l : port.readUntil("ok"))
        dev::grbl::addBuildInfoLine(info, dev::grbl::classifyLine(l));
    EXPECT_EQ(info.plannerBlocks, 15);
    EXPECT_EQ(info.rxBufferBytes, 128);
    port.write("$X\nG91 G1 X0.5 F600\nG4 P0.01\n");
    int oks = 0;
    for (const auto& l : port.readUntil("ok", 5000))
        oks += l == "ok";
    for (; oks < 3; ++oks)
        port.readUntil("ok", 5000);
    port.write("?");
    const auto lines = port.readUntil("<", 5000, true);
    ASSERT_FALSE(lines.empty());
    const auto report = dev::grbl::parseStatusReport(dev::grbl::classifyLine(lines.back()).payload).report;
    ASSERT_TRUE(report) << lines.back();
    EXPECT_EQ(report->state, dev::grbl::MachineState::Idle);
    ASSERT_EQ(report->position.size(), 3u);  // the stage's X and Y, and the Z every GRBL has
    EXPECT_DOUBLE_EQ(report->position[0], 0.5);
}

} // namespace
