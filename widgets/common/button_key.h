#pragma once
// A key that presses a button, and stays through every rewording of it.
// QAbstractButton::setText() replaces the button's own shortcut with the new text's
// mnemonic, so a key set with setShortcut() died at the first language switch or the
// first "Pause" → "Resume", and a screen had to remember to set it again each time.
// This key belongs to a QShortcut of the button's instead: setText() cannot touch it.
// Like a button's own shortcut it works only while the button is on screen in the
// active window and enabled, and a key two visible buttons share does nothing.
#include <QKeySequence>

class QAbstractButton;
class QShortcut;

namespace ui {

/// Makes `key` click `button` (replacing a key given before). Returns the shortcut.
QShortcut* setButtonKey(QAbstractButton* button, const QKeySequence& key);
/// The key setButtonKey() gave `button`, or its own shortcut when it has none.
QKeySequence buttonKey(const QAbstractButton* button);

} // namespace ui
