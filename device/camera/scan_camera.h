#pragma once
// A camera taking a scan's tiles (dev::jobs::ScanTileCamera over any dev::camera::Camera): asks
// for the next frame started after the settle, with the plan's geometry; says when the
// exposure is over; writes the TIFF on its own writer thread (one at a time, in the order
// taken) while the stage moves on; hands back the file and its SHA-256.
//
// Threads: lives on the runner's thread (the GUI's, or the CLI's main thread); TIFF
// encoding, the disk write and the checksum run on m_writer; results come back queued.
#include "device/camera/camera.h"
#include "device/jobs/scan_tile_camera.h"

#include <QElapsedTimer>
#include <QHash>
#include <QPointer>
#include <QThreadPool>

namespace dev::camera {

/// The geometry a plan's camera gives the source: sensor size, pixel at the sample, rotation, image_y.
CameraGeometry geometryOfPlan(const motion::scan::ScanPlan& plan);

class ScanCamera : public dev::jobs::ScanTileCamera {
    Q_OBJECT
public:
    explicit ScanCamera(Camera* camera, QObject* parent = nullptr);
    ~ScanCamera() override;

    bool begin(const motion::scan::ScanPlan& plan, const std::string& folder, motion::msg::Message* error) override;
    void take(const dev::jobs::TileShot& shot) override;
    int pendingWrites() const override { return m_pending; }
    double overheadPerTileS() const override { return m_overheadS; }
    std::string sourceName() const override;

    Camera* camera() const { return m_camera; }

private:
    void onCaptured(std::uint64_t id, const Frame& frame);
    void onFailed(std::uint64_t id, const motion::msg::Problem& problem);

    struct InFlight {
        dev::jobs::TileShot shot;
        qint64 askedMs = 0;
    };

    QPointer<Camera> m_camera;
    CameraGeometry m_geometry;
    double m_exposureMs = 0;
    std::string m_folder;
    QHash<quint64, InFlight> m_inFlight;
    std::uint64_t m_nextId = 1;
    int m_pending = 0;
    double m_overheadS;        ///< the camera's time a tile beyond the exposure (a running average)
    QElapsedTimer m_clock;
    QThreadPool m_writer;      ///< one thread: files are written in the order taken
};

} // namespace dev::camera
