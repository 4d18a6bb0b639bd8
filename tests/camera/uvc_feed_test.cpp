// What a USB camera does with its frames, driven with synthetic QVideoFrames (no camera):
// a burst is dropped rather than queued, a capture takes only a frame whose exposure began
// after it was asked, a capture without one times out naming the camera, and a frame that
// cannot be converted fails the capture with the reason.
#if BP_WITH_UVC
#include "device/camera/uvc_frame_feed.h"
#include "integration/wait.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

#include <cstring>
#include <thread>

namespace cam = dev::camera;
using PF = QVideoFrameFormat::PixelFormat;

namespace {

/// A 4 × 2 grey frame, every pixel `value`, exposed from `startUs` on the stream's clock.
QVideoFrame greyFrame(std::uint8_t value, qint64 startUs, PF pf = PF::Format_Y8)
{
    QVideoFrame f(QVideoFrameFormat(QSize(4, 2), pf));
    f.map(QVideoFrame::WriteOnly);
    for (int p = 0; p < f.planeCount(); ++p)
        std::memset(f.bits(p), value, static_cast<std::size_t>(f.mappedBytes(p)));
    f.unmap();
    f.setStartTime(startUs);
    return f;
}

struct FeedRig {
    cam::UvcFrameFeed feed;
    std::vector<cam::Frame> live;
    std::vector<std::pair<std::uint64_t, cam::Frame>> captured;
    std::vector<std::pair<std::uint64_t, motion::msg::Message>> failed;
    std::vector<motion::msg::Message> liveFailed;
    std::int64_t hostUs = 1'000'000;  ///< the host's clock, as the feed sees it, once manual()

    FeedRig()
    {
        feed.setSourceName("uvc:Synthetic");
        // A short period and exposure: the clock's allowance is then 22 ms.
        feed.setFramePeriodUs(1000);
        feed.setExposureMs(1);
        QObject::connect(&feed, &cam::UvcFrameFeed::liveFrame, [this](const cam::Frame& f) { live.push_back(f); });
        QObject::connect(&feed, &cam::UvcFrameFeed::captured, [this](std::uint64_t id, const cam::Frame& f) { captured.emplace_back(id, f); });
        QObject::connect(&feed, &cam::UvcFrameFeed::captureFailed, [this](std::uint64_t id, const motion::msg::Message& m) { failed.emplace_back(id, m); });
        QObject::connect(&feed, &cam::UvcFrameFeed::liveFailed, [this](const motion::msg::Message& m) { liveFailed.push_back(m); });
    }
    /// The host clock is the test's: frames arrive when the test says.
    void manual()
    {
        feed.setHostClock([this] { return hostUs; });
    }
    /// Lets the feed pick up and convert what it was offered.
    void settle()
    {
        for (int i = 0; i < 5; ++i) {
            QCoreApplication::processEvents();
            itest::waitFor([] { return false; }, 20);
        }
    }
};

} // namespace

TEST(UvcFeed, ABurstFasterThanTheConsumerIsDroppedNotQueued)
{
    FeedRig rig;
    rig.feed.setLive(true);
    for (int i = 1; i <= 10; ++i)  // ten frames before the feed's thread gets a look
        rig.feed.offer(greyFrame(static_cast<std::uint8_t>(i * 10), i * 1000));
    ASSERT_TRUE(itest::waitFor([&] { return !rig.live.empty(); }, 5000));
    rig.settle();
    ASSERT_EQ(rig.live.size(), 1u) << "only the newest frame is converted";
    EXPECT_EQ(rig.live[0].pixels[0], 100);
    EXPECT_EQ(rig.live[0].sequence, 10u) << "the sequence counts the dropped frames, so the gap shows";
    // The next frame after the first was delivered is taken.
    rig.feed.offer(greyFrame(111, 11000));
    ASSERT_TRUE(itest::waitFor([&] { return rig.live.size() == 2; }, 5000));
    EXPECT_EQ(rig.live[1].pixels[0], 111);
    EXPECT_EQ(rig.live[1].sequence, 11u);
}

TEST(UvcFeed, FramesFromAnotherThreadAreTakenOnTheFeedsThread)
{
    FeedRig rig;
    rig.feed.setLive(true);
    std::thread streaming([&] {
        for (int i = 1; i <= 50; ++i)
            rig.feed.offer(greyFrame(static_cast<std::uint8_t>(i), i * 1000));
    });
    streaming.join();
    ASSERT_TRUE(itest::waitFor([&] { return !rig.live.empty() && rig.live.back().sequence == 50; }, 5000));
    EXPECT_LT(rig.live.size(), 50u);
    EXPECT_EQ(rig.live.back().pixels[0], 50);
}

