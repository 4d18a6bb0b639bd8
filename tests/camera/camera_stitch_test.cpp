// The simulated camera's scan stitched by the imaging library, judged against the
// simulator's TRUE work point of every tile (where the camera looked), on a stage whose
// pitch error puts the grating's readings microns off: registration must find the true
// positions, and do clearly better than the measured ones it starts from.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/camera/camera_geometry.h"
#include "device/camera/scan_camera.h"
#include "device/camera/sim_camera.h"
#include "device/files/accuracy/grid/stage_errors_file.h"
#include "device/files/scan_run_log.h"
#include "device/files/stitch_positions.h"
#include "device/files/text_file.h"
#include "device/jobs/scan_runner.h"
#include "device/link/simulated_link.h"
#include "device/sim/machine_config.h"
#include "imaging/stitch.h"
#include "motion/message_print.h"

#include "integration/wait.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace cam = dev::camera;

namespace {

/// A stage whose work point runs 5 µm per mm ahead of the grating in X and 4 µm per mm
/// behind it in Y: about one pixel per tile step at 1 µm a pixel, three over the row. It
/// is written as a benchpilot.stage-errors file would give it (--stage-errors), straight
/// and square, without lost motion, so the pitch is the only error the images see.
constexpr const char* kPitchErrors = R"({"schema": "benchpilot.stage-errors", "version": 1,
  "x": {"pitch_poly_um": [-100, 5], "straightness_poly_um": [0]},
  "y": {"pitch_poly_um": [80, -4], "straightness_poly_um": [0]},
  "squareness_urad": 0, "backlash_um": {"x": 0, "y": 0}})";

/// 4 × 3 tiles of a 256 × 256 px sensor at 1 µm a pixel, 15 % overlap.
motion::scan::ScanPlan stitchTwelveTiles()
{
    motion::scan::ScanPlan p;
    p.name = "stitch";
    p.camera.source = motion::scan::FieldSource::Sensor;
    p.camera.sensorWidthPx = p.camera.sensorHeightPx = 256;
    p.camera.sensorPixelUm = 10;
    p.camera.magnification = 10;
    const double field = 0.256, step = field * 0.85;
    p.region.cornerA = {20, 20};
    p.region.cornerB = {20 + field + 2.9 * step, 20 + field + 1.9 * step};
    p.overlapX = p.overlapY = 0.15;
    p.speedMmS = 10;
    p.settleS = 0.02;
    p.exposureS = 0.01;
    return p;
}

/// Where the camera truly looked and what the grating read, at each capture.
struct Shot {
    double trueXMm, trueYMm, readXMm, readYMm;
};

/// The in-process simulated stage given the errors above, a client on it, and the
/// simulated camera recording the true work point of every capture.
struct PitchedStage {
    static dev::sim::MachineConfig config()
    {
        const auto read = dev::files::accuracy::stageErrorsFromJson(kPitchErrors, "pitch.stage-errors.json");
        EXPECT_TRUE(read.ok());
        dev::sim::MachineConfig c = dev::sim::stageConfig();
        if (read.ok())
            dev::sim::applyStageErrors(c, *read);
        return c;
    }

    PitchedStage() : link(config(), 0)
    {
        client.setTransport(link.hostEnd());
        dev::sim::SimMachine* m = &link.machine();
        cam::SimCameraSettings s;
        s.seed = 11;
        camera = std::make_unique<cam::SimCamera>(
            [m, this]() -> std::optional<cam::WorkPoint> {
                shots.push_back({m->workPointLogical(0), m->workPointLogical(1), m->measuredLogical(0), m->measuredLogical(1)});
                return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()};
            },
            s);
    }
    ~PitchedStage() { client.setTransport(nullptr); }

    bool homed()
    {
        client.connectLink();
        if (!itest::waitFor([this] { return client.state() == dev::LinkState::Ready; }, 5000))
            return false;
        link.host().setTimeScale(20);
        bool answered = false, refused = false;
        client.home(0, [&](const std::optional<dev::RequestError>& e) {
            answered = true;
            refused = e.has_value();
        });
        const bool ok = itest::waitFor(
            [&] {
                if (!answered)
                    return false;
                if (refused)
                    return true;
                for (const auto& a : client.status().axes)
                    if (!a.homed || a.moving)
                        return false;
                return !client.status().axes.empty();
            },
            30000);
        link.host().setTimeScale(10);
        return ok && !refused;
    }

    dev::SimulatedLink link;
    dev::BenchPilotClient client;
    std::unique_ptr<cam::SimCamera> camera;
    std::vector<Shot> shots;
};

struct Rms {
    double rms = 0, worst = 0;
};

/// RMS and worst distance (px) between positions and the truth, both taken relative to tile 0.
Rms againstTruth(const std::vector<Eigen::Vector2d>& positions, const std::vector<Eigen::Vector2d>& truth)
{
    Rms r;
    double sum = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const double d = ((positions[i] - positions[0]) - (truth[i] - truth[0])).norm();
        sum += d * d;
        r.worst = std::max(r.worst, d);
    }
    r.rms = std::sqrt(sum / static_cast<double>(positions.size()));
    return r;
}

} // namespace

