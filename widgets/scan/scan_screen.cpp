#include "widgets/scan/scan_screen.h"
#include "widgets/common/button_key.h"

#include "device/camera/scan_camera.h"
#include "device/files/scan_exports.h"
#include "device/files/scan_plan_file.h"
#include "device/jobs/machine_model.h"
#include "device/jobs/scan_launch.h"
#include "device/jobs/scan_runner.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"
#include "widgets/camera/live_view.h"
#include "widgets/scan/scan_plan_form.h"
#include "widgets/scan/scan_stage_map.h"
#include "widgets/scan/mosaic_viewer.h"
#include "widgets/scan/stitch_panel.h"

#include "widgets/wording/wording.h"

#include <QCheckBox>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

using ui::words::duration;

using namespace motion::scan;
using dev::jobs::ScanRunner;

ScanScreen::ScanScreen(dev::Instrument* stage, QWidget* parent)
    : QWidget(parent), m_stage(stage), m_runner(new ScanRunner(stage, this)), m_launch(std::make_unique<dev::jobs::ScanLaunch>(m_runner))
{
    auto* v = new QVBoxLayout(this);
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("scanSummary"));
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont big = m_summary->font();
    big.setPointSizeF(big.pointSizeF() + 1.5);
    big.setBold(true);
    m_summary->setFont(big);
    v->addWidget(m_summary);
    m_problems = new QLabel;
    m_problems->setObjectName(QStringLiteral("scanProblems"));
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color: #b71c1c;"));
    v->addWidget(m_problems);

    auto* split = new QSplitter(Qt::Horizontal);
    auto* left = new QWidget;
    auto* lv = new QVBoxLayout(left);
    lv->setContentsMargins(0, 0, 0, 0);
    m_map = new ScanStageMap;
    lv->addWidget(m_map, 1);
    auto* mapBar = new QHBoxLayout;
    auto* fitStage = new QToolButton;
    fitStage->setText(tr("Whole stage"));
    fitStage->setToolTip(tr("Show the whole travel"));
    auto* fitPlan = new QToolButton;
    fitPlan->setText(tr("Zoom to scan"));
    fitPlan->setToolTip(tr("Show the scan's tiles"));
    connect(fitStage, &QToolButton::clicked, m_map, &ScanStageMap::fitStage);
    connect(fitPlan, &QToolButton::clicked, m_map, &ScanStageMap::fitPlan);
    m_pointer = new QLabel;
    mapBar->addWidget(fitStage);
    mapBar->addWidget(fitPlan);
    mapBar->addWidget(m_pointer, 1);
    lv->addLayout(mapBar);
    // The camera goes in a tab beside the map (setCameraSession): the live view needs the room.
    m_leftTabs = new QTabWidget;
    m_leftTabs->setObjectName(QStringLiteral("scanLeftTabs"));
    m_leftTabs->addTab(left, tr("Stage map"));
    m_leftTabs->tabBar()->setVisible(false);
    split->addWidget(m_leftTabs);

    auto* right = new QWidget;
    auto* rv = new QVBoxLayout(right);
    rv->setContentsMargins(0, 0, 0, 0);
    m_fileRow = buildFileRow();
    rv->addWidget(m_fileRow);
    m_form = new ScanPlanForm;
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_form);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    rv->addWidget(scroll, 1);
    rv->addWidget(buildRunPanel());
    right->setMinimumWidth(400);
    split->addWidget(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setSizes({900, 440});
    v->addWidget(split, 1);

    m_replanTimer = new QTimer(this);
    m_replanTimer->setSingleShot(true);
    m_replanTimer->setInterval(30);  // coalesce a burst of edits into one plan
    connect(m_replanTimer, &QTimer::timeout, this, &ScanScreen::replan);
    connect(m_form, &ScanPlanForm::planChanged, this, &ScanScreen::scheduleReplan);
    connect(m_form, &ScanPlanForm::regionKindChanged, this, [this](RegionKind k) {
        m_map->setDrawMode(k == RegionKind::Polygon ? ScanStageMap::DrawMode::Polygon : ScanStageMap::DrawMode::Rectangle);
    });
    connect(m_map, &ScanStageMap::rectangleDrawn, this, [this](const Rect& r) {
        ScanPlan p = plan();
        if (p.region.kind == RegionKind::CentreSize) {
            p.region.centre = r.centre();
            p.region.widthMm = r.widthMm();
            p.region.heightMm = r.heightMm();
        } else {
            p.region.kind = RegionKind::Corners;
            p.region.cornerA = {r.x0Mm, r.y0Mm};
            p.region.cornerB = {r.x1Mm, r.y1Mm};
        }
        m_form->setPlan(p);
    });
    connect(m_map, &ScanStageMap::polygonDrawn, this, [this](const std::vector<Point2>& vs) {
        ScanPlan p = plan();
        p.region.kind = RegionKind::Polygon;
        p.region.vertices = vs;
        m_form->setPlan(p);
    });
    connect(m_map, &ScanStageMap::pointerMoved, this, [this](const std::optional<Point2>& at) {
        m_pointer->setText(at ? tr("X %1  Y %2 mm").arg(at->xMm, 0, 'f', 3).arg(at->yMm, 0, 'f', 3) : QString());
    });

    connect(m_runner, &ScanRunner::stateChanged, this, &ScanScreen::updateRunUi);
    connect(m_runner, &ScanRunner::progress, this, &ScanScreen::updateRunUi);
    connect(m_runner, &ScanRunner::tileTaken, this, [this](int tile) {
        if (tile >= 0 && static_cast<std::size_t>(tile) < m_taken.size())
            m_taken[static_cast<std::size_t>(tile)] = 1;
        m_map->setProgress(m_taken, m_runner->isActive() ? m_runner->currentTile() : -1);
    });
    connect(m_runner, &ScanRunner::triggered, this, [this](int tile, quint64) { m_map->setProgress(m_taken, tile); });
    connect(m_runner, &ScanRunner::problem, this, [this](const motion::msg::Message& m) { emit problem(ui::words::text(m)); });
    connect(m_runner, &ScanRunner::finished, this, [this](const QStringList& exports) {
        emit notice(tr("Scan finished: %1 tiles taken. Exports written to %2.").arg(m_runner->totalTiles()).arg(m_runner->folder()));
        (void)exports;
    });
    connect(m_stage, &dev::Instrument::statusChanged, this, &ScanScreen::onStatus);
    connect(m_stage, &dev::Instrument::identified, this, &ScanScreen::onStageIdentity);
    connect(m_stage, &dev::Instrument::limitsChanged, this, &ScanScreen::onStageIdentity);
    connect(m_stage, &dev::Instrument::stateChanged, this, &ScanScreen::updateRunUi);
    connect(m_stage, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (s != dev::LinkState::Ready)
            m_map->setStagePosition(std::nullopt);  // where the stage was is not where it is
    });

    setOutputFolder(QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                        .filePath(QStringLiteral("BenchPilot scans/scan")));
    m_form->setPlan(ScanPlan{});
    replan();
    m_map->fitStage();
}

