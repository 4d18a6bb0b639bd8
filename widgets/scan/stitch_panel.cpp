#include "widgets/scan/stitch_panel.h"

#include "widgets/common/button_key.h"
#include "widgets/scan/mosaic_folder.h"
#include "widgets/scan/mosaic_viewer.h"
#include "widgets/scan/stitch_quality_map.h"
#include "widgets/wording/wording.h"

#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QSplitter>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

StitchPanel::StitchPanel(Source source, QWidget* parent) : QWidget(parent), m_source(std::move(source)), m_job(new dev::jobs::StitchJob(this))
{
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    m_stitch = new QPushButton;
    m_stitch->setObjectName(QStringLiteral("stitchButton"));
    setButtonKey(m_stitch, QKeySequence(Qt::CTRL | Qt::Key_T));
    row->addWidget(m_stitch);
    m_busy = new QProgressBar;
    m_busy->setRange(0, 0);  // how long registration takes is not known ahead
    m_busy->setMaximumWidth(160);
    m_busy->setVisible(false);
    row->addWidget(m_busy);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("stitchState"));
    m_state->setWordWrap(true);
    row->addWidget(m_state, 1);
    layout->addLayout(row);
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("stitchSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);
    m_map = new StitchQualityMap;
    m_viewer = new MosaicViewer;
    m_viewer->setObjectName(QStringLiteral("mosaicViewer"));
    auto* views = new QSplitter(Qt::Horizontal);  // the tab is wider than it is tall
    views->addWidget(m_viewer);
    views->addWidget(m_map);
    views->setStretchFactor(0, 3);
    views->setStretchFactor(1, 1);
    layout->addWidget(views, 1);
    m_tile = new QLabel;
    m_tile->setObjectName(QStringLiteral("stitchTile"));
    m_tile->setWordWrap(true);
    m_tile->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_tile);

    connect(m_stitch, &QPushButton::clicked, this, [this] { stitch(); });
    connect(m_job, &dev::jobs::StitchJob::finished, this, &StitchPanel::onFinished);
    connect(m_job, &dev::jobs::StitchJob::failed, this, [this](const motion::msg::Problems& problems) {
        updateUi();
        m_state->setText(tr("Stitching failed."));
        emit problem(tr("Stitching %1 failed: %2").arg(QDir::toNativeSeparators(m_folder), words::problems(problems).join(QLatin1Char(' '))));
    });
    connect(m_map, &StitchQualityMap::tileClicked, this, &StitchPanel::showTile);
    connect(m_job, &dev::jobs::StitchJob::liveStarted, this, &StitchPanel::onLiveStarted);
    connect(m_job, &dev::jobs::StitchJob::liveTile, m_map, &StitchQualityMap::setLiveTile);
    connect(m_job, &dev::jobs::StitchJob::livePair, m_map, &StitchQualityMap::setLivePair);
    connect(m_job, &dev::jobs::StitchJob::liveTile, this, &StitchPanel::updateUi);
    connect(m_job, &dev::jobs::StitchJob::liveDropped, this, [this] {
        updateUi();
        m_state->setText(tr("The scan stopped: nothing is written; the live mosaic begins again when the scan resumes."));
    });
    connect(m_viewer, &MosaicViewer::problem, this, &StitchPanel::problem);
    connect(m_viewer, &MosaicViewer::notice, this, &StitchPanel::notice);
    connect(m_viewer, &MosaicViewer::openRequested, this, [this] {
        const dev::jobs::StitchRequest request = m_source();
        QString error;
        const auto shown = loadStitchedFolder(request.folder, request.plan.camera, &error);
        if (!shown) {
            emit problem(error);
            return;
        }
        m_camera = request.plan.camera;
        m_map->setResult(shown->result);
        m_viewer->showStitch(shown->result, m_camera, shown->mosaicPath);
    });
    retranslateUi();
    updateUi();
}

bool StitchPanel::stitch()
{
    if (m_job->isRunning() || m_scanRunning)
        return false;
    const dev::jobs::StitchRequest request = m_source();
    motion::msg::Message error;
    if (!m_job->start(request, &error)) {
        emit problem(words::text(error));
        return false;
    }
    m_folder = request.folder;
    m_camera = request.plan.camera;
    m_map->clear();
    m_viewer->clear();
    m_summary->clear();
    m_tile->clear();
    updateUi();
    return true;
}

void StitchPanel::setScanRunning(bool running)
{
    m_scanRunning = running;
    m_viewer->setScanRunning(running);
    updateUi();
}

void StitchPanel::followScan(dev::jobs::ScanRunner* runner) { m_job->follow(runner, m_source); }

void StitchPanel::onLiveStarted()
{
    m_folder = m_job->folder();
    const motion::scan::Camera camera = m_source().plan.camera;
    m_camera = camera;  // the viewer shows the result with it
    const double px = 1000 / std::max(1e-9, motion::scan::pixelAtSampleUm(camera));
    m_map->beginLive(m_job->livePlannedPx(), QSizeF(motion::scan::fieldWidthMm(camera) * px, motion::scan::fieldHeightMm(camera) * px));
    m_summary->clear();
    m_tile->clear();
    updateUi();
}

