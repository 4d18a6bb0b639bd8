#include "device/jobs/stitch_job.h"

#include "device/files/scan_exports.h"
#include "device/files/scan_run_log.h"
#include "device/files/stitch_positions.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <thread>

namespace dev::jobs {

namespace {

motion::msg::Problems oneProblem(motion::msg::Message m) { return {motion::msg::Problem("", std::move(m))}; }

bool saveText(const QString& path, const std::string& text, motion::msg::Message* error)
{
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly) && f.write(text.data(), static_cast<qint64>(text.size())) == static_cast<qint64>(text.size()) && f.commit())
        return true;
    *error = motion::msg::make("scan.stitch.cannot_write", {motion::msg::verbatim("file", QDir::toNativeSeparators(path).toStdString()),
                                                           motion::msg::verbatim("detail", f.errorString().toStdString())});
    return false;
}

} // namespace

StitchJob::StitchJob(QObject* parent) : QObject(parent), m_shared(std::make_shared<Shared>()) { m_shared->owner = this; }

StitchJob::~StitchJob()
{
    m_shared->owner = nullptr;
    dropLive();
}

bool StitchJob::start(const StitchRequest& request, motion::msg::Message* error)
{
    if (m_running || m_live) {
        *error = motion::msg::make("scan.stitch.running");
        return false;
    }
    const QDir dir(request.folder);
    const QString logPath = dir.filePath(QLatin1String(dev::files::scan::kRunLogFile));
    QFile log(logPath);
    if (!log.open(QIODevice::ReadOnly)) {
        *error = motion::msg::make("scan.stitch.no_run_log", {motion::msg::verbatim("folder", QDir::toNativeSeparators(request.folder).toStdString())});
        return false;
    }
    const QByteArray text = log.readAll();
    auto taken = dev::files::scan::parseTakenTiles(std::string_view(text.constData(), static_cast<std::size_t>(text.size())),
                                                    dev::files::scan::kRunLogFile);
    if (!taken) {
        *error = taken.error();
        return false;
    }
    const double pixelUm = motion::scan::pixelAtSampleUm(request.plan.camera);
    if (taken->empty() || !(pixelUm > 0)) {
        *error = motion::msg::make("scan.stitch.no_images", {motion::msg::verbatim("folder", QDir::toNativeSeparators(request.folder).toStdString())});
        return false;
    }
    std::vector<imaging::StitchTile> tiles;
    for (const dev::files::scan::TakenTile& t : *taken) {
        const QString path = dir.filePath(QString::fromStdString(t.image));
        if (!QFileInfo::exists(path)) {
            *error = motion::msg::make("scan.stitch.image_missing", {motion::msg::verbatim("file", t.image), motion::msg::integer("tile", t.tile + 1, motion::msg::Unit::None)});
            return false;
        }
        const motion::scan::Point2 px = dev::files::scan::stageToPixels(request.plan.camera, {t.measuredXMm, t.measuredYMm});
        tiles.push_back({t.image, path.toStdString(), Eigen::Vector2d(px.xMm, px.yMm)});  // Point2 holds pixels here
    }

    m_running = true;
    m_tileCount = static_cast<int>(tiles.size());
    m_pixelUm = pixelUm;
    m_folder = request.folder;
    m_lastWasLive = false;
    imaging::StitchOptions so = optionsFor(request.plan, request.folder, request, pixelUm);
    const std::shared_ptr<Shared> shared = m_shared;
    const QString folder = request.folder;
    const QString mosaic = QString::fromStdString(so.mosaicPath);
    // A thread of its own, detached: the job object may go (its window closed) while a
    // folder stitches; the result is then dropped, and the files are whole either way.
    const QString flatPath = request.flatPath;
    const double dark = request.darkLevel;
    std::thread([shared, tiles = std::move(tiles), so = std::move(so), folder, mosaic, flatPath, dark]() mutable {
        QElapsedTimer clock;
        clock.start();
        auto result = [&]() -> motion::msg::Checked<imaging::StitchResult> {
            if (!flatPath.isEmpty()) {
                auto flat = imaging::FlatField::fromFile(flatPath.toStdString(), dark, QFileInfo(flatPath).fileName().toStdString());
                if (!flat)
                    return motion::msg::Checked<imaging::StitchResult>::refused(flat.problems());
                so.flatField = std::make_shared<const imaging::FlatField>(flat.take());
            }
            return imaging::stitch(tiles, so);
        }();
        complete(shared, std::move(result), folder, mosaic, clock, 0);
    }).detach();
    return true;
}

