// The joystick driver over a real client and the simulated stage: two axes at once, refreshes
// limited to what changes plus the watchdog keep-alive, and what that costs the link.
#include "device/client/joystick_driver.h"
#include "device/sim/path_queue.h"
#include "sim_session.h"

#include <QElapsedTimer>

#include <gtest/gtest.h>

#include <cmath>

using itest::SimSession;
using itest::waitFor;

namespace {

struct Rig {
    SimSession s{dev::proto::DeviceKind::Stage};
    dev::JoystickDriver stick{&s.client};
    int jogFrames = 0;
    qint64 jogBytes = 0;
    Rig()
    {
        s.tap.afterWrite = [this](const QByteArray& bytes) {
            if (itest::containsFrame(bytes, dev::proto::MsgType::JogVelocity)) {
                ++jogFrames;
                jogBytes += bytes.size();
            }
        };
        EXPECT_TRUE(s.connect());
    }
};

}  // namespace

TEST(PatternsJoystickDriver, ADragAtAThousandWishesASecondCostsAtMostFiftyFramesASecond)
{
    Rig r;
    const double x0 = r.s.link.machine().commandedLogical(0), y0 = r.s.link.machine().commandedLogical(1);
    const qint64 bytes0 = r.s.link.pair().bytesCarried(dev::LoopbackPair::A);
    QElapsedTimer t;
    t.start();
    int wishes = 0;
    // A stick swept around in circles for 2 s, a wish every millisecond (a fast mouse).
    while (t.elapsed() < 2000) {
        const double a = t.elapsed() / 1000.0 * 3.0;
        r.stick.setVelocities({{0, 2.0 * std::cos(a)}, {1, 2.0 * std::sin(a) + 2.5}});
        ++wishes;
        itest::spin(1);
    }
    const double seconds = t.elapsed() / 1000.0;
    const qint64 allBytes = r.s.link.pair().bytesCarried(dev::LoopbackPair::A) - bytes0;
    r.stick.stop();
    EXPECT_GT(wishes, 300);
    EXPECT_LE(r.jogFrames, seconds * 1000 / dev::JoystickDriver::kMinIntervalMs + 2);
    EXPECT_GE(r.jogFrames, 10);
    // What the link carries from the host: 115 200 Bd is 11 520 bytes a second.
    const double jogShare = r.jogBytes / seconds / 11520.0;
    const double hostShare = allBytes / seconds / 11520.0;
    std::printf("joystick: %d wishes → %d JOG_VELOCITY frames in %.2f s (%.1f /s), %.0f B/s = %.1f %% of 115200 Bd; "
                "all host traffic %.1f %%\n",
                wishes, r.jogFrames, seconds, r.jogFrames / seconds, r.jogBytes / seconds, 100 * jogShare, 100 * hostShare);
    EXPECT_LT(jogShare, 0.10);
    // Both axes moved together.
    EXPECT_GT(std::fabs(r.s.link.machine().commandedLogical(0) - x0), 0.1);
    EXPECT_GT(r.s.link.machine().commandedLogical(1) - y0, 2.0);
}

TEST(PatternsJoystickDriver, HoldingStillOnlyKeepsTheWatchdogFed)
{
    Rig r;
    r.stick.setVelocities({{0, 1.0}, {1, -1.0}});
    itest::spin(100);
    const int before = r.jogFrames;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 1000) {
        r.stick.setVelocities({{0, 1.0 + 1e-4}, {1, -1.0}});  // jitter below the resolution
        itest::spin(2);
    }
    const int keepAlive = r.jogFrames - before;
    EXPECT_LE(keepAlive, 1000 / dev::BenchPilotClient::kJogRefreshMs + 2);
    EXPECT_GE(keepAlive, 5);
    EXPECT_TRUE(r.s.link.machine().status().axes[0].flags & dev::proto::AxisJogging);
    r.stick.stop();
}

TEST(PatternsJoystickDriver, ReleaseStopsBothAxesAtOnce)
{
    Rig r;
    r.stick.setVelocities({{0, 3.0}, {1, 3.0}});
    ASSERT_TRUE(waitFor([&] { return std::fabs(r.s.link.machine().axis(0).referenceVelocity()) > 2.9; }, 2000));
    const int before = r.jogFrames;
    r.stick.setVelocities({{0, 0.0}, {1, 0.0}});
    EXPECT_EQ(r.jogFrames, before + 1);  // the stop went out without waiting for the interval
    ASSERT_TRUE(waitFor([&] { return !r.s.link.machine().status().axes[0].flags && !r.s.link.machine().status().axes[1].flags; }, 2000));
    EXPECT_FALSE(r.stick.active());
}

TEST(PatternsJoystickDriver, AnEStopDisarmsTheStickUntilItReturnsToTheCentre)
{
    Rig r;
    r.stick.setVelocities({{0, 2.0}});
    itest::spin(100);
    ASSERT_FALSE(r.s.call([&](auto cb) { r.s.client.estop(cb); }));
    ASSERT_TRUE(waitFor([&] { return r.stick.blocked(); }, 2000));
    const int frames = r.jogFrames;
    r.stick.setVelocities({{0, 2.5}});  // still pushed: ignored
    itest::spin(200);
    EXPECT_EQ(r.jogFrames, frames);
    ASSERT_FALSE(r.s.call([&](auto cb) { r.s.client.reset(cb); }));
    r.stick.setVelocities({{0, 0.0}});  // back to the centre re-arms it
    EXPECT_FALSE(r.stick.blocked());
    r.stick.setVelocities({{0, 1.0}});
    EXPECT_EQ(r.jogFrames, frames + 1);
    r.stick.stop();
}
