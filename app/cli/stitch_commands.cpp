// benchpilot-cli stitch: a folder of tiles and where each was taken → a pyramidal
// OME-TIFF mosaic, Fiji's registered TileConfiguration and a JSON report
// (docs/stitching.md). The positions come from the scan's run log (mm, turned into
// pixels by the camera's geometry) or from a TileConfiguration (pixels).
#include "cli_session.h"
#include "command.h"

#include "device/files/scan_plan_file.h"
#include "device/files/scan_run_log.h"
#include "device/files/stitch_positions.h"
#include "imaging/stitch.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSet>

#include <chrono>
#include <cmath>
#include <future>
#include <limits>

namespace app::cli {
namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("app::cli", text);
}

/// How stage millimetres become image pixels (docs/scan.md, "Exports"): the image x
/// axis at `rotationDeg` from stage +X, its y axis (down the image) along stage −Y or +Y.
struct Geometry {
    double pixelUm = 0;
    double rotationDeg = 0;
    bool imageYAlongMinusY = true;

    Eigen::Vector2d ex() const
    {
        const double a = rotationDeg * M_PI / 180;
        return {std::cos(a), std::sin(a)};
    }
    Eigen::Vector2d ey() const
    {
        const double a = rotationDeg * M_PI / 180;
        return imageYAlongMinusY ? Eigen::Vector2d(std::sin(a), -std::cos(a)) : Eigen::Vector2d(-std::sin(a), std::cos(a));
    }
    Eigen::Vector2d toPx(const Eigen::Vector2d& mm) const { return Eigen::Vector2d(mm.dot(ex()), mm.dot(ey())) * 1000.0 / pixelUm; }
    Eigen::Vector2d toMm(const Eigen::Vector2d& px) const { return (px.x() * ex() + px.y() * ey()) * pixelUm / 1000.0; }
};

bool looksLikeRunLog(const QString& path, const QByteArray& text)
{
    if (path.endsWith(QLatin1String(".jsonl"), Qt::CaseInsensitive))
        return true;
    const QByteArray t = text.trimmed();
    return !t.isEmpty() && t.front() == '{';
}

bool isTileImage(const QString& name)
{
    const QString n = name.toLower();
    return (n.endsWith(QLatin1String(".tif")) || n.endsWith(QLatin1String(".tiff"))) && !n.endsWith(QLatin1String(".ome.tif")) &&
           !n.endsWith(QLatin1String(".ome.tiff")) && !n.endsWith(QLatin1String(".partial"));
}

bool saveText(const QString& path, const std::string& text, QString* error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()) || !f.commit()) {
        *error = f.errorString();
        return false;
    }
    return true;
}

