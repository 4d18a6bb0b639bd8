#pragma once
// What the Calibration screen gets from the composition root: both instruments, the
// file dialogs and the confirmation, and how a gauge's port is opened (a serial port,
// or "sim": the in-process simulator's gauge on the instrument's machine), and the
// telemetry rate a circular test samples at while it runs.
class QWidget;

namespace ui {
class CalibrationScreen;
class MessageBanner;
}
namespace dev::tele {
class TelemetryHub;
}

namespace app {

class InstrumentSession;
struct MainWindowOptions;

ui::CalibrationScreen* makeCalibrationScreen(InstrumentSession* const sessions[2], QWidget* window, ui::MessageBanner* banner,
                                             dev::tele::TelemetryHub* hub, const MainWindowOptions& options);

} // namespace app
