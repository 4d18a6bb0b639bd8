#pragma once
// An on-screen joystick: a round pad with a knob that follows a drag and springs back to the
// centre when let go. Deflection is x right, y up, inside the unit circle. It draws the
// dead-band so a person sees where motion begins.
#include <QPointF>
#include <QWidget>

namespace ui {

class JoystickPad : public QWidget {
    Q_OBJECT
public:
    explicit JoystickPad(QWidget* parent = nullptr);

    QPointF deflection() const { return m_deflection; }
    /// Shows a deflection set by other means (arrow keys); a drag in progress wins.
    void showDeflection(QPointF d);
    void setDeadband(double share);
    bool dragging() const { return m_dragging; }
    /// Lets go as if the mouse were released (focus lost, window hidden, E-stop).
    void release();

    QSize sizeHint() const override { return {260, 260}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override { return w; }

signals:
    void deflectionChanged(QPointF deflection);
    void released();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    QPointF centre() const;
    double radius() const;
    void setFromPosition(QPointF pos);

    QPointF m_deflection;
    double m_deadband = 0.08;
    bool m_dragging = false;
};

} // namespace ui
