// The main window's language (the menu, switching at run time, rewording every screen)
// and what it keeps between runs (window layout, connections, each screen's choices).
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
#include <QAction>
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
#include <QKeySequence>
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

#include <iterator>

namespace app {
namespace {
// One settings group per instrument, in the order of the instrument list.
constexpr const char* kSettingsKeys[] = {"analyzer", "stage"};
} // namespace

void MainWindow::buildFileMenu()
{
    // Quitting goes through close(), so a running job or unsaved recipe still asks first. The
    // key belongs to the window, so it works while the menu is closed and in a window built
    // without menus.
    m_quitAction = new QAction(this);
    m_quitAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));  // QKeySequence::Quit is empty on some platforms
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    addAction(m_quitAction);
}

void MainWindow::buildLanguageMenu()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_quitAction);
    m_settingsMenu = menuBar()->addMenu(QString());
    m_languageMenu = m_settingsMenu->addMenu(QString());
    m_languages = new QActionGroup(this);
    // The languages are named in their own words, so a person who cannot read the
    // current one still finds theirs.
    const std::pair<QString, QString> entries[] = {{QStringLiteral("system"), QString()},
                                                   {QStringLiteral("en"), QStringLiteral("English")},
                                                   {QStringLiteral("zh_CN"), QStringLiteral("简体中文")}};
    for (const auto& [code, name] : entries) {
        QAction* a = m_languageMenu->addAction(name);
        a->setData(code);
        a->setCheckable(true);
        m_languages->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = code] { setLanguage(code); });
    }
    QSettings st;
    m_languageSetting = m_options.persistSettings ? st.value(QStringLiteral("language"), QStringLiteral("system")).toString()
                                                  : m_options.translators->language();
    menuBar()->addMenu(new HelpMenu(this));
}

void MainWindow::setLanguage(const QString& language)
{
    m_languageSetting = language;
    if (m_options.persistSettings)
        QSettings().setValue(QStringLiteral("language"), language);
    if (m_options.translators) {
        const QString before = m_options.translators->language();
        m_options.translators->setLanguage(language);  // LanguageChange reaches every widget
        // Texts the screens set once with tr() are reworded here, after the widgets that
        // word themselves on LanguageChange have done so (what they keep from before, a
        // device's description say, is reworded with the rest); the texts screens build
        // as things change come in the new language by themselves.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        ui::Retranslator::retranslate(QApplication::topLevelWidgets(), before, m_options.translators->language());
    }
    retranslateUi();
}

void MainWindow::retranslateUi()
{
    setWindowTitle(tr("BenchPilot"));
    for (const auto& reword : m_connectionTexts)
        reword();
    const std::pair<const char*, QString> titles[] = {
        {"jog", tr("Jog")},         {"plots", tr("Plots")},         {"profiles", tr("Profiles")},
        {"tuning", tr("Tuning")},   {"joystick", tr("Joystick")},   {"patterns", tr("Patterns")},
        {"plates", tr("Plates")},   {"scan", tr("Scan")},
    };
    for (int i = 0; i < m_screenNames.size() && i < m_nav->count(); ++i)
        for (const auto& [name, title] : titles)
            if (m_screenNames[i] == QLatin1String(name))
                m_nav->item(i)->setText(title);
    for (int i = 0; i < kInstrumentCount; ++i) {
        m_instruments[i].bar->setTitle(instrumentTitle(i));
        if (m_hub)
            m_hub->setInstrumentName(i, m_instruments[i].session->name());
        if (m_tuning)
            m_tuning->renameInstrument(i, m_instruments[i].session->name());
        if (m_jogTabs && m_jogTabs->count() >= kInstrumentCount)
            m_jogTabs->setTabText(i, instrumentTitle(i));
    }
    m_reset->setText(tr("Reset E-stop"));
    m_reset->setToolTip(tr("Clear the E-stop latch on both instruments (axes stay where they are)"));
    m_estop->setText(tr("E-STOP\n(Esc)"));
    m_estop->setToolTip(tr("Stop all motion on both instruments at once (Esc, from any screen)"));
    if (m_logDock)
        m_logDock->setWindowTitle(tr("Event log"));
    m_quitAction->setText(tr("&Quit"));
    if (m_fileMenu)
        m_fileMenu->setTitle(tr("&File"));
    if (m_settingsMenu) {
        m_settingsMenu->setTitle(tr("&Settings"));
        m_languageMenu->setTitle(tr("&Language"));
        for (QAction* a : m_languages->actions()) {
            if (a->data().toString() == QLatin1String("system"))
                a->setText(tr("System default"));
            a->setChecked(a->data().toString() == m_languageSetting);
        }
    }
    updateStatusBar();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    // A hold whose key-up went to another application must not keep the machine moving.
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        for (const auto& slot : m_instruments)
            slot.session->instrument()->stopAllJogs();
    QMainWindow::changeEvent(event);
}

