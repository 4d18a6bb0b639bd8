// benchpilot-cli's stitching scan commands:
//   scan plan  --roi x0,y0,x1,y1 --fov w,h --overlap o[,o] --order … [--format …]
//              prints the plan file, a summary, or the tile positions as Fiji,
//              Micro-Manager or CSV read them;
//   scan run   PLAN.json [--out DIR] on --sim stage or --port: runs the scan,
//              continues a run stopped part-way, writes the exports with the
//              measured positions; with --camera stitches the tiles as they come
//              (scan_live_stitch.h). See docs/scan.md.
#include "camera_cli.h"
#include "cli_session.h"
#include "command.h"
#include "scan_live_stitch.h"

#include "device/camera/scan_camera.h"

#include "device/files/scan_exports.h"
#include "device/files/camera/camera_profile_file.h"
#include "device/files/scan_plan_file.h"
#include "device/jobs/scan_launch.h"
#include "device/jobs/scan_runner.h"
#include "motion/plans/scan/scan_estimate.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace app::cli {
namespace {

using namespace motion::scan;
using dev::jobs::ScanRunner;

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// The option a person typed for a plan field, so a refusal names what to change.
QString optionFor(const std::string& field, bool fromSensor)
{
    static const std::pair<const char*, const char*> kFields[] = {
        {"region.corners_mm", "--roi"},        {"region.centre_mm", "--centre"},      {"region.size_mm", "--size"},
        {"region.vertices_mm", "--polygon"},   {"camera.sensor_pixel_um", "--sensor-um"}, {"camera.magnification", "--mag"},
        {"camera.pixel_um", "--pixel-um"},     {"camera.rotation_deg", "--rotation"}, {"overlap", "--overlap"},
        {"approach.overtravel_mm", "--overtravel"}, {"motion.speed_mm_s", "--speed"}, {"timing.settle_s", "--settle"},
        {"timing.exposure_s", "--exposure"},   {"timing.tolerance_um", "--tolerance-um"}, {"export.file_pattern", "--pattern"},
        {"export.first_index", "--first-index"}, {"export.mm_xy_stage", "--mm-stage"}, {"compensation", "--compensate"}};
    if (field.rfind("camera.field_mm", 0) == 0 || field.rfind("camera.sensor_px", 0) == 0)
        return fromSensor ? QStringLiteral("--sensor") : QStringLiteral("--fov");
    for (const auto& [prefix, option] : kFields)
        if (field.rfind(prefix, 0) == 0)
            return QString::fromLatin1(option);
    return QString::fromStdString(field);
}

/// "1,2,3" → exactly `count` numbers (or 1..count when `upTo`), reported against --option.
bool readNumbers(Invocation& inv, const char* option, int count, QVector<double>& out, bool upTo = false)
{
    if (!inv.numbers(QString::fromLatin1(option), out, upTo ? 0 : count))
        return false;
    if (upTo && (out.isEmpty() || out.size() > count)) {
        inv.report(tr("--%1 '%2' needs 1 to %3 comma-separated numbers").arg(QLatin1String(option), inv.value(QLatin1String(option))).arg(count));
        return false;
    }
    return true;
}

bool readNumber(Invocation& inv, const char* option, double& value)
{
    return !inv.isSet(QString::fromLatin1(option)) || inv.number(QString::fromLatin1(option), value);
}

/// The plan the options describe; false after saying what is wrong.
bool planFromOptions(Invocation& inv, ScanPlan& p)
{
    auto set = [&](const char* o) { return inv.isSet(QString::fromLatin1(o)); };
    const int regions = int(set("roi")) + int(set("centre") || set("size")) + int(set("polygon"));
    if (regions != 1) {
        inv.usage(regions == 0 ? tr("give the region: --roi x0,y0,x1,y1, --centre x,y with --size w,h, or --polygon 'x,y;x,y;…'")
                               : tr("give one region: --roi, --centre/--size or --polygon"));
        return false;
    }
    QVector<double> v;
    if (set("roi")) {
        if (!readNumbers(inv, "roi", 4, v))
            return false;
        p.region.kind = RegionKind::Corners;
        p.region.cornerA = {v[0], v[1]};
        p.region.cornerB = {v[2], v[3]};
    } else if (set("polygon")) {
        p.region.kind = RegionKind::Polygon;
        for (const QString& corner : inv.value(QStringLiteral("polygon")).split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
            const QStringList xy = corner.split(QLatin1Char(','));
            bool okX = false, okY = false;
            const double x = xy.size() == 2 ? xy[0].trimmed().toDouble(&okX) : 0, y = xy.size() == 2 ? xy[1].trimmed().toDouble(&okY) : 0;
            if (!okX || !okY) {
                inv.usage(tr("--polygon: corner '%1' is not x,y in mm").arg(corner.trimmed()));
                return false;
            }
            p.region.vertices.push_back({x, y});
        }
    } else {
        QVector<double> c, s;
        if (!readNumbers(inv, "centre", 2, c) || !readNumbers(inv, "size", 2, s))
            return false;
        p.region.kind = RegionKind::CentreSize;
        p.region.centre = {c[0], c[1]};
        p.region.widthMm = s[0];
        p.region.heightMm = s[1];
    }
    if (set("fov") == set("sensor")) {
        inv.usage(tr("give the camera field: --fov w,h in mm, or --sensor W,H px with --sensor-um and --mag"));
        return false;
    }
    if (set("fov")) {
        if (!readNumbers(inv, "fov", 2, v))
            return false;
        p.camera.source = FieldSource::Direct;
        p.camera.fieldWidthMm = v[0];
        p.camera.fieldHeightMm = v[1];
        if (!readNumber(inv, "pixel-um", p.camera.samplePixelUm))
            return false;
    } else {
        if (!readNumbers(inv, "sensor", 2, v))
            return false;
        if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) || v[0] < 1 || v[1] < 1 || v[0] > 1e5 || v[1] > 1e5) {
            inv.usage(tr("--sensor '%1' must be two whole pixel counts").arg(inv.value(QStringLiteral("sensor"))));
            return false;
        }
        p.camera.source = FieldSource::Sensor;
        p.camera.sensorWidthPx = static_cast<int>(v[0]);
        p.camera.sensorHeightPx = static_cast<int>(v[1]);
        if (!inv.number(QStringLiteral("sensor-um"), p.camera.sensorPixelUm) || !inv.number(QStringLiteral("mag"), p.camera.magnification))
            return false;
    }
    if (!readNumber(inv, "rotation", p.camera.rotationDeg))
        return false;
    if (set("overlap")) {
        if (!readNumbers(inv, "overlap", 2, v, true))
            return false;
        p.overlapX = v[0];
        p.overlapY = v.size() > 1 ? v[1] : v[0];
    }
    const QString order = inv.value(QStringLiteral("order"));
    const auto o = orderFromName(order.toStdString());
    if (!o) {
        inv.usage(tr("--order '%1' is not one of snake-rows, rows, snake-cols, cols").arg(order));
        return false;
    }
    p.order = *o;
    const QString start = inv.value(QStringLiteral("start"));
    const auto c = startCornerFromName(start.toStdString());
    if (!c) {
        inv.usage(tr("--start '%1' is not one of top-left, top-right, bottom-left, bottom-right").arg(start));
        return false;
    }
    p.start = *c;
    p.approach.unidirectional = set("unidirectional");
    p.compensation.enabled = set("compensate");
    double firstIndex = p.naming.firstIndex;
    if (!readNumber(inv, "overtravel", p.approach.overtravelMm) || !readNumber(inv, "speed", p.speedMmS)
        || !readNumber(inv, "settle", p.settleS) || !readNumber(inv, "exposure", p.exposureS)
        || !readNumber(inv, "tolerance-um", p.toleranceUm) || !readNumber(inv, "first-index", firstIndex))
        return false;
    p.naming.firstIndex = static_cast<int>(std::clamp(firstIndex, -1.0, 2e6));
    if (set("name"))
        p.name = inv.value(QStringLiteral("name")).toStdString();
    if (set("pattern"))
        p.naming.filePattern = inv.value(QStringLiteral("pattern")).toStdString();
    if (set("mm-stage"))
        p.naming.mmXyStage = inv.value(QStringLiteral("mm-stage")).toStdString();
    return true;
}

