#include "widgets/camera/camera_session.h"

#include "device/camera/camera_source.h"
#include "widgets/wording/wording.h"

namespace ui {

CameraSession::CameraSession(QObject* parent) : QObject(parent) {}

CameraSession::~CameraSession() { drop(); }

QStringList CameraSession::availableSources() const
{
    QStringList out = m_lister ? m_lister() : QStringList();
    if (!out.contains(QStringLiteral("sim")))
        out.prepend(QStringLiteral("sim"));
    for (const QString& s : m_recent)
        if (!out.contains(s))
            out << s;
    return out;
}

QStringList CameraSession::knownSources() const
{
    QStringList out{QStringLiteral("sim")};
    for (const QString& s : m_recent)
        if (!out.contains(s))
            out << s;
    return out;
}

QString CameraSession::sourceProblem(const QString& source)
{
    dev::camera::SourceSpec spec;
    motion::msg::Message error;
    return dev::camera::parseSource(source.trimmed().toStdString(), &spec, &error) ? QString() : ui::words::text(error);
}

bool CameraSession::open(const QString& source)
{
    if (m_inUse) {
        emit problem(tr("The camera is taking a scan's tiles: pause or abort the scan before changing it."));
        return false;
    }
    drop();
    setSource(source);
    if (const QString wrong = sourceProblem(m_source); !wrong.isEmpty()) {
        emit problem(wrong);
        emit stateChanged();
        return false;
    }
    QString error;
    m_camera = m_factory ? m_factory(m_source, &error) : nullptr;
    if (!m_camera) {
        emit problem(error.isEmpty() ? tr("Camera %1: this build cannot open it.").arg(m_source) : error);
        emit stateChanged();
        return false;
    }
    dev::camera::Camera* cam = m_camera.get();
    connect(cam, &dev::camera::Camera::opened, this, [this, cam] {
        m_opening = false;
        m_recent.removeAll(m_source);
        m_recent.prepend(m_source);
        m_recent = m_recent.mid(0, kRecent);
        if (cam->capabilities().exposure)
            cam->setExposureMs(m_exposureMs);
        if (cam->capabilities().live)
            cam->startLive();
        emit stateChanged();
    });
    connect(cam, &dev::camera::Camera::closed, this, [this] { emit stateChanged(); });
    connect(cam, &dev::camera::Camera::liveFrame, this, [this](const dev::camera::Frame& frame) {
        const bool recovered = !m_liveProblem.isEmpty();
        m_liveProblem.clear();
        emit liveFrame(frame);
        if (recovered)
            emit stateChanged();
    });
    connect(cam, &dev::camera::Camera::failed, this, [this, cam](std::uint64_t requestId, const motion::msg::Problem& p) {
        if (requestId != 0)
            return;  // a capture's failure is its asker's to tell
        m_opening = false;
        // Said once on the banner; the view keeps saying it until a frame comes.
        const QString why = ui::words::problem(p);
        if (why != m_liveProblem)
            emit problem(tr("Camera %1: %2").arg(cam->source(), why));
        m_liveProblem = why;
        emit stateChanged();
    });
    m_opening = true;
    emit stateChanged();
    cam->open();
    return true;
}

void CameraSession::close()
{
    if (!m_camera)
        return;
    if (m_inUse) {
        emit problem(tr("The camera is taking a scan's tiles: pause or abort the scan before closing it."));
        return;
    }
    drop();
    emit stateChanged();
}

void CameraSession::drop()
{
    m_opening = false;
    m_liveProblem.clear();
    if (!m_camera)
        return;
    std::unique_ptr<dev::camera::Camera> cam = std::move(m_camera);
    cam->disconnect(this);
    if (cam->isOpen()) {
        cam->stopLive();
        cam->close();
    }
}

bool CameraSession::isOpen() const { return m_camera && m_camera->isOpen(); }

void CameraSession::setExposureMs(double ms)
{
    m_exposureMs = ms;
    if (dev::camera::Camera* cam = camera(); cam && cam->capabilities().exposure)
        cam->setExposureMs(ms);
}

void CameraSession::setAutoContrast(bool on)
{
    if (m_autoContrast == on)
        return;
    m_autoContrast = on;
    emit autoContrastChanged(on);
}

} // namespace ui
