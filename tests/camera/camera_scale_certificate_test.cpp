// A glass scale's calibration certificate: the example reads, a certificate of another
// scale (a graduation off the scale's pitch, or beyond its length) is refused by file,
// line and column before anything runs, and a loaded certificate moves each camera
// reading by the certified deviation of the graduation read.
#include "device/camera/scale_reading_source.h"
#include "device/camera/sim_camera.h"
#include "device/files/accuracy/scale_certificate_csv.h"
#include "integration/accuracy_support.h"
#include "integration/cli_in_process.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <gtest/gtest.h>

using namespace itest;
namespace cam = dev::camera;
using dev::files::accuracy::ScaleGeometry;

namespace {

QString writeCertificate(const QTemporaryDir& dir, const char* name, const char* text)
{
    const QString path = dir.filePath(QLatin1String(name));
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

} // namespace

TEST(ScaleCertificate, TheExampleReadsAndInterpolatesBetweenItsGraduations)
{
    const auto read = dev::files::accuracy::loadScaleCertificateFile(
        QStringLiteral(BP_SOURCE_DIR "/resources/examples/glass-scale-100mm.scale-certificate.csv"), ScaleGeometry{});
    ASSERT_TRUE(read.ok()) << motion::msg::debugFormat(read.problems());
    EXPECT_EQ(read->graduationMm.size(), 11u);
    EXPECT_NEAR(read->deviationAtUm(15), 0.165, 1e-12);
    EXPECT_NEAR(read->deviationAtUm(100), -0.12, 1e-12);
    EXPECT_NEAR(read->deviationAtUm(120), -0.12, 1e-12) << "held beyond the last graduation";
}

TEST(ScaleCertificate, ACertificateOfAnotherScaleIsRefusedByFileLineAndColumn)
{
    QTemporaryDir dir;
    const QString offPitch = writeCertificate(dir, "other.scale-certificate.csv",
                                              "# benchpilot.scale-certificate 1\ngraduation_mm,deviation_um\n0,0\n10.05,0.1\n");
    const auto a = dev::files::accuracy::loadScaleCertificateFile(offPitch, ScaleGeometry{});
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(a.problems().front().message.id, "accuracy.certificate.off_pitch");
    EXPECT_EQ(a.problems().front().line, 4);
    EXPECT_EQ(a.problems().front().column, 1);
    const QString beyond = writeCertificate(dir, "long.scale-certificate.csv",
                                            "# benchpilot.scale-certificate 1\ndeviation_um,graduation_mm\n0,0\n0.1,150\n");
    const auto b = dev::files::accuracy::loadScaleCertificateFile(beyond, ScaleGeometry{});
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.problems().front().message.id, "accuracy.certificate.outside_scale");
    EXPECT_EQ(b.problems().front().line, 4);
    EXPECT_EQ(b.problems().front().column, 5);
    const auto noHeader = dev::files::accuracy::scaleCertificateFromCsv("graduation_mm,deviation_um\n0,0\n", "x.csv", ScaleGeometry{});
    EXPECT_FALSE(noHeader.ok());
    // The run is refused before anything moves or is written.
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("accuracy"), QStringLiteral("run"),
                                    QStringLiteral("--axis"), QStringLiteral("X"), QStringLiteral("--targets"), QStringLiteral("10:90:5"),
                                    QStringLiteral("--source"), QStringLiteral("camera"), QStringLiteral("--certificate"), offPitch,
                                    QStringLiteral("--out"), out});
    EXPECT_EQ(r.code, 1) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("other.scale-certificate.csv:4:1"))) << qPrintable(r.err);
    EXPECT_FALSE(QFileInfo::exists(out));
}

TEST(ScaleCertificate, ACertifiedDeviationMovesTheCameraReadingByItsAmount)
{
    AccuracyStage stage;
    ASSERT_TRUE(stage.ready());
    auto move = [&](int axis, double mm) {
        return !stage.session.call([&](auto cb) { stage.session.client.move({{axis, mm}}, false, 20, cb); }, 30000) && stage.session.waitStill(30000);
    };
    ASSERT_TRUE(move(1, 50.075)) << "over the X scale's short lines";
    ASSERT_TRUE(move(0, 30.0));
    dev::sim::SimMachine* m = &stage.session.link.machine();
    cam::SimCameraSettings s;
    s.specimen = cam::SpecimenKind::LineScales;
    cam::SimCamera camera([m]() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()}; },
                          s);
    auto readWith = [&](std::optional<motion::metrology::ScaleCertificate> certificate) -> std::optional<double> {
        cam::ScaleReadingOptions o;
        o.certificate = std::move(certificate);
        cam::ScaleReadingSource source(&camera, o);
        if (!openSource(source))
            return std::nullopt;
        dev::jobs::StopContext stop;
        stop.total = 1;
        stop.axes = {0};
        stop.letters = {QLatin1Char('X')};
        stop.targetsMm = {30.0};
        std::optional<double> value;
        bool done = false;
        source.take(stop, [&](const dev::jobs::TakeResult& r) {
            if (r.problem.empty() && r.valuesMm.size() == 1)
                value = r.valuesMm.front();
            done = true;
        });
        waitFor([&] { return done; }, 30000);
        return value;
    };
    const auto plain = readWith(std::nullopt);
    motion::metrology::ScaleCertificate c;
    c.graduationMm = {0, 100};
    c.deviationUm = {1.5, 3.5};  // 2.1 µm at 30 mm
    const auto certified = readWith(c);
    ASSERT_TRUE(plain && certified);
    EXPECT_NEAR((*certified - *plain) * 1e3, 2.1, 0.02);
}
