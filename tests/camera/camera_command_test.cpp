// command:CMD and folder:DIR. The operator's capture program, without a shell: placeholders filled, the
// file it wrote read (16-bit TIFF kept at 16 bits), and a failing, hanging, silent or
// missing program each named with its own stderr.
#include "device/camera/camera_source.h"
#include "device/camera/command_camera.h"
#include "device/camera/folder_camera.h"
#include "device/camera/tile_tiff.h"
#include "motion/message_print.h"

#include "integration/wait.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTimer>

#include <gtest/gtest.h>

#include <cstring>

namespace cam = dev::camera;

namespace {

struct Shot {
    std::optional<cam::Frame> frame;
    std::optional<motion::msg::Message> failure;
};

Shot take(cam::Camera& c, const cam::CaptureRequest& r)
{
    Shot s;
    QObject::connect(&c, &cam::Camera::captured, [&](std::uint64_t, const cam::Frame& f) { s.frame = f; });
    QObject::connect(&c, &cam::Camera::failed, [&](std::uint64_t, const motion::msg::Problem& p) { s.failure = p.message; });
    c.open();
    c.capture(r);
    itest::waitFor([&] { return s.frame || s.failure; }, 20000);
    QObject::disconnect(&c, nullptr, nullptr, nullptr);
    return s;
}

cam::CaptureRequest request(const QTemporaryDir& dir)
{
    cam::CaptureRequest r;
    r.id = 7;
    r.tile = 4;
    r.xMm = 12.5;
    r.yMm = 40.25;
    r.fileHint = dir.filePath(QStringLiteral("tile_005.tif")).toStdString();
    return r;
}

/// A shell script in `dir` (the camera runs it as "sh SCRIPT …": no shell of its own).
QString script(const QTemporaryDir& dir, const char* name, const char* body)
{
    const QString path = dir.filePath(QString::fromLatin1(name));
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(body);
    return path;
}

} // namespace

TEST(CommandCamera, TheProgramsFileIsReadWithThePlaceholdersFilledIn)
{
    QTemporaryDir dir;
    QImage img(8, 4, QImage::Format_RGB888);
    img.fill(QColor(10, 20, 30));
    const QString src = dir.filePath(QStringLiteral("src.png"));
    ASSERT_TRUE(img.save(src));
    const QString log = dir.filePath(QStringLiteral("args.txt"));
    const QString sh = script(dir, "cap.sh", "cp \"$1\" \"$2\"; echo \"$3 $4 $5\" > \"$6\"\n");
    cam::CommandCamera c(QStringLiteral("sh %1 %2 {file} {tile} {x_mm} {y_mm} %3").arg(sh, src, log));
    const Shot s = take(c, request(dir));
    ASSERT_TRUE(s.frame) << (s.failure ? motion::msg::debugString(*s.failure) : std::string());
    EXPECT_EQ(s.frame->width, 8);
    EXPECT_EQ(s.frame->format, cam::PixelFormat::Rgb8);
    EXPECT_EQ(s.frame->pixels[0], 10);
    EXPECT_EQ(s.frame->pixels[2], 30);
    QFile f(log);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll().trimmed(), QByteArray("4 12.5000 40.2500"));
    EXPECT_EQ(QDir(dir.path()).entryList({QStringLiteral("*.capture.*")}, QDir::Files).size(), 0) << "the program's file is taken away";

    // A 16-bit TIFF stays 16-bit.
    cam::Frame grey;
    grey.width = 3;
    grey.height = 1;
    grey.format = cam::PixelFormat::Grey16;
    grey.pixels.resize(6);
    const std::uint16_t v[3] = {100, 40000, 65535};
    std::memcpy(grey.pixels.data(), v, 6);
    motion::msg::Message error;
    const QString tif = dir.filePath(QStringLiteral("grey.tif"));
    ASSERT_TRUE(cam::writeTileTiff(tif.toStdString(), grey, {}, nullptr, &error));
    cam::CommandCamera c16(QStringLiteral("cp %1 {file}").arg(tif));
    const Shot s16 = take(c16, request(dir));
    ASSERT_TRUE(s16.frame);
    EXPECT_EQ(s16.frame->format, cam::PixelFormat::Grey16);
    EXPECT_EQ(s16.frame->pixels, grey.pixels);
}

