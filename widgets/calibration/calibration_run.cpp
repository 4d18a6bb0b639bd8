// The Calibration screen's runs: sources, the axis/XY runner and the circle runner,
// progress and time left, manual entry, results, before/after and the report.
#include "widgets/calibration/calibration_screen.h"

#include "device/camera/scale_reading_source.h"
#include "device/files/accuracy/accuracy_run_folders.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "device/jobs/accuracy/circle_telemetry.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/circle_runner.h"
#include "device/jobs/accuracy/gauge_source.h"
#include "device/jobs/accuracy/interferometer_source.h"
#include "device/jobs/accuracy/manual_source.h"
#include "device/jobs/accuracy/readback_source.h"
#include "widgets/calibration/grid_map_panel.h"
#include "widgets/camera/camera_session.h"
#include "device/link/transport.h"
#include "widgets/calibration/deviation_plot.h"
#include "widgets/calibration/fit_panel.h"
#include "widgets/calibration/polar_plot.h"
#include "widgets/calibration/test_form.h"
#include "widgets/report/accuracy_report.h"
#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QRegularExpression>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>

#include <cmath>

namespace ui {

using ui::words::duration;

using motion::metrology::AxisTest;
using motion::metrology::CircularTest;

namespace {

QString um(std::optional<double> mm) { return mm ? QLocale().toString(*mm * 1e3, 'f', 2) : QStringLiteral("—"); }

const char* const kFigureKeys[] = {"A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean"};

/// "A_up" as ISO writes it: A↑; the mean reversal value B̄ (a symbol, the same in every language).
QString figureLabel(const char* key)
{
    return QString::fromLatin1(key)
        .replace(QStringLiteral("_up"), QStringLiteral("↑"))
        .replace(QStringLiteral("_down"), QStringLiteral("↓"))
        .replace(QStringLiteral("B_mean"), QStringLiteral("B\u0304"));
}

void setRows(QTableWidget* t, const std::vector<QStringList>& rows)
{
    t->setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < static_cast<int>(rows.size()); ++r)
        for (int c = 0; c < rows[static_cast<std::size_t>(r)].size() && c < t->columnCount(); ++c) {
            auto* item = new QTableWidgetItem(rows[static_cast<std::size_t>(r)][c]);
            item->setToolTip(item->text());  // a narrow column elides the name: whole here
            t->setItem(r, c, item);
        }
}

} // namespace

std::unique_ptr<dev::jobs::ReadingSource> CalibrationScreen::makeSource(int axis, QString* error)
{
    const QString kind = m_sourceBox->currentData().toString();
    if (kind == QLatin1String("readback"))
        return std::make_unique<dev::jobs::ReadbackSource>(cur());
    if (kind == QLatin1String("interferometer"))
        return std::make_unique<dev::jobs::InterferometerSource>();
    if (kind == QLatin1String("camera")) {
        dev::camera::Camera* camera = m_cameraSession ? m_cameraSession->camera() : nullptr;
        if (!camera) {
            *error = tr("Open a camera first, on the Scan or Jog screen's Camera tab, with the glass scale under it "
                        "(on the simulator: the sim camera, with benchpilot started with --specimen line-scales).");
            return nullptr;
        }
        dev::camera::ScaleReadingOptions o;
        o.failedImagesFolder = m_folder->text().trimmed();
        return std::make_unique<dev::camera::ScaleReadingSource>(camera, o);
    }
    if (kind == QLatin1String("manual")) {
        auto m = std::make_unique<dev::jobs::ManualSource>();
        m_manual = m.get();
        connect(m.get(), &dev::jobs::ManualSource::entryWanted, this, &CalibrationScreen::onManualWanted);
        connect(m.get(), &dev::jobs::ManualSource::entryDone, this, [this] { m_manualRow->hide(); });
        return m;
    }
    const QString port = m_port->text().trimmed();
    if (port.isEmpty()) {
        *error = tr("Name the gauge's port (or sim for the simulator's gauge).");
        return nullptr;
    }
    dev::Transport* t = m_gaugeFactory ? m_gaugeFactory(m_current, port, axis, this, error) : nullptr;
    if (!t) {
        if (error->isEmpty())
            *error = tr("There is no way to open a gauge here.");
        return nullptr;
    }
    auto source = std::make_unique<dev::jobs::GaugeSource>(t, port == QLatin1String("sim") ? tr("simulated gauge") : port);
    // Whatever the factory made for the transport (a serial port, or a simulated gauge with
    // its loopback pair) goes with the source: the object the factory hung on this screen.
    QObject* top = t;
    while (top->parent() && top->parent() != this)
        top = top->parent();
    if (top->parent() == this)
        top->setParent(source.get());
    return source;
}

