#pragma once
// The Joystick and Patterns screens as the main window holds them: a joystick tab per
// instrument, one Patterns screen over both, and what they run on — a pattern runner per
// instrument, streaming through its paths() — with their settings kept between runs.
#include <QObject>

#include <functional>

class QSettings;
class QTabWidget;
class QWidget;

namespace dev {
class Instrument;
}
namespace dev::jobs {
class PatternRunner;
}
namespace dev::tele {
class TelemetryHub;
}
namespace ui {
class JoystickScreen;
class PatternScreen;
}

namespace app {

class InstrumentSession;

class MotionScreens : public QObject {
    Q_OBJECT
public:
    struct Hooks {
        std::function<bool(const QString& question)> confirm;  ///< empty: go ahead without asking
        std::function<bool(const QString& question)> confirmLongMove;  ///< may be waived for the session; empty: confirm asks
        std::function<void(const QString& message)> warn;      ///< a banner
        std::function<QString(const QString& title, const QString& filter, bool save)> chooseFile;  ///< empty: defaults
        /// The instrument the screens drive (gated while a script has control, api_wiring.h); empty: the session's.
        std::function<dev::Instrument*(int index)> instrument;
    };

    MotionScreens(InstrumentSession* const sessions[2], dev::tele::TelemetryHub* hub, const Hooks& hooks, QObject* parent = nullptr);
    ~MotionScreens() override;

    QTabWidget* joystickTabs() const { return m_joyTabs; }
    ui::JoystickScreen* joystick(int instrument) const { return m_joystick[instrument]; }
    ui::PatternScreen* patterns() const { return m_patterns; }
    dev::jobs::PatternRunner* runner(int instrument) const { return m_runners[instrument]; }
    void showInstrument(int index);
    /// E-stop: the sticks let go at once (the device stops everything anyway).
    void stopSticks();
    void load(QSettings& settings);
    void save(QSettings& settings) const;

private:
    QTabWidget* m_joyTabs;
    ui::JoystickScreen* m_joystick[2];
    dev::jobs::PatternRunner* m_runners[2];
    ui::PatternScreen* m_patterns;
};

} // namespace app
