#pragma once
#include <QColor>
#include <QWidget>

namespace ui {

/// A small round indicator, the way front panels show switch and state lamps.
class StatusLamp : public QWidget {
    Q_OBJECT
public:
    /// Unknown: the lamp's state cannot be known now (no live link), drawn hollow so it is
    /// never read as a state the machine is in.
    enum class Tone { Off, Ok, Active, Warning, Alarm, Unknown };
    explicit StatusLamp(const QString& toolTip = {}, QWidget* parent = nullptr);
    void setTone(Tone tone);
    Tone tone() const { return m_tone; }
    QSize sizeHint() const override { return {16, 16}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    Tone m_tone = Tone::Off;
};

} // namespace ui
