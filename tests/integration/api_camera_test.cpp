// The API's camera inside the GUI: a script's snap on the GUI's in-process simulator
// sees what the objective truly sees (the stage's errors included), as the GUI's own
// live view and benchpilot-cli --sim do, not where the grating says the stage is.
#include "api_support.h"

#include "device/camera/sim_camera.h"
#include "imaging/tiff_read.h"

#include <QDir>

#include <cmath>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

/// What the simulated camera with the snap's defaults records at (xMm, yMm).
dev::camera::Frame renderAt(double xMm, double yMm)
{
    dev::camera::SimCamera camera([xMm, yMm]() -> std::optional<dev::camera::WorkPoint> { return dev::camera::WorkPoint{xMm, yMm, {}}; },
                                  dev::camera::SimCameraSettings{});
    dev::camera::Frame out;
    QObject::connect(&camera, &dev::camera::Camera::captured, [&out](std::uint64_t, const dev::camera::Frame& f) { out = f; });
    camera.open();
    dev::camera::CaptureRequest r;
    r.id = 1;
    camera.capture(r);
    itest::waitFor([&out] { return !out.isEmpty(); }, 20000);
    return out;
}

double meanAbsDifference(const imaging::ImageU16& image, const dev::camera::Frame& frame)
{
    if (frame.format != dev::camera::PixelFormat::Grey16 || frame.width != image.width || frame.height != image.height)
        return -1;
    const auto* p = reinterpret_cast<const std::uint16_t*>(frame.pixels.data());
    double sum = 0;
    for (std::size_t i = 0; i < image.px.size(); ++i)
        sum += std::abs(static_cast<double>(image.px[i]) - static_cast<double>(p[i]));
    return sum / static_cast<double>(image.px.size());
}

} // namespace

TEST(ApiCamera, ASnapOnTheGuisSimulatorSeesTheTruePositionNotTheGratings)
{
    ApiFixture f(false, 0);
    QTemporaryDir work;
    ApiTestClient c(f.path);
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("camera")}, {QStringLiteral("cwd"), work.path()}});
    const QString lease = ApiTestClient::result(c.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
    f.stage.link.host().setTimeScale(20);
    QJsonObject a = c.call(QStringLiteral("device.home"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                                                      {QStringLiteral("axes"), QStringLiteral("XY")},
                                                                      {QStringLiteral("lease"), lease}},
                           60000);
    ASSERT_FALSE(a.contains(QStringLiteral("error"))) << QJsonDocument(a).toJson().toStdString();
    // Far out on X, where the simulated stage's pitch error is several pixels.
    a = c.call(QStringLiteral("device.move"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                                          {QStringLiteral("targets"), QJsonObject{{QStringLiteral("X"), 90}, {QStringLiteral("Y"), 60}}},
                                                          {QStringLiteral("lease"), lease}},
               60000);
    ASSERT_FALSE(a.contains(QStringLiteral("error"))) << QJsonDocument(a).toJson().toStdString();
    f.stage.link.host().setTimeScale(1);

    a = c.call(QStringLiteral("camera.snap"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                                          {QStringLiteral("camera"), QStringLiteral("sim")},
                                                          {QStringLiteral("out"), QStringLiteral("snap.tif")},
                                                          {QStringLiteral("lease"), lease}},
               60000);
    ASSERT_FALSE(a.contains(QStringLiteral("error"))) << QJsonDocument(a).toJson().toStdString();
    const auto snap = imaging::readTiff(QDir(work.path()).filePath(QStringLiteral("snap.tif")).toStdString());
    ASSERT_TRUE(snap.ok());

    const dev::sim::SimMachine& m = f.stage.link.machine();
    const double trueX = m.workPointLogical(0), trueY = m.workPointLogical(1);
    const double readX = m.measuredLogical(0), readY = m.measuredLogical(1);
    ASSERT_GT(std::hypot(trueX - readX, trueY - readY) * 1000, 3 * 0.65) << "the stage's error is too small here to tell the two apart";
    const double toTrue = meanAbsDifference(snap->grey, renderAt(trueX, trueY));
    const double toRead = meanAbsDifference(snap->grey, renderAt(readX, readY));
    ASSERT_GE(toTrue, 0);
    ASSERT_GE(toRead, 0);
    EXPECT_LT(toTrue, 0.2 * toRead) << "the snap looks where the grating reads, not where the stage is: " << toTrue << " against " << toRead;
}
