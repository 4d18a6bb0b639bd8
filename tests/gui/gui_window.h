#pragma once
// The main window as the GUI tests drive it: on the in-process simulators, with
// no saved settings read or written and no dialogs.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "gui_wait.h"

#include <QDir>
#include <QPushButton>
#include <QSize>

#include <memory>

namespace guitest {

inline app::MainWindowOptions testWindowOptions()
{
    app::MainWindowOptions o;
    o.persistSettings = false;
    o.confirmDialogs = false;
    return o;
}

/// The push button under `root` whose text is `text`, or nullptr.
inline QPushButton* button(QWidget* root, const QString& text)
{
    for (auto* b : root->findChildren<QPushButton*>())
        if (b->text() == text)
            return b;
    return nullptr;
}

/// BP_GUI_SHOTS=DIR keeps a picture of `window` as DIR/`name` for a person to look at.
inline void keepPicture(QWidget* window, const QString& name)
{
    const QString folder = qEnvironmentVariable("BP_GUI_SHOTS");
    if (!folder.isEmpty())
        window->grab().save(QDir(folder).filePath(name));
}

/// Shown at `size` with both instruments' links ready; nullptr if they never are.
inline std::unique_ptr<app::MainWindow> openReadyWindow(QSize size, const app::MainWindowOptions& options = testWindowOptions())
{
    auto w = std::make_unique<app::MainWindow>(options);
    w->resize(size);
    w->show();
    if (!waitFor([&] { return w->analyzer()->instrument()->isReady() && w->stage()->instrument()->isReady(); }, 5000))
        return nullptr;
    return w;
}

} // namespace guitest