void MainWindow::loadSettings()
{
    static_assert(std::size(kSettingsKeys) == kInstrumentCount, "a settings group per instrument");
    QSettings st;
    restoreGeometry(st.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(st.value(QStringLiteral("window/state")).toByteArray());
    for (int i = 0; i < kInstrumentCount; ++i) {
        st.beginGroup(QStringLiteral("connection/%1").arg(QLatin1String(kSettingsKeys[i])));
        ui::ConnectionChoice c;
        c.simulator = st.value(QStringLiteral("simulator"), true).toBool();
        c.port = st.value(QStringLiteral("port")).toString();
        c.serialNumber = st.value(QStringLiteral("serial_number")).toString();
        c.baud = st.value(QStringLiteral("baud"), 115200).toInt();
        c.profile = st.value(QStringLiteral("profile")).toString();
        for (const QString& path : st.value(QStringLiteral("profiles")).toStringList())
            m_instruments[i].bar->addProfile(path, false);
        st.endGroup();
        m_instruments[i].bar->setChoice(c);
        m_instruments[i].jog->setSpeedFraction(st.value(QStringLiteral("jog/%1/speed").arg(QLatin1String(kSettingsKeys[i])), 0.2).toDouble());
    }
    m_motion->load(st);
    m_nav->setCurrentRow(std::clamp(st.value(QStringLiteral("window/screen"), 0).toInt(), 0, m_nav->count() - 1));
    QString scanError;
    const QString scanPlan = st.value(QStringLiteral("scan/plan")).toString();
    if (!scanPlan.isEmpty() && !m_scan->setPlanText(scanPlan, &scanError))
        m_log->addNote(tr("Scan"), tr("settings"), tr("the last scan plan did not load: %1").arg(scanError), true);
    if (st.contains(QStringLiteral("scan/folder")))
        m_scan->setOutputFolder(st.value(QStringLiteral("scan/folder")).toString());
    m_camera->setRecentSources(st.value(QStringLiteral("camera/recent")).toStringList());
    m_camera->setSource(st.value(QStringLiteral("camera/source"), QStringLiteral("sim")).toString());
    m_camera->setExposureMs(st.value(QStringLiteral("camera/exposure_ms"), 10.0).toDouble());
    m_camera->setAutoContrast(st.value(QStringLiteral("camera/auto_contrast"), true).toBool());
    m_scan->setTakesImages(st.value(QStringLiteral("scan/take_images"), false).toBool());
    m_jogTabs->setCurrentIndex(std::clamp(st.value(QStringLiteral("window/instrument"), 0).toInt(), 0, 1));
    m_tuning->restoreState(st.value(QStringLiteral("tuning/state")).toMap());
}

void MainWindow::saveSettings()
{
    QSettings st;
    st.setValue(QStringLiteral("window/geometry"), saveGeometry());
    st.setValue(QStringLiteral("window/state"), saveState());
    st.setValue(QStringLiteral("window/screen"), m_nav->currentRow());
    st.setValue(QStringLiteral("window/instrument"), m_jogTabs->currentIndex());
    st.setValue(QStringLiteral("tuning/state"), m_tuning->saveState());
    m_motion->save(st);
    st.setValue(QStringLiteral("scan/plan"), m_scan->planText());
    st.setValue(QStringLiteral("scan/folder"), m_scan->outputFolder());
    st.setValue(QStringLiteral("scan/take_images"), m_scan->takesImages());
    st.setValue(QStringLiteral("camera/source"), m_camera->source());
    st.setValue(QStringLiteral("camera/recent"), m_camera->recentSources());
    st.setValue(QStringLiteral("camera/exposure_ms"), m_camera->exposureMs());
    st.setValue(QStringLiteral("camera/auto_contrast"), m_camera->autoContrast());
    for (int i = 0; i < kInstrumentCount; ++i) {
        const ui::ConnectionChoice c = m_instruments[i].session->choice();
        st.beginGroup(QStringLiteral("connection/%1").arg(QLatin1String(kSettingsKeys[i])));
        st.setValue(QStringLiteral("simulator"), c.simulator);
        st.setValue(QStringLiteral("port"), c.port);
        st.setValue(QStringLiteral("serial_number"), c.serialNumber);
        st.setValue(QStringLiteral("baud"), c.baud);
        st.setValue(QStringLiteral("profile"), c.profile);
        st.setValue(QStringLiteral("profiles"), m_instruments[i].bar->profiles());
        st.endGroup();
        st.setValue(QStringLiteral("jog/%1/speed").arg(QLatin1String(kSettingsKeys[i])), m_instruments[i].jog->speedFraction());
    }
}

} // namespace app
