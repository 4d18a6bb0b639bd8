#include "device/camera/camera_calibration.h"

#include "device/protocol/messages.h"
#include "imaging/registration.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace dev::camera {

namespace {

namespace msg = motion::msg;

constexpr double kCalUmPerMm = 1000.0;
/// A registration whose answer lies this close to the search bound is at the bound;
/// the search reaches half as far again as the longest step, and 20 px beyond.
constexpr double kCalSearchReach = 1.5;
constexpr double kCalSearchMarginPx = 20;

msg::Arg calAxis(int axis) { return msg::verbatim("axis", axis == 0 ? "X" : "Y"); }

} // namespace

imaging::ImageF frameToGrey(const Frame& f)
{
    imaging::ImageF out;
    if (f.isEmpty())
        return out;
    out.width = f.width;
    out.height = f.height;
    const std::size_t n = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height);
    out.px.resize(n);
    const std::size_t bpp = static_cast<std::size_t>(bytesPerPixel(f.format));
    if (f.pixels.size() < n * bpp) {
        out = {};
        return out;
    }
    const std::uint8_t* p = f.pixels.data();
    for (std::size_t i = 0; i < n; ++i) {
        switch (f.format) {
        case PixelFormat::Grey8: out.px[i] = p[i]; break;
        case PixelFormat::Grey16: {
            std::uint16_t v;
            std::memcpy(&v, p + 2 * i, 2);
            out.px[i] = v;
            break;
        }
        case PixelFormat::Rgb8: out.px[i] = (static_cast<float>(p[3 * i]) + p[3 * i + 1] + p[3 * i + 2]) / 3.0f; break;
        }
    }
    return out;
}

dev::files::camera::CameraProfile profileOf(const CalibrationResult& r, const std::string& whenIso)
{
    // By the whole number of units in one, so the file shows 0.69919, not 0.6991900000000001.
    const auto round = [](double v, double unit) { return std::round(v / unit) / std::round(1 / unit); };
    const imaging::CameraStageFit& f = r.fit;
    dev::files::camera::CameraProfile p;
    p.camera = r.camera;
    p.sensorWidthPx = r.widthPx;
    p.sensorHeightPx = r.heightPx;
    // As many digits as the fit can know: 1e-5 µm a pixel is 0.03 px across 2048 px.
    p.pixelXUm = round(f.pixelXUm, 1e-5);
    p.pixelYUm = round(f.pixelYUm, 1e-5);
    p.rotationDeg = round(f.rotationDeg, 1e-3);
    p.imageYAlongPlusY = f.imageYAlongPlusY;
    p.calibrated = true;
    p.calibration.when = whenIso;
    p.calibration.images = static_cast<int>(r.steps.size()) + 1;
    p.calibration.stepUm = round(r.stepUm, 1e-3);
    p.calibration.residualRmsPx = round(f.residualRmsPx, 1e-3);
    p.calibration.residualMaxPx = round(f.residualMaxPx, 1e-3);
    p.calibration.skewDeg = round(f.skewDeg, 1e-3);
    p.calibration.returnPx = std::isfinite(r.returnPx) ? round(r.returnPx, 1e-3) : 0;
    return p;
}

