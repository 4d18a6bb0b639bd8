// benchpilot-cli accuracy run: an ISO 230-2 axis test (or a test file's axis or XY-line
// test) on the instrument, its readings from the readback, a gauge, a person or an
// interferometer's later import; the readings CSV, the result JSON and the PDF report
// written into --out. Runs continue from their log in --out after any stop.
#include "accuracy_cli.h"
#include "accuracy_sources.h"
#include "camera_cli.h"
#include "cli_session.h"
#include "command.h"

#include "device/camera/scale_reading_source.h"
#include "device/files/accuracy/accuracy_run_folders.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/link/simulated_link.h"
#include "motion/metrology/compensation/polynomial_fit.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "widgets/report/accuracy_report.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>

#include <cmath>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

const std::vector<std::pair<QString, QString>> kOptionOf = {
    {QStringLiteral("targets_mm"), QStringLiteral("--targets")}, {QStringLiteral("grid"), QStringLiteral("--targets")},
    {QStringLiteral("cycles"), QStringLiteral("--cycles")},       {QStringLiteral("feed_mm_s"), QStringLiteral("--feed")},
    {QStringLiteral("dwell_s"), QStringLiteral("--dwell")},       {QStringLiteral("overrun_mm"), QStringLiteral("--overrun")},
    {QStringLiteral("axis"), QStringLiteral("--axis")},
};

/// --targets: "start:end:count" (a grid) or "a,b,c" (a list).
bool parseTargets(Invocation& inv, const QString& text, motion::metrology::AxisTest& t)
{
    const QStringList grid = text.split(QLatin1Char(':'));
    bool ok = true;
    if (grid.size() == 3) {
        motion::metrology::TargetGrid g;
        bool a = false, b = false, c = false;
        g.startMm = grid[0].toDouble(&a);
        g.endMm = grid[1].toDouble(&b);
        g.count = grid[2].toInt(&c);
        if (!(a && b && c)) {
            inv.usage(tr("--targets '%1': START:END:COUNT, such as 10:90:9, or a list such as 10,30,50").arg(text));
            return false;
        }
        g.irregular = inv.isSet(QStringLiteral("irregular"));
        t.grid = g;
        return true;
    }
    for (const QString& word : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const double v = word.trimmed().toDouble(&ok);
        if (!ok) {
            inv.usage(tr("--targets '%1': START:END:COUNT, such as 10:90:9, or a list such as 10,30,50").arg(text));
            return false;
        }
        t.targetsMm.push_back(v);
    }
    return true;
}

/// The test from --test FILE, or from the options.
bool buildTest(Invocation& inv, dev::files::accuracy::AccuracyTest& out)
{
    if (inv.isSet(QStringLiteral("test"))) {
        const auto read = dev::files::accuracy::loadAccuracyTestFile(inv.path(inv.value(QStringLiteral("test"))));
        if (reportProblems(inv, read.problems) || !read.test)
            return false;
        if (std::holds_alternative<motion::metrology::CircularTest>(*read.test)) {
            inv.usage(tr("%1 is a circular test: run it with 'accuracy circle --test'").arg(inv.value(QStringLiteral("test"))));
            return false;
        }
        out = *read.test;
        return true;
    }
    motion::metrology::AxisTest t;
    t.axis = inv.value(QStringLiteral("axis")).toUpper().toStdString();
    t.name = "accuracy-" + t.axis;
    if (!inv.isSet(QStringLiteral("targets"))) {
        inv.usage(tr("give --targets START:END:COUNT (or a list), or --test FILE"));
        return false;
    }
    if (!parseTargets(inv, inv.value(QStringLiteral("targets")), t))
        return false;
    double cycles = 5;
    if (!inv.number(QStringLiteral("cycles"), cycles, 5.0) || !inv.number(QStringLiteral("feed"), t.feedMmS, t.feedMmS)
        || !inv.number(QStringLiteral("dwell"), t.dwellS, t.dwellS) || !inv.number(QStringLiteral("overrun"), t.overrunMm, t.overrunMm))
        return false;
    if (std::floor(cycles) != cycles) {
        inv.usage(tr("--cycles '%1' must be a whole number").arg(inv.value(QStringLiteral("cycles"))));
        return false;
    }
    t.cycles = static_cast<int>(cycles);
    t.bidirectional = !inv.isSet(QStringLiteral("unidirectional"));
    const auto problems = motion::metrology::validate(t);
    if (reportProblems(inv, problems, kOptionOf))
        return false;
    out = t;
    return true;
}