ScanScreen::~ScanScreen() = default;

QWidget* ScanScreen::buildFileRow()
{
    auto* w = new QWidget;
    auto* h = new QHBoxLayout(w);
    h->setContentsMargins(0, 0, 0, 0);
    auto* fresh = new QPushButton(tr("New"));
    fresh->setToolTip(tr("Start from the default plan"));
    auto* open = new QPushButton(tr("Open plan…"));
    setButtonKey(open, QKeySequence::Open);
    open->setToolTip(tr("Open a scan plan file (%1)").arg(QKeySequence(QKeySequence::Open).toString()));
    auto* save = new QPushButton(tr("Save plan…"));
    setButtonKey(save, QKeySequence::Save);
    save->setToolTip(tr("Save this plan as a file (%1)").arg(QKeySequence(QKeySequence::Save).toString()));
    connect(fresh, &QPushButton::clicked, this, [this] { m_form->setPlan(ScanPlan{}); });
    connect(open, &QPushButton::clicked, this, [this] {
        const QString path = choose(FileAction::Open, tr("Open scan plan"), tr("Scan plans (*.scan.json *.json)"));
        if (!path.isEmpty())
            openPlan(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = choose(FileAction::Save, tr("Save scan plan"), tr("Scan plans (*.scan.json)"));
        if (!path.isEmpty())
            savePlan(path.endsWith(QLatin1String(".json")) ? path : path + QStringLiteral(".scan.json"));
    });
    h->addWidget(fresh);
    h->addWidget(open);
    h->addWidget(save);
    h->addStretch(1);
    return w;
}

QWidget* ScanScreen::buildRunPanel()
{
    auto* w = new QWidget;
    auto* v = new QVBoxLayout(w);
    v->setContentsMargins(0, 4, 0, 0);
    auto* folderRow = new QHBoxLayout;
    m_folder = new QLineEdit;
    m_folder->setObjectName(QStringLiteral("scanFolder"));
    m_folder->setToolTip(tr("The run log and the exports go here; a run stopped part-way continues from its log"));
    auto* browse = new QToolButton;
    browse->setText(QStringLiteral("…"));
    connect(browse, &QToolButton::clicked, this, [this] {
        const QString dir = choose(FileAction::Folder, tr("Folder for the run log and exports"), m_folder->text());
        if (!dir.isEmpty())
            setOutputFolder(dir);
    });
    folderRow->addWidget(new QLabel(tr("Output")));
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    v->addLayout(folderRow);
    m_useCamera = new QCheckBox(tr("Take an image at each tile"));
    m_useCamera->setObjectName(QStringLiteral("scanUseCamera"));
    m_useCamera->setToolTip(tr("The camera open on the Camera tab takes each tile once it has settled; the images go to the "
                               "output folder"));
    m_useCamera->setVisible(false);  // until there is a camera to take them
    connect(m_useCamera, &QCheckBox::toggled, this, &ScanScreen::updateRunUi);
    v->addWidget(m_useCamera);
    auto* buttons = new QHBoxLayout;
    m_runButton = new QPushButton(tr("Run"));
    m_runButton->setObjectName(QStringLiteral("scanRun"));
    setButtonKey(m_runButton, QKeySequence(Qt::CTRL | Qt::Key_R));
    m_pauseButton = new QPushButton(tr("Pause"));
    setButtonKey(m_pauseButton, QKeySequence(Qt::CTRL | Qt::Key_P));
    m_pauseButton->setToolTip(tr("Stop after the tile in progress (Ctrl+P)"));
    m_abortButton = new QPushButton(tr("Abort"));
    setButtonKey(m_abortButton, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    m_abortButton->setToolTip(tr("Stop the stage now; the tiles taken are kept and Resume continues (Ctrl+Shift+A)"));
    m_exportButton = new QPushButton(tr("Export"));
    m_exportButton->setToolTip(tr("Write TileConfiguration.txt (Fiji), positions.pos (Micro-Manager) and scan.csv to the output folder"));
    connect(m_runButton, &QPushButton::clicked, this, [this] { run(); });
    connect(m_pauseButton, &QPushButton::clicked, this, &ScanScreen::pause);
    connect(m_abortButton, &QPushButton::clicked, this, &ScanScreen::abort);
    connect(m_exportButton, &QPushButton::clicked, this, [this] { exportFiles(); });
    for (QPushButton* b : {m_runButton, m_pauseButton, m_abortButton, m_exportButton})
        buttons->addWidget(b);
    v->addLayout(buttons);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("scanProgress"));
    m_progress->setFormat(tr("%v of %m tiles"));
    v->addWidget(m_progress);
    m_runState = new QLabel;
    m_runState->setObjectName(QStringLiteral("scanRunState"));
    m_runState->setWordWrap(true);
    v->addWidget(m_runState);
    return w;
}

ScanPlan ScanScreen::plan() const { return m_form->plan(); }
QString ScanScreen::planText() const { return QString::fromStdString(dev::files::scan::writePlan(plan())); }

bool ScanScreen::setPlanText(const QString& text, QString* error)
{
    const auto r = dev::files::scan::parsePlan(text.toStdString());
    if (!r.plan) {
        *error = QString::fromStdString(r.problems.format("plan")).trimmed();
        return false;
    }
    setPlan(*r.plan);
    return true;
}

void ScanScreen::setPlan(const ScanPlan& p)
{
    m_form->setPlan(p);
    replan();
    m_map->fitPlan();
}

QString ScanScreen::outputFolder() const { return m_folder->text(); }
void ScanScreen::setOutputFolder(const QString& folder) { m_folder->setText(folder); }

void ScanScreen::setCameraSession(CameraSession* session)
{
    if (m_camera || !session)
        return;
    m_camera = session;
    m_cameraPanel = new CameraPanel(session, m_stage);
    m_cameraPanel->setObjectName(QStringLiteral("scanCamera"));
    m_leftTabs->addTab(m_cameraPanel, tr("Camera"));
    m_leftTabs->tabBar()->setVisible(true);
    connect(m_cameraPanel, &CameraPanel::problem, this, &ScanScreen::problem);
    connect(m_cameraPanel, &CameraPanel::notice, this, &ScanScreen::notice);
    connect(session, &CameraSession::stateChanged, this, &ScanScreen::updateRunUi);
    m_stitchPanel = new StitchPanel([this] {
        dev::jobs::StitchRequest r;
        r.folder = outputFolder().trimmed();
        r.plan = plan();
        return r;
    });
    m_stitchPanel->setObjectName(QStringLiteral("scanMosaic"));
    m_stitchPanel->followScan(m_runner);
    // A double-click in the mosaic is a move like any other: the long-move question when far.
    m_stitchPanel->viewer()->setStage(m_stage);
    m_stitchPanel->viewer()->setConfirm([this](const QString& q) { return m_confirmLongMove ? m_confirmLongMove(q) : confirm(q); });
    m_leftTabs->addTab(m_stitchPanel, tr("Mosaic"));
    connect(m_stitchPanel, &StitchPanel::problem, this, &ScanScreen::problem);
    connect(m_stitchPanel, &StitchPanel::notice, this, &ScanScreen::notice);
    m_useCamera->setVisible(true);
    replan();
}

bool ScanScreen::takesImages() const { return m_useCamera->isChecked(); }
void ScanScreen::setTakesImages(bool on) { m_useCamera->setChecked(on); }

dev::camera::Camera* ScanScreen::runCamera() const
{
    return m_camera && m_useCamera->isChecked() ? m_camera->camera() : nullptr;
}

void ScanScreen::showTab(int index) { m_leftTabs->setCurrentIndex(std::clamp(index, 0, m_leftTabs->count() - 1)); }

bool ScanScreen::openPlan(const QString& path)
{
    ScanPlan p;
    dev::files::json::Problems problems;
    if (!dev::files::scan::loadPlan(path, &p, &problems)) {
        emit problem(tr("Cannot open the plan:\n%1").arg(ui::words::fileProblems(problems, QFileInfo(path).fileName()).join(QLatin1Char('\n'))));
        return false;
    }
    setPlan(p);
    // Each plan keeps its run next to it unless a folder was chosen on purpose.
    const QFileInfo fi(path);
    setOutputFolder(fi.dir().filePath(fi.completeBaseName().section(QLatin1Char('.'), 0, 0) + QStringLiteral("-run")));
    emit notice(tr("Opened %1: %2 tiles.").arg(fi.fileName()).arg(m_layout.tiles.size()));
    return true;
}

bool ScanScreen::savePlan(const QString& path)
{
    if (const QString typed = m_form->entryProblem(); !typed.isEmpty()) {
        emit problem(tr("The plan is not saved: %1").arg(typed));  // a file never gets a number nobody typed
        return false;
    }
    motion::msg::Message error;
    if (!dev::files::scan::savePlan(path, plan(), &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    emit notice(tr("Saved the plan to %1.").arg(path));
    return true;
}

StageModel ScanScreen::stageModel() const
{
    if (m_stage->isReady() && m_stage->identity().kind == dev::proto::DeviceKind::Stage)
        return dev::jobs::stageModelOf(m_stage->identity(), m_stage->softLimits());
    return StageModel{};
}

void ScanScreen::onStageIdentity()
{
    if (!m_stage->isReady() || m_stage->identity().kind != dev::proto::DeviceKind::Stage)
        return;
    const auto& a = m_stage->identity().axes;
    if (a.size() >= 2)
        m_map->setTravel({a[0].travelMin, a[1].travelMin, a[0].travelMax, a[1].travelMax});
    const auto& l = m_stage->softLimits();
    m_map->setSoftLimits(l.size() >= 2 ? std::optional<Rect>(Rect{l[0].min, l[1].min, l[0].max, l[1].max}) : std::nullopt);
    scheduleReplan();
}

void ScanScreen::onStatus(const dev::InstrumentStatus& s)
{
    if (m_stage->isReady() && s.axes.size() >= 2 && s.axes[0].homed && s.axes[1].homed)
        m_map->setStagePosition(Point2{s.axes[0].measured, s.axes[1].measured});
    else
        m_map->setStagePosition(std::nullopt);
}

void ScanScreen::scheduleReplan() { m_replanTimer->start(); }

void ScanScreen::replan()
{
    const ScanPlan p = plan();
    auto problems = validate(p, stageModel());
    QStringList lines;
    if (const QString typed = m_form->entryProblem(); !typed.isEmpty())
        lines << typed;
    if (!m_form->polygonError().isEmpty())
        lines << tr("Polygon: %1").arg(m_form->polygonError());
    lines << ui::words::problems(problems);
    m_valid = lines.isEmpty();
    m_layout = m_valid ? layoutScan(p) : ScanLayout{};
    m_estimate = m_valid ? estimateScan(p, m_layout, stageModel()) : ScanEstimate{};
    m_problems->setText(lines.join(QLatin1Char('\n')));
    m_problems->setVisible(!lines.isEmpty());
    m_map->setPlan(p, m_layout);
    if (m_cameraPanel)  // the plan's camera says the pixel size where the frames do not
        m_cameraPanel->liveView()->setFallbackPixelUm(pixelAtSampleUm(p.camera));
    // A run of this very plan keeps showing its progress.
    m_taken.assign(m_layout.tiles.size(), 0);
    if (m_valid && m_launch->holds(layoutFingerprint(p, m_layout)))
        for (int t = 0; t < static_cast<int>(m_taken.size()); ++t)
            m_taken[static_cast<std::size_t>(t)] = m_runner->isTaken(t);
    m_map->setProgress(m_taken, m_runner->isActive() ? m_runner->currentTile() : -1);
    m_summary->setText(summaryText());
    updateRunUi();
}


QString ScanScreen::summaryText() const
{
    if (!m_valid)
        return tr("No tiles: fix the plan below");
    const auto& g = m_layout.grid;
    const QString grid = static_cast<int>(m_layout.tiles.size()) == g.columns * g.rows
        ? tr("%1 × %2").arg(g.columns).arg(g.rows)
        : tr("%1 of %2 × %3 in the outline").arg(m_layout.tiles.size()).arg(g.columns).arg(g.rows);
    return tr("%1 tiles (%2) · step %3 × %4 mm · about %5 (moves %6, settle %7, exposure %8) · travel %9 mm")
        .arg(m_layout.tiles.size())
        .arg(grid)
        .arg(g.stepXMm, 0, 'f', 3)
        .arg(g.stepYMm, 0, 'f', 3)
        .arg(duration(m_estimate.totalS), duration(m_estimate.moveS), duration(m_estimate.settleS), duration(m_estimate.exposureS))
        .arg(m_estimate.travelMm, 0, 'f', 1);
}

QString ScanScreen::problemsText() const { return m_problems->text(); }

void ScanScreen::updateRunUi()
{
    const auto st = m_runner->state();
    const bool active = m_runner->isActive();
    const bool resumable = st == ScanRunner::State::Paused || st == ScanRunner::State::Stopped;
    m_form->setEnabled(!active);
    m_fileRow->setEnabled(!active);  // the plan that runs stays the plan on screen
    m_folder->setEnabled(!active);
    m_map->setDrawingEnabled(!active);
    if (m_stitchPanel)
        m_stitchPanel->setScanRunning(active);
    m_runButton->setText(resumable && m_runner->takenTiles() > 0 ? tr("Resume") : tr("Run"));
    m_runButton->setToolTip(tr("Run the scan on the stage, or continue it at the next tile (Ctrl+R)"));
    m_runButton->setEnabled(!active && m_valid && m_stage->isReady());
    m_pauseButton->setEnabled(st == ScanRunner::State::Running);
    m_abortButton->setEnabled(active);
    m_exportButton->setEnabled(m_valid && !active);
    m_useCamera->setEnabled(!active);
    if (m_camera)
        m_camera->setInUse(active && m_useCamera->isChecked());
    const int total = m_runner->totalTiles() > 0 ? m_runner->totalTiles() : static_cast<int>(m_layout.tiles.size());
    m_progress->setRange(0, std::max(1, total));
    m_progress->setValue(m_runner->totalTiles() > 0 ? m_runner->takenTiles() : 0);
    QString text;
    if (!m_stage->isReady())
        text = tr("The stage is not connected.");
    else if (m_runner->totalTiles() == 0)
        text = tr("Ready. The run log and exports go to the output folder.");
    else if (active)
        text = tr("%1 · tile %2 of %3 · about %4 left")
                   .arg(ui::words::term(ScanRunner::stateTerm(st)))
                   .arg(m_runner->currentTile() + 1)
                   .arg(m_runner->totalTiles())
                   .arg(duration(m_runner->etaS()));
    else
        text = tr("%1 · %2 of %3 tiles taken").arg(ui::words::term(ScanRunner::stateTerm(st))).arg(m_runner->takenTiles()).arg(m_runner->totalTiles());
    m_runState->setText(text);
}

void ScanScreen::changeEvent(QEvent* event)
{
    // The window rewords the buttons after this event (ui::Retranslator), which drops their
    // keys: they are set again once it has.
    if (event->type() == QEvent::LanguageChange)
        QTimer::singleShot(0, this, &ScanScreen::updateRunUi);
    QWidget::changeEvent(event);
}

bool ScanScreen::confirm(const QString& question) { return !m_confirm || m_confirm(question); }

QString ScanScreen::choose(FileAction action, const QString& title, const QString& filter)
{
    return m_chooser ? m_chooser(action, title, filter) : QString();
}

bool ScanScreen::run()
{
    if (m_runner->isActive())
        return false;
    replan();
    if (!m_valid) {
        emit problem(tr("The plan has problems: %1").arg(m_problems->text()));
        return false;
    }
    const QString folder = outputFolder().trimmed();
    if (folder.isEmpty()) {
        emit problem(tr("Choose an output folder for the run log and the exports."));
        return false;
    }
    if (m_useCamera->isChecked() && !runCamera()) {
        emit problem(tr("Open a camera on the Camera tab first, or clear “Take an image at each tile”."));
        return false;
    }
    handCameraToRunner();
    using Kind = dev::jobs::ScanDecision::Kind;
    dev::jobs::ScanDecision d = m_launch->prepare(plan(), folder);
    if (d.kind == Kind::OtherScansLog) {
        if (!confirm(tr("%1\n\nStart this scan anew in that folder? The old run log is kept under another name.").arg(ui::words::text(d.error)))) {
            emit problem(ui::words::text(d.error));
            return false;
        }
        d = m_launch->beginAnew();
    }
    if (d.kind == Kind::AllTaken) {
        if (!confirm(tr("Every tile of this scan is already taken in %1. Take them all again? The old run log is kept "
                        "under another name.").arg(folder)))
            return false;
        d = m_launch->beginAnew();
    }
    if (d.kind != Kind::Blocked && d.kind != Kind::Ready) {
        emit problem(ui::words::text(d.error));
        return false;
    }
    replan();  // the run's taken tiles on the map
    if (d.kind == Kind::Blocked) {
        QStringList blockers;
        for (const motion::msg::Message& m : d.blockers)
            blockers << ui::words::text(m);
        emit problem(tr("The scan cannot start: %1").arg(blockers.join(QStringLiteral("; "))));
        return false;
    }
    const dev::jobs::ScanOutlook& o = d.outlook;
    // Only the move is news when the scan is short: that question may be waived for the session.
    const Confirm ask = o.longApproach && !o.longRun && m_confirmLongMove ? m_confirmLongMove
                                                                          : Confirm([this](const QString& q) { return confirm(q); });
    if (o.needsConfirmation()
        && !ask(o.resume ? tr("Continue the scan at tile %1 of %2? About %3 are left.").arg(o.takenTiles + 1).arg(o.totalTiles).arg(duration(o.etaS))
                         : tr("Run %1 tiles on the stage? It takes about %2, starting with a move to (%3, %4) mm.")
                               .arg(o.totalTiles)
                               .arg(duration(o.etaS))
                               .arg(o.firstTileMm.xMm, 0, 'f', 2)
                               .arg(o.firstTileMm.yMm, 0, 'f', 2)))
        return false;
    motion::msg::Message error;
    if (!m_launch->start(&error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    if (o.resume)
        emit notice(tr("Continuing at tile %1 of %2 (the run log has the first %3).").arg(o.takenTiles + 1).arg(o.totalTiles).arg(o.takenTiles));
    return true;
}

void ScanScreen::handCameraToRunner()
{
    // Set before the run is prepared: resuming checks the images taken, and the estimate
    // counts the camera's time. A camera swapped since the last run gets a new wrapper.
    dev::camera::Camera* cam = runCamera();
    if (!cam) {
        m_runner->setCamera(nullptr);
        m_scanCamera.reset();
        return;
    }
    if (!m_scanCamera || m_scanCamera->camera() != cam)
        m_scanCamera = std::make_unique<dev::camera::ScanCamera>(cam);
    m_runner->setCamera(m_scanCamera.get());
}

void ScanScreen::pause() { m_runner->pause(); }
void ScanScreen::abort() { m_runner->abort(); }

bool ScanScreen::exportFiles()
{
    replan();
    if (!m_valid) {
        emit problem(tr("The plan has problems: nothing to export."));
        return false;
    }
    const ScanPlan p = plan();
    QStringList written;
    motion::msg::Message error;
    // The run's measured positions when this plan ran into this folder, else the planned ones.
    const QString folder = outputFolder();
    const bool measured = m_launch->holds(layoutFingerprint(p, m_layout), &folder) && m_runner->takenTiles() > 0;
    const bool ok = measured ? m_runner->writeExports(&written, &error)
                             : dev::files::scan::writeExports(outputFolder(), p, m_layout, dev::files::scan::plannedRecords(p, m_layout), &written, &error);
    if (!ok) {
        emit problem(tr("Export failed: %1").arg(ui::words::text(error)));
        return false;
    }
    emit notice(measured ? tr("Exported %1 tiles with the positions measured so far to %2.").arg(m_layout.tiles.size()).arg(outputFolder())
                         : tr("Exported %1 planned tile positions to %2.").arg(m_layout.tiles.size()).arg(outputFolder()));
    return true;
}

} // namespace ui
