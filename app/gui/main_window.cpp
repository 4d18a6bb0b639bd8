#include "main_window.h"

#include "widgets/retranslator.h"

#include "about_dialog.h"
#include "instrument_session.h"
#include "long_move_question.h"
#include "motion_screens.h"
#include "plates_wiring.h"
#include "api_panel.h"
#include "app/api/api_server.h"
#include "device/files/shipped_data.h"
#include "device/jobs/pattern_runner.h"
#include "widgets/plates/recipe_editor.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "device/jobs/scan_runner.h"
#include "device/telemetry/telemetry_hub.h"
#include "widgets/connection_bar.h"
#include "widgets/event_log.h"
#include "widgets/input_policy.h"
#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plots_screen.h"
#include "widgets/patterns/pattern_screen.h"
#include "widgets/profiles_screen.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/scan/scan_screen.h"
#include "calibration_wiring.h"
#include "camera_wiring.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/wording/wording.h"

#include "widgets/wording/translators.h"

#include <QApplication>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QShortcut>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace app {
namespace {
/// Each instrument's group in the settings, in instrument order (0 analyzer, 1 stage).

/// A screen's scroll area: it asks for all its screen needs up to what a 1366 × 768 laptop
/// leaves a screen beside the navigation, the connections, the event log and the status bar
/// (MainWindowSize tests hold the sum). Beyond that the screen scrolls instead of growing the
/// window past the display and pushing E-STOP off it.
class ScreenScroll : public QScrollArea {
public:
    static constexpr int kMostWidthPx = 1212;
    static constexpr int kMostHeightPx = 517;
    using QScrollArea::QScrollArea;
    QSize minimumSizeHint() const override
    {
        if (!widget())
            return QScrollArea::minimumSizeHint();
        const QSize need = widget()->minimumSizeHint().expandedTo(widget()->minimumSize());
        return need.boundedTo(QSize(kMostWidthPx, kMostHeightPx));
    }
};

/// Holds a screen in its scroll area without the screen's height-for-width. A screen with a
/// word-wrapped label reports height-for-width, and QScrollArea then sizes it to its
/// preferred height for the width, not its minimum: Tuning at 1366 × 768 scrolled by 90 px
/// with room for all it needs (found in an Xvfb session). Here the screen fills the room and
/// scrolls only when its minimum does not fit.
class ScreenHolder : public QWidget {
public:
    explicit ScreenHolder(QWidget* screen) : m_screen(screen) { screen->setParent(this); }
    QSize minimumSizeHint() const override { return m_screen->minimumSizeHint().expandedTo(m_screen->minimumSize()); }
    QSize sizeHint() const override { return m_screen->sizeHint(); }

protected:
    void resizeEvent(QResizeEvent*) override { m_screen->setGeometry(rect()); }
    bool event(QEvent* e) override
    {
        if (e->type() == QEvent::LayoutRequest)
            updateGeometry();
        return QWidget::event(e);
    }

private:
    QWidget* m_screen;
};
} // namespace

