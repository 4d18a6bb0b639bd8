// The camera as the accuracy bench's reading source: the simulated camera reads the glass
// line scale along X at each stop of an ISO 230-2 test, and the figures agree with the
// same test read by the simulator's gauge at the work point; where no line can be seen
// the reading fails with the finder's reason and the image kept.
#include "device/camera/scale_reading_source.h"
#include "device/camera/sim_camera.h"
#include "integration/accuracy_support.h"
#include "motion/message_print.h"
#include "motion/metrology/linear/iso230_2.h"

#include <QDir>
#include <QFileInfo>

#include <gtest/gtest.h>

#include <cmath>

using namespace itest;
using dev::jobs::AccuracyRunner;
namespace cam = dev::camera;

namespace {

struct CameraBench {
    AccuracyStage stage;
    std::unique_ptr<cam::SimCamera> camera;

    bool ready()
    {
        if (!stage.ready())
            return false;
        dev::sim::SimMachine* m = &stage.session.link.machine();
        cam::SimCameraSettings s;
        s.specimen = cam::SpecimenKind::LineScales;
        camera = std::make_unique<cam::SimCamera>(
            [m]() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()}; }, s);
        return true;
    }
    bool moveY(double y)
    {
        return !stage.session.call([&](auto cb) { stage.session.client.move({{1, y}}, false, 20, cb); }, 30000) && stage.session.waitStill(30000);
    }
    /// Runs the test read by `source` into `folder`; the evaluation, or nullopt with the runner's last word in `said`.
    std::optional<motion::metrology::Evaluation> run(dev::jobs::ReadingSource& source, const QString& folder, motion::msg::Message* said)
    {
        if (!openSource(source))
            return std::nullopt;
        AccuracyRunner r(&stage.session.client);
        motion::msg::Problems problems;
        if (!r.prepare(smallTest({10, 30, 50, 70, 90}, 2), &source, folder, false, &problems)) {
            ADD_FAILURE() << describe(problems);
            return std::nullopt;
        }
        QObject::connect(&r, &AccuracyRunner::problem, [said](const motion::msg::Message& m) { *said = m; });
        if (!r.start())
            return std::nullopt;
        waitFor([&] { return !r.isActive(); }, 120000);
        if (r.state() != AccuracyRunner::State::Finished)
            return std::nullopt;
        return r.evaluation();
    }
};

/// The camera's reading at each stop, and the gauge's at the same rest beside it: the
/// two are compared on the same positions, so the stage's scatter from one run to
/// another (a grating count, 0.5 µm, on A's ±2s) is not taken for a disagreement.
class CameraAndGauge : public dev::jobs::ReadingSource {
public:
    CameraAndGauge(dev::jobs::ReadingSource* camera, dev::jobs::ReadingSource* gauge) : m_camera(camera), m_gauge(gauge) {}
    dev::jobs::ReadingKind kind() const override { return m_camera->kind(); }
    motion::msg::Message describe() const override { return m_camera->describe(); }
    void open(OpenDone done) override
    {
        m_gauge->open([this, done](const motion::msg::Message& problem) {
            if (!problem.empty())
                done(problem);
            else
                m_camera->open(done);
        });
    }
    void take(const dev::jobs::StopContext& stop, TakeDone done) override
    {
        m_gauge->take(stop, [this, stop, done](const dev::jobs::TakeResult& g) {
            if (!g.valuesMm.empty())
                gaugeReadings.push_back({stop.targetsMm.front(), stop.direction, stop.cycle, g.valuesMm.front()});
            m_camera->take(stop, done);
        });
    }
    void cancel() override
    {
        m_gauge->cancel();
        m_camera->cancel();
    }
    std::vector<motion::metrology::Reading> gaugeReadings;

private:
    dev::jobs::ReadingSource* m_camera;
    dev::jobs::ReadingSource* m_gauge;
};

} // namespace

TEST(CameraScaleReading, AnIsoTestReadByTheCameraAgreesWithTheGaugeAtTheWorkPoint)
{
    CameraBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveY(50.075)) << "the X scale's short lines run from Y 50 to 50.15 mm";

    motion::msg::Message said;
    dev::SimulatedGauge gauge(b.stage.session.link.machine(), 0);
    dev::jobs::GaugeSource gaugeSource(gauge.hostEnd(), QStringLiteral("simulated gauge"));
    auto byGauge = b.run(gaugeSource, b.stage.dir.filePath(QStringLiteral("gauge")), &said);
    ASSERT_TRUE(byGauge) << said;

    // And the camera, with the gauge read at the same rests.
    cam::ScaleReadingSource cameraSource(b.camera.get(), cam::ScaleReadingOptions{});
    CameraAndGauge both(&cameraSource, &gaugeSource);
    const auto byCamera = b.run(both, b.stage.dir.filePath(QStringLiteral("camera")), &said);
    ASSERT_TRUE(byCamera) << said;
    ASSERT_EQ(both.gaugeReadings.size(), 20u);
    const motion::metrology::Evaluation gaugeBesideCamera = motion::metrology::evaluate(both.gaugeReadings);
    std::printf("A, E by the gauge of its own run: %.2f, %.2f um\n", *byGauge->figures.aMm * 1e3, *byGauge->figures.eMm * 1e3);
    byGauge = gaugeBesideCamera;

    const double aGauge = *byGauge->figures.aMm * 1e3, aCamera = *byCamera->figures.aMm * 1e3;
    const double eGauge = *byGauge->figures.eMm * 1e3, eCamera = *byCamera->figures.eMm * 1e3;
    std::printf("A: gauge %.2f um, camera %.2f um; E: gauge %.2f um, camera %.2f um\n", aGauge, aCamera, eGauge, eCamera);
    ASSERT_GT(eGauge, 50) << "the stage's error is larger than half a graduation: which line is which must be told";
    EXPECT_NEAR(aCamera, aGauge, 1.0);
    EXPECT_NEAR(eCamera, eGauge, 1.0);
}

TEST(CameraScaleReading, WhereNoLineIsSeenTheReadingFailsWithWhyAndItsImage)
{
    CameraBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveY(20)) << "bare glass: the scale is at Y 50 mm";
    cam::ScaleReadingOptions o;
    o.failedImagesFolder = b.stage.dir.path();
    cam::ScaleReadingSource source(b.camera.get(), o);
    motion::msg::Message said;
    EXPECT_FALSE(b.run(source, b.stage.dir.filePath(QStringLiteral("run")), &said));
    EXPECT_EQ(said.id, "camera.reading.no_line") << said;
    const motion::msg::Arg* cause = said.arg("cause");
    ASSERT_TRUE(cause && std::holds_alternative<std::shared_ptr<const motion::msg::Message>>(cause->value));
    EXPECT_EQ(std::get<std::shared_ptr<const motion::msg::Message>>(cause->value)->id.rfind("imaging.line.", 0), 0u) << said;
    EXPECT_TRUE(QFileInfo::exists(QDir(b.stage.dir.path()).filePath(QStringLiteral("reading-001.tif"))));
}
