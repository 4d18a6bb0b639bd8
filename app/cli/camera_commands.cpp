// benchpilot-cli's camera commands:
//   camera list              the sources this build can take, and the simulated specimens;
//   camera snap --camera SOURCE --out FILE.tif [--exposure-ms N]
//                            one image, with where the stage stood, as a tile TIFF;
//   camera calibrate ...     the camera against the stage, into a camera profile (camera_calibrate.cpp).
// See docs/camera.md.
#include "camera_cli.h"
#include "cli_session.h"

#include "device/camera/camera_source.h"
#include "device/camera/tile_tiff.h"
#if BP_WITH_UVC
#include "device/camera/uvc_devices.h"
#include "device/camera/video_frame_convert.h"
#endif
#include "device/link/simulated_link.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QPointer>

#include <cmath>

namespace app::cli {
namespace {

namespace cam = dev::camera;

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// Longest wait for a frame beyond its exposure: a simulated 2048² frame takes tens of ms.
constexpr int kSnapGraceMs = 30000;

QString problemText(const motion::msg::Message& m) { return ui::words::text(m); }

/// The USB cameras found now, each with the formats it offers; asks the multimedia backend
/// (see uvc_devices.h for what that costs), so only `camera list` calls it.
QJsonArray usbCameras()
{
    QJsonArray out;
#if BP_WITH_UVC
    for (const cam::UvcDevice& d : cam::listUvcCameras()) {
        QJsonArray formats;
        for (const cam::UvcFormat& f : d.formats)
            formats.append(QJsonObject{{QStringLiteral("width"), f.size.width()},
                                       {QStringLiteral("height"), f.size.height()},
                                       {QStringLiteral("pixel_format"), QString::fromStdString(cam::videoFormatName(f.pixelFormat))},
                                       {QStringLiteral("min_fps"), static_cast<double>(f.minFps)},
                                       {QStringLiteral("max_fps"), static_cast<double>(f.maxFps)},
                                       {QStringLiteral("accepted"), f.accepted}});
        out.append(QJsonObject{{QStringLiteral("source"), QStringLiteral("uvc:") + d.name},
                               {QStringLiteral("name"), d.name},
                               {QStringLiteral("id"), d.id},
                               {QStringLiteral("default"), d.isDefault},
                               {QStringLiteral("formats"), formats}});
    }
#endif
    return out;
}

/// "1920×1080, 1280×720": the sizes of a listed camera's formats BenchPilot reads, largest first.
QString acceptedSizes(const QJsonObject& camera)
{
    QStringList sizes;
    QList<QPair<qint64, QString>> sorted;
    for (const auto& v : camera.value(QStringLiteral("formats")).toArray()) {
        const QJsonObject f = v.toObject();
        const QString size = QStringLiteral("%1×%2").arg(f.value(QStringLiteral("width")).toInt()).arg(f.value(QStringLiteral("height")).toInt());
        if (!f.value(QStringLiteral("accepted")).toBool() || sizes.contains(size))
            continue;
        sizes << size;
        sorted.append({-static_cast<qint64>(f.value(QStringLiteral("width")).toInt()) * f.value(QStringLiteral("height")).toInt(), size});
    }
    std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    QStringList out;
    for (const auto& s : sorted)
        out << s.second;
    return out.join(QStringLiteral(", "));
}

int cameraList(Invocation& inv)
{
    QJsonArray sources;
    const bool onlyAvailable = inv.isSet(QStringLiteral("available"));
    auto add = [&](const QString& source, const QString& what, bool available) {
        if (onlyAvailable && !available)
            return;
        sources.append(QJsonObject{{QStringLiteral("source"), source}, {QStringLiteral("description"), what},
                                   {QStringLiteral("available"), available}});
    };
    add(QStringLiteral("sim"), tr("the simulated camera on the in-process simulator's stage (--sim stage)"), true);
    add(QStringLiteral("sim:PATH"), tr("the simulated camera benchpilot-sim serves on a socket (--camera-socket)"), true);
    add(QStringLiteral("uvc[:NAME]"), tr("a USB camera through Qt Multimedia: NAME as camera list names it, NAME@WIDTHxHEIGHT for a resolution"), BP_WITH_UVC != 0);
    add(QStringLiteral("command:CMD"), tr("your capture program, run for each image with {file} {tile} {x_mm} {y_mm}"), true);
    add(QStringLiteral("folder:DIR"), tr("the next complete new image a camera's own software saves in DIR"), true);
    QJsonArray specimens;
    for (const std::string& s : cam::specimenNames())
        specimens.append(QString::fromStdString(s));
    const QJsonArray cameras = usbCameras();
    if (inv.json()) {
        inv.printJson(QJsonObject{{QStringLiteral("sources"), sources}, {QStringLiteral("cameras"), cameras}, {QStringLiteral("specimens"), specimens}});
        return Ok;
    }
    QTextStream& out = inv.out();
    for (const auto& v : sources) {
        const QJsonObject o = v.toObject();
        out << o.value(QStringLiteral("source")).toString().leftJustified(14) << ' ' << o.value(QStringLiteral("description")).toString()
            << (o.value(QStringLiteral("available")).toBool() ? QString() : tr(" (not in this build yet)")) << '\n';
    }
    if (BP_WITH_UVC) {
        if (cameras.isEmpty())
            out << tr("USB cameras: none found") << '\n';
        else
            out << tr("USB cameras:") << '\n';
        for (const auto& v : cameras) {
            const QJsonObject c = v.toObject();
            out << "  " << c.value(QStringLiteral("source")).toString() << "  (" << c.value(QStringLiteral("id")).toString() << ')'
                << (c.value(QStringLiteral("default")).toBool() ? tr(", the default") : QString()) << '\n';
            const QString sizes = acceptedSizes(c);
            out << "    " << (sizes.isEmpty() ? tr("no format BenchPilot can read") : sizes) << '\n';
        }
    }
    out << tr("Simulated specimens (--specimen): %1\n").arg(QStringLiteral("slide, grid-plate, line-scales"));
    out.flush();
    return Ok;
}

int cameraSnap(Invocation& inv)
{
    if (!inv.isSet(QStringLiteral("camera")))
        return inv.usage(tr("needs --camera SOURCE (sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR; see camera list)"));
    if (!inv.isSet(QStringLiteral("out")))
        return inv.usage(tr("needs --out FILE.tif"));
    const QString file = inv.path(inv.value(QStringLiteral("out")));
    if (!file.endsWith(QLatin1String(".tif")) && !file.endsWith(QLatin1String(".tiff")))
        return inv.usage(tr("--out '%1': the image is a TIFF, give a name ending in .tif").arg(file));
    double exposureMs = 0;
    if (!inv.number(QStringLiteral("exposure-ms"), exposureMs, 10.0))
        return Usage;
    if (!(exposureMs > 0 && exposureMs <= 60000))
        return inv.usage(tr("--exposure-ms must be above 0 and at most 60000"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    std::unique_ptr<cam::Camera> camera = cameraFor(inv, s, inv.value(QStringLiteral("camera")));
    if (!camera)
        return Usage;
    if (const int rc = openCamera(inv, camera.get()); rc != Ok)
        return rc;
    std::optional<cam::Frame> frame;
    std::optional<motion::msg::Message> failure;
    QObject::connect(camera.get(), &cam::Camera::captured, [&](std::uint64_t, const cam::Frame& f) { frame = f; });
    QObject::connect(camera.get(), &cam::Camera::failed, [&](std::uint64_t, const motion::msg::Problem& p) {
        if (!failure)
            failure = p.message;
    });
    if (camera->capabilities().exposure)
        camera->setExposureMs(exposureMs);
    const auto& st = s->instrument()->status();
    cam::CaptureRequest req;
    req.id = 1;
    req.fileHint = file.toStdString();
    if (st.axes.size() >= 2) {
        req.xMm = st.axes[0].measured;
        req.yMm = st.axes[1].measured;
    }
    camera->capture(req);
    // A camera's own software fired by the stage's trigger output: the snap fires it too.
    if (camera->capabilities().needsTriggerOutput && s->instrument()->can(dev::Capability::TriggerOutput))
        s->instrument()->pulseTrigger(exposureMs / 1000.0);
    if (!spinUntil([&] { return frame || failure; }, static_cast<int>(exposureMs) + kSnapGraceMs))
        return inv.refused(tr("the camera %1 gave no image within %2 s").arg(camera->source()).arg(kSnapGraceMs / 1000));
    if (failure)
        return inv.refused(problemText(*failure));
    cam::TileMetadata meta;
    meta.label = QFileInfo(file).fileName().toStdString();
    if (st.axes.size() >= 2)
        meta.measuredMm = {req.xMm, req.yMm};
    meta.deviceTimeUs = frame->deviceTimeUs;
    meta.source = camera->source().toStdString();
    std::string sha;
    motion::msg::Message error;
    if (!cam::writeTileTiff(file.toStdString(), *frame, meta, &sha, &error))
        return inv.refused(problemText(error));
    if (inv.json()) {
        QJsonObject o{{QStringLiteral("file"), file},
                      {QStringLiteral("camera"), camera->source()},
                      {QStringLiteral("width"), frame->width},
                      {QStringLiteral("height"), frame->height},
                      {QStringLiteral("bit_depth"), frame->bitDepth},
                      {QStringLiteral("exposure_ms"), frame->exposureMs},
                      {QStringLiteral("pixel_um"), frame->pixelUm},
                      {QStringLiteral("sha256"), QString::fromStdString(sha)}};
        if (!meta.measuredMm.empty())
            o.insert(QStringLiteral("measured_mm"), QJsonArray{meta.measuredMm[0], meta.measuredMm[1]});
        inv.printJson(o);
    } else {
        inv.out() << tr("wrote %1: %2 × %3 px, %4-bit, %5 ms").arg(file).arg(frame->width).arg(frame->height).arg(frame->bitDepth).arg(frame->exposureMs)
                  << (meta.measuredMm.empty() ? QString() : tr(", at %1, %2 mm").arg(meta.measuredMm[0], 0, 'f', 4).arg(meta.measuredMm[1], 0, 'f', 4))
                  << '\n';
        inv.out().flush();
    }
    return Ok;
}

} // namespace

int openCamera(Invocation& inv, dev::camera::Camera* camera)
{
    std::optional<motion::msg::Message> failure;
    bool opened = false;
    // Connected before open(): a camera that is not there says so at once, from open() itself.
    const auto failedLink = QObject::connect(camera, &cam::Camera::failed, [&](std::uint64_t id, const motion::msg::Problem& p) {
        if (id == 0 && !failure)
            failure = p.message;
    });
    const auto openedLink = QObject::connect(camera, &cam::Camera::opened, [&] { opened = true; });
    camera->open();
    const bool settled = camera->isOpen() || failure || spinUntil([&] { return opened || failure; }, kSnapGraceMs);
    QObject::disconnect(failedLink);
    QObject::disconnect(openedLink);
    if (failure)
        return inv.refused(problemText(*failure));
    if (!settled || !camera->isOpen())
        return inv.refused(tr("the camera %1 did not open within %2 s").arg(camera->source()).arg(kSnapGraceMs / 1000));
    return Ok;
}

QList<QCommandLineOption> cameraOptions(const char* defaultSpecimen)
{
    return {option("specimen", "with --camera sim: what lies on the simulated stage: slide, grid-plate or line-scales", "NAME", defaultSpecimen),
            option("camera-seed", "with --camera sim: the simulated specimen's and noise's seed", "N", "1"),
            option("camera-true", "with --camera sim: the simulated camera's true geometry where it differs from the plan's: pixel-um=X[:Y],rotation-deg=D,mirror", "SPEC")};
}

std::unique_ptr<dev::camera::Camera> cameraFor(Invocation& inv, CliSession* session, const QString& source, const char* defaultSpecimen)
{
    cam::SimContext sim;
    const QString specimen = inv.isSet(QStringLiteral("specimen")) ? inv.value(QStringLiteral("specimen")) : QLatin1String(defaultSpecimen);
    const auto kind = cam::specimenFromName(specimen.toStdString());
    if (!kind) {
        inv.usage(tr("--specimen '%1' is not one of slide, grid-plate, line-scales").arg(specimen));
        return nullptr;
    }
    sim.settings.specimen = *kind;
    // benchpilot-sim chose its camera's specimen and seed when it started: one asked here would be ignored.
    if (source.startsWith(QLatin1String("sim:")) && (inv.isSet(QStringLiteral("specimen")) || inv.isSet(QStringLiteral("camera-seed")) || inv.given(QStringLiteral("camera-true")))) {
        inv.usage(tr("--camera %1: the specimen, its seed and the camera's true geometry are benchpilot-sim's own (its --specimen, --camera-seed and --camera-true)").arg(source));
        return nullptr;
    }
    if (inv.given(QStringLiteral("camera-true"))) {
        std::string bad;
        if (!cam::parseSimTrueGeometry(inv.value(QStringLiteral("camera-true")).toStdString(), &sim.settings.trueGeometry, &bad)) {
            inv.usage(tr("--camera-true: '%1' is not pixel-um=X[:Y] (above 0), rotation-deg=D (-360 to 360) or mirror").arg(QString::fromStdString(bad)));
            return nullptr;
        }
    }
    double seed = 1;
    if (!inv.number(QStringLiteral("camera-seed"), seed, 1.0))
        return nullptr;
    if (!(seed >= 0 && seed < 9007199254740992.0 && std::floor(seed) == seed)) {
        inv.usage(tr("--camera-seed must be a whole number from 0"));
        return nullptr;
    }
    sim.settings.seed = static_cast<std::uint64_t>(seed);
    if (auto* link = session ? qobject_cast<dev::SimulatedLink*>(session->simulator()) : nullptr) {
        // Guarded: the GUI's link goes away on a reconnect, perhaps while its camera lives.
        QPointer<dev::SimulatedLink> guarded(link);
        sim.workPoint = [guarded]() -> std::optional<cam::WorkPoint> {
            if (!guarded || guarded->machine().axisCount() < 2)
                return std::nullopt;
            const dev::sim::SimMachine& m = guarded->machine();
            return cam::WorkPoint{m.workPointLogical(0), m.workPointLogical(1), m.timeUs()};
        };
    } else if (session && session->instrument()) {
        // No simulator in this process (benchpilot-sim's pty, a real stage): the simulated
        // camera looks where the stage says it is; only the in-process simulator knows
        // the true work point apart from the reading.
        QPointer<dev::Instrument> instrument = session->instrument();
        sim.workPoint = [instrument]() -> std::optional<cam::WorkPoint> {
            if (!instrument || instrument->status().axes.size() < 2)
                return std::nullopt;
            const auto& st = instrument->status();
            return cam::WorkPoint{st.axes[0].measured, st.axes[1].measured, st.deviceTimeUs};
        };
    }
    motion::msg::Message error;
    auto camera = cam::makeCamera(source.toStdString(), sim, &error);
    if (!camera)
        inv.usage(QStringLiteral("--camera: ") + ui::words::text(error));
    return camera;
}

void addCameraCommands(std::vector<Command>& list)
{
    Command listCmd{QStringLiteral("list"), tr("the cameras BenchPilot can take images from, and the simulated specimens"), {}, {}, {}, cameraList, {}};
    listCmd.options = {option("available", "only the sources this build can open")};
    listCmd.api.access = Access::Compute;
    listCmd.api.params = {optionParam("available", ParamType::Boolean)};
    listCmd.api.example = QJsonObject{{QStringLiteral("available"), true}};
    QList<QCommandLineOption> snapOptions{option("camera", "sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR (see camera list)", "SOURCE"),
                                          option("out", "the image file to write (TIFF)", "FILE.tif"),
                                          option("exposure-ms", "exposure, ms, where the camera lets it be set", "N", "10")};
    snapOptions << cameraOptions();
    Command snap{QStringLiteral("snap"), tr("take one image and write it as a TIFF with where the stage stood"), {},
                 tr("With --sim stage and --camera sim the simulated camera renders the specimen at the stage's true "
                    "position; on benchpilot-sim's pty, --camera sim:PATH takes it from the socket that benchpilot-sim "
                    "serves with --camera-socket PATH (see docs/camera.md)."),
                 snapOptions, cameraSnap, {}};
    snap.api.access = Access::Control;
    snap.api.params = {optionParam("camera", ParamType::Text, true), optionParam("out", ParamType::File, true),
                       optionParam("exposure-ms", ParamType::Number), optionParam("specimen", ParamType::Text),
                       optionParam("camera-seed", ParamType::Number)};
    snap.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("camera"), QStringLiteral("sim")},
                                   {QStringLiteral("out"), QStringLiteral("snap.tif")}};
    list.push_back({QStringLiteral("camera"), tr("cameras: list the sources, take an image, calibrate against the stage"), {},
                    tr("See docs/camera.md for the sources, the image files and the simulated specimens."), {}, {}, {listCmd, snap, cameraCalibrateCommand()}});
}

} // namespace app::cli
