#include "calibration_wiring.h"

#include "instrument_session.h"
#include "main_window.h"

#include "device/jobs/accuracy/circle_telemetry.h"
#include "device/link/serial_transport.h"
#include "device/link/simulated_gauge.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/telemetry_hub.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/message_banner.h"

#include <QFileDialog>
#include <QMessageBox>
#include <QStandardPaths>

#include <array>

namespace app {

ui::CalibrationScreen* makeCalibrationScreen(InstrumentSession* const sessions[2], QWidget* window, ui::MessageBanner* banner,
                                             dev::tele::TelemetryHub* hub, const MainWindowOptions& options)
{
    auto* screen = new ui::CalibrationScreen({sessions[0]->instrument(), sessions[1]->instrument()}, {sessions[0]->name(), sessions[1]->name()});
    screen->setFileChooser([window](ui::CalibrationScreen::FileAction a, const QString& title, const QString& filter) {
        const QString docs = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        using A = ui::CalibrationScreen::FileAction;
        if (a == A::OpenTest || a == A::OpenSequence || a == A::OpenCapture)
            return QFileDialog::getOpenFileName(window, title, docs, filter);
        if (a == A::SaveTest || a == A::SaveCompensation)
            return QFileDialog::getSaveFileName(window, title, docs, filter);
        return QFileDialog::getExistingDirectory(window, title, docs);
    });
    if (options.confirmDialogs)
        screen->setConfirm([window](const QString& q) {
            return QMessageBox::question(window, QObject::tr("Calibration"), q, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
                == QMessageBox::Yes;
        });
    // The sessions themselves, not the caller's list of them: that list may be a temporary.
    const std::array<InstrumentSession*, 2> gaugeSessions{sessions[0], sessions[1]};
    screen->setGaugeFactory([gaugeSessions](int index, const QString& port, int axis, QObject* owner, QString* error) -> dev::Transport* {
        if (port == QLatin1String("sim")) {
            auto* link = qobject_cast<dev::SimulatedLink*>(gaugeSessions[static_cast<std::size_t>(index)]->link());
            if (!link) {
                *error = QObject::tr("'sim' is the in-process simulator's gauge: connect the instrument to the simulator first.");
                return nullptr;
            }
            return (new dev::SimulatedGauge(link->machine(), axis, {}, owner))->hostEnd();
        }
        return new dev::SerialTransport(port, 9600, owner);
    });
    // A circle is sampled from the instrument's measured X and Y; the history streams them
    // at 100 Hz, so for the run the hub is asked for the test's own rate (the union of every
    // consumer's wants is what the device sends), and the wish ends with the run.
    QObject::connect(screen, &ui::CalibrationScreen::circleRunStarting, hub, [hub](dev::jobs::CircleRunner* runner, int index) {
        QVector<dev::tele::ChannelKey> keys;
        for (const dev::proto::ChannelRef& ref : dev::jobs::circleChannels(*runner))
            keys.push_back(dev::tele::ChannelKey{index, ref});
        hub->setWanted(QStringLiteral("circular test"), keys, dev::jobs::kCircleSampleRateHz);
        QObject::connect(runner, &dev::jobs::CircleRunner::finished, hub, [hub] { hub->setWanted(QStringLiteral("circular test"), {}, 0); });
        QObject::connect(runner, &QObject::destroyed, hub, [hub] { hub->setWanted(QStringLiteral("circular test"), {}, 0); });
    });
    QObject::connect(screen, &ui::CalibrationScreen::problem, banner, [banner](const QString& m) { banner->show(ui::MessageBanner::Level::Warning, m); });
    QObject::connect(screen, &ui::CalibrationScreen::notice, banner, [banner](const QString& m) { banner->show(ui::MessageBanner::Level::Info, m); });
    return screen;
}

} // namespace app
