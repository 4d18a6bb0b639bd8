#pragma once
// The Jog screen of one instrument: per-axis readouts and lamps, step jog,
// hold-to-jog (buttons and keys), homing, zero, go-to, soft limits.
#include "device/client/instrument.h"

#include <QWidget>

#include <functional>

class QGridLayout;
class QLabel;
class QPushButton;
class QSlider;

namespace dev::tele {
class TelemetryHub;
}

namespace ui {

class AxisRow;
class LiveStrip;

class JogScreen : public QWidget {
    Q_OBJECT
public:
    /// Asked before anything that moves the machine far; true = go ahead. The
    /// composition root supplies a dialog; without one the answer is yes.
    using Confirm = std::function<bool(const QString& question)>;

    JogScreen(dev::Instrument* client, QWidget* parent = nullptr);
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    /// Asked before a long move instead of Confirm (app/ offers "don't ask again this session"
    /// there); unset: Confirm asks. Destructive questions (homing with liquid) always go to Confirm.
    void setConfirmLongMove(Confirm confirm) { m_confirmLongMove = std::move(confirm); }
    /// Jog speed as a share of each axis' maximum, 0.01–1.
    double speedFraction() const;
    void setSpeedFraction(double f);
    /// Moves farther than this share of an axis' travel ask for confirmation first.
    static constexpr double kFarMoveShare = 0.25;
    /// Shows the live position / following-error strip of the axis last jogged.
    void setTelemetry(dev::tele::TelemetryHub* hub, int instrument);
    /// While this screen is not shown, the jog keys still move its instrument when
    /// `mine` says so (the window's screen shown leaves the arrow keys to jogging and is
    /// about this instrument); a text field being edited keeps them all the same.
    void setKeysFromOtherScreens(std::function<bool()> mine) { m_keysElsewhere = std::move(mine); }
    /// Puts `panel` (the stage's camera) under the axes, taking the room left.
    void addPanel(QWidget* panel);
    /// Ends every hold of a key or button (the window changed screens under a held key).
    void endHolds() { endAllHolds(); }

signals:
    void problem(const QString& message);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    void showEvent(QShowEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void changeEvent(QEvent* event) override;

public:
    /// True while a text field of this screen is being edited: the arrow keys are the field's then.
    bool typing() const;
    /// What the keys do now, as the screen says it ("Keys jog the axes" or how to get them back).
    QString keysModeText() const;

private:
    void rebuild();
    void refresh();
    void showKeysMode();
    void showKeys();
    bool keysAreMine() const;
    bool handleJogKey(QKeyEvent* event, bool press);
    void startHold(int axis, int direction);
    void endHold(int axis);
    void endAllHolds();
    void homeAxes(quint8 mask);
    void goTo(int axis, double target);
    int axisForKey(int key, int* direction) const;
    double holdVelocity(int axis, int direction) const;
    bool confirm(const QString& question);

    dev::Instrument* m_client;
    Confirm m_confirm;
    Confirm m_confirmLongMove;
    std::function<bool()> m_keysElsewhere;
    QLabel* m_title;
    QLabel* m_state;
    QPushButton* m_homeAll;
    QPushButton* m_setHome;    ///< shown where the instrument cannot home but can take a position as home
    QPushButton* m_unlock;     ///< shown while the controller does not trust its position
    QLabel* m_hostLossNote;    ///< what a lost link costs on a device without a jog watchdog
    QPushButton* m_stop;
    QSlider* m_speed;
    QLabel* m_speedLabel;
    QLabel* m_keys = nullptr; ///< which keys jog which axis
    QLabel* m_keysMode;        ///< whether the keys jog or type, and how to switch
    QGridLayout* m_grid;
    QWidget* m_gridHost;
    QList<AxisRow*> m_rows;
    LiveStrip* m_strip;        ///< hidden until setTelemetry()
    QHash<int, int> m_holds;   ///< axis → direction while a button or key is held
    bool m_fast = false;       ///< Shift held: full speed
};

} // namespace ui