imaging::StitchOptions StitchJob::optionsFor(const motion::scan::ScanPlan& plan, const QString& folder, const StitchRequest& request, double pixelUm)
{
    const QDir dir(folder);
    imaging::StitchOptions so;
    so.placement.stageSigmaPx = std::max(0.1, request.repeatabilityUm / pixelUm);
    so.mosaic.pixelSizeUm = pixelUm;
    so.planCamera = imaging::PlanCameraGeometry{pixelUm, request.plan.camera.rotationDeg, request.plan.camera.imageY == motion::scan::ImageY::StagePlusY};
    so.mosaic.imageName = dir.dirName().toStdString();
    so.mosaicPath = dir.filePath(request.mosaicName).toStdString();
    const motion::scan::Camera camera = plan.camera;
    so.stageMmAt = [camera, pixelUm](const Eigen::Vector2d& p) -> std::optional<Eigen::Vector2d> {
        // The inverse of stageToPixels: its axes are orthonormal, so the transpose.
        const motion::scan::Point2 ex = dev::files::scan::stageToPixels(camera, {1, 0});
        const motion::scan::Point2 ey = dev::files::scan::stageToPixels(camera, {0, 1});
        const double s = pixelUm * pixelUm / 1e6;  // each column is (1000 / pixelUm) long
        return Eigen::Vector2d((p.x() * ex.xMm + p.y() * ex.yMm) * s, (p.x() * ey.xMm + p.y() * ey.yMm) * s);
    };
    return so;
}

void StitchJob::complete(const std::shared_ptr<Shared>& shared, motion::msg::Checked<imaging::StitchResult> result, const QString& folder,
                         const QString& mosaic, const QElapsedTimer& clock, double placedS)
{
    // `clock` started when the work began (the live stitch: at the last tile); the
    // report's seconds count from there.
    QStringList written;
    motion::msg::Problems problems = result.problems();
    if (result) {
        motion::msg::Message writeError;
        const QString registered = QDir(folder).filePath(QStringLiteral("TileConfiguration.registered.txt"));
        QString report = mosaic;
        report.chop(mosaic.endsWith(QLatin1String(".ome.tif")) ? 8 : 0);
        report += QStringLiteral(".stitch.json");
        const double seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
        if (saveText(registered, imaging::registeredTileConfiguration(*result), &writeError)
            && saveText(report, imaging::stitchJson(*result, seconds, QFileInfo(mosaic).fileName().toStdString()) + "\n", &writeError))
            written = {mosaic, registered, report};
        else
            problems = oneProblem(writeError);
    }
    const double seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
    auto out = std::make_shared<motion::msg::Checked<imaging::StitchResult>>(std::move(result));
    // Handed back through the application object, which outlives every job; whether
    // the job is still there is asked on its own thread.
    QMetaObject::invokeMethod(QCoreApplication::instance(), [shared, out, written, problems, seconds, placedS] {
        StitchJob* job = shared->owner;
        if (!job)
            return;
        job->m_running = false;
        job->m_seconds = seconds;
        job->m_livePlacedAfterS = placedS;
        if (*out && !written.isEmpty()) {
            job->m_result = out->take();
            job->m_written = written;
            emit job->finished();
        } else {
            emit job->failed(problems);
        }
    }, Qt::QueuedConnection);
}

} // namespace dev::jobs
