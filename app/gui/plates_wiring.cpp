#include "plates_wiring.h"

#include "main_window.h"
#include "device/files/plates/plate_paths.h"
#include "widgets/plates/plates_screen.h"

#include "widgets/wording/wording.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>

namespace app {

namespace {
dev::jobs::InterruptedChoice askAboutInterrupted(QWidget* window, const dev::jobs::InterruptedOp& op)
{
    QMessageBox box(QMessageBox::Warning, QObject::tr("A well was interrupted"),
                    QObject::tr("The run stopped during \"%1\", after its plunger move had been sent.\n\n%2.\n\n"
                                "Skip counts the well as done; Do again repeats it in full.")
                        .arg(ui::words::text(op.label), ui::words::sentence(ui::words::text(op.evidence))),
                    QMessageBox::NoButton, window);
    auto* skip = box.addButton(QObject::tr("Skip"), QMessageBox::AcceptRole);
    auto* redo = box.addButton(QObject::tr("Do again"), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() == skip)
        return dev::jobs::InterruptedChoice::Skip;
    if (box.clickedButton() == redo)
        return dev::jobs::InterruptedChoice::Redo;
    return dev::jobs::InterruptedChoice::Cancel;
}
} // namespace

void wirePlatesScreen(ui::PlatesScreen* screen, QWidget* window, const MainWindowOptions& options)
{
    screen->setFileChooser([window, screen](const QString& title, const QString& filter, bool save) {
        const QString dir = screen->recipePath().isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                                            : QFileInfo(screen->recipePath()).absolutePath();
        return save ? QFileDialog::getSaveFileName(window, title, dir, filter) : QFileDialog::getOpenFileName(window, title, dir, filter);
    });
    if (options.confirmDialogs) {
        screen->setConfirm([window](const QString& q) {
            return QMessageBox::question(window, QObject::tr("Confirm"), q, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
                == QMessageBox::Yes;
        });
        // Asked only from the Resume buttons (never from a device signal).
        screen->setInterruptedDecider([window](const dev::jobs::InterruptedOp& op) { return askAboutInterrupted(window, op); });
    }
    if (!options.persistSettings)
        return;
    // The same places as benchpilot-cli's defaults: both see one calibration.
    screen->setRunLogDirectory(dev::files::plates::defaultRunLogDirectory());
    screen->setCalibrationFile(dev::files::plates::defaultCalibrationPath());
    const QString last = QSettings().value(QStringLiteral("plates/recipe")).toString();
    if (!last.isEmpty() && QFileInfo::exists(last))
        screen->openRecipe(last);
}

void savePlatesSettings(ui::PlatesScreen* screen, const MainWindowOptions& options)
{
    if (options.persistSettings && !screen->recipePath().isEmpty())
        QSettings().setValue(QStringLiteral("plates/recipe"), screen->recipePath());
}

} // namespace app
