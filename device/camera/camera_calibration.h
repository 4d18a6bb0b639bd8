#pragma once
// Camera–stage calibration as a job: from where the stage stands, it moves by known steps
// along X and Y (±1 … ±N steps each way), takes an image at each, registers it against
// the image taken at the start (imaging/registration.h, expecting no shift and searching
// as far as the steps reach, so a turned or mirrored camera is found as well as a square
// one), comes back to the start for one more image (what the stage did not return shows
// as the return shift), and fits the camera–stage mapping (imaging/camera_stage_fit.h)
// from the grating's measured steps.
//
// It refuses to start unless the stage is connected, homed and every step lies inside the
// soft limits; it stops cleanly (the stage stopped, a message saying why) on Stop, a lost
// link, a stage event (E-stop, limit, fault) or a camera failure, and never moves after.
//
// Threads: the object lives on the instrument's thread (the GUI's or the CLI's); each
// registration runs on the job's own worker and comes back as a queued call.
#include "device/camera/camera.h"
#include "device/client/instrument.h"
#include "device/files/camera/camera_profile_file.h"
#include "device/jobs/arrival_by_status.h"
#include "imaging/camera_stage_fit.h"
#include "imaging/image.h"
#include "imaging/registration.h"

#include <QObject>
#include <QPointer>
#include <QThreadPool>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace dev::camera {

struct CalibrationOptions {
    double stepPx = 100;        ///< one step, in the camera's nominal pixels
    int stepsEachWay = 2;       ///< ±1 … ±N steps along X and along Y
    double nominalPixelUm = 0;  ///< 0: the first frame's own pixel size
    double speedMmS = 0;        ///< 0: the stage's default
    double moveTimeoutS = 60;   ///< a move not done by then stops the job
    double captureTimeoutS = 30;  ///< beyond the exposure
};

struct CalibrationStep {
    Eigen::Vector2d stageUm{0, 0};  ///< the grating's measured step from the start
    Eigen::Vector2d shiftPx{0, 0};  ///< registered image shift
    double ncc = 0;
    bool registered = false;
};

struct CalibrationResult {
    imaging::CameraStageFit fit;
    std::vector<CalibrationStep> steps;
    double nominalPixelUm = 0;
    double stepUm = 0;           ///< the largest step
    double returnPx = 0;         ///< the image back at the start against the first
    int widthPx = 0, heightPx = 0;
    std::string camera;          ///< the source's name
};

class CameraCalibration : public QObject {
    Q_OBJECT
public:
    CameraCalibration(dev::Instrument* stage, Camera* camera, QObject* parent = nullptr);
    ~CameraCalibration() override;

    /// What keeps the job from starting now (camera.calibration.*): empty = ready. The steps
    /// are checked against the soft limits once the pixel size is known (the first frame).
    std::vector<motion::msg::Message> preflight(const CalibrationOptions& options) const;
    bool start(const CalibrationOptions& options, motion::msg::Message* error);
    /// Stops the stage and the job (failed with camera.calibration.stopped).
    void stop();
    bool isRunning() const { return m_running; }
    /// Images in all: the start, 4 × stepsEachWay steps, the return.
    static int imagesFor(const CalibrationOptions& o) { return 2 + 4 * o.stepsEachWay; }

signals:
    void progress(int imagesTaken, int imagesTotal);
    void finished(const dev::camera::CalibrationResult& result);
    void failed(const motion::msg::Message& why);

private:
    enum class Phase { Idle, Moving, Settling, Capturing, Registering };

    void fail(const motion::msg::Message& why, bool stopStage);
    void planSteps();
    void moveTo(int index);  ///< index into m_targetsMm; the last one is the start again
    void onArrived();
    void capture();
    void onFrame(const Frame& frame);
    void onRegistered(int index, const imaging::PairRegistration& reg);
    void finish();

    QPointer<dev::Instrument> m_stage;
    QPointer<Camera> m_camera;
    CalibrationOptions m_options;
    bool m_running = false;
    Phase m_phase = Phase::Idle;
    Eigen::Vector2d m_startMm{0, 0};        ///< commanded, where the job returns
    Eigen::Vector2d m_startMeasuredMm{0, 0};
    Eigen::Vector2d m_measuredMm{0, 0};     ///< at the image being taken
    std::vector<Eigen::Vector2d> m_targetsMm;  ///< the steps, then the start
    int m_index = -1;                        ///< −1: the start image
    unsigned m_waitingAxes = 0;
    bool m_moveAccepted = false;
    dev::jobs::ArrivalByStatus m_arrival;
    std::uint64_t m_requestId = 0;
    std::shared_ptr<const imaging::ImageF> m_reference;
    CalibrationResult m_result;
    int m_imagesTaken = 0;
    QTimer m_watchdog;
    QThreadPool m_pool;  ///< one thread: registrations in order
    QList<QMetaObject::Connection> m_links;
};

/// The camera profile a calibration gives, rounded to what the fit can know; `whenIso`
/// is the calibration's time (ISO 8601 UTC).
dev::files::camera::CameraProfile profileOf(const CalibrationResult& r, const std::string& whenIso);

/// A frame's grey values as a float image (RGB averaged).
imaging::ImageF frameToGrey(const Frame& frame);

} // namespace dev::camera

Q_DECLARE_METATYPE(dev::camera::CalibrationResult)
