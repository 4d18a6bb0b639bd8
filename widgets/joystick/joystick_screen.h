#pragma once
// The Joystick screen of one instrument: drag a knob to move X and Y together at a speed that
// grows with the deflection (dead-band, expo, maximum speed adjustable), a spring-back slider
// for Z on the analyzer, arrow keys as a stick pushed to the rim, live positions and the XY
// travel to scale with the trail. Motion stops on release, focus loss, hiding, link loss and
// E-stop; the device's jog watchdog is the last line of defence.
#include "device/client/instrument.h"
#include "motion/jog/joystick_curve.h"

#include <QSet>
#include <QWidget>

#include <map>

class QLabel;
class QSlider;

namespace dev {
class JoystickDriver;
}

namespace ui {

class JoystickPad;
class NumberField;
class TravelView;

struct JoystickSettings {
    double maxSpeedMmS = 5;
    motion::jog::StickShaping shaping;
};

class JoystickScreen : public QWidget {
    Q_OBJECT
public:
    explicit JoystickScreen(dev::Instrument* client, QWidget* parent = nullptr);
    ~JoystickScreen() override;

    JoystickSettings settings() const;
    void setSettings(const JoystickSettings& s);

    JoystickPad* pad() const { return m_pad; }
    TravelView* travel() const { return m_travel; }
    QSlider* zSlider() const { return m_z; }
    dev::JoystickDriver* driver() const { return m_driver; }
    /// Every axis to zero now (release, focus loss, hide…).
    void stopAll();
    /// The speed line as shown: what the machine is asked to do, an axis held at its soft limit counted at 0.
    QString speedText() const;

signals:
    void problem(const QString& message);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void rebuild();
    void refresh();
    void showSpeed();
    void apply();
    motion::path::Vec2 keyDeflection() const;
    double keyZ() const;

    dev::Instrument* m_client;
    dev::JoystickDriver* m_driver;
    QLabel* m_title;
    QLabel* m_state;
    JoystickPad* m_pad;
    QSlider* m_z;
    QLabel* m_zLabel;
    NumberField* m_maxSpeed;
    NumberField* m_deadband;  ///< %
    NumberField* m_expo;
    /// What the stick answers with: set, or the fields' values when last all valid (Enter or
    /// leaving a field). An invalid field shows its reason and leaves these as they were.
    JoystickSettings m_inForce;
    QLabel* m_readout;
    QLabel* m_hint = nullptr;
    QLabel* m_speed;
    std::map<int, double> m_wish;  ///< axis → velocity the stick asks for (mm/s)
    TravelView* m_travel;
    QSet<int> m_keys;  ///< arrow and page keys held
    int m_zAxis = -1;
};

} // namespace ui