int stitchRun(Invocation& inv)
{
    QElapsedTimer clock;
    clock.start();
    if (inv.arguments().size() != 1)
        return inv.usage(tr("stitch needs one folder of tiles (benchpilot-cli stitch DIR --out mosaic.ome.tif)"));
    const QDir dir(inv.path(inv.arguments().front()));
    if (!dir.exists())
        return inv.usage(tr("%1: no such folder").arg(QDir::toNativeSeparators(dir.path())));

    imaging::StitchOptions so;
    Geometry geo;
    if (inv.isSet(QStringLiteral("plan"))) {
        const QString planPath = inv.path(inv.value(QStringLiteral("plan")));
        motion::scan::ScanPlan plan;
        dev::files::json::Problems problems;
        if (!dev::files::scan::loadPlan(planPath, &plan, &problems))
            return inv.usage(ui::words::fileProblems(problems, QFileInfo(planPath).fileName()).join(QLatin1Char('\n')));
        geo.pixelUm = motion::scan::pixelAtSampleUm(plan.camera);
        geo.rotationDeg = plan.camera.rotationDeg;
        geo.imageYAlongMinusY = plan.camera.imageY == motion::scan::ImageY::StageMinusY;
    }
    if (inv.isSet(QStringLiteral("pixel-um")) && !inv.number(QStringLiteral("pixel-um"), geo.pixelUm))
        return Usage;
    if (inv.isSet(QStringLiteral("pixel-um")) && !(geo.pixelUm > 0 && geo.pixelUm < 1000))
        return inv.usage(tr("--pixel-um must be above 0 and below 1000 µm (got %1)").arg(geo.pixelUm));
    if (inv.isSet(QStringLiteral("rotation")) && !inv.number(QStringLiteral("rotation"), geo.rotationDeg))
        return Usage;
    if (inv.isSet(QStringLiteral("image-y"))) {
        const QString y = inv.value(QStringLiteral("image-y"));
        if (y != QLatin1String("stage-minus-y") && y != QLatin1String("stage-plus-y"))
            return inv.usage(tr("--image-y must be stage-minus-y or stage-plus-y (got '%1')").arg(y));
        geo.imageYAlongMinusY = y == QLatin1String("stage-minus-y");
    }
    double maxShift = so.registration.maxShiftPx;
    if (!inv.number(QStringLiteral("max-shift-px"), maxShift, so.registration.maxShiftPx))
        return Usage;
    if (!(maxShift >= 1 && maxShift <= 10000))
        return inv.usage(tr("--max-shift-px must be from 1 to 10000 px (got %1)").arg(maxShift));
    so.registration.maxShiftPx = maxShift;
    so.placement.maxCorrectionPx = maxShift;
    double repeatUm = 1.0;
    if (!inv.number(QStringLiteral("repeatability-um"), repeatUm, 1.0))
        return Usage;
    if (!(repeatUm > 0 && repeatUm <= 1000))
        return inv.usage(tr("--repeatability-um must be above 0 and at most 1000 µm (got %1)").arg(repeatUm));
    const QString blend = inv.value(QStringLiteral("blend"));
    if (blend != QLatin1String("feather") && blend != QLatin1String("overlay"))
        return inv.usage(tr("--blend must be feather or overlay (got '%1')").arg(blend));
    so.fusion.blend = blend == QLatin1String("overlay") ? imaging::Blend::Overlay : imaging::Blend::Feather;

    QString flatPath;
    if (inv.isSet(QStringLiteral("flat"))) {
        double dark = 0;
        if (!inv.number(QStringLiteral("dark"), dark, 0.0))
            return Usage;
        if (!(dark >= 0 && dark < 65535))
            return inv.usage(tr("--dark must be from 0 to 65535 grey levels (got %1)").arg(dark));
        flatPath = inv.path(inv.value(QStringLiteral("flat")));
        auto flat = imaging::FlatField::fromFile(flatPath.toStdString(), dark, QFileInfo(flatPath).fileName().toStdString());
        if (!flat)
            return inv.usage(ui::words::problems(flat.problems()).join(QLatin1Char('\n')));
        so.flatField = std::make_shared<const imaging::FlatField>(flat.take());
    } else if (inv.isSet(QStringLiteral("dark"))) {
        return inv.usage(tr("--dark is the camera's offset under --flat: give the blank image with --flat"));
    }

    // Where the positions are: --positions, else the run log, else a TileConfiguration.
    QString positions = inv.isSet(QStringLiteral("positions")) ? inv.path(inv.value(QStringLiteral("positions"))) : QString();
    if (positions.isEmpty()) {
        for (const char* name : {dev::files::scan::kRunLogFile, "TileConfiguration.txt"})
            if (dir.exists(QLatin1String(name))) {
                positions = dir.filePath(QLatin1String(name));
                break;
            }
        if (positions.isEmpty())
            return inv.usage(tr("%1 holds neither a scan run log (%2) nor a TileConfiguration.txt: say where the tiles were taken with --positions")
                                 .arg(QDir::toNativeSeparators(dir.path()), QLatin1String(dev::files::scan::kRunLogFile)));
    }
    QFile pf(positions);
    if (!pf.open(QIODevice::ReadOnly))
        return inv.usage(tr("cannot read %1: %2").arg(QDir::toNativeSeparators(positions), pf.errorString()));
    const QByteArray text = pf.read(64 * 1024 * 1024);
    const std::string shownPositions = QFileInfo(positions).fileName().toStdString();

    std::vector<imaging::StitchTile> tiles;
    if (looksLikeRunLog(positions, text)) {
        if (!(geo.pixelUm > 0))
            return inv.usage(tr("%1 gives positions in mm: give the pixel size at the sample with --pixel-um (or the scan plan with --plan)")
                                 .arg(QFileInfo(positions).fileName()));
        auto taken = dev::files::scan::parseTakenTiles(std::string_view(text.constData(), static_cast<std::size_t>(text.size())), shownPositions);
        if (!taken)
            return inv.usage(ui::words::problems(taken.problems()).join(QLatin1Char('\n')));
        for (const dev::files::scan::TakenTile& t : *taken) {
            const QString name = QString::fromStdString(t.image);
            tiles.push_back({t.image, dir.filePath(name).toStdString(), geo.toPx({t.measuredXMm, t.measuredYMm})});
        }
        // The log gives each field's centre: the TileConfiguration's corner is half a field
        // away, the same for every tile, so registration does not care; the OME position does.
        so.stageMmAt = [geo](const Eigen::Vector2d& px) { return std::optional<Eigen::Vector2d>(geo.toMm(px)); };
        // The stage pixels came from this camera: the neighbours' shifts say whether it is right.
        so.planCamera = imaging::PlanCameraGeometry{geo.pixelUm, geo.rotationDeg, !geo.imageYAlongMinusY};
    } else {
        auto entries = imaging::parseTileConfiguration(std::string_view(text.constData(), static_cast<std::size_t>(text.size())), shownPositions);
        if (!entries)
            return inv.usage(ui::words::problems(entries.problems()).join(QLatin1Char('\n')));
        for (const imaging::TileEntry& e : *entries)
            tiles.push_back({e.file, dir.filePath(QString::fromStdString(e.file)).toStdString(), e.positionPx});
    }

    // Every named file there, and every tile image of the folder named.
    QStringList missing;
    QSet<QString> named;
    for (const imaging::StitchTile& t : tiles) {
        const QString name = QString::fromStdString(t.file);
        named.insert(QFileInfo(name).fileName());
        if (!QFileInfo::exists(QString::fromStdString(t.path)))
            missing << tr("%1 names %2, which is not in the folder").arg(QFileInfo(positions).fileName(), name);
    }
    if (!missing.isEmpty())
        return inv.usage(missing.join(QLatin1Char('\n')));
    const QString outPath = inv.path(inv.isSet(QStringLiteral("out")) ? inv.value(QStringLiteral("out")) : dir.filePath(QStringLiteral("mosaic.ome.tif")));
    QStringList unnamed;
    for (const QString& f : dir.entryList(QDir::Files, QDir::Name))
        if (isTileImage(f) && !named.contains(f) && dir.filePath(f) != outPath && QFileInfo(dir.filePath(f)) != QFileInfo(flatPath))
            unnamed << f;
    if (!unnamed.isEmpty())
        return inv.usage(tr("%1 places %2 tiles, but the folder also holds tile images it does not name: %3. "
                            "Stitch a folder of one scan, or give positions for every image.")
                             .arg(QFileInfo(positions).fileName())
                             .arg(tiles.size())
                             .arg(unnamed.mid(0, 3).join(QStringLiteral(", ")) + (unnamed.size() > 3 ? QStringLiteral(", …") : QString())));

    so.placement.stageSigmaPx = geo.pixelUm > 0 ? std::max(0.1, repeatUm / geo.pixelUm) : 2.0;
    so.mosaic.pixelSizeUm = geo.pixelUm;
    so.mosaic.imageName = QDir(dir).dirName().toStdString();
    so.mosaicPath = inv.isSet(QStringLiteral("no-mosaic")) ? std::string() : outPath.toStdString();
    // Registration and fusion take seconds on a real folder. They run beside the command,
    // which waits as every command does (spinUntil): inside the GUI the API runs commands
    // on its own thread, and the screens and other clients' calls go on meanwhile.
    auto job = std::async(std::launch::async, [&tiles, &so] { return imaging::stitch(tiles, so); });
    spinUntil([&job] { return job.wait_for(std::chrono::seconds(0)) == std::future_status::ready; }, std::numeric_limits<int>::max());
    auto result = job.get();  // at once, unless the wait was cut short (the server shutting down)
    if (!result)
        return inv.usage(ui::words::problems(result.problems()).join(QLatin1Char('\n')));

    // Fiji's registered TileConfiguration beside the images, as Fiji writes it; the report beside the mosaic.
    QString error;
    const QString registered = dir.filePath(QStringLiteral("TileConfiguration.registered.txt"));
    if (!saveText(registered, imaging::registeredTileConfiguration(*result), &error))
        return inv.refused(tr("cannot write %1: %2").arg(QDir::toNativeSeparators(registered), error));
    const double seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
    const std::string json = imaging::stitchJson(*result, seconds, so.mosaicPath.empty() ? std::string() : QFileInfo(outPath).fileName().toStdString());
    QString reportPath = outPath;
    reportPath.replace(QRegularExpression(QStringLiteral("(\\.ome)?\\.tiff?$"), QRegularExpression::CaseInsensitiveOption), QString());
    reportPath += QStringLiteral(".stitch.json");
    if (!saveText(reportPath, json + "\n", &error))
        return inv.refused(tr("cannot write %1: %2").arg(QDir::toNativeSeparators(reportPath), error));

    if (inv.json()) {
        inv.printJson(QJsonDocument::fromJson(QByteArray::fromStdString(json)).object());
        return Ok;
    }
    const imaging::Placement& p = result->placement;
    int accepted = 0, byStage = 0;
    for (const imaging::TilePair& pair : result->pairs)
        accepted += pair.reg.accepted();
    for (bool s : p.placedByStage)
        byStage += s;
    QTextStream& out = inv.out();
    out << tr("%1 tiles, %2 pairs: %3 trusted, %4 rejected as outliers, %5 not trusted; %6 tiles placed by the stage\n")
               .arg(tiles.size())
               .arg(result->pairs.size())
               .arg(accepted)
               .arg(p.rejectedPairs)
               .arg(static_cast<int>(result->pairs.size()) - accepted - p.rejectedPairs)
               .arg(byStage);
    out << tr("correction from the stage: RMS %1 px, worst %2 px\n").arg(p.rmsCorrectionPx, 0, 'f', 2).arg(p.worstCorrectionPx, 0, 'f', 2);
    if (p.stageModel.used)
        out << tr("stage model from %1 pairs: scale x %2 ppm, y %3 ppm, rotation %4 µrad, shear %5 µrad; beyond it RMS %6 px, worst %7 px\n")
                   .arg(p.stageModel.pairs)
                   .arg(p.stageModel.scaleXPpm(), 0, 'f', 0)
                   .arg(p.stageModel.scaleYPpm(), 0, 'f', 0)
                   .arg(p.stageModel.rotationUrad(), 0, 'f', 0)
                   .arg(p.stageModel.shearUrad(), 0, 'f', 0)
                   .arg(p.rmsBeyondModelPx, 0, 'f', 2)
                   .arg(p.worstBeyondModelPx, 0, 'f', 2);
    if (result->cameraCheck && result->planCamera)
        for (const motion::msg::Message& m : imaging::geometryAdvice(*result->cameraCheck, *result->planCamera))
            out << tr("warning: %1\n").arg(ui::words::text(m));
    if (!so.mosaicPath.empty())
        out << tr("wrote %1 (%2 × %3 px), %4 and %5 in %6 s\n")
                   .arg(QDir::toNativeSeparators(outPath))
                   .arg(result->frame.width)
                   .arg(result->frame.height)
                   .arg(QFileInfo(registered).fileName(), QFileInfo(reportPath).fileName())
                   .arg(seconds, 0, 'f', 1);
    out.flush();
    return Ok;
}

} // namespace