TEST(CameraStitch, RegisteredPositionsMatchTheTrueWorkPointsAndBeatTheGratingOnAPitchedStage)
{
    PitchedStage stage;
    ASSERT_TRUE(stage.homed());
    QTemporaryDir dir;
    cam::ScanCamera scanCamera(stage.camera.get());
    dev::jobs::ScanRunner runner(&stage.client);
    runner.setCamera(&scanCamera);
    const motion::scan::ScanPlan plan = stitchTwelveTiles();
    motion::msg::Message error;
    ASSERT_TRUE(runner.prepare(plan, dir.path(), false, &error)) << error;
    ASSERT_TRUE(runner.start(&error)) << error;
    ASSERT_TRUE(itest::waitFor([&] { return runner.state() == dev::jobs::ScanRunner::State::Finished; }, 90000));
    ASSERT_EQ(stage.shots.size(), 12u) << "one capture a tile";

    // The tiles as `benchpilot-cli stitch DIR --plan` reads them: the run log's measured
    // positions turned into image pixels by the plan's camera.
    std::string text;
    ASSERT_TRUE(dev::files::readText(QDir(dir.path()).filePath(QLatin1String(dev::files::scan::kRunLogFile)), &text, &error)) << error;
    const auto taken = dev::files::scan::parseTakenTiles(text, dev::files::scan::kRunLogFile);
    ASSERT_TRUE(taken);
    ASSERT_EQ(taken->size(), 12u);
    const cam::CameraGeometry geometry = cam::geometryOfPlan(plan);
    double exX, exY, eyX, eyY;
    geometry.axes(&exX, &exY, &eyX, &eyY);
    const double px2 = geometry.pixelUm * geometry.pixelUm * 1e-6;
    const auto toPx = [&](double xMm, double yMm) { return Eigen::Vector2d((xMm * exX + yMm * exY) / px2, (xMm * eyX + yMm * eyY) / px2); };

    std::vector<imaging::StitchTile> tiles;
    std::vector<Eigen::Vector2d> truth;
    for (const dev::files::scan::TakenTile& t : *taken) {
        tiles.push_back({t.image, QDir(dir.path()).filePath(QString::fromStdString(t.image)).toStdString(), toPx(t.measuredXMm, t.measuredYMm)});
        // Its capture: the one whose grating reading the log holds (tiles lie 0.2 mm apart,
        // the reading at the capture and the logged one agree to the servo's jitter).
        const Shot* best = nullptr;
        for (const Shot& s : stage.shots)
            if (!best || std::hypot(s.readXMm - t.measuredXMm, s.readYMm - t.measuredYMm) <
                             std::hypot(best->readXMm - t.measuredXMm, best->readYMm - t.measuredYMm))
                best = &s;
        ASSERT_LT(std::hypot(best->readXMm - t.measuredXMm, best->readYMm - t.measuredYMm), 0.002) << t.image;
        truth.push_back(toPx(best->trueXMm, best->trueYMm));
    }

    // Stitched with the CLI's defaults (1 µm repeatability, 40 px bound), no mosaic.
    imaging::StitchOptions so;
    so.placement.stageSigmaPx = 1.0 / geometry.pixelUm;
    auto result = imaging::stitch(tiles, so);
    ASSERT_TRUE(result);
    std::vector<Eigen::Vector2d> stagePx;
    for (const imaging::StitchTile& t : tiles)
        stagePx.push_back(t.stagePx);
    const Rms measured = againstTruth(stagePx, truth);
    const Rms registered = againstTruth(result->placement.positionsPx, truth);
    int accepted = 0;
    for (const imaging::TilePair& p : result->pairs)
        accepted += p.reg.accepted();
    std::printf("12 tiles, %zu pairs (%d accepted); against the true work points, relative to tile 0: "
                "measured RMS %.3f px (worst %.3f), registered RMS %.3f px (worst %.3f)\n",
                result->pairs.size(), accepted, measured.rms, measured.worst, registered.rms, registered.worst);

    EXPECT_EQ(result->pairs.size(), 17u);
    EXPECT_EQ(accepted, 17) << "the slide is textured everywhere here";
    for (bool byStage : result->placement.placedByStage)
        EXPECT_FALSE(byStage);
    EXPECT_GT(measured.rms, 1.0) << "the pitch error shows in the grating's positions";
    EXPECT_LE(registered.rms, 0.3);
    EXPECT_LT(registered.rms, measured.rms / 4) << "registration finds where the camera truly looked";

    // The pitch error is the grating's scale against the camera's: the stage model finds
    // it (+5 µm/mm in X, −4 µm/mm in Y), so the prior no longer pulls against the pairs.
    const imaging::StageModel& model = result->placement.stageModel;
    std::printf("stage model: used %d, scale x %.0f ppm, y %.0f ppm, rotation %.0f µrad, shear %.0f µrad\n", model.used, model.scaleXPpm(),
                model.scaleYPpm(), model.rotationUrad(), model.shearUrad());
    EXPECT_TRUE(model.used);
    EXPECT_NEAR(model.scaleXPpm(), 5000, 1000);  // three rows of 256 px: a few hundred ppm of spread
    EXPECT_NEAR(model.scaleYPpm(), -4000, 1000);
    EXPECT_LE(registered.rms, 0.1) << "with the stage model, nothing pulls the tiles off the pairs";
}
