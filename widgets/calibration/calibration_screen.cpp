// The Calibration screen's layout, wording and files; running and results are in
// calibration_run.cpp.
#include "widgets/calibration/calibration_screen.h"
#include "widgets/common/button_key.h"

#include "device/files/accuracy/compensation/compensation_file.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/circle_runner.h"
#include "widgets/calibration/deviation_plot.h"
#include "widgets/calibration/fit_panel.h"
#include "widgets/calibration/grid_map_panel.h"
#include "widgets/calibration/polar_plot.h"
#include "widgets/calibration/test_form.h"
#include "widgets/calibration/wheel_guard.h"
#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

CalibrationScreen::CalibrationScreen(QVector<dev::Instrument*> instruments, const QStringList& names, QWidget* parent)
    : QWidget(parent), m_instruments(std::move(instruments)), m_names(names)
{
    setObjectName(QStringLiteral("calibrationScreen"));
    auto* split = new QSplitter(Qt::Horizontal);
    split->addWidget(buildLeft());
    m_tabs = new QTabWidget;
    m_tabs->setObjectName(QStringLiteral("calibrationTabs"));
    auto* livePage = new QWidget;
    auto* liveLayout = new QVBoxLayout(livePage);
    m_live = new DeviationPlot;
    m_live->setObjectName(QStringLiteral("calibrationLivePlot"));
    m_livePolar = new PolarPlot;
    m_livePolar->setObjectName(QStringLiteral("calibrationLivePolar"));
    m_livePolar->hide();
    liveLayout->addWidget(m_live);
    liveLayout->addWidget(m_livePolar);
    m_tabs->addTab(livePage, QString());
    m_tabs->addTab(buildResults(), QString());
    m_fit = new FitPanel;
    m_fit->setObjectName(QStringLiteral("calibrationFit"));
    m_tabs->addTab(m_fit, QString());
    m_tabs->addTab(buildBeforeAfter(), QString());
    m_tabs->addTab(buildCircle(), QString());
    m_gridMap = new GridMapPanel;
    m_gridMap->setFolderSource([this] { return outputFolder(); });
    connect(m_gridMap, &GridMapPanel::problem, this, &CalibrationScreen::problem);
    connect(m_gridMap, &GridMapPanel::notice, this, &CalibrationScreen::notice);
    m_tabs->addTab(m_gridMap, QString());
    split->addWidget(m_tabs);
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(4, 4, 4, 4);
    v->addWidget(split);
    connect(m_fit, &FitPanel::problem, this, &CalibrationScreen::problem);
    connect(m_fit, &FitPanel::notice, this, &CalibrationScreen::notice);
    connect(m_form, &AccuracyTestForm::changed, this, &CalibrationScreen::updateRunUi);
    connect(m_form, &AccuracyTestForm::changed, this, &CalibrationScreen::previewTargets);
    for (dev::Instrument* i : m_instruments)
        if (i) {
            connect(i, &dev::Instrument::stateChanged, this, &CalibrationScreen::updateRunUi);
            connect(i, &dev::Instrument::identified, this, [this] { setInstrument(m_current); });
        }
    setInstrument(m_instruments.size() > 1 ? 1 : 0);
    previewTargets();
    retranslateUi();
}

CalibrationScreen::~CalibrationScreen() = default;

void CalibrationScreen::setCameraSession(CameraSession* session)
{
    m_cameraSession = session;
    m_gridMap->setCameraSession(session);
}

