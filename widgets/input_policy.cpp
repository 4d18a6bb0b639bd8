#include "widgets/input_policy.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QVariant>

namespace ui {
namespace {
const char* const kUsualTip = "bpUsualToolTip";

/// The spin box or combo box a wheel event over `w` would turn (its line edit is a child).
QWidget* wheelTaker(QObject* o)
{
    for (int depth = 0; o && depth < 3; ++depth, o = o->parent()) {
        if (qobject_cast<QAbstractSpinBox*>(o) || qobject_cast<QComboBox*>(o))
            return static_cast<QWidget*>(o);
        if (!o->isWidgetType() || static_cast<QWidget*>(o)->isWindow())
            break;
    }
    return nullptr;
}
} // namespace

void InputPolicy::install()
{
    if (!qApp || qApp->property("bpInputPolicy").toBool())
        return;
    qApp->setProperty("bpInputPolicy", true);
    qApp->installEventFilter(new InputPolicy(qApp));
}

bool InputPolicy::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Polish) {
        // The wheel would otherwise give these the focus (Qt::WheelFocus) and then turn them.
        if (auto* w = qobject_cast<QWidget*>(watched); w && (qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w))
                                                       && w->focusPolicy() == Qt::WheelFocus)
            w->setFocusPolicy(Qt::StrongFocus);
    } else if (event->type() == QEvent::Wheel) {
        if (QWidget* taker = wheelTaker(watched); taker && !taker->hasFocus() && !taker->isAncestorOf(QApplication::focusWidget())) {
            // Ignored and filtered: QApplication hands it to the parents (a scroll area scrolls).
            event->ignore();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

void setUsualToolTip(QWidget* w, const QString& tip)
{
    w->setProperty(kUsualTip, tip);
    if (w->isEnabled())
        w->setToolTip(tip);
}

void setEnabledOr(QWidget* w, const QString& whyNot)
{
    if (!w->property(kUsualTip).isValid())
        w->setProperty(kUsualTip, w->toolTip());
    const QString usual = w->property(kUsualTip).toString();
    w->setEnabled(whyNot.isEmpty());
    if (whyNot.isEmpty())
        w->setToolTip(usual);
    else
        w->setToolTip(usual.isEmpty() ? whyNot : QStringLiteral("%1\n%2").arg(whyNot, usual));
}

} // namespace ui
