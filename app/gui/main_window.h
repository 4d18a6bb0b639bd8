#pragma once
// The composition root's window: both instruments' connections, the screens,
// E-stop on every screen, banner, event log and status bar.
#include <QMainWindow>

class QListWidget;
class QPushButton;
class QStackedWidget;
class QTabWidget;
class QLabel;

namespace tele {
class TelemetryHub;
}

namespace ui {
class ConnectionBar;
class EventLog;
class JogScreen;
class MessageBanner;
class PlotsScreen;
class TuningScreen;
class PlatesScreen;
class ScanScreen;
class CalibrationScreen;
} // namespace ui

namespace app {

class InstrumentSession;
class MotionScreens;

struct MainWindowOptions {
    bool persistSettings = true;  ///< false for screenshots and tests: read nothing, write nothing
    bool confirmDialogs = true;   ///< false in tests: far moves go ahead without asking
    bool autoConnect = true;      ///< connect both instruments at start
};

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(const MainWindowOptions& options = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    InstrumentSession* analyzer() { return m_sessions[0]; }
    InstrumentSession* stage() { return m_sessions[1]; }
    /// Screen names are the lower-case navigation words: "jog", "profiles", …
    QStringList screenNames() const;
    bool showScreen(const QString& name);
    void showInstrument(int index);  ///< 0 analyzer, 1 stage, on screens that have a choice
    ui::JogScreen* jogScreen(int index) { return m_jog[index]; }
    ui::PlotsScreen* plotsScreen() { return m_plots; }
    ui::TuningScreen* tuningScreen() { return m_tuning; }
    /// The Joystick and Patterns screens (motion_screens.h).
    MotionScreens* motionScreens() { return m_motion; }
    ui::PlatesScreen* platesScreen() { return m_plates; }
    ui::ScanScreen* scanScreen() { return m_scan; }
    ui::CalibrationScreen* calibrationScreen() { return m_calibration; }
    tele::TelemetryHub* telemetry() { return m_hub; }
    ui::MessageBanner* banner() { return m_banner; }
    ui::EventLog* eventLog() { return m_log; }
    QPushButton* estopButton() { return m_estop; }

public slots:
    void emergencyStop();
    void resetEStop();

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void addScreen(const QString& name, const QString& title, QWidget* screen);
    void wireSession(int index, ui::ConnectionBar* bar);
    void updateStatusBar();
    void updateEStopUi();
    void loadSettings();
    void saveSettings();
    bool confirm(const QString& question);

    MainWindowOptions m_options;
    InstrumentSession* m_sessions[2];
    tele::TelemetryHub* m_hub;  ///< every instrument's telemetry, for the plots
    ui::PlotsScreen* m_plots;
    ui::TuningScreen* m_tuning;
    ui::PlatesScreen* m_plates;
    ui::ScanScreen* m_scan;
    ui::CalibrationScreen* m_calibration;
    ui::ConnectionBar* m_bars[2];
    ui::JogScreen* m_jog[2];
    QTabWidget* m_jogTabs;
    MotionScreens* m_motion;
    QListWidget* m_nav;
    QStackedWidget* m_stack;
    QStringList m_screenNames;
    ui::MessageBanner* m_banner;
    ui::EventLog* m_log;
    QPushButton* m_estop;
    QPushButton* m_reset;
    QLabel* m_statusLabels[2];
};

} // namespace app