TEST(UvcFeed, ACaptureTakesOnlyAFrameWhoseExposureBeganAfterItWasAsked)
{
    // The stream's clock is the host's less 1 s. The clock's allowance is 22 ms (exposure
    // 1 ms + period 1 ms + the pipeline's 20 ms), so a frame is placed 22 ms before the
    // stream says it began, plus whatever delay the fastest frame so far had (none here).
    FeedRig rig;
    rig.manual();
    rig.hostUs = 1'000'000;
    rig.feed.offer(greyFrame(1, 0));  // teaches the feed the stream's clock
    rig.settle();
    rig.hostUs = 1'100'000;
    rig.feed.waitForFrame(42, 60000);
    // Began at host 1.095 s, 5 ms before the request, and arrives 40 ms after it: not the tile's.
    rig.hostUs = 1'140'000;
    rig.feed.offer(greyFrame(2, 95'000));
    rig.settle();
    EXPECT_TRUE(rig.captured.empty());
    EXPECT_TRUE(rig.feed.waiting());
    // Began at 1.115 s, 15 ms after the request: still within the allowance, so skipped too.
    rig.hostUs = 1'160'000;
    rig.feed.offer(greyFrame(3, 115'000));
    rig.settle();
    EXPECT_TRUE(rig.captured.empty());
    // Began at 1.125 s, beyond the allowance: the one.
    rig.hostUs = 1'170'000;
    rig.feed.offer(greyFrame(4, 125'000));
    ASSERT_TRUE(itest::waitFor([&] { return !rig.captured.empty(); }, 5000));
    EXPECT_EQ(rig.captured[0].first, 42u);
    EXPECT_EQ(rig.captured[0].second.pixels[0], 4);
    EXPECT_EQ(rig.captured[0].second.exposureMs, 1);
    EXPECT_EQ(rig.captured[0].second.startedHostUs, 1'125'000 - 22'000);
    EXPECT_EQ(rig.captured[0].second.sequence, 4u);
    EXPECT_FALSE(rig.feed.waiting());
    EXPECT_TRUE(rig.failed.empty());
}

TEST(UvcFeed, ANewStreamTakesOnlyFramesBegunAfterItStarted)
{
    // A scan tile switched the camera to the plan's size: frames of the old stream, and
    // the new stream's clock, are not trusted from before the switch.
    FeedRig rig;
    rig.manual();
    rig.feed.offer(greyFrame(1, 0));
    rig.settle();
    rig.hostUs = 1'100'000;
    rig.feed.waitForFrame(3, 60000);
    rig.hostUs = 1'500'000;
    rig.feed.restartStream();
    // Would have done before the switch (began 300 ms after the request), not after it.
    rig.hostUs = 1'510'000;
    rig.feed.offer(greyFrame(2, 400'000));
    rig.settle();
    EXPECT_TRUE(rig.captured.empty());
    // The straggler taught the clock too small an offset for the new stream: its frames are
    // placed earlier than they began, never later, and one begun well after the switch is taken.
    rig.hostUs = 2'050'000;
    rig.feed.offer(greyFrame(6, 500'000));
    ASSERT_TRUE(itest::waitFor([&] { return !rig.captured.empty(); }, 5000));
    EXPECT_EQ(rig.captured[0].second.pixels[0], 6);
}

TEST(UvcFeed, ACaptureWithoutAFrameTimesOutNamingTheCamera)
{
    FeedRig rig;
    rig.feed.waitForFrame(7, 30);
    ASSERT_TRUE(itest::waitFor([&] { return !rig.failed.empty(); }, 5000));
    EXPECT_EQ(rig.failed[0].first, 7u);
    EXPECT_EQ(rig.failed[0].second.id, "camera.uvc.timeout");
    EXPECT_TRUE(ui::words::text(rig.failed[0].second).contains(QStringLiteral("uvc:Synthetic"))) << ui::words::text(rig.failed[0].second).toStdString();
    EXPECT_FALSE(rig.feed.waiting());
    // A frame that comes after the timeout answers nothing.
    rig.feed.offer(greyFrame(9, 5'000'000));
    rig.settle();
    EXPECT_TRUE(rig.captured.empty());
    EXPECT_EQ(rig.failed.size(), 1u);
}

TEST(UvcFeed, AFrameThatCannotBeConvertedFailsTheCaptureAndIsSaidOnceLive)
{
    FeedRig rig;
    rig.manual();
    rig.feed.setLive(true);
    rig.feed.offer(greyFrame(1, 0));  // teaches the feed the stream's clock
    ASSERT_TRUE(itest::waitFor([&] { return !rig.live.empty(); }, 5000));
    rig.feed.waitForFrame(5, 60000);
    rig.hostUs += 1'000'000;
    rig.feed.offer(greyFrame(0, 1'000'000, PF::Format_AYUV));
    ASSERT_TRUE(itest::waitFor([&] { return !rig.failed.empty(); }, 5000));
    EXPECT_EQ(rig.failed[0].first, 5u);
    EXPECT_EQ(rig.failed[0].second.id, "camera.uvc.format_unsupported");
    ASSERT_EQ(rig.liveFailed.size(), 1u);
    for (int i = 0; i < 3; ++i) {
        rig.hostUs += 1000;
        rig.feed.offer(greyFrame(0, 2'000'000 + i * 1000, PF::Format_AYUV));
        rig.settle();
    }
    EXPECT_EQ(rig.liveFailed.size(), 1u) << "a live view of an unreadable format says so once, not every frame";
}

TEST(UvcFeed, ACancelledCaptureIsNotAnsweredByAFrameConvertedForIt)
{
    FeedRig rig;
    rig.manual();
    rig.feed.offer(greyFrame(1, 0));
    rig.settle();
    rig.feed.waitForFrame(1, 60000);
    rig.hostUs += 1'000'000;
    rig.feed.offer(greyFrame(2, 1'000'000));
    rig.feed.cancel();  // closed, say, while the frame was being converted
    rig.settle();
    EXPECT_TRUE(rig.captured.empty());
    EXPECT_TRUE(rig.failed.empty());
}

#endif // BP_WITH_UVC
