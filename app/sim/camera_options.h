#pragma once
// benchpilot-sim's camera options: --camera-socket PATH serves the simulated camera beside the
// pty (dev::camera::SimCameraServer), and --specimen, --camera-seed, --camera-sensor,
// --camera-pixel-um choose what it shows and the camera a request without one gets;
// --camera-true makes the camera truly other than it is asked to be (sim_true_geometry.h).
#include "device/camera/sim_camera.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

namespace app::sim {

struct CameraChoice {
    bool serve = false;
    QString path;
    dev::camera::SimCameraSettings settings;
};

class CameraOptions {
public:
    CameraOptions();
    void addTo(QCommandLineParser& parser) const;
    /// What was asked, or the reason it cannot be served (for an instrument `kind`, beside
    /// the paths `taken` by the pty and the gauge) in `why`.
    bool read(const QCommandLineParser& parser, const QString& kind, const QStringList& taken, CameraChoice* choice, QString* why) const;

private:
    QCommandLineOption m_socket, m_specimen, m_seed, m_sensor, m_pixel, m_true;
};

} // namespace app::sim
