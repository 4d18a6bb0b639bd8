// benchpilot-cli camera calibrate --camera SOURCE [--step-px N] [--steps N] [--pixel-um P]
//                                 [--home] [--at X,Y] --out PROFILE.json [--json]
// Moves the stage by known steps around where it stands, registers the images and writes
// the camera profile (docs/camera.md, "Calibrating the camera against the stage").
#include "camera_cli.h"
#include "cli_session.h"

#include "device/camera/camera_calibration.h"
#include "device/files/camera/camera_profile_file.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonObject>

#include <cmath>

namespace app::cli {
namespace {

namespace cam = dev::camera;

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// The longest a calibration may take: a dozen moves and images, each bounded by the job.
constexpr int kCalibrateWaitMs = 15 * 60 * 1000;

double calRound(double v, double unit) { return std::round(v / unit) / std::round(1 / unit); }

int cameraCalibrate(Invocation& inv)
{
    if (!inv.isSet(QStringLiteral("camera")))
        return inv.usage(tr("needs --camera SOURCE (sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR; see camera list)"));
    if (!inv.isSet(QStringLiteral("out")))
        return inv.usage(tr("needs --out PROFILE.json, the camera profile to write"));
    const QString file = inv.path(inv.value(QStringLiteral("out")));
    cam::CalibrationOptions o;
    double steps = 2;
    if (!inv.number(QStringLiteral("step-px"), o.stepPx, 100.0) || !inv.number(QStringLiteral("steps"), steps, 2.0)
        || !inv.number(QStringLiteral("pixel-um"), o.nominalPixelUm, 0.0))
        return Usage;
    if (!(o.stepPx >= 1 && o.stepPx <= 10000))
        return inv.usage(tr("--step-px must be from 1 to 10000"));
    if (!(steps >= 1 && steps <= 10 && std::floor(steps) == steps))
        return inv.usage(tr("--steps must be a whole number from 1 to 10"));
    o.stepsEachWay = static_cast<int>(steps);
    if (inv.isSet(QStringLiteral("pixel-um")) && !(o.nominalPixelUm > 0 && o.nominalPixelUm <= 1000))
        return inv.usage(tr("--pixel-um must be above 0 and at most 1000"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    std::unique_ptr<cam::Camera> camera = cameraFor(inv, s, inv.value(QStringLiteral("camera")));
    if (!camera)
        return Usage;
    if (const int rc = openCamera(inv, camera.get()); rc != Ok)
        return rc;
    dev::Instrument* stage = s->instrument();
    if (inv.isSet(QStringLiteral("home"))) {
        if (const int rc = s->request([&](auto cb) { stage->home(0, cb); }, tr("home")))
            return rc;
        if (!s->waitUntilHomed(0b11))
            return inv.refused(tr("homing did not finish"));
    }
    if (inv.isSet(QStringLiteral("at"))) {
        const QStringList xy = inv.value(QStringLiteral("at")).split(QLatin1Char(','));
        bool okX = false, okY = false;
        const double x = xy.size() == 2 ? xy[0].trimmed().toDouble(&okX) : 0;
        const double y = xy.size() == 2 ? xy[1].trimmed().toDouble(&okY) : 0;
        if (!okX || !okY)
            return inv.usage(tr("--at must be X,Y in mm (got '%1')").arg(inv.value(QStringLiteral("at"))));
        if (const int rc = s->request([&](auto cb) { stage->move({{0, x}, {1, y}}, false, 0, cb); }, tr("move")))
            return rc;
        if (!spinUntil([&] { return stage->status().axes.size() >= 2 && !stage->status().anyMoving() && std::fabs(stage->status().axes[0].commanded - x) < 1e-3
                                    && std::fabs(stage->status().axes[1].commanded - y) < 1e-3; },
                       kCalibrateWaitMs))
            return inv.refused(tr("the stage did not reach %1, %2 mm").arg(x).arg(y));
    }
    cam::CameraCalibration job(stage, camera.get());
    std::optional<cam::CalibrationResult> result;
    std::optional<motion::msg::Message> failure;
    QObject::connect(&job, &cam::CameraCalibration::finished, [&](const cam::CalibrationResult& r) { result = r; });
    QObject::connect(&job, &cam::CameraCalibration::failed, [&](const motion::msg::Message& m) { failure = m; });
    if (!inv.json())
        QObject::connect(&job, &cam::CameraCalibration::progress, [&](int taken, int total) {
            inv.err() << tr("image %1 of %2").arg(taken).arg(total) << '\n';
            inv.err().flush();
        });
    motion::msg::Message error;
    if (!job.start(o, &error))
        return inv.refused(ui::words::text(error));
    if (!spinUntil([&] { return result || failure; }, kCalibrateWaitMs)) {
        job.stop();
        return inv.refused(tr("the calibration did not finish within %1 min").arg(kCalibrateWaitMs / 60000));
    }
    if (failure)
        return inv.refused(ui::words::text(*failure));
    const dev::files::camera::CameraProfile p = cam::profileOf(*result, QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString());
    if (!dev::files::camera::saveCameraProfileFile(file, p, &error))
        return inv.refused(ui::words::text(error));
    if (inv.json()) {
        QJsonArray stepList;
        for (const cam::CalibrationStep& st : result->steps)
            stepList.append(QJsonObject{{QStringLiteral("stage_um"), QJsonArray{calRound(st.stageUm.x(), 1e-3), calRound(st.stageUm.y(), 1e-3)}},
                                     {QStringLiteral("shift_px"), QJsonArray{calRound(st.shiftPx.x(), 1e-3), calRound(st.shiftPx.y(), 1e-3)}},
                                     {QStringLiteral("score"), calRound(st.ncc, 1e-3)},
                                     {QStringLiteral("registered"), st.registered}});
        inv.printJson(QJsonObject{{QStringLiteral("file"), file},
                                  {QStringLiteral("camera"), QString::fromStdString(p.camera)},
                                  {QStringLiteral("sensor_px"), QJsonArray{p.sensorWidthPx, p.sensorHeightPx}},
                                  {QStringLiteral("pixel_um"), QJsonArray{p.pixelXUm, p.pixelYUm}},
                                  {QStringLiteral("rotation_deg"), p.rotationDeg},
                                  {QStringLiteral("image_y"), p.imageYAlongPlusY ? QStringLiteral("stage-plus-y") : QStringLiteral("stage-minus-y")},
                                  {QStringLiteral("skew_deg"), p.calibration.skewDeg},
                                  {QStringLiteral("residual_rms_px"), p.calibration.residualRmsPx},
                                  {QStringLiteral("residual_max_px"), p.calibration.residualMaxPx},
                                  {QStringLiteral("return_px"), p.calibration.returnPx},
                                  {QStringLiteral("nominal_pixel_um"), result->nominalPixelUm},
                                  {QStringLiteral("steps"), stepList}});
        return Ok;
    }
    QTextStream& out = inv.out();
    out << tr("pixel %1 × %2 µm, rotation %3°, image y along stage %4; residual %5 px RMS (worst %6 px), %7 images")
               .arg(p.pixelXUm, 0, 'f', 5)
               .arg(p.pixelYUm, 0, 'f', 5)
               .arg(p.rotationDeg, 0, 'f', 3)
               .arg(p.imageYAlongPlusY ? QStringLiteral("+Y") : QStringLiteral("−Y"))
               .arg(p.calibration.residualRmsPx, 0, 'f', 3)
               .arg(p.calibration.residualMaxPx, 0, 'f', 3)
               .arg(p.calibration.images)
        << '\n'
        << tr("The pixel size comes from the stage's own steps: it carries the stage's scale error.") << '\n'
        << tr("wrote %1").arg(file) << '\n';
    out.flush();
    return Ok;
}

} // namespace

Command cameraCalibrateCommand()
{
    QList<QCommandLineOption> options{option("camera", "sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR (see camera list)", "SOURCE"),
                                      option("out", "the camera profile to write", "PROFILE.json"),
                                      option("step-px", "one step, in the camera's pixels (nominal)", "N", "100"),
                                      option("steps", "steps each way along X and Y (1 to 10)", "N", "2"),
                                      option("pixel-um", "the camera's nominal pixel at the sample, µm (default: what the camera says)", "P"),
                                      option("home", "home the stage first"),
                                      option("at", "move to X,Y mm first (default: calibrate where the stage stands)", "X,Y")};
    options << cameraOptions();
    Command c{QStringLiteral("calibrate"), tr("measure the camera's pixel size, rotation and mirror against the stage, and write a camera profile"),
              {},
              tr("Moves the stage by ±1…±N steps along X and Y around where it stands (homed, inside its soft limits), takes an "
                    "image at each, registers it against the first, returns to the start and fits the camera–stage mapping. "
                    "The pixel size comes from the stage's own steps, so it carries the stage's scale error (docs/camera.md)."),
              options, cameraCalibrate, {}};
    c.api.access = Access::Control;
    c.api.params = {optionParam("camera", ParamType::Text, true), optionParam("out", ParamType::File, true),
                    optionParam("step-px", ParamType::Number),   optionParam("steps", ParamType::Integer),
                    optionParam("pixel-um", ParamType::Number),  optionParam("specimen", ParamType::Text),
                    optionParam("camera-seed", ParamType::Number), optionParam("camera-true", ParamType::Text),
                    optionParam("home", ParamType::Boolean), optionParam("at", ParamType::Text)};
    c.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("camera"), QStringLiteral("sim")},
                                {QStringLiteral("out"), QStringLiteral("scope.camera-profile.json")}};
    return c;
}

} // namespace app::cli
