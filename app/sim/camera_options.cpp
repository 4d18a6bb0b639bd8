#include "camera_options.h"

#include "device/camera/sim_wire.h"

#include <QCoreApplication>

namespace app::sim {

CameraOptions::CameraOptions()
    : m_socket(QStringLiteral("camera-socket"), QCoreApplication::translate("sim", "serve the simulated camera on a local socket here (the camera sim:PATH)"),
               QStringLiteral("path")),
      m_specimen(QStringLiteral("specimen"), QCoreApplication::translate("sim", "with --camera-socket: what lies on the stage: slide, grid-plate or line-scales"),
                 QStringLiteral("name"), QStringLiteral("slide")),
      m_seed(QStringLiteral("camera-seed"), QCoreApplication::translate("sim", "with --camera-socket: the specimen's and the noise's seed"), QStringLiteral("n"),
             QStringLiteral("1")),
      m_sensor(QStringLiteral("camera-sensor"), QCoreApplication::translate("sim", "with --camera-socket: the sensor in pixels when a request gives no camera"),
               QStringLiteral("w,h"), QStringLiteral("2048,2048")),
      m_pixel(QStringLiteral("camera-pixel-um"), QCoreApplication::translate("sim", "with --camera-socket: a pixel at the sample in µm when a request gives no camera"),
              QStringLiteral("um"), QStringLiteral("0.65")),
      m_true(QStringLiteral("camera-true"),
             QCoreApplication::translate("sim", "with --camera-socket: the camera's true geometry where it differs from what it is asked: pixel-um=X[:Y],rotation-deg=D,mirror"),
             QStringLiteral("spec"))
{
}

void CameraOptions::addTo(QCommandLineParser& parser) const { parser.addOptions({m_socket, m_specimen, m_seed, m_sensor, m_pixel, m_true}); }

bool CameraOptions::read(const QCommandLineParser& p, const QString& kind, const QStringList& taken, CameraChoice* choice, QString* why) const
{
    namespace cam = dev::camera;
    choice->serve = p.isSet(m_socket);
    if (!choice->serve) {
        if (p.isSet(m_specimen) || p.isSet(m_seed) || p.isSet(m_sensor) || p.isSet(m_pixel) || p.isSet(m_true)) {
            *why = QCoreApplication::translate("sim", "--specimen, --camera-seed, --camera-sensor, --camera-pixel-um and --camera-true are for the camera socket (--camera-socket PATH)");
            return false;
        }
        return true;
    }
    choice->path = p.value(m_socket);
    if (kind != QLatin1String("stage")) {
        *why = QCoreApplication::translate("sim", "--camera-socket is for the simulated stage (--instrument stage)");
        return false;
    }
    if (choice->path.isEmpty()) {
        *why = QCoreApplication::translate("sim", "--camera-socket needs a path");
        return false;
    }
    if (taken.contains(choice->path)) {
        *why = QCoreApplication::translate("sim", "--camera-socket needs a path of its own, not the pty's");
        return false;
    }
    cam::SimCameraSettings& s = choice->settings;
    const auto chosen = cam::specimenFromName(p.value(m_specimen).toStdString());
    if (!chosen) {
        *why = QCoreApplication::translate("sim", "--specimen must be slide, grid-plate or line-scales (got '%1')").arg(p.value(m_specimen));
        return false;
    }
    s.specimen = *chosen;
    bool ok = false;
    const qulonglong seed = p.value(m_seed).toULongLong(&ok);
    if (!ok || seed > static_cast<qulonglong>(cam::kSimWireMaxInteger)) {
        *why = QCoreApplication::translate("sim", "--camera-seed must be a whole number from 0 (got '%1')").arg(p.value(m_seed));
        return false;
    }
    s.seed = seed;
    const QStringList sensor = p.value(m_sensor).split(QLatin1Char(','));
    bool okW = false, okH = false;
    const int w = sensor.size() == 2 ? sensor[0].trimmed().toInt(&okW) : 0;
    const int h = sensor.size() == 2 ? sensor[1].trimmed().toInt(&okH) : 0;
    if (!okW || !okH || w < 1 || h < 1 || w > cam::kSimWireMaxSidePx || h > cam::kSimWireMaxSidePx) {
        *why = QCoreApplication::translate("sim", "--camera-sensor must be W,H in pixels, each from 1 to %1 (got '%2')").arg(cam::kSimWireMaxSidePx).arg(p.value(m_sensor));
        return false;
    }
    s.geometry.sensorWidthPx = w;
    s.geometry.sensorHeightPx = h;
    const double pixelUm = p.value(m_pixel).toDouble(&ok);
    if (!ok || !(pixelUm > 0 && pixelUm <= cam::kSimWireMaxPixelUm)) {
        *why = QCoreApplication::translate("sim", "--camera-pixel-um must be above 0 and at most %1 (got '%2')").arg(cam::kSimWireMaxPixelUm).arg(p.value(m_pixel));
        return false;
    }
    s.geometry.pixelUm = pixelUm;
    std::string bad;
    if (p.isSet(m_true) && !cam::parseSimTrueGeometry(p.value(m_true).toStdString(), &s.trueGeometry, &bad)) {
        *why = QCoreApplication::translate("sim", "--camera-true: '%1' is not pixel-um=X[:Y] (above 0), rotation-deg=D (-360 to 360) or mirror").arg(QString::fromStdString(bad));
        return false;
    }
    return true;
}

} // namespace app::sim
