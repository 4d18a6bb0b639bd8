// An interferometer's capture imported on the Calibration screen. The run wrote its
// target sequence; the operator captured with the interferometer's own software and
// exported CSV; the export is matched to the sequence stop by stop, all or nothing
// (dev::files::accuracy::importInterferometerCsv), and evaluated like any axis run. The
// readings, result and report go beside the sequence, as the CLI's `accuracy import`
// writes them.
#include "widgets/calibration/calibration_screen.h"

#include "device/files/accuracy/interferometer_csv.h"
#include "device/files/accuracy/readings_csv.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/circle_runner.h"
#include "widgets/calibration/test_form.h"
#include "widgets/wording/wording.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

namespace ui {

QString CalibrationScreen::fileProblemLines(const motion::msg::Problems& problems)
{
    QStringList lines;
    for (const auto& p : problems)
        if (p.isError())
            lines << ui::words::problem(p);
    return lines.join(QLatin1Char('\n'));
}

void CalibrationScreen::chooseAndImportCapture()
{
    const QString sequence = choose(FileAction::OpenSequence, tr("The run's target sequence"), tr("Target sequences (*.targets.csv)"));
    if (sequence.isEmpty())
        return;
    const QString capture = choose(FileAction::OpenCapture, tr("The interferometer's CSV export of that run"), tr("CSV files (*.csv)"));
    if (!capture.isEmpty())
        importCapture(sequence, capture);
}

bool CalibrationScreen::importCapture(const QString& sequencePath, const QString& capturePath)
{
    if ((m_runner && m_runner->isActive()) || (m_circle && m_circle->isActive())) {
        emit problem(tr("A test is running: import the capture when it has finished."));
        return false;
    }
    // The sequence holds targets and directions only; the axis and its tolerances are
    // the test's, so the test the capture belongs to must be the one on screen: its
    // stops are compared with the sequence's before anything is read or written.
    const dev::files::accuracy::AccuracyTest onScreen = m_form->test();
    const auto* test = std::get_if<motion::metrology::AxisTest>(&onScreen);
    if (!test) {
        emit problem(tr("Only an axis test's capture can be imported: show the axis test it belongs to."));
        return false;
    }
    const auto sequence = dev::files::accuracy::loadTargetSequence(sequencePath);
    if (!sequence.ok()) {
        emit problem(tr("The target sequence cannot be read:\n%1").arg(fileProblemLines(sequence.problems)));
        return false;
    }
    if (const auto mismatch = dev::files::accuracy::sequenceMismatch(sequence.stops, *test)) {
        emit problem(tr("%1 is not the run of the axis test on screen, so nothing was imported: %2. Open the test the capture "
                        "belongs to, then import again.")
                         .arg(QFileInfo(sequencePath).fileName(), ui::words::text(*mismatch)));
        return false;
    }
    const auto imported = dev::files::accuracy::loadInterferometerExport(capturePath, sequence.stops);
    if (!imported.ok()) {
        emit problem(tr("The capture does not match the run's stops, so nothing was imported:\n%1").arg(fileProblemLines(imported.problems)));
        return false;
    }
    const auto evaluation = motion::metrology::evaluate(imported.readings);
    if (!evaluation.ok()) {
        emit problem(tr("The imported readings cannot be evaluated:\n%1").arg(ui::words::problems(evaluation.problems).join(QLatin1Char('\n'))));
        return false;
    }
    QString base = sequencePath;
    if (base.endsWith(QLatin1String(".targets.csv")))
        base.chop(static_cast<int>(qstrlen(".targets.csv")));
    else
        base = QFileInfo(sequencePath).dir().filePath(QFileInfo(sequencePath).completeBaseName());
    const QString readingsPath = base + QStringLiteral(".readings.csv");
    if (QFileInfo::exists(readingsPath)
        && !confirm(tr("%1 exists already. Replace it with the readings of this capture?").arg(readingsPath)))
        return false;
    motion::msg::Message error;
    if (!dev::files::accuracy::saveReadingsCsv(readingsPath, imported.readings, &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    dev::files::accuracy::AccuracyResult r;
    r.axis = test->axis;
    r.evaluation = evaluation;
    r.tolerances = test->tolerances;
    r.reference = "interferometer";
    r.readingsFile = QFileInfo(readingsPath).fileName().toStdString();
    r.createdUtc = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    if (!dev::files::accuracy::saveAccuracyResultFile(base + QStringLiteral(".accuracy-result.json"), r, &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    adoptAxisResult(r, *test, imported.readings, base, motion::msg::make("accuracy.source.interferometer"));
    emit notice(tr("Imported %n reading(s) from %1: results in %2.", "", static_cast<int>(imported.readings.size()))
                    .arg(QFileInfo(capturePath).fileName(), QFileInfo(readingsPath).absolutePath()));
    updateRunUi();
    return true;
}

} // namespace ui
