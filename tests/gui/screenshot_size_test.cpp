// `benchpilot --screenshot FILE --size WxH` renders the window at that size;
// a window that cannot shrink to it comes out as a larger picture, so the picture itself
// shows whether a screen fits a 1366 × 768 laptop.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>

#include <gtest/gtest.h>

namespace {
QString benchpilotProgram()
{
    const QString dir = qEnvironmentVariable("BP_BIN_DIR");
    return (dir.isEmpty() ? QCoreApplication::applicationDirPath() + QStringLiteral("/../app") : dir) + QStringLiteral("/benchpilot");
}

QSize shotSize(const QStringList& extra, int* exitCode)
{
    const QString file = QDir::temp().filePath(QStringLiteral("bp-size-test-%1.png").arg(QCoreApplication::applicationPid()));
    QFile::remove(file);
    QProcess p;
    p.start(benchpilotProgram(), QStringList{QStringLiteral("--screenshot"), file, QStringLiteral("--settle-ms"), QStringLiteral("50")} + extra);
    EXPECT_TRUE(p.waitForFinished(60000));
    *exitCode = p.exitCode();
    const QImage img(file);
    QFile::remove(file);
    return img.size();
}
} // namespace

TEST(ScreenshotSize, TheWindowIsRenderedAtTheSizeAsked)
{
    int rc = -1;
    EXPECT_EQ(shotSize({QStringLiteral("--screen"), QStringLiteral("tuning"), QStringLiteral("--size"), QStringLiteral("1366x768")}, &rc),
              QSize(1366, 768));
    EXPECT_EQ(rc, 0);
    EXPECT_EQ(shotSize({QStringLiteral("--screen"), QStringLiteral("jog"), QStringLiteral("--size"), QStringLiteral("1920x1080")}, &rc),
              QSize(1920, 1080));
    // Smaller than any window can be: the picture is larger than asked, not a cut-off window.
    const QSize tiny = shotSize({QStringLiteral("--screen"), QStringLiteral("jog"), QStringLiteral("--size"), QStringLiteral("400x300")}, &rc);
    EXPECT_GT(tiny.width(), 400);
    EXPECT_EQ(rc, 0);
    shotSize({QStringLiteral("--size"), QStringLiteral("wide")}, &rc);
    EXPECT_NE(rc, 0) << "a size that is not WxH";
}