bool CalibrationScreen::run()
{
    m_lastProblem = {};
    if (m_opening || (m_runner && m_runner->isActive()) || (m_circle && m_circle->isActive()))
        return false;  // one run at a time (Run is disabled meanwhile and says why)
    if (m_runner && (m_runner->state() == dev::jobs::AccuracyRunner::State::Paused || m_runner->state() == dev::jobs::AccuracyRunner::State::Stopped)
        && m_runOn == m_current && m_form->kind() != AccuracyTestForm::Kind::Circle) {
        // Go on with the run in progress (after a pause, an abort or a lost link).
        motion::msg::Message why;
        if (!m_runner->start(&why)) {
            emit problem(ui::words::text(why));
            return false;
        }
        updateRunUi();
        return true;
    }
    return m_form->kind() == AccuracyTestForm::Kind::Circle ? runCircle() : runAxis();
}

bool CalibrationScreen::runAxis()
{
    const dev::files::accuracy::AccuracyTest test = m_form->test();
    dev::Instrument* inst = cur();
    int axis = 0;
    if (const auto* a = std::get_if<AxisTest>(&test))
        axis = a->axis.size() == 1 && inst ? inst->identity().axisIndex(QChar::fromLatin1(a->axis[0])) : -1;
    // The runner before this one reads through the source about to be replaced: it goes
    // first (its results are already in m_latest and its folder).
    m_runner.reset();
    QString error;
    m_source = makeSource(std::max(0, axis), &error);
    if (!m_source) {
        emit problem(error);
        updateRunUi();
        return false;
    }
    // A gauge's port opens first, so a wrong port is said before anything moves. It
    // answers later (a serial port opens on the event loop): the run starts from there.
    m_opening = true;
    updateRunUi();
    dev::jobs::ReadingSource* source = m_source.get();
    source->open([this, source, test](const motion::msg::Message& openProblem) {
        if (m_source.get() != source || !m_opening)
            return;  // replaced or given up on meanwhile
        m_opening = false;
        if (!openProblem.empty()) {
            emit problem(ui::words::text(openProblem));
            updateRunUi();
            return;
        }
        // Queued: the start may ask a person (a long run, an old log), and a question is
        // never asked from inside a port's signal.
        QMetaObject::invokeMethod(this, [this, test] { startAxis(test); }, Qt::QueuedConnection);
    });
    return true;
}

bool CalibrationScreen::busy() const
{
    using A = dev::jobs::AccuracyRunner::State;
    using C = dev::jobs::CircleRunner::State;
    return (m_runner && (m_runner->isActive() || m_runner->state() == A::Paused))
        || (m_circle && (m_circle->isActive() || m_circle->state() == C::Paused))
        || (m_gridMap && m_gridMap->runner() && m_gridMap->runner()->isActive());
}

