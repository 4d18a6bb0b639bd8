#pragma once
// What the Plates screen gets from the composition root: file dialogs, the
// confirmation and the interrupted-well dialogs, where calibration and run logs
// live, and the recipe it had open last time.
class QWidget;

namespace ui {
class PlatesScreen;
}

namespace app {

struct MainWindowOptions;

void wirePlatesScreen(ui::PlatesScreen* screen, QWidget* window, const MainWindowOptions& options);
/// Remembers the recipe for next time (QSettings), when settings persist.
void savePlatesSettings(ui::PlatesScreen* screen, const MainWindowOptions& options);

} // namespace app