QWidget* CalibrationScreen::buildLeft()
{
    auto* inner = new QWidget;
    auto* v = new QVBoxLayout(inner);
    auto worded = [this](const char* source) {
        auto* l = new QLabel;
        m_worded.append({l, source});
        return l;
    };
    auto* top = new QFormLayout;
    m_instrumentBox = new QComboBox;
    m_instrumentBox->setObjectName(QStringLiteral("calibrationInstrument"));
    WheelGuard::guard(m_instrumentBox);
    m_instrumentBox->addItems(m_names);
    connect(m_instrumentBox, qOverload<int>(&QComboBox::currentIndexChanged), this, &CalibrationScreen::setInstrument);
    top->addRow(worded(QT_TR_NOOP("Instrument")), m_instrumentBox);
    v->addLayout(top);

    auto* testBox = new QGroupBox;
    testBox->setObjectName(QStringLiteral("calibrationTestBox"));
    auto* tv = new QVBoxLayout(testBox);
    m_form = new AccuracyTestForm;
    tv->addWidget(m_form);
    m_formProblems = new QLabel;
    m_formProblems->setObjectName(QStringLiteral("calibrationFormProblems"));
    m_formProblems->setWordWrap(true);
    m_formProblems->setStyleSheet(QStringLiteral("color: #b71c1c"));
    tv->addWidget(m_formProblems);
    auto* files = new QHBoxLayout;
    m_open = new QPushButton;
    m_save = new QPushButton;
    connect(m_open, &QPushButton::clicked, this, [this] {
        const QString path = choose(FileAction::OpenTest, tr("Open an accuracy test"), tr("Accuracy tests (*.accuracy-test.json)"));
        if (!path.isEmpty())
            openTest(path);
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString path = choose(FileAction::SaveTest, tr("Save the accuracy test"), tr("Accuracy tests (*.accuracy-test.json)"));
        if (!path.isEmpty())
            saveTest(path);
    });
    // An interferometer's capture belongs to a test's files: it arrives after the run.
    m_importButton = new QPushButton;
    m_importButton->setObjectName(QStringLiteral("calibrationImport"));
    connect(m_importButton, &QPushButton::clicked, this, &CalibrationScreen::chooseAndImportCapture);
    files->addWidget(m_open);
    files->addWidget(m_save);
    files->addWidget(m_importButton);
    tv->addLayout(files);
    v->addWidget(testBox);

    auto* readBox = new QGroupBox;
    readBox->setObjectName(QStringLiteral("calibrationReadingsBox"));
    auto* rf = new QFormLayout(readBox);
    m_sourceBox = new QComboBox;
    m_sourceBox->setObjectName(QStringLiteral("calibrationSource"));
    WheelGuard::guard(m_sourceBox);
    for (const char* key : {"readback", "gauge", "manual", "interferometer", "camera"})
        m_sourceBox->addItem(QString(), QString::fromLatin1(key));
    rf->addRow(worded(QT_TR_NOOP("From")), m_sourceBox);
    m_port = new QLineEdit;
    m_port->setObjectName(QStringLiteral("calibrationGaugePort"));
    rf->addRow(worded(QT_TR_NOOP("Gauge port")), m_port);
    auto* folderRow = new QHBoxLayout;
    m_folder = new QLineEdit;
    m_folder->setObjectName(QStringLiteral("calibrationFolder"));
    m_folder->setText(QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)).filePath(QStringLiteral("BenchPilot/accuracy")));
    m_browse = new QPushButton;
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString dir = choose(FileAction::Folder, tr("Folder for the run's log, readings and report"), QString());
        if (!dir.isEmpty())
            m_folder->setText(dir);
    });
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_browse);
    rf->addRow(worded(QT_TR_NOOP("Folder")), folderRow);
    connect(m_sourceBox, qOverload<int>(&QComboBox::currentIndexChanged), this, &CalibrationScreen::updateRunUi);
    v->addWidget(readBox);

    auto* runBox = new QGroupBox;
    runBox->setObjectName(QStringLiteral("calibrationRunBox"));
    auto* rv = new QVBoxLayout(runBox);
    auto* buttons = new QHBoxLayout;
    m_runButton = new QPushButton;
    m_runButton->setObjectName(QStringLiteral("calibrationRun"));
    setButtonKey(m_runButton, QKeySequence(Qt::CTRL | Qt::Key_R));
    m_pauseButton = new QPushButton;
    m_pauseButton->setObjectName(QStringLiteral("calibrationPause"));
    setButtonKey(m_pauseButton, QKeySequence(Qt::CTRL | Qt::Key_P));
    m_abortButton = new QPushButton;
    m_abortButton->setObjectName(QStringLiteral("calibrationAbort"));
    setButtonKey(m_abortButton, QKeySequence(Qt::CTRL | Qt::Key_Period));
    connect(m_runButton, &QPushButton::clicked, this, [this] { run(); });
    connect(m_pauseButton, &QPushButton::clicked, this, &CalibrationScreen::pause);
    connect(m_abortButton, &QPushButton::clicked, this, &CalibrationScreen::abort);
    buttons->addWidget(m_runButton);
    buttons->addWidget(m_pauseButton);
    buttons->addWidget(m_abortButton);
    rv->addLayout(buttons);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("calibrationProgress"));
    rv->addWidget(m_progress);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("calibrationState"));
    m_state->setWordWrap(true);
    rv->addWidget(m_state);
    m_manualRow = new QWidget;
    auto* mv = new QVBoxLayout(m_manualRow);
    mv->setContentsMargins(0, 0, 0, 0);
    m_manualPrompt = new QLabel;
    m_manualPrompt->setObjectName(QStringLiteral("calibrationManualPrompt"));
    m_manualPrompt->setWordWrap(true);
    m_manualPrompt->setStyleSheet(QStringLiteral("font-weight: bold"));
    mv->addWidget(m_manualPrompt);
    auto* mh = new QHBoxLayout;
    m_manualValue = new QLineEdit;
    m_manualValue->setObjectName(QStringLiteral("calibrationManualValue"));
    m_manualEnter = new QPushButton;
    m_manualEnter->setObjectName(QStringLiteral("calibrationManualEnter"));
    connect(m_manualValue, &QLineEdit::returnPressed, this, [this] { enterManual(m_manualValue->text()); });
    connect(m_manualEnter, &QPushButton::clicked, this, [this] { enterManual(m_manualValue->text()); });
    mh->addWidget(m_manualValue, 1);
    mh->addWidget(m_manualEnter);
    mv->addLayout(mh);
    m_manualRow->hide();
    rv->addWidget(m_manualRow);
    v->addStretch(1);

    // The definition scrolls; Run, its progress and the manual prompt stay in view
    // below it, so a person at a dial indicator never scrolls to type a reading.
    auto* scroll = new QScrollArea;
    scroll->setWidget(inner);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* column = new QWidget;
    column->setObjectName(QStringLiteral("calibrationLeft"));
    auto* cv = new QVBoxLayout(column);
    cv->setContentsMargins(0, 0, 0, 0);
    cv->addWidget(scroll, 1);
    cv->addWidget(runBox);
    column->setMinimumWidth(360);
    column->setMaximumWidth(430);
    return column;
}

