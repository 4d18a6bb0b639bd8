#pragma once
// Arrow buttons for putting the tip over a well by eye: hold to move slowly, or
// click to step by the chosen distance. X left/right, Y back/front (machine Y
// grows toward the operator), Z up/down. Releasing, hiding or losing the link
// stops the motion (the device's jog watchdog does too).
#include "device/client/instrument.h"

#include <QWidget>

class QComboBox;
class QPushButton;
class QSlider;

namespace ui {

class JogPad : public QWidget {
    Q_OBJECT
public:
    explicit JogPad(dev::Instrument* client, QWidget* parent = nullptr);
    /// mm for a click, or 0 for hold-to-move.
    double stepMm() const;
    void setStepMm(double mm);

protected:
    void hideEvent(QHideEvent* event) override;

private:
    QPushButton* arrow(const QString& text, char axis, int direction, const QString& tip);
    void press(char axis, int direction);
    void release(char axis);
    double speed(char axis) const;

    dev::Instrument* m_client;
    QComboBox* m_step;
    QSlider* m_speed;
};

} // namespace ui
