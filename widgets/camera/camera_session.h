#pragma once
// The camera the GUI has open, shared by every screen that shows it (the Scan
// screen, the stage's Jog screen) and handed to a scan run: one source at a time,
// opened and closed here, so two screens never open one device twice.
//
// Sources are made by a factory the composition root supplies (the widgets do not
// know how a simulated, USB, command or folder camera is built), and listed by a
// lister it supplies ("sim", "uvc:NAME" for each camera found, …).
#include "device/camera/camera.h"

#include <QObject>
#include <QStringList>

#include <functional>
#include <memory>

namespace ui {

class CameraSession : public QObject {
    Q_OBJECT
public:
    /// Builds the camera for `source` (not yet opened), or nullptr with `error` worded.
    using Factory = std::function<std::unique_ptr<dev::camera::Camera>(const QString& source, QString* error)>;
    /// The sources that can be known to exist now, as a person would type them.
    using Lister = std::function<QStringList()>;

    explicit CameraSession(QObject* parent = nullptr);
    ~CameraSession() override;
    void setFactory(Factory factory) { m_factory = std::move(factory); }
    void setLister(Lister lister) { m_lister = std::move(lister); }

    /// The lister's sources, then the ones opened lately (most recent first), each once.
    /// The lister may ask the system for its USB cameras (a fraction of a second): called
    /// when the operator opens the choice, never while a window is built.
    QStringList availableSources() const;
    /// "sim" and the sources opened lately, without asking the lister.
    QStringList knownSources() const;
    /// Sources opened lately, most recent first (kept between runs by the app).
    QStringList recentSources() const { return m_recent; }
    void setRecentSources(const QStringList& sources) { m_recent = sources.mid(0, kRecent); }
    static constexpr int kRecent = 8;
    /// "" when `source` has a form a camera can be made from; otherwise what is wrong.
    static QString sourceProblem(const QString& source);

    /// Closes any camera open, then builds and opens `source`; false (with problem())
    /// when it cannot even be built. Opening ends in stateChanged() or problem().
    bool open(const QString& source);
    void close();
    bool isOpen() const;
    bool isOpening() const { return m_camera && !m_camera->isOpen() && m_opening; }
    /// The camera open now, or nullptr.
    dev::camera::Camera* camera() const { return m_camera && m_camera->isOpen() ? m_camera.get() : nullptr; }
    /// The source last asked for (kept between runs by the app), open or not.
    QString source() const { return m_source; }
    void setSource(const QString& source) { m_source = source.trimmed(); }

    /// Why the open camera's live picture stopped coming (worded), until the next frame; "" when it comes.
    QString liveProblem() const { return m_liveProblem; }

    double exposureMs() const { return m_exposureMs; }
    void setExposureMs(double ms);
    /// While a scan takes its tiles with the camera, it is not closed or swapped under it.
    void setInUse(bool inUse) { m_inUse = inUse; }
    bool inUse() const { return m_inUse; }
    bool autoContrast() const { return m_autoContrast; }
    void setAutoContrast(bool on);

signals:
    void stateChanged();  ///< opened, closed, or failed to open
    void problem(const QString& message);
    void liveFrame(const dev::camera::Frame& frame);
    void autoContrastChanged(bool on);

private:
    void drop();

    Factory m_factory;
    Lister m_lister;
    std::unique_ptr<dev::camera::Camera> m_camera;
    QString m_source;
    QString m_liveProblem;
    QStringList m_recent;
    double m_exposureMs = 10;
    bool m_autoContrast = true;
    bool m_opening = false;
    bool m_inUse = false;
};

} // namespace ui