bool CalibrationScreen::startAxis(const dev::files::accuracy::AccuracyTest& test, const QString& into)
{
    dev::Instrument* inst = cur();
    const std::string name = std::visit([](const auto& t) { return t.name; }, test);
    const QString base = QDir(m_folder->text()).filePath(QString::fromStdString(name));
    // The newest run of this test: a stopped one goes on there, a finished one is offered a
    // run beside it (accuracy_run_folders.h).
    const QString folder = into.isEmpty() ? dev::files::accuracy::latestRunFolder(base) : into;
    m_runner = std::make_unique<dev::jobs::AccuracyRunner>(inst);
    motion::msg::Problems problems;
    if (!m_runner->prepare(test, m_source.get(), folder, false, &problems)) {
        QStringList lines;
        for (const auto& p : problems)
            if (p.isError())
                lines << ui::words::problem(p);
        const bool otherLog = !problems.empty() && problems.back().message.id == "accuracy.run.other_log";
        if (otherLog && confirm(tr("%1\n\nKeep that log aside and start this test afresh?").arg(lines.join(QLatin1Char('\n'))))) {
            if (!m_runner->prepare(test, m_source.get(), folder, true, &problems)) {
                emit problem(lines.join(QLatin1Char('\n')));
                m_runner.reset();
                updateRunUi();
                return false;
            }
        } else {
            emit problem(lines.join(QLatin1Char('\n')));
            m_runner.reset();
            updateRunUi();
            return false;
        }
    }
    const double eta = m_runner->etaS();
    if (eta > kConfirmLongerThanS
        && !confirm(tr("The test takes about %1 (%2 readings). The axes move on their own until it ends. Run it?")
                        .arg(duration(eta))
                        .arg(m_runner->totalReadings() - m_runner->readingsTaken()))) {
        m_runner.reset();
        updateRunUi();
        return false;
    }
    connect(m_runner.get(), &dev::jobs::AccuracyRunner::readingTaken, this, &CalibrationScreen::onReading);
    connect(m_runner.get(), &dev::jobs::AccuracyRunner::progress, this, &CalibrationScreen::updateRunUi);
    connect(m_runner.get(), &dev::jobs::AccuracyRunner::stateChanged, this, &CalibrationScreen::updateRunUi);
    connect(m_runner.get(), &dev::jobs::AccuracyRunner::problem, this, [this](const motion::msg::Message& m) {
        m_lastProblem = m;
        emit problem(ui::words::text(m));
        updateRunUi();
    });
    connect(m_runner.get(), &dev::jobs::AccuracyRunner::finished, this, &CalibrationScreen::onAxisFinished);
    m_runOn = m_current;
    m_live->show();
    m_livePolar->hide();
    m_live->clearAll();
    // The frame of the whole test from the start: it had spanned -0.5 … 1.5 mm until the
    // first reading, then grown with each (seen under Xvfb).
    const auto* axisTest = std::get_if<motion::metrology::AxisTest>(&test);
    m_live->showTargets(axisTest ? motion::metrology::targetsOf(*axisTest) : std::vector<double>{});
    m_tabs->setCurrentIndex(0);
    if (m_runner->state() == dev::jobs::AccuracyRunner::State::Finished) {
        onAxisFinished();  // its results on screen: the "before" of a run after it
        if (!into.isEmpty() || m_source->kind() == dev::jobs::ReadingKind::Interferometer)
            return true;
        // The operator ran it to measure again (after compensation): a new run beside the
        // finished one, which stays as it is for the before/after comparison.
        const QString next = dev::files::accuracy::nextRunFolder(base);
        if (!confirm(tr("%1 holds a finished run of this test. Run the test again into %2? Both runs are kept, and "
                        "Before / after compares the new one with this one.")
                         .arg(QDir::toNativeSeparators(folder), QDir::toNativeSeparators(next))))
            return true;
        return startAxis(test, next);
    }
    onReading();
    emit accuracyRunStarting(m_runner.get(), m_runOn);
    motion::msg::Message why;
    if (!m_runner->start(&why)) {
        emit problem(ui::words::text(why));
        updateRunUi();
        return false;
    }
    updateRunUi();
    return true;
}