MainWindow::MainWindow(const MainWindowOptions& options, QWidget* parent) : QMainWindow(parent), m_options(options)
{
    setWindowTitle(tr("BenchPilot"));
    m_longMoves = new LongMoveQuestion(this, m_options.answer);
    ui::InputPolicy::install();  // the wheel turns only a focused spin box or combo, on every screen
    const dev::proto::DeviceKind kinds[kInstrumentCount] = {dev::proto::DeviceKind::Analyzer, dev::proto::DeviceKind::Stage};
    for (int i = 0; i < kInstrumentCount; ++i)
        m_instruments[i].session = new InstrumentSession(kinds[i], instrumentTitle(i), this);
    m_hub = new dev::tele::TelemetryHub(this);
    // Every instrument's positions and following errors from connection on, shown or
    // not, so "what just happened?" can be answered on the Plots screen (docs/telemetry.md, "History").
    m_hub->enableHistory();
    for (int i = 0; i < kInstrumentCount; ++i)
        m_hub->addInstrument(i, m_instruments[i].session->name(), m_instruments[i].session->instrument());
    // The screens drive the instruments through the API's gate: while a script holds
    // control their motion asks first (api_wiring.h).
    m_api = new ApiWiring(sessions().data(), m_hub, m_options.api, this);

    auto* central = new QWidget(this);
    auto* v = new QVBoxLayout(central);
    v->setContentsMargins(6, 6, 6, 0);

    // Connections on the left, the E-stop on the right: both visible on every screen.
    auto* top = new QHBoxLayout;
    auto* bars = new QVBoxLayout;
    for (int i = 0; i < kInstrumentCount; ++i) {
        m_instruments[i].bar = new ui::ConnectionBar(instrumentTitle(i), central);
        bars->addWidget(m_instruments[i].bar);
    }
    top->addLayout(bars, 1);
    // Messages sit beside the E-stop in the row the connections make tall anyway: no row of
    // their own, so one that comes or goes moves nothing under the operator's pointer.
    m_banner = new ui::MessageBanner(central);
    top->addWidget(m_banner, 1);
    if (m_api->strip())
        top->addWidget(m_api->strip(), 1);  // who has control: only while a script has it
    m_reset = new QPushButton(tr("Reset E-stop"), central);
    m_reset->setToolTip(tr("Clear the E-stop latch on both instruments (axes stay where they are)"));
    m_reset->setMinimumHeight(48);
    m_reset->setVisible(false);
    m_estop = new QPushButton(tr("E-STOP\n(Esc)"), central);
    m_estop->setObjectName(QStringLiteral("estop"));
    m_estop->setToolTip(tr("Stop all motion on both instruments at once (Esc, from any screen)"));
    m_estop->setMinimumSize(120, 56);
    m_estop->setStyleSheet(QStringLiteral("#estop { background:#c62828; color:white; font-weight:bold; font-size:15px;"
                                          " border:3px solid #7f0000; border-radius:8px; }"
                                          "#estop:pressed { background:#8e0000; }"));
    m_estop->setFocusPolicy(Qt::NoFocus);
    top->addWidget(m_reset);
    top->addWidget(m_estop);
    v->addLayout(top);


    auto* body = new QHBoxLayout;
    m_nav = new QListWidget(central);
    m_nav->setFixedWidth(130);
    m_nav->setFocusPolicy(Qt::NoFocus);
    m_stack = new QStackedWidget(central);
    body->addWidget(m_nav);
    body->addWidget(m_stack, 1);
    v->addLayout(body, 1);
    setCentralWidget(central);

    m_camera = new ui::CameraSession(this);
    m_camera->setFactory(m_options.cameraFactory ? m_options.cameraFactory : ui::CameraSession::Factory([this](const QString& source, QString* error) {
        return makeCamera(source, m_instruments[1].session, error, m_options.specimen);
    }));
    m_camera->setLister(m_options.cameraLister ? m_options.cameraLister : ui::CameraSession::Lister(&listCameras));
    connect(m_camera, &ui::CameraSession::problem, this, &MainWindow::warn);
    const auto chooseSnapFile = [this](const QString& title, const QString& filter) {
        return QFileDialog::getSaveFileName(this, title, QStandardPaths::writableLocation(QStandardPaths::PicturesLocation), filter);
    };
    m_jogTabs = new QTabWidget;
    for (int i = 0; i < kInstrumentCount; ++i) {
        auto* jog = m_instruments[i].jog = new ui::JogScreen(m_api->screenInstrument(i));
        if (m_options.confirmDialogs) {
            jog->setConfirm([this](const QString& q) { return confirm(q); });
            jog->setConfirmLongMove([this](const QString& q) { return m_longMoves->ask(q); });
        }
        connect(jog, &ui::JogScreen::problem, this, &MainWindow::warn);
        jog->setTelemetry(m_hub, i);
        if (i == 1) {  // the stage is where the microscope's camera looks
            m_jogCamera = new ui::CameraPanel(m_camera, m_api->screenInstrument(i));
            m_jogCamera->setObjectName(QStringLiteral("jogCamera"));
            m_jogCamera->setFileChooser(chooseSnapFile);
            if (m_options.confirmDialogs)
                m_jogCamera->setConfirm([this](const QString& q) { return confirm(q); });
            connect(m_jogCamera, &ui::CameraPanel::problem, this, &MainWindow::warn);
            connect(m_jogCamera, &ui::CameraPanel::notice, this, &MainWindow::inform);
            jog->addPanel(m_jogCamera);
        }
        m_jogTabs->addTab(jog, m_instruments[i].session->name());
    }
    connect(m_jogTabs, &QTabWidget::currentChanged, this, [this](int i) { m_instruments[i].jog->setFocus(); });
    addScreen(QStringLiteral("jog"), tr("Jog"), m_jogTabs);
    m_plots = new ui::PlotsScreen(m_hub);
    m_plots->setFileChooser([this](const QString& title, const QString& filter) {
        return QFileDialog::getSaveFileName(this, title, QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation), filter);
    });
    connect(m_plots, &ui::PlotsScreen::problem, this, &MainWindow::warn);
    addScreen(QStringLiteral("plots"), tr("Plots"), m_plots);
    addScreen(QStringLiteral("profiles"), tr("Profiles"), new ui::ProfilesScreen);
    m_tuning = new ui::TuningScreen(m_hub);
    for (int i = 0; i < kInstrumentCount; ++i)
        m_tuning->addInstrument(i, m_instruments[i].session->name(), m_api->screenInstrument(i));
    m_tuning->setFileChooser([this](const QString& title, const QString& filter, bool save) {
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        return save ? QFileDialog::getSaveFileName(this, title, dir, filter) : QFileDialog::getOpenFileName(this, title, dir, filter);
    });
    if (m_options.confirmDialogs)
        m_tuning->setConfirm([this](const QString& q) {
            return QMessageBox::question(this, tr("Apply gains"), q, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
                == QMessageBox::Yes;
        });
    connect(m_tuning, &ui::TuningScreen::problem, this, &MainWindow::warn);
    addScreen(QStringLiteral("tuning"), tr("Tuning"), m_tuning);
    {
        MotionScreens::Hooks hooks;
        if (m_options.confirmDialogs) {
            hooks.confirm = [this](const QString& q) { return confirm(q); };
            hooks.confirmLongMove = [this](const QString& q) { return m_longMoves->ask(q); };
            hooks.chooseFile = [this](const QString& title, const QString& filter, bool save) {
                const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
                return save ? QFileDialog::getSaveFileName(this, title, dir, filter) : QFileDialog::getOpenFileName(this, title, dir, filter);
            };
        }
        hooks.warn = [this](const QString& m) { warn(m); };
        hooks.instrument = [this](int i) { return m_api->screenInstrument(i); };
        m_motion = new MotionScreens(sessions().data(), m_hub, hooks, this);
        addScreen(QStringLiteral("joystick"), tr("Joystick"), m_motion->joystickTabs());
        addScreen(QStringLiteral("patterns"), tr("Patterns"), m_motion->patterns());
    }
    m_plates = new ui::PlatesScreen(m_api->screenInstrument(0));
    connect(m_plates, &ui::PlatesScreen::problem, this, &MainWindow::warn);
    connect(m_plates, &ui::PlatesScreen::note, this, &MainWindow::inform);
    wirePlatesScreen(m_plates, this, m_options);
    addScreen(QStringLiteral("plates"), tr("Plates"), m_plates);
    m_scan = new ui::ScanScreen(m_api->screenInstrument(1));
    m_scan->setFileChooser([this](ui::ScanScreen::FileAction a, const QString& title, const QString& filter) {
        const QString docs = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        if (a == ui::ScanScreen::FileAction::Open)
            return QFileDialog::getOpenFileName(this, title, docs, filter);
        if (a == ui::ScanScreen::FileAction::Save)
            return QFileDialog::getSaveFileName(this, title, docs, filter);
        return QFileDialog::getExistingDirectory(this, title, filter.isEmpty() ? docs : filter);
    });
    if (m_options.confirmDialogs) {
        m_scan->setConfirm([this](const QString& q) { return confirm(q); });
        m_scan->setConfirmLongMove([this](const QString& q) { return m_longMoves->ask(q); });
    }
    m_scan->setCameraSession(m_camera);
    m_scan->cameraPanel()->setFileChooser(chooseSnapFile);
    if (m_options.confirmDialogs)
        m_scan->cameraPanel()->setConfirm([this](const QString& q) { return confirm(q); });
    connect(m_scan, &ui::ScanScreen::problem, this, &MainWindow::warn);
    connect(m_scan, &ui::ScanScreen::notice, this, &MainWindow::inform);
    addScreen(QStringLiteral("scan"), tr("Scan"), m_scan);
    m_calibration = makeCalibrationScreen(sessions().data(), this, m_banner, m_hub, m_options);
    m_calibration->setCameraSession(m_camera);
    addScreen(QStringLiteral("calibration"), tr("Calibration"), m_calibration);
    connect(m_nav, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    // The jog keys work on every screen: a screen about one instrument jogs that one, any
    // other the instrument of the Jog screen's tab. The Joystick screen's arrow keys are its
    // stick's. A key held while the screen changes stops its axis.
    for (int i = 0; i < kInstrumentCount; ++i)
        m_instruments[i].jog->setKeysFromOtherScreens([this, i] {
            const QString screen = m_screenNames.value(m_nav->currentRow());
            if (screen == QLatin1String("jog") || screen == QLatin1String("joystick"))
                return false;
            const int instrument = screen == QLatin1String("plates") ? 0 : screen == QLatin1String("scan") ? 1 : m_jogTabs->currentIndex();
            return instrument == i;
        });
    connect(m_nav, &QListWidget::currentRowChanged, this, [this] {
        for (auto& slot : m_instruments)
            slot.jog->endHolds();
    });
    m_nav->setCurrentRow(0);

    m_log = new ui::EventLog;
    auto* dock = m_logDock = new QDockWidget(tr("Event log"), this);
    dock->setObjectName(QStringLiteral("eventLogDock"));
    dock->setWidget(m_log);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    // The log starts three (compact) rows high: what just happened stays in view on a 768-pixel
    // screen. Two rows of the table's usual height said almost nothing; more height leaves the
    // Jog screen no room to spare at 708 px, where a message coming would then move it.
    const int titlePx = dock->minimumSizeHint().height() - m_log->minimumSizeHint().height();
    resizeDocks({dock}, {titlePx + m_log->heightForRows(3)}, Qt::Vertical);
    wireApi(dock);

    for (auto& slot : m_instruments) {
        slot.statusLabel = new QLabel(this);
        statusBar()->addWidget(slot.statusLabel, 1);
    }
    for (int i = 0; i < kInstrumentCount; ++i)
        wireSession(i, m_instruments[i].bar);
    auto* statsTimer = new QTimer(this);
    connect(statsTimer, &QTimer::timeout, this, &MainWindow::updateStatusBar);
    statsTimer->start(500);

    auto* esc = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    esc->setContext(Qt::ApplicationShortcut);
    connect(esc, &QShortcut::activated, this, &MainWindow::emergencyStop);
    connect(m_estop, &QPushButton::clicked, this, &MainWindow::emergencyStop);
    connect(m_reset, &QPushButton::clicked, this, &MainWindow::resetEStop);
    for (int i = 1; i <= 9 && i <= m_nav->count(); ++i) {
        auto* sc = new QShortcut(QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_0 + i)), this);
        connect(sc, &QShortcut::activated, this, [this, i] { m_nav->setCurrentRow(i - 1); });
    }

    buildFileMenu();
    if (m_options.translators)
        buildLanguageMenu();
    retranslateUi();

    // A first start on a laptop: the preferred size must not put E-STOP past the screen's
    // edge. A screen smaller than it gets the window maximized (the window manager then
    // allows for its frame and panels) and sized to the screen where no manager does.
    // Tests and screenshots size their window themselves.
    const QSize preferred(1400, 860);
    const QSize room = screen() && m_options.persistSettings ? screen()->availableGeometry().size() : preferred;
    resize(preferred.boundedTo(room));
    if (preferred.boundedTo(room) != preferred)
        setWindowState(windowState() | Qt::WindowMaximized);
    ui::ConnectionChoice choices[kInstrumentCount];
    if (m_options.persistSettings)
        loadSettings();
    for (int i = 0; i < kInstrumentCount; ++i) {
        if (m_options.connection[i])
            m_instruments[i].bar->setChoice(*m_options.connection[i]);
        choices[i] = m_instruments[i].bar->choice();
    }
    if (m_options.showInstrument >= 0)
        showInstrument(m_options.showInstrument);
    if (m_options.autoConnect)
        for (int i = 0; i < kInstrumentCount; ++i)
            m_instruments[i].session->connectTo(choices[i]);
    updateStatusBar();
}