QWidget* CalibrationScreen::buildResults()
{
    auto* page = new QWidget;
    auto* v = new QVBoxLayout(page);
    m_verdict = new QLabel;
    m_verdict->setObjectName(QStringLiteral("calibrationVerdict"));
    m_verdict->setWordWrap(true);
    v->addWidget(m_verdict);
    auto* h = new QHBoxLayout;
    m_figures = new QTableWidget(0, 4);
    m_figures->setObjectName(QStringLiteral("calibrationFigures"));
    m_figures->verticalHeader()->setVisible(false);
    m_figures->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_figures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_figures->setMinimumWidth(330);  // every column readable without a scroll bar
    m_figures->setMaximumWidth(380);
    h->addWidget(m_figures);
    m_resultPlot = new DeviationPlot;
    m_resultPlot->setObjectName(QStringLiteral("calibrationResultPlot"));
    h->addWidget(m_resultPlot, 1);
    v->addLayout(h, 1);
    auto* buttons = new QHBoxLayout;
    m_saveComp = new QPushButton;
    m_saveComp->setObjectName(QStringLiteral("calibrationSaveCompensation"));
    m_reportButton = new QPushButton;
    m_reportButton->setObjectName(QStringLiteral("calibrationReport"));
    connect(m_saveComp, &QPushButton::clicked, this, &CalibrationScreen::saveCompensation);
    connect(m_reportButton, &QPushButton::clicked, this, &CalibrationScreen::writeReport);
    buttons->addWidget(m_saveComp);
    buttons->addWidget(m_reportButton);
    buttons->addStretch(1);
    v->addLayout(buttons);
    return page;
}

