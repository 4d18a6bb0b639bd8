// The camera calibration job (device/camera/camera_calibration.h) on the in-process
// simulated stage with a simulated camera that is truly other than it says: the fit finds
// the truth; the stage comes back to the start; Stop, a pulled cable and a camera that
// fails stop it with the reason and nothing moves after; steps beyond the soft limits
// are refused before anything moves.
#include "device/camera/camera_calibration.h"
#include "device/camera/sim_camera.h"
#include "integration/sim_session.h"

#include <QTimer>

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

using namespace itest;
namespace cam = dev::camera;

namespace {

struct CalRig {
    explicit CalRig(const cam::SimTrueGeometry& truth) : session(dev::proto::DeviceKind::Stage, kUnpaced)
    {
        dev::sim::SimMachine* m = &session.link.machine();
        cam::SimCameraSettings s;
        s.geometry.sensorWidthPx = s.geometry.sensorHeightPx = 256;
        s.trueGeometry = truth;
        s.seed = 5;
        std::atomic<bool>* blind = &cameraBlind;
        camera = std::make_unique<cam::SimCamera>(
            [m, blind]() -> std::optional<cam::WorkPoint> {
                if (*blind)
                    return std::nullopt;
                return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()};
            },
            s);
        camera->open();
    }
    bool readyAt(double xMm, double yMm)
    {
        if (!session.connect() || !session.homeAll())
            return false;
        session.link.host().setTimeScale(10);
        if (session.call([&](auto cb) { session.client.move({{0, xMm}, {1, yMm}}, false, 0, cb); }))
            return false;
        return session.waitStill();
    }
    cam::CalibrationOptions options() const
    {
        // The grating reads in 0.5 µm counts, so each rest is known to ±0.25 µm (σ ≈ 0.14 µm
        // per end of a step). Over steps of ±60 and ±120 px (±37 and ±74 µm) that makes a
        // pixel size good to σ ≈ 0.17 %: the 0.5 % below is three of them. Steps of 30 px
        // left it at 1.4 σ, and it failed about one run in seven.
        cam::CalibrationOptions o;
        o.stepPx = 60;
        o.stepsEachWay = 2;
        return o;
    }
    SimSession session;
    std::atomic<bool> cameraBlind{false};
    std::unique_ptr<cam::SimCamera> camera;
};

struct CalOutcome {
    std::optional<cam::CalibrationResult> result;
    std::optional<motion::msg::Message> failure;
    bool done() const { return result || failure; }
};

void watch(cam::CameraCalibration& job, CalOutcome& out)
{
    QObject::connect(&job, &cam::CameraCalibration::finished, [&out](const cam::CalibrationResult& r) { out.result = r; });
    QObject::connect(&job, &cam::CameraCalibration::failed, [&out](const motion::msg::Message& m) { out.failure = m; });
}

} // namespace

TEST(CameraCalibration, FindsTheTruePixelRotationAndMirrorAndReturnsToTheStart)
{
    cam::SimTrueGeometry truth;
    truth.pixelXUm = 0.60;
    truth.pixelYUm = 0.62;
    truth.rotationDeg = -3;
    truth.mirrored = true;
    CalRig rig(truth);
    ASSERT_TRUE(rig.readyAt(40, 40));
    cam::CameraCalibration job(&rig.session.client, rig.camera.get());
    CalOutcome out;
    watch(job, out);
    motion::msg::Message error;
    ASSERT_TRUE(job.start(rig.options(), &error)) << error.id;
    ASSERT_TRUE(waitFor([&] { return out.done(); }, 120000));
    ASSERT_TRUE(out.result) << out.failure->id;
    const imaging::CameraStageFit& f = out.result->fit;
    EXPECT_DOUBLE_EQ(out.result->nominalPixelUm, 0.65) << "the camera says its asked pixel";
    EXPECT_NEAR(f.pixelXUm, 0.60, 0.60 * 0.005);
    EXPECT_NEAR(f.pixelYUm, 0.62, 0.62 * 0.005);
    EXPECT_NEAR(f.rotationDeg, -3, 0.1);
    EXPECT_TRUE(f.imageYAlongPlusY);
    // What is left is the stage's own: its grating reads in 0.5 µm counts, about 0.8 px here,
    // and the images follow the true work point.
    EXPECT_LT(f.residualRmsPx, 1.0);
    // Back at the start each axis rests within one count of its target: up to
    // √2 × 0.5 µm / 0.60 µm ≈ 1.18 px apart, plus the registration's hundredths.
    EXPECT_LT(out.result->returnPx, 1.3);
    EXPECT_EQ(out.result->steps.size(), 9u);
    ASSERT_TRUE(rig.session.waitStill());
    EXPECT_NEAR(rig.session.client.status().axes[0].commanded, 40, 1e-6);
    EXPECT_NEAR(rig.session.client.status().axes[1].commanded, 40, 1e-6);
}

