#pragma once
// What the Calibration screen gets from the composition root: both instruments, the
// file dialogs and the confirmation, and how a gauge's port is opened (a serial port,
// or "sim": the in-process simulator's gauge on the instrument's machine).
class QWidget;

namespace ui {
class CalibrationScreen;
class MessageBanner;
}

namespace app {

class InstrumentSession;
struct MainWindowOptions;

ui::CalibrationScreen* makeCalibrationScreen(InstrumentSession* const sessions[2], QWidget* window, ui::MessageBanner* banner,
                                             const MainWindowOptions& options);

} // namespace app