QString defaultFolder(const Invocation& inv, const dev::files::accuracy::AccuracyTest& t)
{
    const std::string name = std::visit([](const auto& x) { return x.name; }, t);
    return inv.path(QString::fromStdString(name.empty() ? "accuracy" : name));
}

QJsonArray filesJson(const QStringList& files)
{
    QJsonArray a;
    for (const QString& f : files)
        a.append(f);
    return a;
}

} // namespace

int runAccuracy(Invocation& inv)
{
    dev::files::accuracy::AccuracyTest test;
    if (!buildTest(inv, test))
        return Usage;
    const QString spec = inv.value(QStringLiteral("source")).isEmpty() ? QStringLiteral("readback") : inv.value(QStringLiteral("source"));
    double timeScale = 1;
    if (!inv.number(QStringLiteral("time-scale"), timeScale, 1.0))
        return Usage;
    if (inv.isSet(QStringLiteral("time-scale")) && (inv.link().sim.isEmpty() || inv.host().insideGui()))
        return inv.usage(timeScaleRefusal(inv));
    if (!(timeScale > 0 && timeScale <= 100))
        return inv.usage(tr("--time-scale must be from 0 to 100"));
    const QString base = inv.isSet(QStringLiteral("out")) ? inv.path(inv.value(QStringLiteral("out"))) : defaultFolder(inv, test);
    // --new-run: the newest run of the test (accuracy_run_folders.h) goes on if it stopped;
    // a finished one is followed by a run beside it. Without it, --out is the run.
    const bool newRun = inv.isSet(QStringLiteral("new-run"));
    if (newRun && inv.isSet(QStringLiteral("restart")))
        return inv.usage(tr("--new-run keeps every run; --restart sets one aside: give one of them"));
    QString folder = newRun ? dev::files::accuracy::latestRunFolder(base) : base;
    if (timeScale != 1)
        inv.unpaceSimulatedLink();

    CliSession* session = inv.session();
    if (!session)
        return LinkTrouble;
    dev::Instrument* instrument = session->instrument();
    if (auto* link = qobject_cast<dev::SimulatedLink*>(session->link()))
        link->host().setTimeScale(timeScale);
    // Where the other axes stand for the test (the glass scale under the camera, the
    // gauge's anvil): there before the first stop, as a person would jog them.
    QVector<QPair<int, double>> at;
    if (inv.isSet(QStringLiteral("at")) && !session->parseTargets(inv.value(QStringLiteral("at")).split(QLatin1Char(','), Qt::SkipEmptyParts), &at))
        return Usage;
    if (inv.isSet(QStringLiteral("home"))) {
        quint8 mask = 0;
        if (const auto* a = std::get_if<motion::metrology::AxisTest>(&test))
            session->parseAxes(QString::fromStdString(a->axis), &mask);
        else
            session->parseAxes(QStringLiteral("XY"), &mask);
        for (const auto& t : at)
            mask = static_cast<quint8>(mask | (1u << t.first));
        if (int rc = session->request([&](auto cb) { instrument->home(mask, cb); }, tr("home")))
            return rc;
        if (!session->waitUntilHomed(mask))
            return reportFailure(inv, motion::msg::make("accuracy.run.not_homed", {motion::msg::verbatim("axis", "")}), Refused);
    }
    if (!at.isEmpty()) {
        if (int rc = session->request([&](auto cb) { instrument->move(at, false, 0, cb); }, tr("move")))
            return rc;
        if (int rc = session->waitUntilStill(tr("move"), false))
            return rc;
    }
    int axisIndex = 0;
    if (const auto* a = std::get_if<motion::metrology::AxisTest>(&test))
        axisIndex = a->axis.size() == 1 ? instrument->identity().axisIndex(QChar::fromLatin1(a->axis[0])) : -1;
    QObject owner;
    dev::jobs::ReadingSource* source = makeSource(inv, *session, spec, std::max(0, axisIndex), &owner);
    if (!source)
        return Usage;
    motion::msg::Message openProblem;
    bool opened = false;
    source->open([&](const motion::msg::Message& p) {
        openProblem = p;
        opened = true;
    });
    spinUntil([&] { return opened; }, 5000);
    if (!opened || !openProblem.empty())
        return reportFailure(inv, openProblem.empty() ? motion::msg::make("gauge.no_answer") : openProblem, LinkTrouble);

    dev::jobs::AccuracyRunner runner(instrument);
    motion::msg::Problems problems;
    if (!runner.prepare(test, source, folder, inv.isSet(QStringLiteral("restart")), &problems)) {
        reportProblems(inv, problems, kOptionOf);
        return Usage;
    }
    if (runner.state() == dev::jobs::AccuracyRunner::State::Finished && newRun) {
        const QString finished = folder;
        folder = dev::files::accuracy::nextRunFolder(base);
        if (!runner.prepare(test, source, folder, false, &problems)) {
            reportProblems(inv, problems, kOptionOf);
            return Usage;
        }
        inv.err() << tr("%1 holds a finished run of this test: this run goes into %2, beside it.")
                         .arg(QDir::toNativeSeparators(finished), QDir::toNativeSeparators(folder))
                  << "\n";
    } else if (runner.state() == dev::jobs::AccuracyRunner::State::Finished) {
        // Not a dead end: the finished run's results are reported again, and the way to
        // measure again (after compensation) is said.
        inv.err() << tr("%1 holds a finished run of this test: its results follow, nothing was moved. To run the test "
                        "again beside it (after compensation), add --new-run: it goes into %2 and both are kept.")
                         .arg(QDir::toNativeSeparators(folder), QDir::toNativeSeparators(dev::files::accuracy::nextRunFolder(base)))
                  << "\n";
    }
    reportProblems(inv, problems, kOptionOf);  // warnings
    attachStdinPrompter(inv, source, [&] { runner.abort(); });
    motion::msg::Message stopped;
    QObject::connect(&runner, &dev::jobs::AccuracyRunner::problem, &runner, [&](const motion::msg::Message& m) { stopped = m; });
    QObject::connect(&runner, &dev::jobs::AccuracyRunner::progress, &runner, [&](int taken, int total, double eta) {
        inv.host().progressed(QJsonObject{{QStringLiteral("readings_taken"), taken},
                                          {QStringLiteral("readings"), total},
                                          {QStringLiteral("eta_s"), eta}});
        if (inv.json())
            return;  // the one JSON object at the end is the output scripts read
        inv.err() << tr("\r%1 of %2 readings, about %3 s left   ").arg(taken).arg(total).arg(std::lround(eta));
        inv.err().flush();
    });
    if (auto* camera = qobject_cast<dev::camera::ScaleReadingSource*>(source))
        camera->setFailedImagesFolder(folder);  // a reading that finds no line keeps its image there
    if (runner.state() != dev::jobs::AccuracyRunner::State::Finished) {
        motion::msg::Message why;
        if (!runner.start(&why))
            return reportFailure(inv, why, Refused);
        // No wall-clock limit on a person typing; otherwise four times the estimate.
        const bool manual = source->kind() == dev::jobs::ReadingKind::Manual;
        const int limitMs = manual ? 24 * 3600 * 1000
                                   : static_cast<int>(std::min(24.0 * 3600, std::max(inv.link().timeoutS, runner.etaS() / timeScale * 4 + 60)) * 1000);
        const bool done = spinUntil([&] { return !runner.isActive(); }, limitMs);
        if (!inv.json())
            inv.err() << "\n";
        if (!done) {
            runner.abort();
            return reportFailure(inv, motion::msg::make("accuracy.run.timed_out"), Refused);
        }
    }
    if (runner.state() != dev::jobs::AccuracyRunner::State::Finished)
        return reportFailure(inv, stopped.empty() ? motion::msg::make("accuracy.run.aborted") : stopped, Refused);

    QStringList files = runner.results();
    QJsonObject out;
    if (source->kind() == dev::jobs::ReadingKind::Interferometer) {
        out = QJsonObject{{QStringLiteral("ok"), true},
                          {QStringLiteral("readings"), QJsonValue::Null},
                          {QStringLiteral("sequence"), runner.basePath() + QStringLiteral(".targets.csv")}};
    } else if (const auto* a = std::get_if<motion::metrology::AxisTest>(&test)) {
        dev::files::accuracy::AccuracyResult r;
        r.axis = a->axis;
        r.evaluation = runner.evaluation();
        r.tolerances = a->tolerances;
        r.reference = dev::jobs::readingKindName(source->kind());
        r.readingsFile = QFileInfo(runner.basePath() + QStringLiteral(".readings.csv")).fileName().toStdString();
        if (!r.evaluation.ok()) {
            reportProblems(inv, r.evaluation.problems);
            return Refused;
        }
        ui::report::AxisReportInput in;
        in.title = tr("Positioning accuracy of axis %1").arg(QString::fromStdString(a->axis));
        in.instrument = QStringLiteral("%1 (%2)").arg(instrument->identity().model, instrument->identity().family);
        in.source = source->describe();
        in.test = *a;
        in.result = r;
        in.readings = runner.readings();
        in.fit = motion::metrology::fitPolynomials(dev::files::accuracy::fitPointsOf(r.evaluation));
        in.created = QDateTime::currentDateTime().toString(Qt::ISODate);
        const QString pdf = runner.basePath() + QStringLiteral(".report.pdf");
        QString error;
        if (ui::report::canRender()) {
            if (ui::report::writeAxisReport(pdf, in, &error))
                files << pdf;
            else
                inv.report(error);
        }
        out = resultJson(r);
        if (!inv.json()) {
            printFiguresText(inv, r);
        }
    } else {
        const auto e = runner.xyEvaluation();
        auto figures = [](const motion::metrology::Evaluation& ev) {
            dev::files::accuracy::AccuracyResult r;
            r.evaluation = ev;
            return resultJson(r).value(QStringLiteral("figures"));
        };
        out = QJsonObject{{QStringLiteral("x"), figures(e.x)}, {QStringLiteral("y"), figures(e.y)},
                          {QStringLiteral("contour"), figures(e.contour)},
                          {QStringLiteral("theta_deg"), e.thetaRad * 180 / 3.141592653589793}};
        if (!inv.json())
            inv.out() << tr("contour error: A↑ %1 µm, R↑ %2 µm").arg(e.contour.figures.aUpMm * 1e3, 0, 'f', 2).arg(e.contour.figures.rUpMm * 1e3, 0, 'f', 2)
                      << "\n";
    }
    if (inv.json()) {
        out.insert(QStringLiteral("source"), QString::fromLatin1(dev::jobs::readingKindName(source->kind())));
        out.insert(QStringLiteral("folder"), folder);
        out.insert(QStringLiteral("files"), filesJson(files));
        printJson(inv, out);
    } else {
        for (const QString& f : files)
            inv.out() << tr("wrote %1").arg(f) << "\n";
    }
    return Ok;
}