TEST(CameraCalibration, StopStopsTheStageAndSaysSo)
{
    CalRig rig({});
    ASSERT_TRUE(rig.readyAt(40, 40));
    cam::CameraCalibration job(&rig.session.client, rig.camera.get());
    CalOutcome out;
    watch(job, out);
    QObject::connect(&job, &cam::CameraCalibration::progress, [&](int taken, int) {
        if (taken == 3)
            QTimer::singleShot(0, &job, [&job] { job.stop(); });
    });
    motion::msg::Message error;
    ASSERT_TRUE(job.start(rig.options(), &error));
    ASSERT_TRUE(waitFor([&] { return out.done(); }, 60000));
    ASSERT_TRUE(out.failure);
    EXPECT_EQ(out.failure->id, "camera.calibration.stopped");
    EXPECT_FALSE(job.isRunning());
    ASSERT_TRUE(rig.session.waitStill());
}

TEST(CameraCalibration, APulledCableStopsItWithTheReason)
{
    CalRig rig({});
    ASSERT_TRUE(rig.readyAt(40, 40));
    cam::CameraCalibration job(&rig.session.client, rig.camera.get());
    CalOutcome out;
    watch(job, out);
    QObject::connect(&job, &cam::CameraCalibration::progress, [&](int taken, int) {
        if (taken == 2)
            QTimer::singleShot(0, [&] { rig.session.link.pair().unplug(); });
    });
    motion::msg::Message error;
    ASSERT_TRUE(job.start(rig.options(), &error));
    ASSERT_TRUE(waitFor([&] { return out.done(); }, 60000));
    ASSERT_TRUE(out.failure);
    EXPECT_EQ(out.failure->id, "camera.calibration.link_lost");
}

TEST(CameraCalibration, ACameraThatFailsStopsIt)
{
    CalRig rig({});
    ASSERT_TRUE(rig.readyAt(40, 40));
    cam::CameraCalibration job(&rig.session.client, rig.camera.get());
    CalOutcome out;
    watch(job, out);
    QObject::connect(&job, &cam::CameraCalibration::progress, [&](int taken, int) {
        if (taken == 2)
            rig.cameraBlind = true;
    });
    motion::msg::Message error;
    ASSERT_TRUE(job.start(rig.options(), &error));
    ASSERT_TRUE(waitFor([&] { return out.done(); }, 60000));
    ASSERT_TRUE(out.failure);
    EXPECT_EQ(out.failure->id, "camera.calibration.camera_failed");
    ASSERT_TRUE(rig.session.waitStill());
}

TEST(CameraCalibration, StepsBeyondTheSoftLimitsAreRefusedBeforeAnythingMoves)
{
    CalRig rig({});
    ASSERT_TRUE(rig.session.connect());
    cam::CameraCalibration job(&rig.session.client, rig.camera.get());
    motion::msg::Message error;
    EXPECT_FALSE(job.start(rig.options(), &error));
    EXPECT_EQ(error.id, "camera.calibration.not_homed");
    ASSERT_TRUE(rig.session.homeAll());
    // Homed at the travel's edge: the minus steps lie outside.
    const double x0 = rig.session.client.status().axes[0].commanded;
    CalOutcome out;
    watch(job, out);
    ASSERT_TRUE(job.start(rig.options(), &error)) << error.id;
    ASSERT_TRUE(waitFor([&] { return out.done(); }, 60000));
    ASSERT_TRUE(out.failure);
    EXPECT_EQ(out.failure->id, "camera.calibration.beyond_limits");
    EXPECT_DOUBLE_EQ(rig.session.client.status().axes[0].commanded, x0);
}
