#pragma once
// Application-wide input rules, installed once by the composition root (so no
// screen can forget them):
// - a spin box or combo box turns with the mouse wheel only while it has the
//   keyboard focus; over an unfocused one the wheel scrolls what holds it. (The
//   wheel over a recipe panel once set a pump speed to 495.)
#include <QObject>

class QWidget;

namespace ui {

class InputPolicy : public QObject {
    Q_OBJECT
public:
    /// Installs the rules on the application (once; later calls do nothing).
    static void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
};

/// Enables `w` when `whyNot` is empty; otherwise disables it and makes `whyNot`
/// the first line of its tooltip, above what the control does. The control's own
/// tooltip comes back when it is enabled again. A greyed control always says why.
void setEnabledOr(QWidget* w, const QString& whyNot);
/// The tooltip a control shows when enabled (setEnabledOr keeps it aside while disabled).
void setUsualToolTip(QWidget* w, const QString& tip);

} // namespace ui