MainWindow::~MainWindow()
{
    // The API's calls end (their commands run to their ends) while the instruments live.
    delete m_api;
    m_api = nullptr;
    // The sessions are the first children to go; a client that reports "disconnected"
    // while its session is destroyed must not reach updateStatusBar(), which reads the
    // other, possibly already destroyed, session.
    for (const auto& slot : m_instruments)
        slot.session->instrument()->disconnect(this);
}

void MainWindow::wireApi(QDockWidget* logDock)
{
    if (!m_api->startError().isEmpty())
        m_banner->show(ui::MessageBanner::Level::Warning, m_api->startError());
    if (!m_api->server())
        return;
    dev::jobs::PatternRunner* const patterns[kInstrumentCount] = {m_motion->runner(0), m_motion->runner(1)};
    m_api->watchRunners(m_plates->runner(), m_scan->runner(), patterns, m_tuning->runner(), m_calibration);
    if (m_options.confirmDialogs)
        m_api->setAsk([this](const QString& q) {
            QMessageBox box(QMessageBox::Question, tr("A script has control"), q, QMessageBox::Cancel, this);
            auto* take = box.addButton(tr("Take back"), QMessageBox::AcceptRole);
            box.setDefaultButton(QMessageBox::Cancel);
            box.exec();
            return box.clickedButton() == take;
        });
    auto* dock = new QDockWidget(tr("Scripting API"), this);
    dock->setObjectName(QStringLiteral("apiDock"));
    auto* scroll = new QScrollArea(dock);  // a short dock area still shows it, scrolling
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_api->panel());
    dock->setWidget(scroll);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    tabifyDockWidget(logDock, dock);
    logDock->raise();
    dock->hide();  // until asked for (the status bar's API button): no tab bar's height meanwhile
    dock->setFeatures(dock->features() | QDockWidget::DockWidgetClosable);
    statusBar()->addPermanentWidget(m_api->statusButton());
    connect(m_api, &ApiWiring::showPanelRequested, this, [dock] {
        // Floating the first time: the window below keeps its height on a 768-pixel screen.
        if (!dock->isVisible() && !dock->property("shownOnce").toBool()) {
            dock->setProperty("shownOnce", true);
            dock->setFloating(true);
            dock->resize(560, 360);
        }
        dock->show();
        dock->raise();
    });
    connect(m_api, &ApiWiring::note, this, [this](const QString& client, const QString& text, bool problem) {
        m_log->addNote(tr("API"), client.isEmpty() ? tr("server") : client, text, problem);
    });
    connect(m_api, &ApiWiring::handedOver, this, &MainWindow::inform);
}