QWidget* CalibrationScreen::buildBeforeAfter()
{
    auto* page = new QWidget;
    auto* v = new QVBoxLayout(page);
    m_beforeAfterNote = new QLabel;
    m_beforeAfterNote->setObjectName(QStringLiteral("calibrationBeforeAfterNote"));
    m_beforeAfterNote->setWordWrap(true);
    v->addWidget(m_beforeAfterNote);
    auto* h = new QHBoxLayout;
    m_beforeAfter = new QTableWidget(0, 4);
    m_beforeAfter->setObjectName(QStringLiteral("calibrationBeforeAfter"));
    m_beforeAfter->verticalHeader()->setVisible(false);
    m_beforeAfter->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_beforeAfter->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_beforeAfter->setMinimumWidth(370);  // every column readable without a scroll bar
    m_beforeAfter->setMaximumWidth(420);
    h->addWidget(m_beforeAfter);
    m_beforeAfterPlot = new DeviationPlot;
    h->addWidget(m_beforeAfterPlot, 1);
    v->addLayout(h, 1);
    return page;
}

QWidget* CalibrationScreen::buildCircle()
{
    auto* page = new QWidget;
    auto* h = new QHBoxLayout(page);
    m_circleFigures = new QTableWidget(0, 2);
    m_circleFigures->setObjectName(QStringLiteral("calibrationCircleFigures"));
    m_circleFigures->verticalHeader()->setVisible(false);
    // The values whole; the figures' names take the rest, elided with a tooltip (at 1366 px
    // the names pushed the values out of view behind a scroll bar).
    m_circleFigures->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_circleFigures->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_circleFigures->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_circleFigures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_circleFigures->setMaximumWidth(360);
    h->addWidget(m_circleFigures);
    m_polar = new PolarPlot;
    m_polar->setObjectName(QStringLiteral("calibrationPolar"));
    h->addWidget(m_polar, 1);
    return page;
}

void CalibrationScreen::retranslateUi()
{
    for (const auto& [label, source] : m_worded)
        if (label)
            label->setText(tr(source));
    if (auto* box = findChild<QGroupBox*>(QStringLiteral("calibrationTestBox")))
        box->setTitle(tr("Test"));
    if (auto* box = findChild<QGroupBox*>(QStringLiteral("calibrationReadingsBox")))
        box->setTitle(tr("Readings"));
    if (auto* box = findChild<QGroupBox*>(QStringLiteral("calibrationRunBox")))
        box->setTitle(tr("Run"));
    m_instrumentBox->setToolTip(tr("The instrument the test runs on"));
    m_open->setText(tr("Open…"));
    m_save->setText(tr("Save…"));
    m_sourceBox->setItemText(0, tr("the instrument's readback"));
    m_sourceBox->setItemText(1, tr("a gauge on a serial port"));
    m_sourceBox->setItemText(2, tr("typed at each stop (dial indicator)"));
    m_sourceBox->setItemText(3, tr("laser interferometer (import afterwards)"));
    m_sourceBox->setItemText(4, tr("the camera reading a glass scale"));
    m_sourceBox->setToolTip(tr("The readback is what the position loop closes on: it cannot see the work point's error. "
                               "A gauge or an interferometer at the work point can."));
    m_port->setPlaceholderText(tr("/dev/ttyUSB1, or sim for the simulator's gauge"));
    m_browse->setText(tr("Browse…"));
    m_runButton->setToolTip(tr("Run the test, or go on from where it stopped (Ctrl+R)"));
    m_pauseButton->setText(tr("Pause"));
    m_pauseButton->setToolTip(tr("Stop after the reading in progress (Ctrl+P)"));
    m_abortButton->setText(tr("Abort"));
    m_importButton->setText(tr("Import capture…"));
    m_abortButton->setToolTip(tr("Stop the axes now; Run goes on at the next reading later (Ctrl+.)"));
    m_manualEnter->setText(tr("Enter"));
    m_manualValue->setPlaceholderText(tr("reading in mm, e.g. 40.0012"));
    m_tabs->setTabText(0, tr("Live"));
    m_tabs->setTabText(1, tr("Results"));
    m_tabs->setTabText(2, tr("Compensation"));
    m_tabs->setTabText(3, tr("Before / after"));
    m_tabs->setTabText(4, tr("Circle"));
    m_tabs->setTabText(5, tr("Grid map"));
    m_figures->setHorizontalHeaderLabels({tr("figure"), tr("µm"), tr("limit (µm)"), tr("verdict")});
    m_beforeAfter->setHorizontalHeaderLabels({tr("figure"), tr("before (µm)"), tr("after (µm)"), tr("improvement")});
    m_circleFigures->setHorizontalHeaderLabels({tr("figure"), tr("µm")});
    m_saveComp->setText(tr("Save compensation…"));
    m_saveComp->setToolTip(tr("Writes the fitted compensation as a file (*.compensation.json)"));
    m_reportButton->setText(tr("Write PDF report"));
    m_reportButton->setToolTip(tr("The report of the latest run, written into its folder"));
    showResult();
    showBeforeAfter();
    updateRunUi();
}