bool CalibrationScreen::runCircle()
{
    const auto test = m_form->test();
    const auto* c = std::get_if<CircularTest>(&test);
    if (!c)
        return false;
    m_circle = std::make_unique<dev::jobs::CircleRunner>(cur());
    motion::msg::Problems problems;
    if (!m_circle->prepare(*c, &problems)) {
        QStringList lines;
        for (const auto& p : problems)
            if (p.isError())
                lines << ui::words::problem(p);
        emit problem(lines.join(QLatin1Char('\n')));
        return false;
    }
    connect(m_circle.get(), &dev::jobs::CircleRunner::stateChanged, this, &CalibrationScreen::updateRunUi);
    connect(m_circle.get(), &dev::jobs::CircleRunner::progress, this, &CalibrationScreen::updateRunUi);
    connect(m_circle.get(), &dev::jobs::CircleRunner::sampled, this, [this] {
        const auto& t = m_circle->test();
        m_livePolar->showLive(m_circle->current().samplesMm, t.centreMm, t.radiusMm);
    });
    connect(m_circle.get(), &dev::jobs::CircleRunner::problem, this, [this](const motion::msg::Message& m) {
        m_lastProblem = m;
        emit problem(ui::words::text(m));
    });
    connect(m_circle.get(), &dev::jobs::CircleRunner::finished, this, &CalibrationScreen::onCircleFinished);
    // Sampled on the device's clock from the measured positions every instrument streams
    // for the telemetry history; status readings stand in if the link sheds them.
    dev::Instrument* inst = cur();
    connect(inst, &dev::Instrument::telemetryReceived, m_circle.get(), [runner = m_circle.get(), inst](const dev::proto::TelemetryBatch& b) {
        dev::jobs::feedCircleBatch(*runner, *inst, b);
    });
    m_runOn = m_current;
    m_live->hide();
    m_livePolar->show();
    m_livePolar->clearAll();
    m_tabs->setCurrentIndex(0);
    emit circleRunStarting(m_circle.get(), m_runOn);
    motion::msg::Message why;
    if (!m_circle->start(&why)) {
        emit problem(ui::words::text(why));
        return false;
    }
    updateRunUi();
    return true;
}

void CalibrationScreen::pause()
{
    if (m_runner && m_runner->isActive())
        m_runner->pause();
    if (m_circle && m_circle->isActive())
        m_circle->pause();
    updateRunUi();
}

void CalibrationScreen::abort()
{
    m_opening = false;  // a port still opening: the run is not started when it answers
    if (m_runner)
        m_runner->abort();
    if (m_circle)
        m_circle->abort();
    m_manualRow->hide();
    updateRunUi();
}

void CalibrationScreen::onManualWanted(const dev::jobs::StopContext& stop)
{
    QString where;
    for (std::size_t n = 0; n < stop.letters.size(); ++n)
        where += QStringLiteral("%1 %2  ").arg(stop.letters[n]).arg(ui::words::number(stop.targetsMm[n], motion::msg::Unit::Mm));
    m_manualPrompt->setText(tr("Reading %1 of %2: %3%4, cycle %5. What does the indicator show?")
                                .arg(stop.index + 1)
                                .arg(stop.total)
                                .arg(where, ui::words::term(motion::metrology::directionTermId(stop.direction)))
                                .arg(stop.cycle));
    m_manualValue->clear();
    m_manualRow->show();
    m_manualValue->setFocus();
}

bool CalibrationScreen::enterManual(const QString& text)
{
    if (!m_manual || !m_manual->waiting())
        return false;
    std::vector<double> values;
    for (const QString& word : text.split(QRegularExpression(QStringLiteral("[;\\s]+")), Qt::SkipEmptyParts)) {
        bool ok = false;
        double v = QLocale().toDouble(word, &ok);
        if (!ok)
            v = word.toDouble(&ok);  // a '.' typed under a decimal-comma locale
        if (!ok) {
            emit problem(tr("'%1' is not a reading: type the indicator's value in mm.").arg(text));
            return false;
        }
        values.push_back(v);
    }
    if (!m_manual->provide(values)) {
        emit problem(tr("'%1' is not a reading here: type one value per axis, in mm.").arg(text));
        return false;
    }
    return true;
}

void CalibrationScreen::onReading()
{
    if (!m_runner)
        return;
    if (m_runner->isXy()) {
        const auto e = m_runner->xyEvaluation();
        std::vector<motion::metrology::Reading> contour;
        m_live->setData(contour, e.contour);
    } else {
        m_live->setData(m_runner->readings(), m_runner->evaluation());
    }
    updateRunUi();
}