CameraCalibration::CameraCalibration(dev::Instrument* stage, Camera* camera, QObject* parent)
    : QObject(parent), m_stage(stage), m_camera(camera)
{
    qRegisterMetaType<dev::camera::CalibrationResult>();
    m_pool.setMaxThreadCount(1);
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, [this] {
        const double s = m_phase == Phase::Capturing ? m_options.captureTimeoutS : m_options.moveTimeoutS;
        fail(msg::make(m_phase == Phase::Capturing ? "camera.calibration.no_image" : "camera.calibration.move_timeout",
                       {msg::real("seconds", s, msg::Unit::S)}),
             true);
    });
    if (m_stage) {
        m_links << connect(m_stage, &dev::Instrument::eventReceived, this, [this](const dev::DeviceEvent& e) {
            if (!m_running || e.axis > 1)
                return;
            using dev::proto::EventKind;
            switch (e.kind) {
            case EventKind::MotionDone:
                if (m_phase != Phase::Moving || e.axis < 0)
                    return;
                m_waitingAxes &= ~(1u << e.axis);
                if (!m_waitingAxes)
                    onArrived();
                return;
            case EventKind::EStop:
            case EventKind::Stopped:
            case EventKind::LimitHit:
            case EventKind::Fault:
            case EventKind::LostSteps:
                fail(msg::make("camera.calibration.stage_event", {msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e)}),
                     e.kind != EventKind::EStop);
                return;
            default:
                return;
            }
        });
        m_links << connect(m_stage, &dev::Instrument::statusChanged, this, [this](const dev::InstrumentStatus& s) {
            if (m_running && m_phase == Phase::Moving && m_moveAccepted && m_arrival.feed(s))
                onArrived();
        });
        m_links << connect(m_stage, &dev::Instrument::stateChanged, this, [this](dev::LinkState st) {
            if (m_running && st != dev::LinkState::Ready)
                fail(msg::make("camera.calibration.link_lost"), false);
        });
    }
    if (m_camera) {
        m_links << connect(m_camera, &Camera::captured, this, [this](std::uint64_t id, const Frame& f) {
            if (m_running && m_phase == Phase::Capturing && id == m_requestId)
                onFrame(f);
        });
        m_links << connect(m_camera, &Camera::failed, this, [this](std::uint64_t id, const motion::msg::Problem& p) {
            if (m_running && (id == 0 || id == m_requestId))
                fail(msg::make("camera.calibration.camera_failed", {msg::nested("cause", p.message)}), true);
        });
    }
}

CameraCalibration::~CameraCalibration()
{
    for (const auto& c : m_links)
        disconnect(c);
    m_pool.waitForDone();
}

std::vector<msg::Message> CameraCalibration::preflight(const CalibrationOptions& o) const
{
    std::vector<msg::Message> out;
    if (m_running)
        out.push_back(msg::make("camera.calibration.already_running"));
    if (!m_stage || !m_stage->isReady()) {
        out.push_back(msg::make("camera.calibration.not_connected"));
        return out;
    }
    const auto& id = m_stage->identity();
    const auto& st = m_stage->status();
    if (id.kind != dev::proto::DeviceKind::Stage || st.axes.size() < 2) {
        out.push_back(msg::make("camera.calibration.not_a_stage"));
        return out;
    }
    if (st.estop)
        out.push_back(msg::make("camera.calibration.estop_latched"));
    if (!st.axes[0].homed || !st.axes[1].homed)
        out.push_back(msg::make("camera.calibration.not_homed"));
    if (st.anyMoving())
        out.push_back(msg::make("camera.calibration.moving"));
    if (!m_camera)
        out.push_back(msg::make("camera.none"));
    else if (!m_camera->isOpen())
        out.push_back(msg::make("camera.not_open", {msg::verbatim("source", m_camera->source().toStdString())}));
    if (!(o.stepPx >= 1 && o.stepPx <= 10000) || o.stepsEachWay < 1 || o.stepsEachWay > 10)
        out.push_back(msg::make("camera.calibration.bad_steps", {msg::real("step", o.stepPx), msg::integer("steps", o.stepsEachWay)}));
    return out;
}

bool CameraCalibration::start(const CalibrationOptions& options, msg::Message* error)
{
    const auto blockers = preflight(options);
    if (!blockers.empty()) {
        *error = blockers.front();
        return false;
    }
    m_options = options;
    m_result = {};
    m_result.camera = m_camera->source().toStdString();
    m_reference.reset();
    m_targetsMm.clear();
    m_imagesTaken = 0;
    const auto& st = m_stage->status();
    m_startMm = {st.axes[0].commanded, st.axes[1].commanded};
    m_startMeasuredMm = {st.axes[0].measured, st.axes[1].measured};
    m_measuredMm = m_startMeasuredMm;
    m_running = true;
    m_index = -1;
    emit progress(0, imagesFor(m_options));
    capture();
    return true;
}

