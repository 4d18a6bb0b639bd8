#pragma once
// The composition root's window: both instruments' connections, the screens,
// E-stop on every screen, banner, event log and status bar, and the scripting API.
#include "api_wiring.h"
#include "device/camera/camera.h"
#include "device/camera/specimen.h"
#include "widgets/connection_bar.h"

#include <QMainWindow>
#include <QStringList>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QDockWidget;
class QListWidget;
class QPushButton;
class QStackedWidget;
class QTabWidget;
class QLabel;

namespace dev::tele {
class TelemetryHub;
}

namespace ui {
class CameraPanel;
class CameraSession;
class EventLog;
class JogScreen;
class MessageBanner;
class PlotsScreen;
class TuningScreen;
class PlatesScreen;
class ScanScreen;
class CalibrationScreen;
} // namespace ui

namespace ui::words {
class Translators;
}
class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;

namespace app {

class InstrumentSession;
class LongMoveQuestion;
class MotionScreens;

struct MainWindowOptions {
    bool persistSettings = true;  ///< false for screenshots and tests: read nothing, write nothing
    bool confirmDialogs = true;   ///< false in tests: far moves go ahead without asking
    /// Tests: answers the window's own questions (Disconnect during a run, quitting) instead of a dialog.
    std::function<bool(const QString& question)> answer;
    bool autoConnect = true;      ///< connect both instruments at start
    /// Connections given on the command line (--sim, --port), over what was remembered.
    std::optional<ui::ConnectionChoice> connection[2];
    int showInstrument = -1;      ///< 0 analyzer, 1 stage: the instrument the command line named
    ApiOptions api;               ///< the scripting API (docs/api.md); no socket path: none
    /// The program's translators (main.cpp owns them); the Language menu switches
    /// them. nullptr: the window has no Language menu (tests that do not switch).
    ui::words::Translators* translators = nullptr;
    /// Makes the GUI's camera from a source string; unset: camera_wiring.h's. Tests give a fake.
    std::function<std::unique_ptr<dev::camera::Camera>(const QString& source, QString* error)> cameraFactory;
    /// Lists the cameras there are ("sim", "uvc:NAME" …); unset: camera_wiring.h's. Tests count its calls.
    std::function<QStringList()> cameraLister;
    /// What the simulated camera looks at on the in-process simulated stage (--specimen).
    dev::camera::SpecimenKind specimen = dev::camera::SpecimenKind::Slide;
};

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(const MainWindowOptions& options = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    InstrumentSession* analyzer() { return m_instruments[0].session; }
    InstrumentSession* stage() { return m_instruments[1].session; }
    /// Screen names are the lower-case navigation words: "jog", "profiles", …
    QStringList screenNames() const;
    bool showScreen(const QString& name);
    void showInstrument(int index);  ///< 0 analyzer, 1 stage, on screens that have a choice
    ui::JogScreen* jogScreen(int index) { return m_instruments[index].jog; }
    ui::PlotsScreen* plotsScreen() { return m_plots; }
    ui::TuningScreen* tuningScreen() { return m_tuning; }
    /// The Joystick and Patterns screens (motion_screens.h).
    MotionScreens* motionScreens() { return m_motion; }
    ui::PlatesScreen* platesScreen() { return m_plates; }
    ui::ScanScreen* scanScreen() { return m_scan; }
    /// The camera the Scan screen and the stage's Jog screen share, and the Jog screen's panel.
    ui::CameraSession* cameraSession() { return m_camera; }
    ui::CameraPanel* jogCameraPanel() { return m_jogCamera; }
    ui::CalibrationScreen* calibrationScreen() { return m_calibration; }
    dev::tele::TelemetryHub* telemetry() { return m_hub; }
    ui::MessageBanner* banner() { return m_banner; }
    ui::EventLog* eventLog() { return m_log; }
    QPushButton* estopButton() { return m_estop; }
    /// The status bar's line for the analyzer (0) or the stage (1).
    QString statusText(int index) const;
    /// The scripting API's wiring (its server is null when no API was asked for).
    ApiWiring* api() { return m_api; }

public slots:
    void emergencyStop();
    void resetEStop();

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    /// 0 the analyzer, 1 the stage: the order of every per-instrument list here and in the
    /// parts the window wires (the API, the telemetry hub, the motion and calibration screens).
    static constexpr int kInstrumentCount = 2;
    /// What the window keeps of one instrument.
    struct InstrumentSlot {
        InstrumentSession* session = nullptr;
        ui::ConnectionBar* bar = nullptr;
        ui::JogScreen* jog = nullptr;
        QLabel* statusLabel = nullptr;
        bool positionLostShown = false;  ///< the "no longer trusts its position" banner is up
    };
    /// The sessions in instrument order, for the parts that take the list.
    std::array<InstrumentSession*, kInstrumentCount> sessions() const;
    /// The instrument's name for people ("Analyzer", "Stage") in the current language.
    static QString instrumentTitle(int index);
    /// A screen's problem, and its notice, on the banner.
    void warn(const QString& message);
    void inform(const QString& message);

    /// The window's own texts (title, navigation, E-stop, docks, menus); the screens
    /// reword themselves on the same LanguageChange.
    void retranslateUi();
    /// Installs `language` ("system", "en", "zh_CN") at once and keeps it for the next start.
    void setLanguage(const QString& language);
    void buildFileMenu();
    void buildLanguageMenu();
    void addScreen(const QString& name, const QString& title, QWidget* screen);
    void wireApi(QDockWidget* logDock);
    void wireSession(int index, ui::ConnectionBar* bar);
    void updateStatusBar();
    void updateEStopUi();
    void loadSettings();
    void saveSettings();
    bool confirm(const QString& question);
    /// The jobs running on instrument `index` now, for people ("a plate run"); empty: none.
    QStringList runningJobs(int index) const;
    /// Asks when a job runs on it (widgets/common/confirmation.h); true: go ahead.
    bool confirmDisconnect(int index);

    MainWindowOptions m_options;
    LongMoveQuestion* m_longMoves;  ///< the long-move question, waivable for this session only
    std::array<InstrumentSlot, kInstrumentCount> m_instruments;
    ApiWiring* m_api;
    dev::tele::TelemetryHub* m_hub;  ///< every instrument's telemetry, for the plots
    ui::PlotsScreen* m_plots;
    ui::TuningScreen* m_tuning;
    ui::PlatesScreen* m_plates;
    ui::ScanScreen* m_scan;
    ui::CameraSession* m_camera = nullptr;
    ui::CameraPanel* m_jogCamera = nullptr;
    ui::CalibrationScreen* m_calibration;
    QTabWidget* m_jogTabs;
    MotionScreens* m_motion;
    QListWidget* m_nav;
    QStackedWidget* m_stack;
    QStringList m_screenNames;
    ui::MessageBanner* m_banner;
    ui::EventLog* m_log;
    QPushButton* m_estop;
    QPushButton* m_reset;
    std::vector<std::function<void()>> m_connectionTexts;  ///< each instrument's connection bar and status text, worded anew
    bool m_latchShown = false;  ///< the status bar shows an E-stop latch
    QDockWidget* m_logDock = nullptr;
    QMenu* m_fileMenu = nullptr;
    QAction* m_quitAction = nullptr;
    QMenu* m_settingsMenu = nullptr;
    QMenu* m_languageMenu = nullptr;
    QActionGroup* m_languages = nullptr;
    QString m_languageSetting = QStringLiteral("system");
};

} // namespace app