void MainWindow::addScreen(const QString& name, const QString& title, QWidget* screen)
{
    m_screenNames << name;
    m_nav->addItem(title);
    // Every screen scrolls when its content is taller or wider than the window: a screen in a
    // busy state (tuning results, long file names) can no longer grow the window past a 1366 × 768
    // laptop's screen and push E-STOP off it.
    auto* scroll = new ScreenScroll(m_stack);
    scroll->setObjectName(QStringLiteral("screenScroll_%1").arg(name));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setFocusPolicy(Qt::NoFocus);
    scroll->setWidget(new ScreenHolder(screen));
    m_stack->addWidget(scroll);
}

QStringList MainWindow::screenNames() const { return m_screenNames; }

bool MainWindow::showScreen(const QString& name)
{
    const int i = m_screenNames.indexOf(name);
    if (i < 0)
        return false;
    m_nav->setCurrentRow(i);
    return true;
}

void MainWindow::showInstrument(int index)
{
    m_jogTabs->setCurrentIndex(index);
    m_motion->showInstrument(index);
}

bool MainWindow::confirm(const QString& question)
{
    if (m_options.answer)
        return m_options.answer(question);
    return QMessageBox::question(this, tr("Confirm move"), question, QMessageBox::Yes | QMessageBox::Cancel,
                                 QMessageBox::Cancel)
        == QMessageBox::Yes;
}

