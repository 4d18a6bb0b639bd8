#pragma once
#include <QString>

namespace app {

class MainWindow;

/// The Calibration screen at work: the stage's X measured by the simulator's gauge,
/// the fit uploaded and enabled, the same test again; the before/after view shown
/// (run logs, readings and reports go under `scratchFolder`).
bool showCalibrationAtWork(MainWindow& window, const QString& scratchFolder);

} // namespace app