void CalibrationScreen::onAxisFinished()
{
    m_manualRow->hide();
    const auto* a = std::get_if<AxisTest>(&m_runner->test());
    if (m_source && m_source->kind() == dev::jobs::ReadingKind::Interferometer) {
        emit notice(tr("Every stop is visited. Capture with the interferometer, then import its export against %1 "
                       "(Import capture…).")
                        .arg(m_runner->basePath() + QStringLiteral(".targets.csv")));
        updateRunUi();
        return;
    }
    if (a) {
        dev::files::accuracy::AccuracyResult r;
        r.axis = a->axis;
        r.evaluation = m_runner->evaluation();
        r.tolerances = a->tolerances;
        r.reference = m_source ? dev::jobs::readingKindName(m_source->kind()) : "";
        r.readingsFile = QFileInfo(m_runner->basePath() + QStringLiteral(".readings.csv")).fileName().toStdString();
        r.createdUtc = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
        adoptAxisResult(r, *a, m_runner->readings(), m_runner->basePath(),
                        m_source ? m_source->describe() : motion::msg::make("accuracy.source.recorded", {motion::msg::verbatim("reference", r.reference)}));
    } else {
        const auto e = m_runner->xyEvaluation();
        m_verdict->setText(tr("Linked XY line: contour error A↑ %1 µm, R↑ %2 µm (%3 readings).")
                               .arg(um(e.contour.figures.aUpMm), um(e.contour.figures.rUpMm))
                               .arg(m_runner->readingsTaken()));
        m_tabs->setCurrentIndex(1);
    }
    emit notice(tr("The test is done: results in %1.").arg(m_runner->folder()));
    updateRunUi();
}

void CalibrationScreen::adoptAxisResult(const dev::files::accuracy::AccuracyResult& r, const AxisTest& test,
                                        const std::vector<motion::metrology::Reading>& readings, const QString& basePath,
                                        const motion::msg::Message& source)
{
    // The same run shown again (Run on its finished folder) is not its own "before".
    if (m_latest && m_latest->axis == r.axis && m_latestBasePath != basePath)
        m_previous = m_latest;
    m_latest = r;
    m_latestTest = test;
    m_latestReadings = readings;
    m_latestBasePath = basePath;
    m_latestSource = source;
    m_fit->setEvaluation(r.axis, r.evaluation);
    showResult();
    showBeforeAfter();
    writeReport();
    m_tabs->setCurrentIndex(1);
}

void CalibrationScreen::onCircleFinished()
{
    const auto e = m_circle->evaluation();
    m_circleResult = e;
    m_polar->setEvaluation(e, m_circle->test().radiusMm);
    std::vector<QStringList> rows;
    for (const auto& run : e.runs) {
        const QString dir = ui::words::term(motion::metrology::rotationTermId(run.rotation));
        rows.push_back({tr("G, %1").arg(dir), um(run.circularDeviationMm)});
        rows.push_back({tr("radial deviation, %1").arg(dir), QStringLiteral("%1 … %2").arg(um(run.radialDeviationMinMm), um(run.radialDeviationMaxMm))});
    }
    if (e.bidirectionalDeviationMm)
        rows.push_back({tr("G(b)"), um(*e.bidirectionalDeviationMm)});
    if (e.hysteresisMm)
        rows.push_back({tr("H hysteresis"), um(*e.hysteresisMm)});
    setRows(m_circleFigures, rows);
    m_tabs->setCurrentIndex(4);
    if (ui::report::canRender()) {
        ui::report::CircleReportInput in;
        in.title = tr("Circular test, radius %1").arg(ui::words::number(m_circle->test().radiusMm, motion::msg::Unit::Mm));
        in.instrument = cur() ? QStringLiteral("%1 (%2)").arg(cur()->identity().model, cur()->identity().family) : QString();
        in.test = m_circle->test();
        in.evaluation = e;
        in.created = QDateTime::currentDateTime().toString(Qt::ISODate);
        QDir().mkpath(m_folder->text());
        QString error;
        const QString pdf = QDir(m_folder->text()).filePath(QString::fromStdString(m_circle->test().name) + QStringLiteral(".report.pdf"));
        if (ui::report::writeCircleReport(pdf, in, &error))
            emit notice(tr("The circular test is done: report %1.").arg(pdf));
        else
            emit problem(error);
    }
    updateRunUi();
}