void MainWindow::wireSession(int i, ui::ConnectionBar* bar)
{
    InstrumentSession* s = m_instruments[i].session;
    dev::Instrument* c = s->instrument();
    connect(bar, &ui::ConnectionBar::connectRequested, this, [s](const ui::ConnectionChoice& ch) { s->connectTo(ch); });
    connect(bar, &ui::ConnectionBar::disconnectRequested, this, [this, i, s, bar] {
        if (!confirmDisconnect(i))
            return;
        bar->showActivity({});
        s->disconnectLink();
    });
    // A port is asked which protocol it speaks before a backend takes it (a few seconds at most).
    connect(s, &InstrumentSession::detecting, bar, &ui::ConnectionBar::showActivity);
    connect(s, &InstrumentSession::connectFailed, this, [this, s, bar](const QString& why) {
        bar->showActivity({});
        bar->showState(dev::LinkState::Disconnected, s->instrument()->linkDescription());
        m_banner->show(ui::MessageBanner::Level::Error, QStringLiteral("%1: %2").arg(s->name(), why));
        m_log->addNote(s->name(), tr("link error"), why, true);
    });
    connect(bar, &ui::ConnectionBar::profileFileRequested, this, [this, bar] {
        // The profiles BenchPilot ships are where a first-time user looks for one.
        const QString shipped = dev::files::shippedMachinesDirectory();
        const QString path = QFileDialog::getOpenFileName(this, tr("Machine profile"),
                                                          shipped.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) : shipped,
                                                          tr("Machine profiles (*.machine.json);;All files (*)"));
        if (!path.isEmpty())
            bar->addProfile(path);
    });
    connect(c, &dev::Instrument::stateChanged, bar, [bar] { bar->showActivity({}); });
    // A controller's own messages and the lines a backend did not understand: logged, never banners.
    connect(c, &dev::Instrument::noted, this, [this, s](const motion::msg::Message& m) { m_log->addNote(s->name(), tr("device"), ui::words::text(m)); });
    // A controller that no longer trusts its position (GRBL's alarm after an E-stop or a reset in
    // motion): say so once, and what to do.
    connect(c, &dev::Instrument::statusChanged, this, [this, s, i](const dev::InstrumentStatus& st) {
        if (st.positionLost && !m_instruments[i].positionLostShown)
            m_banner->show(ui::MessageBanner::Level::Error, [s] {
                return tr("%1: the controller no longer trusts its position (an alarm, an E-stop or a reset while it was "
                          "moving). Home it, or Unlock on the Jog screen to take the position it believes.")
                    .arg(s->name());
            });
        m_instruments[i].positionLostShown = st.positionLost;
    });
    auto showState = [this, i, c, bar] {
        const auto& id = c->identity();
        const QString who = c->state() == dev::LinkState::Ready || c->state() == dev::LinkState::Identified
            ? QStringLiteral("%1 · %2 · %3").arg(ui::words::modelName(id), id.firmware, c->linkDescription())
            : c->linkDescription();
        bar->showState(c->state(), who);
        updateStatusBar();
        updateEStopUi();
        (void)i;
    };
    connect(c, &dev::Instrument::stateChanged, this, showState);
    m_connectionTexts.push_back(showState);  // the link's description is worded: again on a language switch
    // A lost link, and what it cut short, are a state that ends once the link is ready again:
    // a banner still saying "link lost" over a working link is the screen contradicting the machine.
    const QString linkKey = QStringLiteral("link.%1").arg(i);
    connect(c, &dev::Instrument::stateChanged, this, [this, s, linkKey](dev::LinkState st) {
        if (st == dev::LinkState::Lost)
            m_banner->show(
                ui::MessageBanner::Level::Error,
                [s] { return tr("%1: link lost. Motion on the instrument stops by itself; reconnect when the cable is back.").arg(s->name()); },
                linkKey);
        if (st == dev::LinkState::Ready)
            m_banner->withdraw(linkKey);
        m_log->addNote(s->kind(), "log.kind.link", motion::msg::make("telemetry.link_state", {motion::msg::term("state", dev::linkStateTerm(st))}),
                       st == dev::LinkState::Lost);
    });
    connect(c, &dev::Instrument::statusChanged, this, [this] { updateEStopUi(); });
    connect(c, &dev::Instrument::linkError, this, [this, s, linkKey](const motion::msg::Message& m) {
        m_banner->show(ui::MessageBanner::Level::Error, [s, m] { return QStringLiteral("%1: %2").arg(s->name(), ui::words::text(m)); }, linkKey);
        m_log->addNote(s->kind(), "log.kind.link_error", m, true);
    });
    connect(c, &dev::Instrument::requestFailed, this, [this, s, linkKey](const dev::RequestError& e) {
        // A request the operator's own Disconnect cut short is what they asked for: logged, no alarm.
        const motion::msg::Arg* cause = e.message.id == "request.abandoned" ? e.message.arg("cause") : nullptr;
        const auto* inner = cause ? std::get_if<std::shared_ptr<const motion::msg::Message>>(&cause->value) : nullptr;
        if (inner && *inner && (*inner)->id == "link.disconnected") {
            m_log->addNote(s->kind(), "log.kind.refused", e.message, false);
            return;
        }
        // Refused because the E-stop was latched: a fact that ends with the reset, as the E-stop's own message does.
        const bool latched = e.kind == dev::RequestError::Kind::Device && e.code == dev::proto::ErrorCode::EStopActive;
        const QString key = latched ? QStringLiteral("estop") : e.kind == dev::RequestError::Kind::LinkDown ? linkKey : QString();
        m_banner->show(
            ui::MessageBanner::Level::Error, [s, why = e.message] { return QStringLiteral("%1: %2").arg(s->name(), ui::words::text(why)); }, key);
        m_log->addNote(s->kind(), "log.kind.refused", e.message, true);
    });
    connect(c, &dev::Instrument::eventReceived, this, [this, s, c](const dev::DeviceEvent& e) {
        m_log->addEvent(s->kind(), c->identity(), e);
        if (e.kind == dev::proto::EventKind::LimitHit || e.kind == dev::proto::EventKind::Fault || e.kind == dev::proto::EventKind::LostSteps)
            m_banner->show(ui::MessageBanner::Level::Warning, [s, e] { return QStringLiteral("%1: %2").arg(s->name(), ui::words::eventDetail(e)); });
    });
    showState();
}