void CameraCalibration::stop()
{
    if (m_running)
        fail(msg::make("camera.calibration.stopped"), true);
}

void CameraCalibration::fail(const msg::Message& why, bool stopStage)
{
    if (!m_running)
        return;
    m_running = false;
    m_phase = Phase::Idle;
    m_watchdog.stop();
    if (stopStage && m_stage && m_stage->isReady())
        m_stage->stop();
    emit failed(why);
}

void CameraCalibration::planSteps()
{
    const double stepMm = m_options.stepPx * m_result.nominalPixelUm / kCalUmPerMm;
    for (int k = 1; k <= m_options.stepsEachWay; ++k)
        for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)})
            m_targetsMm.push_back(m_startMm + dir * stepMm * k);
    m_targetsMm.push_back(m_startMm);  // back where it began
    m_result.stepUm = stepMm * kCalUmPerMm * m_options.stepsEachWay;
}

void CameraCalibration::moveTo(int index)
{
    m_index = index;
    m_phase = Phase::Moving;
    m_waitingAxes = 3;
    m_moveAccepted = false;
    const Eigen::Vector2d t = m_targetsMm[static_cast<std::size_t>(index)];
    m_arrival.expect({{0, t.x()}, {1, t.y()}});
    m_watchdog.start(static_cast<int>(std::lround(m_options.moveTimeoutS * 1000)));
    const QPointer<CameraCalibration> self(this);
    m_stage->move({{0, t.x()}, {1, t.y()}}, false, m_options.speedMmS, [self](const std::optional<dev::RequestError>& e) {
        if (!self || !self->m_running || self->m_phase != Phase::Moving)
            return;
        if (!e) {
            self->m_moveAccepted = true;
            return;
        }
        if (e->kind == dev::RequestError::Kind::LinkDown || e->kind == dev::RequestError::Kind::Timeout)
            self->fail(msg::make("camera.calibration.link_lost"), false);
        else
            self->fail(msg::make("camera.calibration.move_refused", {msg::nested("cause", e->message)}), true);
    });
}

void CameraCalibration::onArrived()
{
    if (m_phase != Phase::Moving)
        return;
    m_phase = Phase::Settling;
    // The grating's reading at rest is the step the fit uses, not the commanded one.
    const QPointer<CameraCalibration> self(this);
    m_stage->readStatus([self](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || !self->m_running || self->m_phase != Phase::Settling)
            return;
        if (e || s.axes.size() < 2) {
            self->fail(msg::make("camera.calibration.link_lost"), false);
            return;
        }
        self->m_measuredMm = {s.axes[0].measured, s.axes[1].measured};
        self->capture();
    });
}

void CameraCalibration::capture()
{
    m_phase = Phase::Capturing;
    CaptureRequest req;
    req.id = ++m_requestId;
    req.xMm = m_measuredMm.x();
    req.yMm = m_measuredMm.y();
    m_watchdog.start(static_cast<int>(std::lround((m_options.captureTimeoutS + m_camera->exposureMs() / 1000.0) * 1000)));
    m_camera->capture(req);
}

