// The API's stitch method inside the server: registration and fusion take seconds on a
// real folder, and in the GUI the API runs commands on the GUI's own thread (on a
// fiber), so the stitch must run beside it, not on it: another call sent after it is
// answered while it still works.
#include "api_support.h"

#include "imaging/tiff_write.h"

#include <QDir>
#include <QFile>

#include <random>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

/// A 3 × 3 folder of 1024 × 1024 16-bit tiles with a TileConfiguration, 10 % overlap.
void writeStitchFolder(const QString& dir)
{
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> grey(0, 65535);
    QString config = QStringLiteral("dim = 2\n");
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            imaging::ImageU16 tile(1024, 1024);
            for (auto& p : tile.px)
                p = static_cast<std::uint16_t>(grey(rng));
            const QString name = QStringLiteral("tile_%1.tif").arg(r * 3 + c + 1, 3, 10, QLatin1Char('0'));
            EXPECT_TRUE(imaging::writeTiff(QDir(dir).filePath(name).toStdString(), tile).empty());
            config += QStringLiteral("%1; ; (%2, %3)\n").arg(name).arg(c * 922).arg(r * 922);
        }
    QFile f(QDir(dir).filePath(QStringLiteral("TileConfiguration.txt")));
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(config.toUtf8());
}

} // namespace

TEST(ApiStitch, AnotherCallIsAnsweredWhileAStitchWorks)
{
    ApiFixture f(false, 0);
    QTemporaryDir work;
    const QString tiles = work.filePath(QStringLiteral("tiles"));
    ASSERT_TRUE(QDir().mkpath(tiles));
    writeStitchFolder(tiles);

    ApiTestClient c(f.path);
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("stitcher")}, {QStringLiteral("cwd"), work.path()}});
    // Both lines in one write: the server reads them in one go, the stitch first.
    const QByteArray stitch = QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), 101},
                                                        {QStringLiteral("method"), QStringLiteral("stitch")},
                                                        {QStringLiteral("params"), QJsonObject{{QStringLiteral("dir"), QStringLiteral("tiles")}}}})
                                  .toJson(QJsonDocument::Compact);
    const QByteArray status = QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), 102},
                                                        {QStringLiteral("method"), QStringLiteral("control.status")}})
                                  .toJson(QJsonDocument::Compact);
    c.sendRaw(stitch + '\n' + status + '\n');
    const QJsonObject first = c.nextAnswer(60000);
    const QJsonObject second = c.nextAnswer(60000);
    EXPECT_EQ(first.value(QStringLiteral("id")).toInt(), 102) << "control.status waited for the stitch";
    EXPECT_EQ(second.value(QStringLiteral("id")).toInt(), 101);
    const QJsonObject report = ApiTestClient::result(first.value(QStringLiteral("id")).toInt() == 101 ? first : second);
    EXPECT_EQ(report.value(QStringLiteral("tiles")).toArray().size(), 9) << QJsonDocument(first).toJson().toStdString();
    EXPECT_TRUE(QFile::exists(QDir(tiles).filePath(QStringLiteral("mosaic.ome.tif"))));
}