void MainWindow::updateStatusBar()
{
    for (auto& slot : m_instruments) {
        dev::Instrument* c = slot.session->instrument();
        const dev::LinkStats st = c->stats();
        QString text = QStringLiteral("%1: %2").arg(slot.session->name(), ui::words::term(dev::linkStateTerm(c->state())));
        // "ready" while the E-stop is latched would contradict the red banner: the latch is the state.
        const bool latched = c->isReady() && c->status().estop;
        if (latched)
            text = tr("%1: E-STOP latched — press Reset E-stop to clear").arg(slot.session->name());
        if (c->state() == dev::LinkState::Ready)
            text += QStringLiteral(" · %1").arg(ui::words::modelName(c->identity()));
        const quint64 bad = st.crcErrors + st.malformed + st.oversize;
        if (bad || st.droppedBytes)
            text += tr(" · %1 bad frames, %2 bytes skipped").arg(bad).arg(st.droppedBytes);
        if (st.retransmits || st.timeouts)
            text += tr(" · %1 retries, %2 timeouts").arg(st.retransmits).arg(st.timeouts);
        if (st.lostSamples)
            text += tr(" · %1 samples lost").arg(st.lostSamples);
        slot.statusLabel->setText(text);
        slot.statusLabel->setStyleSheet(latched ? QStringLiteral("color:#b71c1c; font-weight:bold;") : QString());
    }
}