void addStitchCommands(std::vector<Command>& list)
{
    Command stitch{QStringLiteral("stitch"), tr("stitch a folder of tiles into a pyramidal OME-TIFF mosaic"), tr("DIR"),
                   tr("Registers every pair of neighbouring tiles over their expected overlap, places all tiles by weighted least "
                      "squares with the stage positions as priors, and fuses them (docs/stitching.md). Positions: the scan's run log "
                      "or TileConfiguration.txt in DIR, or --positions. Writes the mosaic (--out), TileConfiguration.registered.txt "
                      "in DIR and a .stitch.json report beside the mosaic."),
                   {option("positions", "TileConfiguration.txt (pixels) or scan-run.jsonl (mm) naming every tile image", "FILE"),
                    option("plan", "the scan plan: pixel size, rotation and image_y of its camera", "PLAN.json"),
                    option("pixel-um", "one pixel at the sample, µm", "P"),
                    option("rotation", "camera rotation against stage +X, degrees (with a run log)", "DEG"),
                    option("image-y", "image rows run along stage-minus-y or stage-plus-y (with a run log)", "AXIS"),
                    option("max-shift-px", "how far registration may move a tile from its stage position, px", "N", "40"),
                    option("repeatability-um", "the stage's repeatability (1σ), µm: the weight of its positions", "UM", "1"),
                    option("blend", "feather (linear in the overlaps) or overlay", "MODE", "feather"),
                    option("flat", "a blank image taken with the same light and exposure: every tile is divided by its shading", "TIFF"),
                    option("dark", "the camera's offset (a closed shutter's mean) under --flat, grey levels", "LEVEL", "0"),
                    option("out", "the mosaic file (default: DIR/mosaic.ome.tif)", "FILE"),
                    option("no-mosaic", "register and place only: the TileConfiguration and the report")},
                   stitchRun,
                   {}};
    stitch.api.access = Access::Compute;
    stitch.api.params = {{QStringLiteral("dir"), ParamType::File, tr("the folder of tiles"), true, {}, {}},
                         optionParam("positions", ParamType::File),
                         optionParam("plan", ParamType::File),
                         optionParam("pixel-um", ParamType::Number),
                         optionParam("rotation", ParamType::Number),
                         optionParam("max-shift-px", ParamType::Number),
                         optionParam("repeatability-um", ParamType::Number),
                         optionParam("flat", ParamType::File),
                         optionParam("dark", ParamType::Number),
                         optionParam("out", ParamType::File)};
    // The API's page runs this on the folder scan.run's example fills with the simulated
    // camera's images (scan.run comes first in the method list).
    stitch.api.example = QJsonObject{{QStringLiteral("dir"), QStringLiteral("slide-run")}, {QStringLiteral("plan"), QStringLiteral("slide.scan.json")}};
    list.push_back(stitch);
}

} // namespace app::cli
