#include "scan_live_stitch.h"

#include "cli_session.h"
#include "command.h"

#include "device/jobs/scan_runner.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QGuiApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QSaveFile>

#include <algorithm>
#include <limits>

namespace app::cli {
namespace {

QJsonArray pairOf(const Eigen::Vector2d& v) { return QJsonArray{v.x(), v.y()}; }

} // namespace

ScanLiveStitch::ScanLiveStitch(Invocation& inv, dev::jobs::ScanRunner* runner) : m_inv(inv), m_runner(runner)
{
    m_job.follow(runner, [] { return dev::jobs::StitchRequest{}; });  // the folder and plan are the runner's
    QObject::connect(&m_job, &dev::jobs::StitchJob::livePair, &m_job, [this](const imaging::TilePair& p) { onPair(p); });
    // The quality map keeps each tile's thumbnail, as the Mosaic tab's does.
    QObject::connect(&m_job, &dev::jobs::StitchJob::liveStarted, &m_job, [this] {
        const motion::scan::Camera& camera = m_runner->plan().camera;
        const double px = 1000 / std::max(1e-9, motion::scan::pixelAtSampleUm(camera));
        m_drawing.beginLive(m_job.livePlannedPx(), QSizeF(motion::scan::fieldWidthMm(camera) * px, motion::scan::fieldHeightMm(camera) * px));
    });
    QObject::connect(&m_job, &dev::jobs::StitchJob::liveTile, &m_job,
                     [this](int tile, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail) {
                         m_drawing.setLiveTile(tile, stagePx, size.isValid() ? QSizeF(size) : QSizeF(), std::move(thumbnail));
                     });
    QObject::connect(&m_job, &dev::jobs::StitchJob::finished, &m_job, [this] { m_done = true; });
    QObject::connect(&m_job, &dev::jobs::StitchJob::failed, &m_job, [this](const motion::msg::Problems& p) {
        m_problems = p;
        m_done = true;
    });
}

QString ScanLiveStitch::tileFile(int tile) const
{
    const std::string& image = m_runner->image(tile).file;
    return QString::fromStdString(image.empty() ? m_runner->records().at(static_cast<std::size_t>(tile)).label : image);
}

void ScanLiveStitch::onPair(const imaging::TilePair& p)
{
    ++m_pairs;
    if (m_inv.json()) {
        m_inv.printJson(QJsonObject{{QStringLiteral("pair"), QJsonObject{{QStringLiteral("a"), tileFile(p.a)},
                                                                          {QStringLiteral("b"), tileFile(p.b)},
                                                                          {QStringLiteral("shift_px"), pairOf(p.reg.shiftPx)},
                                                                          {QStringLiteral("score"), p.reg.ncc},
                                                                          {QStringLiteral("accepted"), p.reg.accepted()},
                                                                          {QStringLiteral("status"), QLatin1String(imaging::pairStatusName(p.reg.status))}}},
                                    {QStringLiteral("pairs_registered"), m_pairs}});
        return;
    }
    m_inv.out() << QCoreApplication::translate("app::cli", "pair %1 + %2 registered: shift %3, %4 px, score %5, %6\n")
                       .arg(tileFile(p.a), tileFile(p.b))
                       .arg(p.reg.shiftPx.x(), 0, 'f', 2)
                       .arg(p.reg.shiftPx.y(), 0, 'f', 2)
                       .arg(p.reg.ncc, 0, 'f', 3)
                       .arg(ui::words::term(ui::pairVerdictTerm(p.reg.status)));
    m_inv.out().flush();
}

int ScanLiveStitch::stitchFolder(const motion::scan::ScanPlan& plan, const QString& folder)
{
    dev::jobs::StitchRequest request;
    request.folder = folder;
    request.plan = plan;
    motion::msg::Message error;
    if (!m_job.start(request, &error))
        return m_inv.refused(QCoreApplication::translate("app::cli", "stitching %1 failed: %2").arg(QDir::toNativeSeparators(folder), ui::words::text(error)));
    return finish();
}

int ScanLiveStitch::finish()
{
    // The scan's end handed the stitch its last tile (StitchJob::onScanFinished); without
    // a live stitch (no pixel size, a scan of no tiles) there is nothing to wait for.
    if (!m_job.isRunning() && !m_done)
        return Ok;
    spinUntil([this] { return m_done; }, std::numeric_limits<int>::max());
    if (!m_job.result() || m_job.written().isEmpty())
        return m_inv.refused(QCoreApplication::translate("app::cli", "the scan is whole, but stitching it failed: %1 (benchpilot-cli stitch %2 tries again)")
                                 .arg(ui::words::problems(m_problems).join(QLatin1Char(' ')), QDir::toNativeSeparators(m_job.folder())));
    const imaging::StitchResult& r = *m_job.result();
    QStringList files = m_job.written();
    // The quality map as the Mosaic tab draws it. Its legend needs fonts, which need a
    // QGuiApplication: benchpilot-cli and the GUI have one; a host without (a test's
    // QCoreApplication) writes the other three files.
    ui::StitchQualityDrawing& drawing = m_drawing;
    drawing.setResult(r);
    ui::StitchSummaryFigures figures{m_job.pixelUm(), drawing.magnification(), m_job.seconds(), m_job.lastWasLive(), m_job.livePlacedAfterS()};
    const QStringList lines = ui::stitchSummaryLines(r, figures);
    QString mapProblem;
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance())) {
        const QString png = QDir(m_job.folder()).filePath(QLatin1String(ui::kQualityMapFile));
        QSaveFile file(png);
        const QImage image = drawing.render(QSize(ui::kQualityMapWidthPx, ui::kQualityMapHeightPx), lines);
        if (file.open(QIODevice::WriteOnly) && image.save(&file, "PNG") && file.commit())
            files << png;
        else
            mapProblem = QCoreApplication::translate("app::cli", "the quality map could not be written to %1: %2").arg(QDir::toNativeSeparators(png), file.errorString());
    }
    QStringList advice;
    if (r.cameraCheck && r.planCamera)
        for (const motion::msg::Message& m : imaging::geometryAdvice(*r.cameraCheck, *r.planCamera))
            advice << ui::words::text(m);
    if (m_inv.json()) {
        int accepted = 0, byStage = 0;
        for (const imaging::TilePair& pair : r.pairs)
            accepted += pair.reg.accepted();
        for (bool s : r.placement.placedByStage)
            byStage += s;
        QJsonArray written;
        for (const QString& f : files)
            written << f;
        QJsonArray adviceIds;
        if (r.cameraCheck && r.planCamera)
            for (const motion::msg::Message& m : imaging::geometryAdvice(*r.cameraCheck, *r.planCamera))
                adviceIds << QString::fromStdString(m.id);
        const imaging::Placement& p = r.placement;
        m_inv.printJson(QJsonObject{{QStringLiteral("stitched"),
                                     QJsonObject{{QStringLiteral("files"), written},
                                                 {QStringLiteral("tiles"), static_cast<int>(r.tiles.size())},
                                                 {QStringLiteral("pairs"), static_cast<int>(r.pairs.size())},
                                                 {QStringLiteral("pairs_trusted"), accepted},
                                                 {QStringLiteral("pairs_rejected"), p.rejectedPairs},
                                                 {QStringLiteral("placed_by_stage"), byStage},
                                                 {QStringLiteral("rms_correction_px"), p.rmsCorrectionPx},
                                                 {QStringLiteral("worst_correction_px"), p.worstCorrectionPx},
                                                 {QStringLiteral("stage_model"), p.stageModel.used},
                                                 {QStringLiteral("rms_beyond_model_px"), p.rmsBeyondModelPx},
                                                 {QStringLiteral("worst_beyond_model_px"), p.worstBeyondModelPx},
                                                 {QStringLiteral("pixel_um"), m_job.pixelUm()},
                                                 {QStringLiteral("live"), m_job.lastWasLive()},
                                                 {QStringLiteral("placed_after_s"), m_job.livePlacedAfterS()},
                                                 {QStringLiteral("seconds"), m_job.seconds()},
                                                 {QStringLiteral("camera_check"), adviceIds},
                                                 {QStringLiteral("camera_advice"), QJsonArray::fromStringList(advice)}}}});
    } else {
        QTextStream& out = m_inv.out();
        for (const QString& line : lines)
            out << line << '\n';
        QStringList names;
        for (const QString& f : files)
            names << QFileInfo(f).fileName();
        out << (m_job.lastWasLive() ? QCoreApplication::translate("app::cli", "stitched live into %1: %2\n") : QCoreApplication::translate("app::cli", "stitched %1: %2\n"))
                   .arg(QDir::toNativeSeparators(m_job.folder()), names.join(QStringLiteral(", ")));
        out.flush();
    }
    if (!mapProblem.isEmpty())
        return m_inv.refused(mapProblem);
    return Ok;
}

} // namespace app::cli