void CalibrationScreen::showResult()
{
    if (!m_latest) {
        m_figures->setRowCount(0);
        m_verdict->setText(tr("No axis test has finished yet."));
        m_resultPlot->clearAll();
        m_saveComp->setEnabled(false);
        m_saveComp->setToolTip(tr("Run an axis test first: its fit is what is saved"));
        m_reportButton->setEnabled(false);
        m_reportButton->setToolTip(tr("Run an axis test first"));
        return;
    }
    const auto& r = *m_latest;
    const auto verdicts = motion::metrology::judge(r.evaluation, r.tolerances);
    std::vector<QStringList> rows;
    for (const char* key : kFigureKeys) {
        const auto v = dev::files::accuracy::figureByKey(r.evaluation.figures, key);
        if (!v)
            continue;
        QString limit = QStringLiteral("—"), verdict;
        for (const auto& vd : verdicts)
            if (vd.figure == key) {
                limit = um(vd.limitMm);
                verdict = vd.pass ? tr("pass") : tr("FAIL");
            }
        rows.push_back({figureLabel(key), um(v), limit, verdict});
    }
    setRows(m_figures, rows);
    m_verdict->setText(r.tolerances.empty() ? tr("Axis %1 from %2: no limits given, not judged.").arg(QString::fromStdString(r.axis), QString::fromStdString(r.reference))
                       : motion::metrology::allPass(verdicts) ? tr("Axis %1 from %2: PASS.").arg(QString::fromStdString(r.axis), QString::fromStdString(r.reference))
                                                              : tr("Axis %1 from %2: FAIL.").arg(QString::fromStdString(r.axis), QString::fromStdString(r.reference)));
    m_resultPlot->setBefore(std::nullopt);
    m_resultPlot->setData(m_latestReadings, r.evaluation);
    m_saveComp->setEnabled(m_fit->model().has_value());
    m_saveComp->setToolTip(tr("Writes the fitted compensation as a file (*.compensation.json)"));
    m_reportButton->setEnabled(ui::report::canRender());
    m_reportButton->setToolTip(tr("The report of the latest run, written into its folder"));
}

void CalibrationScreen::showBeforeAfter()
{
    if (!m_latest || !m_previous) {
        m_beforeAfter->setRowCount(0);
        m_beforeAfterNote->setText(tr("Run the same axis test again after enabling the compensation: the two runs are compared here."));
        m_beforeAfterPlot->clearAll();
        return;
    }
    std::vector<QStringList> rows;
    for (const char* key : kFigureKeys) {
        const auto b = dev::files::accuracy::figureByKey(m_previous->evaluation.figures, key);
        const auto a = dev::files::accuracy::figureByKey(m_latest->evaluation.figures, key);
        if (!a && !b)
            continue;
        QString gain = QStringLiteral("—");
        if (a && b && std::fabs(*a) > 1e-9 && std::string(key) != "B_mean")
            gain = QStringLiteral("%1×").arg(QLocale().toString(std::fabs(*b) / std::fabs(*a), 'f', 1));
        rows.push_back({figureLabel(key), um(b), um(a), gain});
    }
    setRows(m_beforeAfter, rows);
    const auto aB = m_previous->evaluation.figures.aMm ? m_previous->evaluation.figures.aMm : std::optional<double>(m_previous->evaluation.figures.aUpMm);
    const auto aA = m_latest->evaluation.figures.aMm ? m_latest->evaluation.figures.aMm : std::optional<double>(m_latest->evaluation.figures.aUpMm);
    m_beforeAfterNote->setText(tr("Axis %1: A %2 µm before, %3 µm after%4.")
                                   .arg(QString::fromStdString(m_latest->axis), um(aB), um(aA))
                                   .arg(aA && *aA > 1e-9 ? tr(": %1 times better").arg(QLocale().toString(*aB / *aA, 'f', 1)) : QString()));
    m_beforeAfterPlot->setBefore(m_previous->evaluation);
    m_beforeAfterPlot->setData(m_latestReadings, m_latest->evaluation);
}