TEST(CommandCamera, AFailingHangingSilentOrMissingProgramIsNamedWithItsStderr)
{
    QTemporaryDir dir;
    QTemporaryDir scripts;
    {
        cam::CommandCamera c(QStringLiteral("sh %1").arg(script(scripts, "fail.sh", "echo no camera found >&2; exit 3\n")));
        const Shot s = take(c, request(dir));
        ASSERT_TRUE(s.failure);
        EXPECT_EQ(s.failure->id, "camera.command.failed");
        const std::string t = motion::msg::debugString(*s.failure);
        EXPECT_NE(t.find("no camera found"), std::string::npos) << t;
        EXPECT_NE(t.find("3"), std::string::npos) << t;
    }
    {
        cam::CommandCamera c(QStringLiteral("sleep 30"));
        c.setTimeoutS(0.3);
        const Shot s = take(c, request(dir));
        ASSERT_TRUE(s.failure);
        EXPECT_EQ(s.failure->id, "camera.command.timeout");
    }
    {
        cam::CommandCamera c(QStringLiteral("sh %1").arg(script(scripts, "silent.sh", "echo wrote nothing >&2\n")));
        const Shot s = take(c, request(dir));
        ASSERT_TRUE(s.failure);
        EXPECT_EQ(s.failure->id, "camera.command.no_file");
        EXPECT_NE(motion::msg::debugString(*s.failure).find("wrote nothing"), std::string::npos);
    }
    {
        cam::CommandCamera c(QStringLiteral("/nonexistent/capture-tool {file}"));
        const Shot s = take(c, request(dir));
        ASSERT_TRUE(s.failure);
        EXPECT_EQ(s.failure->id, "camera.command.cannot_start");
    }
    {
        // The program wrote something that is not an image.
        cam::CommandCamera c(QStringLiteral("sh %1 {file}").arg(script(scripts, "text.sh", "echo text > \"$1\"\n")));
        const Shot s = take(c, request(dir));
        ASSERT_TRUE(s.failure);
        EXPECT_EQ(s.failure->id, "camera.tiff.cannot_read");
    }
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files).size(), 0) << "nothing half-written, nothing left behind";
    // The source name makes the same camera.
    motion::msg::Message error;
    auto made = cam::makeCamera("command:gphoto2 --capture-image-and-download --filename {file}", {}, &error);
    ASSERT_TRUE(made) << error;
    EXPECT_EQ(made->source(), QStringLiteral("command:gphoto2 --capture-image-and-download --filename {file}"));
}

TEST(FolderCamera, TheNextCompleteNewFileIsTakenAndNoFileIsNamed)
{
    QTemporaryDir dir;
    QImage old(4, 4, QImage::Format_Grayscale8);
    old.fill(1);
    ASSERT_TRUE(old.save(dir.filePath(QStringLiteral("old.png"))));  // there before: never taken
    cam::FolderCamera c(dir.path());
    // The camera's software writes under a temporary name and renames it into place.
    QTimer::singleShot(150, [&] {
        QImage img(6, 5, QImage::Format_Grayscale8);
        img.fill(200);
        img.save(dir.filePath(QStringLiteral("img_0001.png.part")), "PNG");
        QFile::rename(dir.filePath(QStringLiteral("img_0001.png.part")), dir.filePath(QStringLiteral("img_0001.png")));
    });
    const Shot s = take(c, request(dir));
    ASSERT_TRUE(s.frame) << (s.failure ? motion::msg::debugString(*s.failure) : std::string());
    EXPECT_EQ(s.frame->width, 6);
    EXPECT_EQ(s.frame->pixels[0], 200);
    EXPECT_TRUE(c.capabilities().needsTriggerOutput);

    c.setTimeoutS(0.3);
    const Shot none = take(c, request(dir));
    ASSERT_TRUE(none.failure);
    EXPECT_EQ(none.failure->id, "camera.folder.timeout");
    EXPECT_NE(motion::msg::debugString(*none.failure).find(dir.path().toStdString()), std::string::npos) << "names the folder";

    cam::FolderCamera gone(dir.filePath(QStringLiteral("nowhere")));
    const Shot g = take(gone, request(dir));
    ASSERT_TRUE(g.failure);
    EXPECT_EQ(g.failure->id, "camera.folder.missing");
}
