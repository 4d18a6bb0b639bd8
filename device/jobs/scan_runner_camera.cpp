// The scan runner's camera: a tile taken by a camera instead of a dwell, its image written
// while the stage moves on, and a resumed run's images checked (scan_runner.h).
#include "device/jobs/scan_runner.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>

#include <cmath>

namespace dev::jobs {

namespace {
/// A camera that has not ended an exposure this long after its end stops the run: a hung
/// source must not hold the stage at one tile for ever. Sources with their own timeout
/// (a command, a folder) report theirs first.
constexpr double kScanCameraGraceS = 60.0;
constexpr double kScanCameraMsPerS = 1e3;
} // namespace

void ScanRunner::setCamera(ScanTileCamera* camera)
{
    for (const auto& c : m_cameraConnections)
        disconnect(c);
    m_cameraConnections.clear();
    m_camera = camera;
    if (!camera)
        return;
    m_cameraTimeout.setSingleShot(true);
    m_cameraConnections << connect(camera, &ScanTileCamera::exposed, this, &ScanRunner::onCameraExposed)
                        << connect(camera, &ScanTileCamera::written, this, &ScanRunner::onImageWritten)
                        << connect(camera, &ScanTileCamera::failed, this, &ScanRunner::onCameraFailed)
                        << connect(&m_cameraTimeout, &QTimer::timeout, this, [this] {
                               if (m_phase != Phase::Exposing)
                                   return;
                               onCameraFailed(currentTile(), motion::msg::make("scan.run.camera_silent",
                                                                       {motion::msg::verbatim("camera", m_camera ? m_camera->sourceName() : std::string()),
                                                                        motion::msg::real("seconds", kScanCameraGraceS, motion::msg::Unit::S)}));
                           });
}

void ScanRunner::addCameraTimeToEstimate()
{
    if (!m_camera)
        return;
    // Each tile costs the camera's own time on top of the exposure, in visiting order.
    const double extra = m_camera->overheadPerTileS();
    int seen = 0;
    for (const auto& w : m_layout.path) {
        if (w.tile < 0)
            continue;
        ++seen;
        if (static_cast<std::size_t>(w.tile) < m_estimate.tileDoneS.size())
            m_estimate.tileDoneS[static_cast<std::size_t>(w.tile)] += extra * seen;
    }
    m_estimate.totalS += extra * seen;
    m_estimate.exposureS += extra * seen;
}

bool ScanRunner::imageIntact(const dev::files::scan::TileImageRef& image) const
{
    if (image.file.empty())
        return false;
    QFile file(QDir(m_folder).filePath(QString::fromStdString(image.file)));
    if (!file.open(QIODevice::ReadOnly))
        return false;
    QCryptographicHash hash(QCryptographicHash::Sha256);
    return hash.addData(&file) && hash.result().toHex().toStdString() == image.sha256;
}

void ScanRunner::takeWithCamera(int tile)
{
    TileShot shot;
    shot.tile = tile;
    shot.file = m_records[static_cast<std::size_t>(tile)].label;
    shot.measuredMm = m_triggerMm;
    shot.deviceTimeUs = m_triggerUs;
    m_cameraTimeout.start(static_cast<int>(std::lround((m_plan.exposureS + kScanCameraGraceS) * kScanCameraMsPerS)));
    m_camera->take(shot);
}

void ScanRunner::onCameraExposed(int tile)
{
    if (m_phase != Phase::Exposing || tile != currentTile())
        return;  // an exposure that ended after a stop: its tile is not recorded
    m_cameraTimeout.stop();
    motion::PositionRecord& r = m_records[static_cast<std::size_t>(tile)];
    r.measuredMm = m_triggerMm;
    r.deviceTimeUs = m_triggerUs;
    r.settleS = m_triggerUs > m_motionDoneUs ? static_cast<double>(m_triggerUs - m_motionDoneUs) * 1e-6 : 0.0;
    if (m_sessionFirstTile < 0)
        m_sessionFirstTile = tile;
    // The stage may move: the image is written meanwhile, and logged once it is whole.
    m_phase = Phase::None;
    ++m_pathIndex;
    nextWaypoint();
}

void ScanRunner::onImageWritten(int tile, const TileImage& image)
{
    if (tile < 0 || tile >= totalTiles())
        return;
    motion::PositionRecord& r = m_records[static_cast<std::size_t>(tile)];
    if (!r.measured() || m_taken[static_cast<std::size_t>(tile)])
        return;  // exposed after a stop, or already logged: never twice
    const dev::files::scan::TileImageRef ref{image.file, image.sha256};
    motion::msg::Message error;
    if (!appendLog(dev::files::scan::runLogLine(r, ref), &error)) {
        r.measuredMm.clear();
        stopWith(motion::msg::make("scan.run.log_failed", {motion::msg::nested("cause", error)}), true);
        return;
    }
    m_images[static_cast<std::size_t>(tile)] = ref;
    m_taken[static_cast<std::size_t>(tile)] = 1;
    ++m_takenCount;
    emit tileTaken(tile);
    emit progress(m_takenCount, totalTiles(), etaS());
    if (m_finishWhenWritten && m_camera && m_camera->pendingWrites() == 0)
        finishRun();
}

void ScanRunner::onCameraFailed(int tile, const motion::msg::Message& reason)
{
    if (tile >= 0 && tile < totalTiles() && !m_taken[static_cast<std::size_t>(tile)])
        m_records[static_cast<std::size_t>(tile)].measuredMm.clear();
    // Whatever the stage is doing (settled at this tile, or on its way to the next while
    // the image was being written), the run stops here; every tile logged stays.
    if (m_state == State::Stopped) {
        emit problem(motion::msg::make("scan.run.camera_failed", {tileArg(tile), motion::msg::nested("cause", reason)}));
        return;
    }
    stopWith(motion::msg::make("scan.run.camera_failed", {tileArg(tile), motion::msg::nested("cause", reason)}), true);
}

} // namespace dev::jobs
