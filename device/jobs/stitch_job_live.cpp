// The stitch job's live side: following a camera scan as it runs (stitch_job.h). Runs on
// the job's (GUI) thread; registration runs on the live stitcher's worker, the placement
// and the files on a thread of their own, as a folder's stitch does.
#include "device/jobs/stitch_job.h"

#include "device/files/scan_exports.h"
#include "device/jobs/scan_runner.h"
#include "imaging/live_stitch.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <thread>

namespace dev::jobs {

struct StitchJob::Live {
    std::shared_ptr<imaging::LiveStitcher> stitcher;
    imaging::StitchOptions options;
    QString folder, mosaic;
};

void StitchJob::follow(ScanRunner* runner, std::function<StitchRequest()> request)
{
    m_runner = runner;
    m_liveRequest = std::move(request);
    connect(runner, &ScanRunner::stateChanged, this, &StitchJob::onScanState);
    connect(runner, &ScanRunner::tileTaken, this, &StitchJob::onScanTile);
    connect(runner, &ScanRunner::finished, this, &StitchJob::onScanFinished);
}

QPointF StitchJob::measuredPx(int tile) const
{
    const motion::scan::ScanPlan& plan = m_runner->plan();
    const motion::scan::Point2 mm = dev::files::scan::stitchPosition(plan, m_runner->records().at(static_cast<std::size_t>(tile)));
    const motion::scan::Point2 px = dev::files::scan::stageToPixels(plan.camera, mm);
    return {px.xMm, px.yMm};  // Point2 holds pixels here
}

void StitchJob::onScanState()
{
    using S = ScanRunner::State;
    const S st = m_runner->state();
    if (st == S::Stopped || st == S::Idle) {
        dropLive();  // a stop writes nothing; a resume begins again from the folder
        return;
    }
    // Pausing and Paused: the live stitch waits with the scan; Finished: onScanFinished.
    if (st != S::Running || m_live || m_running || !m_runner->camera())
        return;
    const motion::scan::ScanPlan& plan = m_runner->plan();
    const double pixelUm = motion::scan::pixelAtSampleUm(plan.camera);
    const int total = m_runner->totalTiles();
    if (!(pixelUm > 0) || total <= 0)
        return;
    StitchRequest request = m_liveRequest ? m_liveRequest() : StitchRequest{};
    request.folder = m_runner->folder();
    request.plan = plan;
    auto live = std::make_shared<Live>();
    live->options = optionsFor(plan, request.folder, request, pixelUm);
    live->folder = request.folder;
    live->mosaic = QString::fromStdString(live->options.mosaicPath);
    const QDir dir(request.folder);
    std::vector<imaging::StitchTile> planned;
    m_livePlannedPx.clear();
    for (int t = 0; t < total; ++t) {
        const motion::PositionRecord& r = m_runner->records().at(static_cast<std::size_t>(t));
        const std::string file = m_runner->image(t).file.empty() ? r.label : m_runner->image(t).file;
        const motion::scan::Point2 px = dev::files::scan::stageToPixels(plan.camera, {r.plannedMm.at(0), r.plannedMm.at(1)});
        planned.push_back({file, dir.filePath(QString::fromStdString(file)).toStdString(), Eigen::Vector2d(px.xMm, px.yMm)});
        m_livePlannedPx.emplace_back(px.xMm, px.yMm);
    }
    if (!request.flatPath.isEmpty()) {
        // A flat-field that cannot be read stitches nothing live; Stitch then says why.
        auto flat = imaging::FlatField::fromFile(request.flatPath.toStdString(), request.darkLevel, QFileInfo(request.flatPath).fileName().toStdString());
        if (!flat)
            return;
        live->options.flatField = std::make_shared<const imaging::FlatField>(flat.take());
    }
    imaging::LiveStitchOptions lo;
    lo.flatField = live->options.flatField;
    lo.registration = live->options.registration;
    lo.placement = live->options.placement;
    lo.memoryMegabytes = live->options.cacheMegabytes;
    lo.planCamera = live->options.planCamera;  // the camera check at the end, as Stitch makes it
    // The events come on the stitcher's worker; they are handed to this thread, and let
    // be there when the live stitch they belong to was dropped meanwhile.
    const std::shared_ptr<Shared> shared = m_shared;
    const int session = ++m_liveSession;
    imaging::LiveStitchEvents events;
    events.tileRead = [shared, session](int tile, int w, int h, std::shared_ptr<const imaging::ImageU16> thumbnail) {
        QMetaObject::invokeMethod(QCoreApplication::instance(), [shared, session, tile, w, h, thumbnail] {
            StitchJob* job = shared->owner;
            if (!job || job->m_liveSession != session)
                return;
            ++job->m_liveTilesRead;
            emit job->liveTile(tile, job->measuredPx(tile), QSize(w, h), thumbnail);
        }, Qt::QueuedConnection);
    };
    events.pairRegistered = [shared, session](const imaging::TilePair& pair) {
        QMetaObject::invokeMethod(QCoreApplication::instance(), [shared, session, pair] {
            StitchJob* job = shared->owner;
            if (job && job->m_liveSession == session)
                emit job->livePair(pair);
        }, Qt::QueuedConnection);
    };
    live->stitcher = std::make_shared<imaging::LiveStitcher>(std::move(planned), lo, std::move(events));
    m_live = live;
    m_liveTilesRead = 0;
    m_folder = request.folder;
    m_pixelUm = pixelUm;
    m_tileCount = total;
    emit liveStarted();
    // A resumed scan: the tiles taken before are read back from the folder.
    for (int t = 0; t < total; ++t)
        if (m_runner->isTaken(t)) {
            const QPointF px = measuredPx(t);
            live->stitcher->add(t, Eigen::Vector2d(px.x(), px.y()));
        }
}

void StitchJob::onScanTile(int tile)
{
    if (!m_live)
        return;
    // Only its position here: the worker reads the image the camera has just written.
    const QPointF px = measuredPx(tile);
    m_live->stitcher->add(tile, Eigen::Vector2d(px.x(), px.y()));
}

void StitchJob::onScanFinished()
{
    if (!m_live)
        return;
    if (m_runner->takenTiles() < m_runner->totalTiles()) {
        dropLive();
        return;
    }
    const std::shared_ptr<Live> live = std::move(m_live);
    m_live.reset();
    m_running = true;
    m_lastWasLive = true;
    QElapsedTimer clock;
    clock.start();
    std::thread([shared = m_shared, live, clock] {
        motion::msg::Checked<imaging::StitchResult> result = live->stitcher->finish();
        const double placedS = static_cast<double>(clock.nsecsElapsed()) / 1e9;
        if (result) {
            motion::msg::Problems fused = imaging::writeMosaic(*result, live->options);
            if (motion::msg::hasErrors(fused))
                result = motion::msg::Checked<imaging::StitchResult>::refused(std::move(fused));
        }
        complete(shared, std::move(result), live->folder, live->mosaic, clock, placedS);
    }).detach();
}

void StitchJob::dropLive()
{
    if (!m_live)
        return;
    ++m_liveSession;
    std::shared_ptr<Live> live = std::move(m_live);
    m_live.reset();
    live->stitcher->cancel();
    // Its worker may be inside one registration: it is waited for on a thread of its own.
    std::thread([gone = std::move(live)]() mutable { gone.reset(); }).detach();
    if (m_shared->owner)
        emit liveDropped();
}

} // namespace dev::jobs
