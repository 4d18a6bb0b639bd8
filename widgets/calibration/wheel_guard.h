#pragma once
// Spin boxes and combos that a mouse wheel scrolling past does not change: the wheel
// reaches them only once they have the focus (house rule; a test definition must not
// change under a scrolling hand).
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QObject>
#include <QWidget>

namespace ui {

class WheelGuard : public QObject {
public:
    using QObject::QObject;
    /// Installs the guard on `w`: StrongFocus, and wheel events ignored until focused.
    static void guard(QWidget* w)
    {
        static WheelGuard* shared = new WheelGuard;  // stateless; lives as long as the program
        w->setFocusPolicy(Qt::StrongFocus);
        w->installEventFilter(shared);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Wheel) {
            auto* w = qobject_cast<QWidget*>(watched);
            if (w && !w->hasFocus()) {
                event->ignore();  // the scroll area behind gets it
                return true;
            }
        }
        return false;
    }
};

} // namespace ui
