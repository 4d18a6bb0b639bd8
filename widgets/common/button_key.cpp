#include "widgets/common/button_key.h"

#include <QAbstractButton>
#include <QShortcut>

namespace ui {

namespace {
const char* const kButtonKeyName = "ui_buttonKey";
}

QShortcut* setButtonKey(QAbstractButton* button, const QKeySequence& key)
{
    auto* shortcut = button->findChild<QShortcut*>(QLatin1String(kButtonKeyName), Qt::FindDirectChildrenOnly);
    if (!shortcut) {
        shortcut = new QShortcut(button);
        shortcut->setObjectName(QLatin1String(kButtonKeyName));
        shortcut->setContext(Qt::WindowShortcut);
        // click(), not animateClick(): a stop key acts at once, not a tenth of a second later.
        QObject::connect(shortcut, &QShortcut::activated, button, [button] {
            if (button->isEnabled() && button->isVisible())
                button->click();
        });
    }
    shortcut->setKey(key);
    return shortcut;
}

QKeySequence buttonKey(const QAbstractButton* button)
{
    if (const auto* shortcut = button->findChild<QShortcut*>(QLatin1String(kButtonKeyName), Qt::FindDirectChildrenOnly))
        return shortcut->key();
    return button->shortcut();
}

} // namespace ui