int scanPlan(Invocation& inv)
{
    const QString format = inv.value(QStringLiteral("format"));
    static const QStringList kFormats = {QStringLiteral("json"), QStringLiteral("summary"), QStringLiteral("tileconfig"),
                                         QStringLiteral("mmpos"), QStringLiteral("csv")};
    if (!kFormats.contains(format))
        return inv.usage(tr("--format '%1' is not one of json, summary, tileconfig, mmpos, csv").arg(format));
    ScanPlan p;
    if (inv.arguments().size() > 1)
        return inv.usage(tr("takes at most one plan file (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
    if (inv.arguments().size() == 1) {
        for (const char* o : {"roi", "centre", "size", "polygon", "fov", "sensor", "overlap"})
            if (inv.isSet(QString::fromLatin1(o)))
                return inv.usage(tr("give a plan file or the plan's options, not both (--%1)").arg(QLatin1String(o)));
        dev::files::json::Problems problems;
        const QString planFile = inv.path(inv.arguments().front());
        if (!dev::files::scan::loadPlan(planFile, &p, &problems))
            return inv.usage(ui::words::fileProblems(problems, QFileInfo(planFile).fileName()).join(QLatin1Char('\n')));
        if (inv.isSet(QStringLiteral("pixel-um"))) {
            if (p.camera.source == FieldSource::Sensor)
                return inv.usage(tr("--pixel-um: the plan's camera gives the pixel size (sensor pixel / magnification)"));
            if (!inv.number(QStringLiteral("pixel-um"), p.camera.samplePixelUm))
                return Usage;
        }
    } else if (!planFromOptions(inv, p)) {
        return Usage;
    }
    // Checked against the standard (simulated) 100 × 100 mm stage; `scan run` checks the connected one.
    const auto problems = validate(p, StageModel{});
    if (!problems.empty()) {
        // Every problem once, each naming the option to change (X and Y of --overlap may say the same).
        QStringList lines;
        for (motion::msg::Problem pr : problems) {
            pr.path = optionFor(pr.path, p.camera.source == FieldSource::Sensor).toStdString();
            const QString line = ui::words::problem(pr);
            if (!lines.contains(line))
                lines << line;
        }
        for (const QString& line : lines)
            inv.report(line);
        return Usage;
    }
    if (format == QLatin1String("tileconfig") && p.camera.source == FieldSource::Direct && !inv.isSet(QStringLiteral("pixel-um"))
        && inv.arguments().isEmpty())
        return inv.usage(tr("--format tileconfig gives pixels: add --pixel-um (one pixel at the sample, µm)"));
    const ScanLayout layout = layoutScan(p);
    QTextStream& out = inv.out();
    if (format == QLatin1String("json")) {
        const std::string text = dev::files::scan::writePlan(p);
        out << QString::fromStdString(text);
        inv.offerJson(QJsonDocument::fromJson(QByteArray::fromStdString(text)).object());
    } else if (format == QLatin1String("summary")) {
        const ScanEstimate e = estimateScan(p, layout, StageModel{});
        inv.printJson(QJsonObject{{QStringLiteral("tiles"), static_cast<int>(layout.tiles.size())},
                                         {QStringLiteral("columns"), layout.grid.columns},
                                         {QStringLiteral("rows"), layout.grid.rows},
                                         {QStringLiteral("field_mm"), QJsonArray{layout.grid.fieldWidthMm, layout.grid.fieldHeightMm}},
                                         {QStringLiteral("step_mm"), QJsonArray{layout.grid.stepXMm, layout.grid.stepYMm}},
                                         {QStringLiteral("moves"), e.moves},
                                         {QStringLiteral("travel_mm"), e.travelMm},
                                         {QStringLiteral("estimate_s"), e.totalS},
                                         {QStringLiteral("moves_s"), e.moveS},
                                         {QStringLiteral("settle_s"), e.settleS},
                                         {QStringLiteral("exposure_s"), e.exposureS}});
    } else {
        const auto records = dev::files::scan::plannedRecords(p, layout);
        const std::string text = format == QLatin1String("tileconfig") ? dev::files::scan::tileConfiguration(p, records)
            : format == QLatin1String("mmpos")                         ? dev::files::scan::microManagerPositions(p, layout)
                                                                       : dev::files::scan::scanCsv(p, layout, records);
        out << QString::fromStdString(text);
    }
    out.flush();
    return Ok;
}

int scanRun(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("needs one plan file: scan run PLAN.json [--out DIR]"));
    const QString planPath = inv.path(inv.arguments().front());
    ScanPlan plan;
    dev::files::json::Problems problems;
    if (!dev::files::scan::loadPlan(planPath, &plan, &problems))
        return inv.usage(ui::words::fileProblems(problems, QFileInfo(planPath).fileName()).join(QLatin1Char('\n')));
    if (inv.isSet(QStringLiteral("camera-profile"))) {
        const QString profilePath = inv.path(inv.value(QStringLiteral("camera-profile")));
        const auto profile = dev::files::camera::loadCameraProfileFile(profilePath);
        if (!profile.ok())
            return inv.usage(ui::words::problems(profile.problems()).join(QLatin1Char('\n')));
        dev::files::camera::applyCameraProfile(*profile, &plan.camera);
        plan.camera.profile = profilePath.toStdString();
    }
    motion::msg::Message error;
    const QString folder = inv.path(inv.isSet(QStringLiteral("out"))
        ? inv.value(QStringLiteral("out"))
        : QFileInfo(inv.arguments().front()).completeBaseName().section(QLatin1Char('.'), 0, 0) + QStringLiteral("-run"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    dev::Instrument* client = s->instrument();
    if (client->identity().kind != dev::proto::DeviceKind::Stage)
        return inv.refused(tr("scans run on the microscope stage; this is the %1 (use --sim stage or --port)").arg(ui::words::term(dev::instrumentTerm(client->identity().kind))));
    // With --camera the camera takes each tile; it is made before prepare(), which checks
    // the images of a run it continues, and opened before the stage homes, so a camera
    // that is not there stops the run before anything moves.
    std::unique_ptr<dev::camera::Camera> camera;
    std::unique_ptr<dev::camera::ScanCamera> scanCamera;
    if (inv.isSet(QStringLiteral("camera"))) {
        camera = cameraFor(inv, s, inv.value(QStringLiteral("camera")));
        if (!camera)
            return Usage;
        if (const int rc = openCamera(inv, camera.get()); rc != Ok)
            return rc;
        scanCamera = std::make_unique<dev::camera::ScanCamera>(camera.get());
    }
    if (inv.isSet(QStringLiteral("home"))) {
        if (const int rc = s->request([&](auto cb) { client->home(0, cb); }, tr("home")))
            return rc;
        if (!s->waitUntilHomed(0b11))
            return inv.refused(tr("homing did not finish"));
    }
    ScanRunner runner(client);
    runner.setCamera(scanCamera.get());
    dev::jobs::ScanLaunch launch(&runner);
    using Kind = dev::jobs::ScanDecision::Kind;
    const dev::jobs::ScanDecision d = launch.prepare(plan, folder, inv.isSet(QStringLiteral("restart")));
    if (d.kind == Kind::OtherScansLog)
        return inv.usage(ui::words::text(d.error) + tr(" (--restart starts over)"));
    if (d.kind == Kind::Refused)
        return inv.refused(ui::words::text(d.error));
    QTextStream& out = inv.out();
    if (d.kind == Kind::AllTaken) {
        QStringList written;
        if (!runner.writeExports(&written, &error))
            return inv.refused(ui::words::text(error));
        out << tr("Every tile of this scan is already taken in %1; exports written again. --restart takes them anew.\n").arg(folder);
        out.flush();
        // Killed between its last tile and its mosaic: the folder is stitched now.
        const bool stitched = QFileInfo::exists(QDir(folder).filePath(QStringLiteral("mosaic.ome.tif")));
        if (scanCamera && !inv.isSet(QStringLiteral("no-stitch")) && !stitched)
            return ScanLiveStitch(inv, &runner).stitchFolder(plan, folder);
        return Ok;
    }
    if (d.kind == Kind::Blocked) {
        QStringList blockers;
        for (const motion::msg::Message& m : d.blockers)
            blockers << ui::words::text(m);
        return inv.refused(blockers.join(QStringLiteral("; ")) + (inv.isSet(QStringLiteral("home")) ? QString() : tr(" (--home homes the stage first)")));
    }
    // A script has no one to ask: a run longer than ScanLaunch::kAskLongerThanS needs --yes.
    if (d.outlook.longRun && !inv.isSet(QStringLiteral("yes")))
        return inv.usage(tr("this scan takes about %1 min on the stage; add --yes to run it").arg(std::ceil(d.outlook.etaS / 60)));
    if (d.outlook.resume)
        out << tr("Continuing at tile %1 of %2 (the run log in %3 has the first %4).\n")
                   .arg(d.outlook.takenTiles + 1).arg(d.outlook.totalTiles).arg(folder).arg(d.outlook.takenTiles);
    // With a camera the scan stitches as it goes, as the Scan screen's does (--no-stitch: not).
    std::unique_ptr<ScanLiveStitch> stitch;
    if (scanCamera && !inv.isSet(QStringLiteral("no-stitch")))
        stitch = std::make_unique<ScanLiveStitch>(inv, &runner);
    QString stopReason;
    QStringList exports;
    QObject::connect(&runner, &ScanRunner::problem, [&](const motion::msg::Message& m) { stopReason = ui::words::text(m); });
    QObject::connect(&runner, &ScanRunner::finished, [&](const QStringList& e) { exports = e; });
    QObject::connect(&runner, &ScanRunner::tileTaken, [&](int tile) {
        const auto& r = runner.records()[static_cast<std::size_t>(tile)];
        const auto& image = runner.image(tile);
        if (inv.json()) {
            QJsonObject o{{QStringLiteral("tile"), tile + 1},
                          {QStringLiteral("file"), QString::fromStdString(r.label)},
                          {QStringLiteral("planned_mm"), QJsonArray{r.plannedMm[0], r.plannedMm[1]}},
                          {QStringLiteral("measured_mm"), QJsonArray{r.measuredMm[0], r.measuredMm[1]}},
                          {QStringLiteral("device_time_us"), static_cast<qint64>(r.deviceTimeUs)}};
            if (!image.file.empty()) {
                o.insert(QStringLiteral("image"), QString::fromStdString(image.file));
                o.insert(QStringLiteral("sha256"), QString::fromStdString(image.sha256));
            }
            inv.printJson(o);
        } else
            out << tr("tile %1/%2 %3 at %4, %5 mm (%6 s to settle)\n")
                       .arg(tile + 1).arg(runner.totalTiles()).arg(QString::fromStdString(r.label))
                       .arg(r.measuredMm[0], 0, 'f', 4).arg(r.measuredMm[1], 0, 'f', 4).arg(r.settleS, 0, 'f', 3);
        out.flush();
    });
    if (!launch.start(&error))
        return inv.refused(ui::words::text(error));
    const auto abortHook = inv.host().onAbort([&runner] { runner.abort(); });  // the API's cancel; the log can continue
    spinUntil([&] { return !runner.isActive(); }, std::numeric_limits<int>::max());
    if (runner.state() != ScanRunner::State::Finished) {
        const bool link = !client->isReady();
        const QString again = tr(" Run the same command again to continue.");
        return link ? inv.linkTrouble(stopReason + again) : inv.refused(stopReason + again);
    }
    if (!stopReason.isEmpty())
        return inv.refused(stopReason);
    out << tr("%1 tiles taken; wrote %2\n").arg(runner.totalTiles()).arg(exports.join(QStringLiteral(", ")));
    out.flush();
    return stitch ? stitch->finish() : Ok;
}

} // namespace

void addScanCommands(std::vector<Command>& list)
{
    const QList<QCommandLineOption> planOptions = {
        option("roi", "region by two corners, mm", "x0,y0,x1,y1"),
        option("centre", "region by its centre, mm (with --size)", "x,y"),
        option("size", "region size, mm (with --centre)", "w,h"),
        option("polygon", "region by its outline's corners, mm", "x,y;x,y;…"),
        option("fov", "camera field at the sample, mm", "w,h"),
        option("pixel-um", "one pixel at the sample, µm (with --fov or a plan file; TileConfiguration is in pixels; plans default to 0.65)", "P"),
        option("sensor", "camera sensor in pixels (with --sensor-um and --mag, instead of --fov)", "W,H"),
        option("sensor-um", "sensor pixel pitch, µm", "P"),
        option("mag", "magnification", "M"),
        option("rotation", "camera rotation against stage +X, degrees", "DEG"),
        option("overlap", "overlap as a share of the field, 0 to 0.9, per axis", "o[,o]"),
        option("order", "snake-rows, rows, snake-cols or cols", "ORDER", "snake-rows"),
        option("start", "top-left, top-right, bottom-left or bottom-right", "CORNER", "top-left"),
        option("unidirectional", "approach every tile from the same side (backlash)"),
        option("overtravel", "overtravel of the unidirectional approach, mm", "MM"),
        option("speed", "speed of the moves between tiles, mm/s", "V"),
        option("settle", "expected settling per tile for the estimate, s", "S"),
        option("exposure", "exposure (dwell) per tile, s", "S"),
        option("tolerance-um", "a tile is taken once the grating is this close, µm", "UM"),
        option("compensate", "run with the stage's own error compensation (it must be enabled on X and Y)"),
        option("name", "the scan's name", "NAME"),
        option("pattern", "tile file names, e.g. tile_{i:03}.tif", "PATTERN"),
        option("first-index", "number of the first tile in file names", "N"),
        option("mm-stage", "Micro-Manager's XY stage device label", "LABEL"),
        option("format", "json (the plan file), summary, tileconfig (Fiji), mmpos (Micro-Manager) or csv", "FORMAT", "json"),
    };
    Command plan{QStringLiteral("plan"), tr("plan a stitching scan and print it (plan file, summary, Fiji, Micro-Manager or CSV)"),
                 tr("[PLAN.json]"),
                 tr("The tile grid steps by exactly field × (1 − overlap), centred on the region: n = max(1, ceil((W − F)/(F(1 − o))) + 1) "
                    "per axis. Checked against the standard 100 × 100 mm stage. With PLAN.json, prints that plan in --format."),
                 planOptions, scanPlan, {}};
    plan.api.access = Access::Compute;
    plan.api.params = {{QStringLiteral("plan"), ParamType::File, tr("a plan file to print in another format (instead of the plan's options)"), false, {}, {}}};
    for (const char* numbers : {"roi", "centre", "size", "fov", "sensor", "overlap"})
        plan.api.params << optionParam(numbers, ParamType::Numbers);
    for (const char* number : {"pixel-um", "sensor-um", "mag", "rotation", "overtravel", "speed", "settle", "exposure", "tolerance-um"})
        plan.api.params << optionParam(number, ParamType::Number);
    plan.api.params << optionParam("first-index", ParamType::Integer);
    plan.api.example = QJsonObject{{QStringLiteral("roi"), QJsonArray{40, 40, 42.5, 41}}, {QStringLiteral("fov"), QJsonArray{1.33, 1.33}},
                                   {QStringLiteral("overlap"), QJsonArray{0.1}}, {QStringLiteral("format"), QStringLiteral("summary")}};
    Command run{QStringLiteral("run"), tr("run a scan plan on the stage, continue a stopped run, write the exports"),
                tr("PLAN.json"),
                tr("Needs the stage (--sim stage or --port) homed (--home does it). The run log and TileConfiguration.txt, "
                   "positions.pos and scan.csv go to --out; a run stopped part-way continues at its next tile when run again. "
                   "With --camera the tiles are stitched as they come: after the last, mosaic.ome.tif, "
                   "TileConfiguration.registered.txt, mosaic.stitch.json and quality-map.png are in --out (--no-stitch: not)."),
                {option("out", "folder for the run log and the exports (default: PLAN-run)", "DIR"),
                 option("home", "home the stage first"), option("restart", "start over even if the folder holds a run (kept aside)"),
                 option("yes", "run a scan that takes longer than a minute without asking"),
                 option("camera", "take an image at every tile: sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR (see camera list)", "SOURCE"),
                 cameraOptions()[0], cameraOptions()[1], cameraOptions()[2],
                 option("camera-profile", "the camera's geometry from this camera profile, not the plan's (camera calibrate writes one)", "FILE"),
                 option("no-stitch", "with --camera: do not stitch the tiles as they come (benchpilot-cli stitch the folder later)")},
                scanRun, {}};
    run.api.access = Access::Control;
    run.api.params = {{QStringLiteral("plan"), ParamType::File, tr("the scan plan file"), true, {}, {}}, optionParam("out", ParamType::File),
                      optionParam("camera", ParamType::Text), optionParam("specimen", ParamType::Text), optionParam("camera-seed", ParamType::Number),
                      optionParam("camera-true", ParamType::Text), optionParam("camera-profile", ParamType::File),
                      optionParam("no-stitch", ParamType::Boolean)};
    run.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("plan"), QStringLiteral("slide.scan.json")},
                                  {QStringLiteral("out"), QStringLiteral("slide-run")}, {QStringLiteral("camera"), QStringLiteral("sim")}};
    list.push_back({QStringLiteral("scan"), tr("stitching scans on the stage: plan, run"), {},
                    tr("See docs/scan.md for the grid rule, the plan file and the exports."), {}, {}, {plan, run}});
}

} // namespace app::cli