void CalibrationScreen::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

dev::Instrument* CalibrationScreen::cur() const
{
    return m_current >= 0 && m_current < m_instruments.size() ? m_instruments[m_current] : nullptr;
}

void CalibrationScreen::setInstrument(int index)
{
    if (index < 0 || index >= m_instruments.size())
        return;
    const bool running = (m_runner && m_runner->isActive()) || (m_circle && m_circle->isActive());
    if (running && index != m_runOn) {
        const QSignalBlocker block(m_instrumentBox);
        m_instrumentBox->setCurrentIndex(m_runOn);
        return;
    }
    m_current = index;
    if (m_gridMap)
        m_gridMap->setInstrument(cur());
    {
        const QSignalBlocker block(m_instrumentBox);
        m_instrumentBox->setCurrentIndex(index);
    }
    QStringList letters;
    if (dev::Instrument* i = cur())
        for (const auto& a : i->identity().axes)
            if (a.unit == dev::proto::AxisUnit::Millimetre)
                letters << QString(a.letter);
    if (letters.isEmpty())
        letters = {QStringLiteral("X"), QStringLiteral("Y")};
    m_form->setAxes(letters);
    m_fit->setInstrument(cur());
    updateRunUi();
}

void CalibrationScreen::setSource(const QString& kind, const QString& port)
{
    const int i = m_sourceBox->findData(kind);
    if (i >= 0)
        m_sourceBox->setCurrentIndex(i);
    if (!port.isEmpty())
        m_port->setText(port);
}

QString CalibrationScreen::outputFolder() const { return m_folder->text(); }
void CalibrationScreen::setOutputFolder(const QString& folder) { m_folder->setText(folder); }

bool CalibrationScreen::openTest(const QString& path)
{
    if ((m_runner && m_runner->isActive()) || (m_circle && m_circle->isActive())) {
        emit problem(tr("A test is running: the test on screen stays until it has finished or been aborted."));
        return false;
    }
    const auto read = dev::files::accuracy::loadAccuracyTestFile(path);
    if (!read.test) {
        emit problem(tr("The test cannot be opened:\n%1").arg(fileProblemLines(read.problems)));
        return false;
    }
    m_form->setTest(*read.test);
    emit notice(tr("Opened %1.").arg(path));
    return true;
}

bool CalibrationScreen::saveTest(const QString& path)
{
    if (const QString typed = m_form->entryProblem(); !typed.isEmpty()) {
        emit problem(tr("The test is not saved: %1").arg(typed));  // a file never gets a number nobody typed
        return false;
    }
    motion::msg::Message error;
    if (!dev::files::accuracy::saveAccuracyTestFile(path, m_form->test(), &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    emit notice(tr("Saved %1.").arg(path));
    return true;
}

void CalibrationScreen::saveCompensation()
{
    const auto model = m_fit->model();
    if (!model)
        return;
    const QString path = choose(FileAction::SaveCompensation, tr("Save the compensation"), tr("Compensations (*.compensation.json)"));
    if (path.isEmpty())
        return;
    dev::files::accuracy::CompensationFile file;
    file.model = *model;
    if (const auto* c = m_fit->fit().chosen())
        file.fit = dev::files::accuracy::FitRecord{c->order, c->sseUm2, c->r2, c->adjustedR2, static_cast<int>(c->points), m_fit->fit().chosenByOperator};
    file.source = m_latest ? m_latest->readingsFile : std::string();
    motion::msg::Message error;
    if (!dev::files::accuracy::saveCompensationFile(path, file, &error))
        emit problem(ui::words::text(error));
    else
        emit notice(tr("Saved %1.").arg(path));
}

QString CalibrationScreen::choose(FileAction action, const QString& title, const QString& filter)
{
    return m_chooser ? m_chooser(action, title, filter) : QString();
}

bool CalibrationScreen::confirm(const QString& question) { return !m_confirm || m_confirm(question); }


} // namespace ui