void CalibrationScreen::writeReport()
{
    if (!m_latest || m_latestBasePath.isEmpty() || !ui::report::canRender())
        return;
    ui::report::AxisReportInput in;
    in.title = tr("Positioning accuracy of axis %1").arg(QString::fromStdString(m_latest->axis));
    in.instrument = cur() ? QStringLiteral("%1 (%2)").arg(cur()->identity().model, cur()->identity().family) : QString();
    in.source = m_latestSource;
    in.test = m_latestTest;
    in.result = *m_latest;
    in.readings = m_latestReadings;
    in.before = m_previous;
    in.fit = m_fit->fit();
    in.created = QDateTime::currentDateTime().toString(Qt::ISODate);
    const QString pdf = m_latestBasePath + QStringLiteral(".report.pdf");
    QString error;
    if (ui::report::writeAxisReport(pdf, in, &error))
        emit notice(tr("Report written: %1").arg(pdf));
    else
        emit problem(error);
}

QString CalibrationScreen::stateText() const { return m_state->text(); }

QString CalibrationScreen::figuresText() const
{
    QStringList lines;
    for (int r = 0; r < m_figures->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < m_figures->columnCount(); ++c)
            cells << (m_figures->item(r, c) ? m_figures->item(r, c)->text() : QString());
        lines << cells.join(QLatin1Char('\t'));
    }
    return lines.join(QLatin1Char('\n'));
}

void CalibrationScreen::previewTargets()
{
    if ((m_runner && m_runner->isActive()) || (m_circle && m_circle->isActive()))
        return;
    if (!m_form->entryProblem().isEmpty())
        return;  // the targets shown stay those of the last valid entry
    const auto test = m_form->test();
    if (const auto* axisTest = std::get_if<motion::metrology::AxisTest>(&test))
        m_live->showTargets(motion::metrology::targetsOf(*axisTest));
}