void CameraCalibration::onFrame(const Frame& frame)
{
    m_watchdog.stop();
    ++m_imagesTaken;
    emit progress(m_imagesTaken, imagesFor(m_options));
    auto grey = std::make_shared<const imaging::ImageF>(frameToGrey(frame));
    if (m_index < 0) {
        m_result.nominalPixelUm = m_options.nominalPixelUm > 0 ? m_options.nominalPixelUm : frame.pixelUm;
        if (!(m_result.nominalPixelUm > 0)) {
            fail(msg::make("camera.calibration.no_pixel_size", {msg::verbatim("source", m_result.camera)}), false);
            return;
        }
        m_result.widthPx = grey->width;
        m_result.heightPx = grey->height;
        const double reachPx = m_options.stepPx * m_options.stepsEachWay;
        if (grey->width <= 0 || reachPx * 2 > std::min(grey->width, grey->height)) {
            fail(msg::make("camera.calibration.steps_too_long",
                           {msg::real("reach", reachPx), msg::integer("width", grey->width), msg::integer("height", grey->height)}),
                 false);
            return;
        }
        planSteps();
        const auto& limits = m_stage->softLimits();
        for (const Eigen::Vector2d& t : m_targetsMm)
            for (int axis = 0; axis < 2 && axis < limits.size(); ++axis) {
                const auto& l = limits[axis];
                const double v = axis == 0 ? t.x() : t.y();
                if (l.max > l.min && (v < l.min || v > l.max)) {
                    fail(msg::make("camera.calibration.beyond_limits", {calAxis(axis), msg::real("target", v, msg::Unit::Mm),
                                                                        msg::real("min", l.min, msg::Unit::Mm), msg::real("max", l.max, msg::Unit::Mm)}),
                         false);
                    return;
                }
            }
        m_reference = grey;
        m_result.steps.assign(m_targetsMm.size(), CalibrationStep{});
        moveTo(0);
        return;
    }
    if (grey->width != m_reference->width || grey->height != m_reference->height) {
        fail(msg::make("camera.calibration.size_changed", {msg::integer("width", grey->width), msg::integer("height", grey->height),
                                                            msg::integer("first_width", m_reference->width),
                                                            msg::integer("first_height", m_reference->height)}),
             false);
        return;
    }
    const int index = m_index;
    m_result.steps[static_cast<std::size_t>(index)].stageUm = (m_measuredMm - m_startMeasuredMm) * kCalUmPerMm;
    imaging::RegistrationOptions ro;
    ro.maxShiftPx = m_options.stepPx * m_options.stepsEachWay * kCalSearchReach + kCalSearchMarginPx;
    const auto reference = m_reference;
    m_phase = Phase::Registering;
    m_pool.start([this, reference, grey, ro, index] {
        const imaging::PairRegistration reg = imaging::registerPair(*reference, *grey, Eigen::Vector2d(0, 0), ro);
        QMetaObject::invokeMethod(this, [this, index, reg] { onRegistered(index, reg); }, Qt::QueuedConnection);
    });
    // The stage goes on to the next step while the image is registered.
    if (index + 1 < static_cast<int>(m_targetsMm.size()))
        moveTo(index + 1);
}

void CameraCalibration::onRegistered(int index, const imaging::PairRegistration& reg)
{
    if (!m_running)
        return;
    CalibrationStep& s = m_result.steps[static_cast<std::size_t>(index)];
    s.shiftPx = reg.shiftPx;
    s.ncc = reg.ncc;
    s.registered = reg.accepted();
    if (index + 1 == static_cast<int>(m_targetsMm.size()))
        finish();
}

void CameraCalibration::finish()
{
    m_running = false;
    m_phase = Phase::Idle;
    m_watchdog.stop();
    std::vector<imaging::CameraStageSample> samples;
    const std::size_t stepCount = m_result.steps.size() - 1;  // the last is the return
    for (std::size_t i = 0; i < stepCount; ++i)
        if (m_result.steps[i].registered)
            samples.push_back({m_result.steps[i].stageUm, m_result.steps[i].shiftPx});
    const CalibrationStep& back = m_result.steps.back();
    m_result.returnPx = back.registered ? back.shiftPx.norm() : NAN;
    // Fewer than three images in four registered: the specimen has too little texture (or the
    // steps reach beyond it) to trust what the others say.
    if (samples.size() * 4 < stepCount * 3) {
        emit failed(msg::make("camera.calibration.not_registered",
                              {msg::integer("registered", static_cast<long long>(samples.size())), msg::integer("total", static_cast<long long>(stepCount))}));
        return;
    }
    const auto fit = imaging::fitCameraStage(samples);
    if (!fit) {
        emit failed(msg::make("camera.calibration.no_fit"));
        return;
    }
    m_result.fit = *fit;
    emit finished(m_result);
}

} // namespace dev::camera