QString MainWindow::statusText(int index) const { return m_instruments[index].statusLabel->text(); }

std::array<InstrumentSession*, MainWindow::kInstrumentCount> MainWindow::sessions() const
{
    std::array<InstrumentSession*, kInstrumentCount> out{};
    for (int i = 0; i < kInstrumentCount; ++i)
        out[i] = m_instruments[i].session;
    return out;
}

QString MainWindow::instrumentTitle(int index) { return index == 0 ? tr("Analyzer") : tr("Stage"); }

void MainWindow::warn(const QString& message) { m_banner->show(ui::MessageBanner::Level::Warning, message); }
void MainWindow::inform(const QString& message) { m_banner->show(ui::MessageBanner::Level::Info, message); }

void MainWindow::updateEStopUi()
{
    bool latched = false;
    for (const auto& slot : m_instruments)
        latched = latched || (slot.session->instrument()->isReady() && slot.session->instrument()->status().estop);
    m_reset->setVisible(latched);
    if (latched != m_latchShown) {
        m_latchShown = latched;
        updateStatusBar();
    }
}

void MainWindow::emergencyStop()
{
    // Both instruments, whichever screen is showing: the operator should not have to think.
    for (const auto& slot : m_instruments)
        slot.jog->clearFocus();
    m_motion->stopSticks();
    for (const auto& slot : m_instruments)
        if (slot.session->instrument()->isReady())
            slot.session->instrument()->estop();
    // A GRBL controller stops with a soft reset: one that was moving loses its position.
    bool positionAtRisk = false;
    for (const auto& slot : m_instruments) {
        const dev::Instrument* c = slot.session->instrument();
        positionAtRisk = positionAtRisk || (c->isReady() && !c->capabilities().testFlag(dev::Capability::StopsOnHostLoss));
    }
    m_banner->show(
        ui::MessageBanner::Level::Error,
        [positionAtRisk] {
            return positionAtRisk ? tr("E-STOP: all motion halted. A GRBL controller that was moving has lost its position: home "
                                       "it (or unlock it on your word) before absolute moves. Check the machine, then press Reset E-stop.")
                                  : tr("E-STOP: all motion halted. Check the machine, then press Reset E-stop.");
        },
        QStringLiteral("estop"));
}