void CalibrationScreen::updateRunUi()
{
    dev::Instrument* inst = cur();
    const bool axisActive = m_runner && m_runner->isActive();
    const bool circleActive = m_circle && m_circle->isActive();
    const bool active = axisActive || circleActive;
    const auto problems = m_form->problems();
    QString formError = m_form->entryProblem();  // a field's own reason before what its NaN breaks
    for (const auto& p : problems)
        if (p.isError() && formError.isEmpty()) {
            formError = ui::words::problem(p);
            break;
        }
    m_formProblems->setText(formError);
    m_formProblems->setVisible(!formError.isEmpty());
    m_form->setEditable(!active);
    // A file opened now would replace the test that runs: held while it runs.
    m_open->setEnabled(!active);
    m_open->setToolTip(active ? tr("A test is running: the test on screen stays until it has finished or been aborted.") : QString());
    m_instrumentBox->setEnabled(!active);
    m_sourceBox->setEnabled(!active && m_form->kind() != AccuracyTestForm::Kind::Circle);
    m_port->setEnabled(!active && m_sourceBox->currentData().toString() == QLatin1String("gauge"));
    m_port->setToolTip(m_port->isEnabled() ? tr("The gauge's serial port (9600 Bd, 8N1); sim reads the simulator's gauge")
                                           : tr("Used when the readings come from a gauge"));
    m_sourceBox->setToolTip(m_form->kind() == AccuracyTestForm::Kind::Circle
                                ? tr("A circular test samples the readback along the path")
                                : tr("The readback is what the position loop closes on: it cannot see the work point's error. "
                                     "A gauge or an interferometer at the work point can."));
    const bool resumable = m_runner && m_runOn == m_current
        && (m_runner->state() == dev::jobs::AccuracyRunner::State::Paused || m_runner->state() == dev::jobs::AccuracyRunner::State::Stopped);
    QString why;
    if (active)
        why = tr("A test is running.");
    else if (m_opening)
        why = tr("Opening the gauge's port…");
    else if (!inst || !inst->isReady())
        why = inst ? ui::words::text(inst->whyNot(dev::Capability::Homing)) : tr("No instrument.");
    else if (!formError.isEmpty())
        why = formError;
    m_runButton->setEnabled(why.isEmpty());
    m_runButton->setText(resumable ? tr("Resume") : tr("Run"));
    m_runButton->setToolTip(why.isEmpty() ? tr("Run the test, or go on from where it stopped (Ctrl+R)") : why);
    m_pauseButton->setEnabled(active);
    m_pauseButton->setToolTip(active ? tr("Stop after the reading in progress (Ctrl+P)") : tr("Nothing is running."));
    m_abortButton->setEnabled(active || (m_runner && m_runner->state() == dev::jobs::AccuracyRunner::State::Paused));
    m_abortButton->setToolTip(m_abortButton->isEnabled() ? tr("Stop the axes now; Run goes on at the next reading later (Ctrl+.)")
                                                         : tr("Nothing is running."));
    const bool axisOnScreen = m_form->kind() == AccuracyTestForm::Kind::Axis;
    m_importButton->setEnabled(!active && axisOnScreen);
    m_importButton->setToolTip(active          ? tr("A test is running.")
                                   : !axisOnScreen ? tr("Only an axis test's capture can be imported: show the axis test it belongs to.")
                                                   : tr("Match an interferometer's CSV export to a run's target sequence and "
                                                        "evaluate it against the axis test on screen"));
    // Progress and the state line are recomputed from the runners, never stored as text.
    QString state;
    if (m_circle && (circleActive || m_form->kind() == AccuracyTestForm::Kind::Circle)) {
        const int done = static_cast<int>(m_circle->runs().size()), total = static_cast<int>(m_circle->rotations().size());
        m_progress->setRange(0, std::max(1, total));
        m_progress->setValue(done);
        state = circleActive ? tr("Circle %1 of %2, about %3 left.").arg(std::min(done + 1, total)).arg(total).arg(duration(m_circle->etaS()))
                             : (m_circle->state() == dev::jobs::CircleRunner::State::Finished ? tr("The circular test is done.") : QString());
    } else if (m_runner) {
        m_progress->setRange(0, std::max(1, m_runner->totalReadings()));
        m_progress->setValue(m_runner->readingsTaken());
        using S = dev::jobs::AccuracyRunner::State;
        switch (m_runner->state()) {
        case S::Running:
        case S::Pausing:
            state = tr("Reading %1 of %2, about %3 left%4.")
                        .arg(std::min(m_runner->readingsTaken() + 1, m_runner->totalReadings()))
                        .arg(m_runner->totalReadings())
                        .arg(duration(m_runner->etaS()))
                        .arg(m_runner->state() == S::Pausing ? tr(" (pausing after this reading)") : QString());
            break;
        // "after N of M": "at reading 7" over seven readings taken read as if the seventh was lost.
        case S::Paused: state = tr("Paused after %1 of %2 readings.").arg(m_runner->readingsTaken()).arg(m_runner->totalReadings()); break;
        case S::Stopped:
            state = tr("Stopped after %1 of %2 readings: %3")
                        .arg(m_runner->readingsTaken())
                        .arg(m_runner->totalReadings())
                        .arg(m_lastProblem.empty() ? QString() : ui::words::text(m_lastProblem));
            break;
        case S::Finished: state = tr("Done: %1 readings.").arg(m_runner->totalReadings()); break;
        case S::Idle: break;
        }
    } else {
        m_progress->setRange(0, 1);
        m_progress->setValue(0);
        state = tr("Define a test, pick where the readings come from, and run it.");
    }
    m_state->setText(state);
}

} // namespace ui
