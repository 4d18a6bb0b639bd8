#include "device/camera/scan_camera.h"

#include "device/camera/tile_tiff.h"
#include "motion/plans/scan/scan_plan.h"

#include <QDir>

#include <cmath>

namespace dev::camera {

namespace {
/// A first guess at the camera's own time a tile, until tiles have been taken: a
/// simulated 2048² frame renders in tens of ms, a USB frame arrives within a frame period.
constexpr double kScanCameraFirstOverheadS = 0.03;
/// Weight of the newest tile in the running average.
constexpr double kScanCameraOverheadWeight = 0.2;
/// A frame one pixel larger or smaller than the plan's sensor is the same camera (sizes
/// rounded from a field in mm); more is another camera or another binning.
constexpr int kScanCameraSizeSlackPx = 1;
} // namespace

CameraGeometry geometryOfPlan(const motion::scan::ScanPlan& plan)
{
    const auto& c = plan.camera;
    CameraGeometry g;
    g.pixelUm = motion::scan::pixelAtSampleUm(c);
    if (c.source == motion::scan::FieldSource::Sensor) {
        g.sensorWidthPx = c.sensorWidthPx;
        g.sensorHeightPx = c.sensorHeightPx;
    } else {
        g.sensorWidthPx = static_cast<int>(std::lround(c.fieldWidthMm * 1e3 / g.pixelUm));
        g.sensorHeightPx = static_cast<int>(std::lround(c.fieldHeightMm * 1e3 / g.pixelUm));
    }
    g.rotationDeg = c.rotationDeg;
    g.imageYAlongMinusY = c.imageY == motion::scan::ImageY::StageMinusY;
    return g;
}

ScanCamera::ScanCamera(Camera* camera, QObject* parent)
    : dev::jobs::ScanTileCamera(parent), m_camera(camera), m_overheadS(kScanCameraFirstOverheadS)
{
    m_writer.setMaxThreadCount(1);
    m_clock.start();
    if (camera) {
        connect(camera, &Camera::captured, this, &ScanCamera::onCaptured);
        connect(camera, &Camera::failed, this, &ScanCamera::onFailed);
    }
}

ScanCamera::~ScanCamera() { m_writer.waitForDone(); }

std::string ScanCamera::sourceName() const { return m_camera ? m_camera->source().toStdString() : std::string("?"); }

bool ScanCamera::begin(const motion::scan::ScanPlan& plan, const std::string& folder, motion::msg::Message* error)
{
    if (!m_camera) {
        *error = motion::msg::make("camera.none");
        return false;
    }
    m_geometry = geometryOfPlan(plan);
    m_folder = folder;
    m_exposureMs = plan.exposureS * 1e3;
    // The plan's exposure, where the source lets BenchPilot set it.
    if (m_camera->capabilities().exposure)
        m_camera->setExposureMs(m_exposureMs);
    if (!m_camera->isOpen())
        m_camera->open();
    return true;
}

void ScanCamera::take(const dev::jobs::TileShot& shot)
{
    if (!m_camera) {
        emit failed(shot.tile, motion::msg::make("camera.none"));
        return;
    }
    CaptureRequest req;
    req.id = m_nextId++;
    req.tile = shot.tile;
    if (shot.measuredMm.size() == 2) {
        req.xMm = shot.measuredMm[0];
        req.yMm = shot.measuredMm[1];
    }
    req.fileHint = QDir(QString::fromStdString(m_folder)).filePath(QString::fromStdString(shot.file)).toStdString();
    req.geometry = m_geometry;
    m_inFlight.insert(req.id, InFlight{shot, m_clock.elapsed()});
    m_camera->capture(req);
}

void ScanCamera::onFailed(std::uint64_t id, const motion::msg::Problem& problem)
{
    const auto it = m_inFlight.find(id);
    if (it == m_inFlight.end())
        return;  // not ours (a live frame, a snap)
    const int tile = it->shot.tile;
    m_inFlight.erase(it);
    emit failed(tile, problem.message);
}

void ScanCamera::onCaptured(std::uint64_t id, const Frame& captured)
{
    const auto it = m_inFlight.find(id);
    if (it == m_inFlight.end())
        return;
    const InFlight job = *it;
    m_inFlight.erase(it);
    const int tile = job.shot.tile;
    const double tookS = static_cast<double>(m_clock.elapsed() - job.askedMs) / 1e3;
    m_overheadS += kScanCameraOverheadWeight * (std::max(0.0, tookS - m_exposureMs / 1e3) - m_overheadS);
    // A camera whose frames are not the plan's sensor would put every tile in the wrong place.
    if (std::abs(captured.width - m_geometry.sensorWidthPx) > kScanCameraSizeSlackPx
        || std::abs(captured.height - m_geometry.sensorHeightPx) > kScanCameraSizeSlackPx) {
        emit failed(tile, motion::msg::make("camera.sensor_mismatch", {motion::msg::verbatim("camera", sourceName()),
                                                               motion::msg::integer("width", captured.width, motion::msg::Unit::None),
                                                               motion::msg::integer("height", captured.height, motion::msg::Unit::None),
                                                               motion::msg::integer("plan_width", m_geometry.sensorWidthPx, motion::msg::Unit::None),
                                                               motion::msg::integer("plan_height", m_geometry.sensorHeightPx, motion::msg::Unit::None)}));
        return;
    }
    // Counted before exposed(): the runner decides on it whether the run can finish.
    ++m_pending;
    emit exposed(tile);
    Frame frame = captured;
    if (frame.pixelUm <= 0)
        frame.pixelUm = m_geometry.pixelUm;
    TileMetadata meta;
    meta.tile = tile;
    meta.label = job.shot.file;
    meta.measuredMm = job.shot.measuredMm;
    meta.deviceTimeUs = frame.deviceTimeUs ? frame.deviceTimeUs : std::optional<std::uint64_t>(job.shot.deviceTimeUs);
    meta.source = sourceName();
    const std::string path = QDir(QString::fromStdString(m_folder)).filePath(QString::fromStdString(job.shot.file)).toStdString();
    const std::string file = job.shot.file;
    const std::optional<std::uint64_t> frameTime = captured.deviceTimeUs;
    m_writer.start([this, frame = std::move(frame), meta, path, file, tile, frameTime] {
        std::string sha;
        motion::msg::Message error;
        const bool ok = writeTileTiff(path, frame, meta, &sha, &error);
        // Back on the runner's thread; the destructor waits for this task.
        QMetaObject::invokeMethod(this, [this, ok, sha, error, file, tile, frameTime] {
            --m_pending;
            if (ok)
                emit written(tile, dev::jobs::TileImage{file, sha, frameTime});
            else
                emit failed(tile, error);
        }, Qt::QueuedConnection);
    });
}

} // namespace dev::camera
