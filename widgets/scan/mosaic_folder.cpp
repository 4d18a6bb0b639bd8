#include "widgets/scan/mosaic_folder.h"

#include "device/files/scan_exports.h"
#include "imaging/pyramid_reader.h"
#include "imaging/tiff_read.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <map>

namespace ui {

namespace {

bool vec2(const QJsonValue& v, Eigen::Vector2d* out)
{
    const QJsonArray a = v.toArray();
    if (a.size() != 2 || !a[0].isDouble() || !a[1].isDouble())
        return false;
    *out = {a[0].toDouble(), a[1].toDouble()};
    return std::isfinite(out->x()) && std::isfinite(out->y());
}

} // namespace

std::optional<StitchedFolder> loadStitchedFolder(const QString& folder, const motion::scan::Camera& camera, QString* error)
{
    const QDir dir(folder);
    QString reportName = QStringLiteral("mosaic.stitch.json");
    if (!dir.exists(reportName)) {
        const QStringList found = dir.entryList({QStringLiteral("*.stitch.json")}, QDir::Files, QDir::Name);
        if (found.size() != 1) {
            *error = QCoreApplication::translate("ui::MosaicFolder", "%1 holds no stitched mosaic (no .stitch.json report): stitch it first.").arg(QDir::toNativeSeparators(folder));
            return std::nullopt;
        }
        reportName = found.front();
    }
    const QString reportPath = dir.filePath(reportName);
    QFile file(reportPath);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QCoreApplication::translate("ui::MosaicFolder", "%1 cannot be read: %2").arg(QDir::toNativeSeparators(reportPath), file.errorString());
        return std::nullopt;
    }
    const QByteArray text = file.readAll();
    QJsonParseError parse{};
    const QJsonDocument doc = QJsonDocument::fromJson(text, &parse);
    if (parse.error != QJsonParseError::NoError) {
        const QByteArray before = text.left(parse.offset);
        const int line = before.count('\n') + 1;
        const int column = int(parse.offset - (before.lastIndexOf('\n') + 1)) + 1;
        *error = QCoreApplication::translate("ui::MosaicFolder", "%1, line %2, column %3: %4").arg(reportName).arg(line).arg(column).arg(parse.errorString());
        return std::nullopt;
    }
    const QJsonObject root = doc.object();
    auto bad = [&](const QString& what) {
        *error = QCoreApplication::translate("ui::MosaicFolder", "%1 is not a stitch report BenchPilot can show: %2").arg(reportName, what);
        return std::nullopt;
    };
    const QString mosaicName = root.value(QLatin1String("mosaic")).toObject().value(QLatin1String("file")).toString();
    if (mosaicName.isEmpty() || mosaicName.contains(QLatin1Char('/')) || mosaicName.contains(QLatin1Char('\\')))
        return bad(QCoreApplication::translate("ui::MosaicFolder", "it names no mosaic file in the folder"));
    StitchedFolder out;
    out.mosaicPath = dir.filePath(mosaicName);
    auto reader = imaging::PyramidReader::open(out.mosaicPath.toStdString(), mosaicName.toStdString());
    if (!reader) {
        *error = words::problems(reader.problems()).join(QLatin1Char(' '));
        return std::nullopt;
    }
    if (!(*reader)->stageMm())
        return bad(QCoreApplication::translate("ui::MosaicFolder", "its mosaic does not say where its top-left pixel was on the stage"));
    // The report's positions are mosaic pixels; the mosaic's top-left on the stage, in the
    // stage-pixel frame, is the offset back (a whole number of pixels, as fusion made it).
    const motion::scan::Point2 o = dev::files::scan::stageToPixels(camera, {(*reader)->stageMm()->x(), (*reader)->stageMm()->y()});
    const Eigen::Vector2d origin(std::round(o.xMm), std::round(o.yMm));
    imaging::StitchResult& r = out.result;
    r.frame.width = (*reader)->width();
    r.frame.height = (*reader)->height();
    r.frame.originPx = origin.cast<int>();
    const QJsonArray tiles = root.value(QLatin1String("tiles")).toArray();
    if (tiles.isEmpty())
        return bad(QCoreApplication::translate("ui::MosaicFolder", "it lists no tiles"));
    std::map<QString, int> index;
    for (int i = 0; i < tiles.size(); ++i) {
        const QJsonObject t = tiles[i].toObject();
        imaging::StitchTile tile;
        Eigen::Vector2d stage, registered;
        tile.file = t.value(QLatin1String("file")).toString().toStdString();
        if (tile.file.empty() || !vec2(t.value(QLatin1String("stage_px")), &stage) || !vec2(t.value(QLatin1String("registered_px")), &registered))
            return bad(QCoreApplication::translate("ui::MosaicFolder", "tile %1 has no file, stage_px or registered_px").arg(i + 1));
        tile.path = dir.filePath(QString::fromStdString(tile.file)).toStdString();
        tile.stagePx = stage + origin;
        r.tiles.push_back(tile);
        r.placement.positionsPx.push_back(registered + origin);
        r.placement.placedByStage.push_back(t.value(QLatin1String("placed_by")).toString() == QLatin1String("stage"));
        index[QString::fromStdString(tile.file)] = i;
    }
    auto info = imaging::readTiffInfo(r.tiles.front().path, r.tiles.front().file);
    if (!info) {
        *error = QCoreApplication::translate("ui::MosaicFolder", "The tile size comes from the tiles: %1").arg(words::problems(info.problems()).join(QLatin1Char(' ')));
        return std::nullopt;
    }
    r.tileWidth = info->width;
    r.tileHeight = info->height;
    for (const QJsonValue& v : root.value(QLatin1String("pairs")).toArray()) {
        const QJsonObject p = v.toObject();
        const auto a = index.find(p.value(QLatin1String("a")).toString()), b = index.find(p.value(QLatin1String("b")).toString());
        imaging::TilePair pair;
        if (a == index.end() || b == index.end() || !vec2(p.value(QLatin1String("shift_px")), &pair.reg.shiftPx))
            continue;  // the viewer needs only the tiles; a pair it cannot place is left off the map
        pair.a = a->second;
        pair.b = b->second;
        pair.reg.ncc = p.value(QLatin1String("score")).toDouble();
        const QString status = p.value(QLatin1String("status")).toString();
        for (auto s : {imaging::PairStatus::Accepted, imaging::PairStatus::LowScore, imaging::PairStatus::Ambiguous, imaging::PairStatus::AtBound,
                       imaging::PairStatus::NoOverlap, imaging::PairStatus::Outlier})
            if (status == QLatin1String(imaging::pairStatusName(s)))
                pair.reg.status = s;
        r.pairs.push_back(pair);
        r.placement.residualPx.push_back(p.value(QLatin1String("residual_px")).toDouble());
    }
    r.placement.rmsCorrectionPx = root.value(QLatin1String("rms_correction_px")).toDouble();
    r.placement.worstCorrectionPx = root.value(QLatin1String("worst_correction_px")).toDouble();
    r.placement.rejectedPairs = root.value(QLatin1String("pairs_rejected")).toInt();
    return out;
}

} // namespace ui
