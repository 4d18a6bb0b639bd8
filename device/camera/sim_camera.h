#pragma once
// The simulated camera: renders what the objective sees at the simulated stage's TRUE work
// point (SimMachine::workPointLogical, not the grating's reading), so the stage's pitch and
// Abbe errors show in the images as they would under a real microscope.
//
// Threads: the object lives on the thread of the simulator it reads (the work point is read
// there, when a capture starts); rendering runs on the camera's own single worker thread and
// the result comes back as a queued call. The destructor waits for a render in flight.
#include "device/camera/camera.h"
#include "device/camera/sim_render.h"
#include "device/camera/sim_true_geometry.h"
#include "device/camera/specimen.h"

#include <QElapsedTimer>
#include <QThreadPool>
#include <QTimer>

#include <functional>
#include <future>
#include <memory>

namespace dev::camera {

struct SimCameraSettings {
    SpecimenKind specimen = SpecimenKind::Slide;
    std::uint64_t seed = 1;
    CameraGeometry geometry;      ///< outside a scan: 2048 × 2048 px, 0.65 µm a pixel, rotation 0
    SimOptics optics;
    double exposureMs = 10;
    double blurUm = 0.6;          ///< σ of the optics at the sample
    /// Where the camera truly differs from the geometry it is asked for (a plan's, or
    /// `geometry`): images are rendered with the truth, frames still report the pixel asked.
    SimTrueGeometry trueGeometry;
};

struct WorkPoint {
    double xMm = 0, yMm = 0;
    std::optional<std::uint64_t> deviceTimeUs;  ///< the simulator's clock
};
/// The true work point now; nullopt when there is no stage to look at (disconnected).
using WorkPointSource = std::function<std::optional<WorkPoint>()>;

class SimCamera : public Camera {
    Q_OBJECT
public:
    SimCamera(WorkPointSource workPoint, const SimCameraSettings& settings, QObject* parent = nullptr);
    ~SimCamera() override;

    QString source() const override { return QStringLiteral("sim"); }
    Capabilities capabilities() const override;
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void startLive() override;
    void stopLive() override;
    void setExposureMs(double ms) override;
    double exposureMs() const override { return m_settings.exposureMs; }
    void capture(const CaptureRequest& request) override;

    const SimCameraSettings& settings() const { return m_settings; }

private:
    void renderAsync(const WorkPoint& at, const CameraGeometry& geometry, std::uint64_t requestId, bool live);
    void scheduleLive();

    WorkPointSource m_workPoint;
    SimCameraSettings m_settings;
    std::shared_future<std::shared_ptr<const Specimen>> m_specimen;
    QThreadPool m_pool;   ///< one thread: renders in the order asked
    bool m_open = false;
    bool m_live = false;
    bool m_liveInFlight = false;
    bool m_liveWithoutStage = false;  ///< the live view found no stage: said once, looked for again
    std::uint64_t m_sequence = 0;
    QTimer m_liveTimer;
};

} // namespace dev::camera