QList<QCommandLineOption> accuracyRunOptions()
{
    return {option("axis", "the axis to test", "letter", "X"),
            option("targets", "START:END:COUNT (a grid) or a list 10,30,50, in mm", "targets"),
            option("irregular", "ISO 230-2's irregular spacing of a grid's inner targets"),
            option("cycles", "cycles (ISO 230-2: 5)", "n", "5"),
            option("unidirectional", "approach every target from below only"),
            option("feed", "feed between stops in mm/s", "mm/s", "5"),
            option("dwell", "wait after arriving before the settle rule, in s", "s", "0.5"),
            option("overrun", "past the end targets so each approach comes from its side, in mm", "mm", "1"),
            option("test", "a test definition file (*.accuracy-test.json) instead of the options above", "file"),
            option("source", "readback, gauge:PATH (gauge:sim with --sim), manual, interferometer or camera[:SOURCE] (a glass scale read by the camera; camera is camera:sim)", "source", "readback"),
            option("gauge-baud", "the gauge port's baud rate", "n", "9600"),
            option("gauge-timeout", "how long the gauge may take to answer, in s", "s", "1"),
            option("out", "folder for the run log, readings CSV, result JSON and PDF report", "dir"),
            option("restart", "keep another test's run log in --out aside and start afresh"),
            option("new-run", "when --out holds a finished run of this test, run it again beside it (into OUT-2, OUT-3, …), keeping both; a stopped newest run goes on"),
            option("home", "home the test's axes first"),
            option("at", "move other axes here first (--home homes them too), e.g. Y=50.075: where the scale or the gauge is", "AXIS=MM[,AXIS=MM]"),
            option("time-scale", "with --sim: run the simulator's clock this many times faster", "k", "1"),
            option("specimen", "with --source camera on the simulator: what the camera looks at: line-scales, grid-plate or slide", "NAME", "line-scales"),
            option("camera-seed", "with --source camera on the simulator: the specimen's and noise's seed", "N", "1"),
            option("certificate", "with --source camera: the glass scale's calibration certificate (*.scale-certificate.csv), applied to every reading", "file"),
            option("scale-length", "with --certificate: the scale's graduated length from 0, in mm (the certificate must lie within it)", "mm", "100")};
}

} // namespace app::cli
