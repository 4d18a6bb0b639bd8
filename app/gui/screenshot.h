#pragma once
#include <QSize>
#include <QString>

#include <functional>

namespace app {

struct ScreenshotRequest {
    QString file;
    QString screen = QStringLiteral("jog");
    QString instrument = QStringLiteral("analyzer");
    int settleMs = 1500;
    bool homeFirst = false;  ///< home and move the shown instrument so the picture shows a working machine
    bool exercise = false;   ///< jog, then move the shown instrument, so live plots show motion
    bool tune = false;       ///< tuning screen: home the stage, tune X with the relay, run a step test
    QString recipe;          ///< plates: open this recipe, home the analyzer and run it while settling
    /// The window's size; a window that cannot shrink to it comes out larger (the picture says so).
    QSize size = QSize(1600, 1000);
};

/// Renders one screen of a fresh main window (simulated instruments, no saved
/// settings) to a PNG. Returns the process exit code; errors go to stderr.
int takeScreenshot(const ScreenshotRequest& request);

/// Runs the event loop until `done` holds or `ms` have passed; what `done` says then.
bool runUntil(const std::function<bool()>& done, int ms);

} // namespace app
