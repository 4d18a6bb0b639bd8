#pragma once
#include <QString>

namespace app {

class MainWindow;

/// Sets a demonstration plan on the Scan screen, homes the stage and runs the scan
/// until a few tiles are taken (run log and exports go under `scratchFolder`).
bool showScanAtWork(MainWindow& window, const QString& scratchFolder);

} // namespace app