void MainWindow::resetEStop()
{
    for (const auto& slot : m_instruments)
        if (slot.session->instrument()->isReady() && slot.session->instrument()->status().estop)
            slot.session->instrument()->reset();
    m_banner->withdraw(QStringLiteral("estop"));
    m_banner->show(ui::MessageBanner::Level::Info, [] { return tr("E-stop cleared. Re-home the axes if anything was moved by hand."); });
}

QStringList MainWindow::runningJobs(int index) const
{
    QStringList out;
    if (index == 0 && m_plates->runHoldsFiles())
        out << tr("a plate run");
    if (index == 1) {
        const auto st = m_scan->runner()->state();
        if (st == dev::jobs::ScanRunner::State::Running || st == dev::jobs::ScanRunner::State::Pausing || st == dev::jobs::ScanRunner::State::Paused)
            out << tr("a scan");
        if (m_tuning->runner()->busy())
            out << tr("a tuning test");
    }
    if (m_motion->runner(index) && m_motion->runner(index)->busy())
        out << tr("a pattern");
    return out;
}

bool MainWindow::confirmDisconnect(int index)
{
    const QStringList jobs = runningJobs(index);
    if (jobs.isEmpty() || (!m_options.confirmDialogs && !m_options.answer))
        return true;
    return confirm(tr("%1 is running %2. Disconnect anyway? The instrument stops the job when the link goes quiet; "
                      "it can be resumed after you connect again.")
                       .arg(m_instruments[index].session->name(), jobs.join(tr(", "))));
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    // The one rule: quitting with unsaved edits or a running job asks first.
    if (m_options.confirmDialogs || m_options.answer) {
        QStringList reasons;
        for (int i = 0; i < kInstrumentCount; ++i)
            for (const QString& job : runningJobs(i))
                reasons << tr("%1 is running %2").arg(m_instruments[i].session->name(), job);
        if (m_plates->recipeEditor()->isModified())
            reasons << tr("the recipe has changes that are not saved");
        if (!reasons.isEmpty() && !confirm(tr("Quit BenchPilot? %1.").arg(reasons.join(tr("; "))))) {
            event->ignore();
            return;
        }
    }
    for (const auto& slot : m_instruments)
        slot.session->instrument()->stopAllJogs();
    if (m_options.persistSettings)
        saveSettings();
    savePlatesSettings(m_plates, m_options);
    QMainWindow::closeEvent(event);
}

} // namespace app