QStringList StitchPanel::summaryLines() const
{
    const auto& r = m_job->result();
    if (!r)
        return {};
    return stitchSummaryLines(*r, {m_job->pixelUm(), m_map->magnification(), m_job->seconds(), m_job->lastWasLive(), m_job->livePlacedAfterS()});
}

QString StitchPanel::summaryText() const { return m_summary->text(); }
QString StitchPanel::tileText() const { return m_tile->text(); }

void StitchPanel::onFinished()
{
    const auto& r = m_job->result();
    if (!r)
        return;
    m_map->setResult(*r);
    if (!m_job->written().isEmpty())
        m_viewer->showStitch(*r, m_camera, m_job->written().front());
    const QStringList lines = summaryLines();
    m_summary->setText(lines.join(QLatin1Char('\n')));
    QStringList written = m_job->written();
    const QString png = QDir(m_folder).filePath(QLatin1String(kQualityMapFile));
    QSaveFile file(png);
    const QImage image = m_map->render(QSize(kQualityMapWidthPx, kQualityMapHeightPx), lines);
    if (file.open(QIODevice::WriteOnly) && image.save(&file, "PNG") && file.commit())
        written << png;
    else
        emit problem(tr("The quality map could not be written to %1: %2").arg(QDir::toNativeSeparators(png), file.errorString()));
    QStringList names;
    for (const QString& f : written)
        names << QFileInfo(f).fileName();
    m_state->setText(tr("Stitched into %1: %2").arg(QDir::toNativeSeparators(m_folder), names.join(QStringLiteral(", "))));
    updateUi();
    emit notice(m_state->text());
    emit finished();
}

void StitchPanel::showTile(int index)
{
    const auto& r = m_job->result();
    if (!r || m_job->isLive() || index < 0 || static_cast<std::size_t>(index) >= r->tiles.size())  // live: no result yet
        return;
    const Eigen::Vector2d d = r->placement.positionsPx[static_cast<std::size_t>(index)] - r->tiles[static_cast<std::size_t>(index)].stagePx;
    QStringList lines;
    lines << tr("Tile %1 (%2): moved %3, %4 px from where the stage put it%5")
                 .arg(index + 1)
                 .arg(QString::fromStdString(r->tiles[static_cast<std::size_t>(index)].file))
                 .arg(d.x(), 0, 'f', 2)
                 .arg(d.y(), 0, 'f', 2)
                 .arg(r->placement.placedByStage[static_cast<std::size_t>(index)] ? tr("; no trusted pair: placed by the stage") : QString());
    for (const imaging::TilePair& p : r->pairs) {
        if (p.a != index && p.b != index)
            continue;
        const int other = p.a == index ? p.b : p.a;
        lines << tr("with tile %1: shift %2, %3 px, score %4, %5")
                     .arg(other + 1)
                     .arg(p.reg.shiftPx.x(), 0, 'f', 2)
                     .arg(p.reg.shiftPx.y(), 0, 'f', 2)
                     .arg(p.reg.ncc, 0, 'f', 3)
                     .arg(words::term(pairVerdictTerm(p.reg.status)));
    }
    m_tile->setText(lines.join(QLatin1Char('\n')));
}

void StitchPanel::updateUi()
{
    const bool running = m_job->isRunning();
    m_stitch->setEnabled(!running && !m_scanRunning);
    m_busy->setVisible(running || m_job->isLive());
    m_busy->setRange(0, m_job->isLive() ? m_job->tileCount() : 0);  // registration's pace is known live only
    m_busy->setValue(m_job->liveTilesRead());
    m_busy->setFormat(m_job->isLive() ? tr("%v of %m tiles") : QString());
    if (m_job->isLive())
        m_state->setText(tr("Stitching live as the scan takes the tiles: %1 of %2 registered").arg(m_job->liveTilesRead()).arg(m_job->tileCount()));
    else if (running)
        m_state->setText(tr("Stitching %1 tiles in %2…").arg(m_job->tileCount()).arg(QDir::toNativeSeparators(m_folder)));
    else if (m_scanRunning)
        m_state->setText(tr("A scan is running into the folder: stitch it when it has finished."));
}

void StitchPanel::retranslateUi()
{
    m_stitch->setText(tr("Stitch"));
    m_stitch->setToolTip(tr("Stitch the images of the scan in the output folder into a mosaic (Ctrl+T)"));
    if (m_job->result() && !m_job->isRunning()) {
        m_summary->setText(summaryLines().join(QLatin1Char('\n')));
        if (m_map->selectedTile() >= 0)
            showTile(m_map->selectedTile());
    } else if (!m_job->isRunning() && m_state->text().isEmpty()) {
        m_state->setText(QString());
    }
    updateUi();
}

void StitchPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace ui
