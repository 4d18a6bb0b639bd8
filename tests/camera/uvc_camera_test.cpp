// A USB camera without a camera: no webcam is attached to the machines these tests run on,
// so what is tested is what can be without one: the rule that picks the frame a capture
// takes, the names a source is given, and the refusals (a camera that is not there) being
// clear, immediate and never a hang.
#include "device/camera/uvc_frame_clock.h"

#if BP_WITH_UVC
#include "device/camera/camera_source.h"
#include "device/camera/uvc_camera.h"
#include "device/camera/uvc_devices.h"
#include "widgets/wording/wording.h"

#include <QElapsedTimer>
#endif

#include <gtest/gtest.h>

namespace cam = dev::camera;

namespace {

/// A camera at 30 frames a second whose stream clock is `offsetUs` behind the host's and
/// whose frames arrive `delayUs` after their exposure started.
struct Stream {
    std::int64_t offsetUs = 5'000'000;
    std::int64_t periodUs = 33'333;
    std::int64_t startUs(int k) const { return k * periodUs; }
    std::int64_t arrivalUs(int k, std::int64_t delayUs) const { return offsetUs + startUs(k) + delayUs; }
};

} // namespace

TEST(UvcFrameClock, AFrameAlreadyBeingExposedWhenAskedIsNotTakenThoughItArrivesAfter)
{
    const Stream s;
    const std::int64_t exposureUs = 20'000;
    cam::UvcFrameClock clock;
    auto start = [&](int k, std::int64_t delayUs) { return clock.exposureStartHostUs(s.startUs(k), -1, s.arrivalUs(k, delayUs), s.periodUs, exposureUs); };
    // Never later than the true start (offset + stream start), whatever the delay was.
    EXPECT_LE(start(0, 40'000), s.offsetUs + s.startUs(0));
    EXPECT_LE(start(1, 45'000), s.offsetUs + s.startUs(1));
    // Asked 10 ms into frame 2's exposure: frame 2 arrives after the request, but began before it.
    const std::int64_t askedUs = s.offsetUs + s.startUs(2) + 10'000;
    ASSERT_GT(s.arrivalUs(2, 40'000), askedUs);
    EXPECT_LT(start(2, 40'000), askedUs);
    // At most one more frame is skipped for safety: frame 4 is taken.
    EXPECT_GE(start(4, 40'000), askedUs);
}

TEST(UvcFrameClock, ALateFrameDoesNotMoveTheClockLater)
{
    const Stream s;
    cam::UvcFrameClock clock;
    const std::int64_t first = clock.exposureStartHostUs(s.startUs(0), -1, s.arrivalUs(0, 40'000), s.periodUs, 20'000);
    // Frame 1 comes 300 ms late (the machine was busy): it is placed one period after frame 0, not later.
    EXPECT_EQ(clock.exposureStartHostUs(s.startUs(1), -1, s.arrivalUs(1, 340'000), s.periodUs, 20'000), first + s.periodUs);
    // A faster frame teaches the clock: frames are placed earlier from then on, never later.
    const std::int64_t fast = clock.exposureStartHostUs(s.startUs(2), -1, s.arrivalUs(2, 30'000), s.periodUs, 20'000);
    EXPECT_EQ(fast, first + 2 * s.periodUs - 10'000);
    // A frame's own end time gives its period when the format does not.
    cam::UvcFrameClock fresh;
    EXPECT_EQ(fresh.exposureStartHostUs(0, 50'000, 1'000'000, 0, 10'000), 1'000'000 - (10'000 + 50'000 + cam::UvcFrameClock::kPipelineSlackUs));
}

TEST(UvcFrameClock, AFrameWithoutAStreamTimeIsPlacedEarlierStill)
{
    cam::UvcFrameClock clock;
    const std::int64_t slack = cam::UvcFrameClock::kPipelineSlackUs;
    EXPECT_EQ(clock.exposureStartHostUs(-1, -1, 1'000'000, 33'333, 20'000), 1'000'000 - (20'000 + 33'333 + slack) - 33'333);
    const std::int64_t p = cam::UvcFrameClock::kFallbackPeriodUs;
    EXPECT_EQ(clock.exposureStartHostUs(-1, -1, 1'000'000, 0, 0), 1'000'000 - (p + p + slack) - p);
}

#if BP_WITH_UVC

TEST(UvcSource, ANameMayCarryAResolution)
{
    auto n = cam::parseUvcName(QStringLiteral("Logitech BRIO@1920x1080"));
    EXPECT_EQ(n.camera, QStringLiteral("Logitech BRIO"));
    ASSERT_TRUE(n.size.has_value());
    EXPECT_EQ(*n.size, QSize(1920, 1080));
    n = cam::parseUvcName(QStringLiteral(" HD Webcam @ 640 x 480 "));
    EXPECT_EQ(n.camera, QStringLiteral("HD Webcam"));
    EXPECT_EQ(*n.size, QSize(640, 480));
    n = cam::parseUvcName(QStringLiteral("cam@home"));  // not a size: part of the name
    EXPECT_EQ(n.camera, QStringLiteral("cam@home"));
    EXPECT_FALSE(n.size.has_value());
    n = cam::parseUvcName(QString());
    EXPECT_TRUE(n.camera.isEmpty());
}

TEST(UvcSource, TheFormatChosenIsTheWholeSensorUncompressedOrThePlansSize)
{
    using PF = QVideoFrameFormat::PixelFormat;
    // A webcam as GStreamer lists one: Motion-JPEG at every size, YUYV up to 1280 × 720,
    // and a format BenchPilot does not read at the largest size.
    const std::vector<cam::UvcFormat> formats = {
        {QSize(640, 480), PF::Format_YUYV, 5, 30, true},     {QSize(1280, 720), PF::Format_YUYV, 5, 10, true},
        {QSize(1280, 720), PF::Format_Jpeg, 5, 30, true},    {QSize(1920, 1080), PF::Format_Jpeg, 5, 30, true},
        {QSize(1920, 1080), PF::Format_Jpeg, 5, 60, true},   {QSize(2592, 1944), PF::Format_P010, 5, 5, false},
    };
    EXPECT_EQ(cam::chooseUvcFormat(formats, std::nullopt), 4) << "the largest it can read, the faster of two alike";
    EXPECT_EQ(cam::chooseUvcFormat(formats, QSize(1280, 720)), 1) << "uncompressed before Motion-JPEG at the same size";
    EXPECT_EQ(cam::chooseUvcFormat(formats, QSize(640, 480)), 0);
    EXPECT_EQ(cam::chooseUvcFormat(formats, QSize(2592, 1944)), -1) << "a size only in a format it cannot read";
    EXPECT_EQ(cam::chooseUvcFormat(formats, QSize(2048, 2048)), -1) << "a plan's sensor the camera does not have";
    EXPECT_EQ(cam::chooseUvcFormat(std::vector<cam::UvcFormat>{}, std::nullopt), -1);
    EXPECT_EQ(cam::uvcSizesText(formats), "1920×1080, 1280×720, 640×480");
}

TEST(UvcSource, NoCameraAttachedIsSaidNamingWhatWasAsked)
{
    const auto none = cam::findUvcCamera(QStringLiteral("Logitech BRIO"), {});
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().id, "camera.uvc.none_found");
    EXPECT_TRUE(ui::words::text(none.error()).contains(QStringLiteral("uvc:Logitech BRIO"))) << ui::words::text(none.error()).toStdString();
    const auto byDefault = cam::findUvcCamera(QString(), {});
    ASSERT_FALSE(byDefault.ok());
    EXPECT_TRUE(ui::words::text(byDefault.error()).contains(QStringLiteral("'uvc'"))) << ui::words::text(byDefault.error()).toStdString();
}

TEST(UvcSource, ACameraThatIsNotThereFailsTheOpenAndTheCaptureAtOnce)
{
    // A name no camera has: on a machine with no camera, none_found; with one, not_found
    // listing it. Either way the failure names the source and comes without waiting.
    const std::string source = "uvc:BenchPilot test camera that is not there";
    motion::msg::Message error;
    auto camera = cam::makeCamera(source, {}, &error);
    ASSERT_TRUE(camera) << ui::words::text(error).toStdString();
    EXPECT_EQ(camera->source().toStdString(), source);
    EXPECT_TRUE(camera->capabilities().live);
    std::vector<std::pair<std::uint64_t, motion::msg::Message>> failures;
    bool opened = false;
    QObject::connect(camera.get(), &cam::Camera::opened, [&] { opened = true; });
    QObject::connect(camera.get(), &cam::Camera::failed, [&](std::uint64_t id, const motion::msg::Problem& p) { failures.emplace_back(id, p.message); });
    camera->open();
    EXPECT_FALSE(opened);
    EXPECT_FALSE(camera->isOpen());
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0].first, 0u);
    const QString said = ui::words::text(failures[0].second);
    EXPECT_TRUE(failures[0].second.id == "camera.uvc.none_found" || failures[0].second.id == "camera.uvc.not_found") << failures[0].second.id;
    EXPECT_TRUE(said.contains(QString::fromStdString(source))) << said.toStdString();

    // A capture after it repeats why, for its own request, at once: nothing waits for a frame.
    cam::CaptureRequest request;
    request.id = 7;
    camera->capture(request);
    ASSERT_EQ(failures.size(), 2u);
    EXPECT_EQ(failures[1].first, 7u);
    EXPECT_EQ(failures[1].second.id, failures[0].second.id);
    camera->close();  // closing a camera that never opened is harmless
    EXPECT_FALSE(camera->isOpen());
}

TEST(UvcSource, TheSourceNamesTheDefaultCameraOrTheOneAsked)
{
    motion::msg::Message error;
    auto plain = cam::makeCamera("uvc", {}, &error);
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->source(), QStringLiteral("uvc"));
    auto named = cam::makeCamera("uvc:HD Webcam@640x480", {}, &error);
    ASSERT_TRUE(named);
    EXPECT_EQ(named->source(), QStringLiteral("uvc:HD Webcam@640x480"));
}

#endif // BP_WITH_UVC
