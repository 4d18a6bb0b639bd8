// benchpilot-cli accuracy run | analyze | circle | import (docs/accuracy.md):
//   run --axis X --targets 10:90:9 --cycles 5 --source readback|gauge:PATH|manual [--out DIR] [--json]
//   analyze READINGS.csv [--json]                 ISO 230-2 figures and the per-target table
//   circle --radius R --feed F [--json]           an ISO 230-4 circular test on X and Y
//   import --sequence TARGETS.csv EXPORT.csv      an interferometer's capture as readings
#include "accuracy_cli.h"
#include "cli_session.h"
#include "command.h"

#include "device/files/accuracy/accuracy_test_file.h"
#include "device/files/accuracy/interferometer_csv.h"
#include "device/files/accuracy/readings_csv.h"
#include "device/files/text_file.h"
#include "device/jobs/accuracy/circle_runner.h"
#include "device/jobs/accuracy/circle_telemetry.h"
#include "device/link/simulated_link.h"
#include "widgets/report/accuracy_report.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace app::cli {

int runAccuracy(Invocation& inv);
QList<QCommandLineOption> accuracyRunOptions();

namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// --tolerance-a etc.: limits in mm for a result that has none.
bool readTolerances(Invocation& inv, motion::metrology::AxisTolerances& t)
{
    const std::pair<const char*, std::optional<double>*> all[] = {{"tolerance-a", &t.aMm}, {"tolerance-r", &t.rMm}, {"tolerance-e", &t.eMm},
                                                                  {"tolerance-m", &t.mMm}, {"tolerance-b", &t.bMm}};
    for (const auto& [name, into] : all) {
        if (!inv.isSet(QString::fromLatin1(name)))
            continue;
        double v = 0;
        if (!inv.number(QString::fromLatin1(name), v))
            return false;
        if (!(v > 0)) {
            inv.usage(tr("--%1 must be above 0 mm").arg(QString::fromLatin1(name)));
            return false;
        }
        *into = v;
    }
    return true;
}

int analyze(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one readings CSV"));
    const QString path = inv.path(inv.arguments().front());
    std::string text, name = QFileInfo(path).fileName().toStdString();
    motion::msg::Message error;
    if (!dev::files::readText(path, &text, &error)) {
        reportProblems(inv, motion::msg::Problems{motion::msg::Problem(name, 0, 0, "", error)});
        return Usage;
    }
    const auto analyzed = dev::files::accuracy::analyzeReadingsCsv(text, name);
    if (reportProblems(inv, analyzed.problems))
        return Usage;
    dev::files::accuracy::AccuracyResult r;
    r.axis = inv.value(QStringLiteral("axis")).isEmpty() ? "X" : inv.value(QStringLiteral("axis")).toUpper().toStdString();
    r.evaluation = analyzed.evaluation;
    if (!readTolerances(inv, r.tolerances))
        return Usage;
    r.readingsFile = name;
    r.createdUtc = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    if (inv.isSet(QStringLiteral("out"))) {
        if (!dev::files::accuracy::saveAccuracyResultFile(inv.path(inv.value(QStringLiteral("out"))), r, &error))
            return reportFailure(inv, error, Refused);
    }
    if (inv.json())
        printJson(inv, resultJson(r));
    else
        printFiguresText(inv, r);
    return Ok;
}

int importInterferometer(Invocation& inv)
{
    if (inv.arguments().size() != 1 || !inv.isSet(QStringLiteral("sequence")))
        return inv.usage(tr("give --sequence TARGETS.csv and the interferometer's CSV export"));
    const auto sequence = dev::files::accuracy::loadTargetSequence(inv.path(inv.value(QStringLiteral("sequence"))));
    if (reportProblems(inv, sequence.problems))
        return Usage;
    const auto imported = dev::files::accuracy::loadInterferometerExport(inv.path(inv.arguments().front()), sequence.stops);
    if (reportProblems(inv, imported.problems))
        return Usage;
    const auto evaluation = motion::metrology::evaluate(imported.readings);
    motion::msg::Message error;
    QString out = inv.path(inv.value(QStringLiteral("out")));
    if (inv.value(QStringLiteral("out")).isEmpty()) {
        out = inv.path(inv.value(QStringLiteral("sequence")));
        out.replace(QStringLiteral(".targets.csv"), QString());
        out += QStringLiteral(".readings.csv");
    }
    if (!dev::files::accuracy::saveReadingsCsv(out, imported.readings, &error))
        return reportFailure(inv, error, Refused);
    dev::files::accuracy::AccuracyResult r;
    r.axis = inv.value(QStringLiteral("axis")).isEmpty() ? "X" : inv.value(QStringLiteral("axis")).toUpper().toStdString();
    r.evaluation = evaluation;
    r.reference = "interferometer";
    r.readingsFile = QFileInfo(out).fileName().toStdString();
    if (!evaluation.ok()) {
        reportProblems(inv, evaluation.problems);
        return Usage;
    }
    if (inv.json()) {
        QJsonObject o = resultJson(r);
        o.insert(QStringLiteral("files"), QJsonArray{out});
        printJson(inv, o);
    } else {
        printFiguresText(inv, r);
        inv.out() << tr("wrote %1").arg(out) << "\n";
    }
    return Ok;
}

QJsonObject circleJson(const motion::metrology::CircularTest& t, const motion::metrology::CircularEvaluation& e)
{
    QJsonObject figures;
    QJsonArray runs;
    bool pass = true;
    for (const auto& run : e.runs) {
        const QString dir = QString::fromLatin1(motion::metrology::rotationName(run.rotation));
        figures.insert(QStringLiteral("G_") + dir, nm6(run.circularDeviationMm));
        if (t.maxGMm && run.circularDeviationMm > *t.maxGMm)
            pass = false;
        runs.append(QJsonObject{{QStringLiteral("rotation"), dir},
                                {QStringLiteral("G_mm"), nm6(run.circularDeviationMm)},
                                {QStringLiteral("radial_min_mm"), nm6(run.radialDeviationMinMm)},
                                {QStringLiteral("radial_max_mm"), nm6(run.radialDeviationMaxMm)},
                                {QStringLiteral("lsq_centre_mm"), QJsonArray{nm6(run.lsq.centreMm.xMm), nm6(run.lsq.centreMm.yMm)}},
                                {QStringLiteral("lsq_radius_mm"), nm6(run.lsq.radiusMm)},
                                {QStringLiteral("samples"), static_cast<int>(run.samples.size())}});
    }
    figures.insert(QStringLiteral("G_b"), e.bidirectionalDeviationMm ? QJsonValue(nm6(*e.bidirectionalDeviationMm)) : QJsonValue());
    figures.insert(QStringLiteral("H"), e.hysteresisMm ? QJsonValue(nm6(*e.hysteresisMm)) : QJsonValue());
    if (t.maxHMm && e.hysteresisMm && *e.hysteresisMm > *t.maxHMm)
        pass = false;
    QJsonObject o{{QStringLiteral("schema"), QStringLiteral("benchpilot.circle-result")},
                  {QStringLiteral("version"), 1},
                  {QStringLiteral("standard"), QStringLiteral("ISO 230-4")},
                  {QStringLiteral("radius_mm"), t.radiusMm},
                  {QStringLiteral("feed_mm_s"), t.feedMmS},
                  {QStringLiteral("centre_mm"), QJsonArray{t.centreMm.xMm, t.centreMm.yMm}},
                  {QStringLiteral("figures"), figures},
                  {QStringLiteral("runs"), runs},
                  {QStringLiteral("magnification"), motion::metrology::autoMagnification(e, t.radiusMm)}};
    o.insert(QStringLiteral("pass"), (t.maxGMm || t.maxHMm) ? QJsonValue(pass) : QJsonValue());
    return o;
}

int circle(Invocation& inv)
{
    motion::metrology::CircularTest t;
    if (inv.isSet(QStringLiteral("test"))) {
        const auto read = dev::files::accuracy::loadAccuracyTestFile(inv.path(inv.value(QStringLiteral("test"))));
        if (reportProblems(inv, read.problems) || !read.test)
            return Usage;
        const auto* c = std::get_if<motion::metrology::CircularTest>(&*read.test);
        if (!c)
            return inv.usage(tr("%1 is not a circular test").arg(inv.value(QStringLiteral("test"))));
        t = *c;
    } else {
        if (!inv.isSet(QStringLiteral("radius")))
            return inv.usage(tr("give --radius R (mm), or --test FILE"));
        QVector<double> centre;
        if (!inv.number(QStringLiteral("radius"), t.radiusMm) || !inv.number(QStringLiteral("feed"), t.feedMmS, 5.0))
            return Usage;
        if (inv.isSet(QStringLiteral("centre"))) {
            if (!inv.numbers(QStringLiteral("centre"), centre, 2))
                return Usage;
            t.centreMm = {centre[0], centre[1]};
        }
        double lead = 45, samples = 360;
        if (!inv.number(QStringLiteral("lead"), lead, 45.0) || !inv.number(QStringLiteral("samples"), samples, 360.0))
            return Usage;
        t.leadArcDeg = lead;
        t.samplesPerRevolution = static_cast<int>(samples);
        const QString dirs = inv.value(QStringLiteral("directions"));
        if (!dirs.isEmpty()) {
            const QStringList d = dirs.split(QLatin1Char(','), Qt::SkipEmptyParts);
            t.clockwise = d.contains(QStringLiteral("cw"));
            t.counterClockwise = d.contains(QStringLiteral("ccw"));
        }
        t.name = "circle";
    }
    double timeScale = 1;
    if (!inv.number(QStringLiteral("time-scale"), timeScale, 1.0))
        return Usage;
    if (inv.isSet(QStringLiteral("time-scale")) && (inv.link().sim.isEmpty() || inv.host().insideGui()))
        return inv.usage(timeScaleRefusal(inv));
    if (timeScale != 1)
        inv.unpaceSimulatedLink();
    const auto staticProblems = motion::metrology::validate(t);
    if (reportProblems(inv, staticProblems, {{QStringLiteral("radius_mm"), QStringLiteral("--radius")},
                                             {QStringLiteral("feed_mm_s"), QStringLiteral("--feed")},
                                             {QStringLiteral("centre_mm"), QStringLiteral("--centre")}}))
        return Usage;
    CliSession* session = inv.session();
    if (!session)
        return LinkTrouble;
    dev::Instrument* instrument = session->instrument();
    if (auto* link = qobject_cast<dev::SimulatedLink*>(session->link()))
        link->host().setTimeScale(timeScale);
    if (inv.isSet(QStringLiteral("home"))) {
        quint8 mask = 0;
        session->parseAxes(QStringLiteral("XY"), &mask);
        if (int rc = session->request([&](auto cb) { instrument->home(mask, cb); }, tr("home")))
            return rc;
        if (!session->waitUntilHomed(mask))
            return reportFailure(inv, motion::msg::make("accuracy.run.not_homed", {motion::msg::verbatim("axis", "XY")}), Refused);
    }
    dev::jobs::CircleRunner runner(instrument);
    motion::msg::Problems problems;
    if (!runner.prepare(t, &problems)) {
        reportProblems(inv, problems);
        return Usage;
    }
    motion::msg::Message stopped;
    QObject::connect(&runner, &dev::jobs::CircleRunner::problem, &runner, [&](const motion::msg::Message& m) { stopped = m; });
    // Sampled on the device's clock: its measured X and Y as telemetry (status readings
    // only if the device does not stream them).
    QObject::connect(instrument, &dev::Instrument::telemetryReceived, &runner,
                     [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedCircleBatch(runner, *instrument, b); });
    session->wantTelemetry(dev::jobs::circleChannels(runner), dev::jobs::kCircleSampleRateHz);
    motion::msg::Message why;
    if (!runner.start(&why))
        return reportFailure(inv, why, Refused);
    const int limitMs = static_cast<int>(std::min(24.0 * 3600, runner.etaS() / timeScale * 4 + 60) * 1000);
    if (!spinUntil([&] { return !runner.isActive(); }, limitMs)) {
        runner.abort();
        return reportFailure(inv, motion::msg::make("accuracy.run.timed_out"), Refused);
    }
    if (runner.state() != dev::jobs::CircleRunner::State::Finished)
        return reportFailure(inv, stopped.empty() ? motion::msg::make("accuracy.run.aborted") : stopped, Refused);
    const auto e = runner.evaluation();
    if (!e.ok()) {
        reportProblems(inv, e.problems);
        return Refused;
    }
    QJsonObject o = circleJson(t, e);
    QJsonArray files;
    if (inv.isSet(QStringLiteral("out"))) {
        const QString dir = inv.path(inv.value(QStringLiteral("out")));
        QDir().mkpath(dir);
        const QString base = QDir(dir).filePath(QStringLiteral("circle-r%1").arg(t.radiusMm));
        QString error;
        std::string csv = "rotation,x_mm,y_mm\r\n";
        for (const auto& run : runner.runs())
            for (const auto& s : run.samplesMm)
                csv += std::string(motion::metrology::rotationName(run.rotation)) + "," + std::to_string(s.xMm) + "," + std::to_string(s.yMm) + "\r\n";
        if (dev::files::writeAtomically(base + QStringLiteral(".circle-samples.csv"), csv, &error))
            files.append(base + QStringLiteral(".circle-samples.csv"));
        if (dev::files::writeAtomically(base + QStringLiteral(".circle-result.json"), QJsonDocument(o).toJson().toStdString(), &error))
            files.append(base + QStringLiteral(".circle-result.json"));
        if (ui::report::canRender()) {
            ui::report::CircleReportInput in;
            in.title = tr("Circular test, radius %1 mm").arg(t.radiusMm);
            in.instrument = QStringLiteral("%1 (%2)").arg(instrument->identity().model, instrument->identity().family);
            in.test = t;
            in.evaluation = e;
            in.created = QDateTime::currentDateTime().toString(Qt::ISODate);
            if (ui::report::writeCircleReport(base + QStringLiteral(".report.pdf"), in, &error))
                files.append(base + QStringLiteral(".report.pdf"));
            else
                inv.report(error);
        }
    }
    o.insert(QStringLiteral("files"), files);
    if (inv.json()) {
        printJson(inv, o);
    } else {
        for (const auto& run : e.runs)
            inv.out() << tr("G %1: %2 µm").arg(ui::words::term(motion::metrology::rotationTermId(run.rotation))).arg(run.circularDeviationMm * 1e3, 0, 'f', 2) << "\n";
        if (e.hysteresisMm)
            inv.out() << tr("H: %1 µm").arg(*e.hysteresisMm * 1e3, 0, 'f', 2) << "\n";
    }
    return Ok;
}

QList<QCommandLineOption> toleranceOptions()
{
    return {option("tolerance-a", "limit on A in mm", "mm"), option("tolerance-r", "limit on R in mm", "mm"),
            option("tolerance-e", "limit on E in mm", "mm"), option("tolerance-m", "limit on M in mm", "mm"),
            option("tolerance-b", "limit on B in mm", "mm")};
}

} // namespace

void addAccuracyCommands(std::vector<Command>& list)
{
    Command accuracy{QStringLiteral("accuracy"), tr("ISO 230-2 positioning tests, ISO 230-4 circular tests, their analysis"),
                     QString(), QString(), {}, {}, {}};
    Command run{QStringLiteral("run"), tr("run a positioning test on an axis and evaluate it (ISO 230-2)"), QString(),
                tr("Moves through the standard linear cycle, takes a reading at every stop once the axis has settled, and writes "
                   "the readings CSV, the result JSON and the PDF report into --out. A run that stopped continues from its log there."),
                accuracyRunOptions(), &runAccuracy, {}};
    QList<QCommandLineOption> analyzeOptions = toleranceOptions();
    analyzeOptions << option("axis", "the axis the readings are of (for the result file)", "letter", "X")
                   << option("out", "also write the result JSON here", "file");
    Command analyzeCmd{QStringLiteral("analyze"), tr("ISO 230-2 figures of a readings CSV"), tr("READINGS.csv"), QString(),
                       analyzeOptions, &analyze, {}};
    Command circleCmd{QStringLiteral("circle"), tr("run a circular test on X and Y (ISO 230-4)"), QString(), QString(),
                      {option("radius", "circle radius in mm", "mm"), option("feed", "feed in mm/s", "mm/s", "5"),
                       option("centre", "centre X,Y in mm", "x,y", "0,0"), option("directions", "cw, ccw or cw,ccw", "list", "cw,ccw"),
                       option("lead", "lead arc before and after the revolution, in degrees", "deg", "45"),
                       option("samples", "samples kept per revolution", "n", "360"),
                       option("test", "a circular test definition file instead of the options above", "file"),
                       option("out", "folder for the samples CSV, the result JSON and the PDF report", "dir"),
                       option("home", "home X and Y first"),
                       option("time-scale", "with --sim: run the simulator's clock this many times faster", "k", "1")},
                      &circle, {}};
    Command importCmd{QStringLiteral("import"), tr("an interferometer's CSV export matched to a run's target sequence"),
                      tr("EXPORT.csv"), QString(),
                      {option("sequence", "the run's target sequence (*.targets.csv)", "file"),
                       option("out", "the readings CSV to write (default: beside the sequence)", "file"),
                       option("axis", "the axis the readings are of", "letter", "X")},
                      &importInterferometer, {}};
    const QList<ApiParam> limits{optionParam("tolerance-a", ParamType::Number), optionParam("tolerance-r", ParamType::Number),
                                 optionParam("tolerance-e", ParamType::Number), optionParam("tolerance-m", ParamType::Number),
                                 optionParam("tolerance-b", ParamType::Number)};
    run.api.access = Access::Control;
    run.api.cliOnly = QStringList{QStringLiteral("time-scale")};
    run.api.params = {optionParam("axis", ParamType::Axis),         optionParam("cycles", ParamType::Integer),
                      optionParam("feed", ParamType::Number),       optionParam("dwell", ParamType::Number),
                      optionParam("overrun", ParamType::Number),    optionParam("test", ParamType::File),
                      optionParam("out", ParamType::File),          optionParam("gauge-baud", ParamType::Integer),
                      optionParam("gauge-timeout", ParamType::Number), optionParam("camera-seed", ParamType::Integer),
                      optionParam("certificate", ParamType::File),  optionParam("scale-length", ParamType::Number)};
    run.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("axis"), QStringLiteral("X")},
                                  {QStringLiteral("targets"), QStringLiteral("20:60:5")}, {QStringLiteral("irregular"), true},
                                  {QStringLiteral("cycles"), 2}, {QStringLiteral("dwell"), 0.1},
                                  {QStringLiteral("home"), true},
                                  {QStringLiteral("out"), QStringLiteral("x-run")}};
    analyzeCmd.api.access = Access::Compute;
    analyzeCmd.api.params = QList<ApiParam>{{QStringLiteral("readings"), ParamType::File, tr("the readings CSV"), true, {}, {}},
                                            optionParam("axis", ParamType::Axis), optionParam("out", ParamType::File)}
                            + limits;
    analyzeCmd.api.example = QJsonObject{{QStringLiteral("readings"), QStringLiteral("resources/examples/stage-x-interferometer.readings.csv")},
                                         {QStringLiteral("tolerance_a"), 0.01}};
    circleCmd.api.access = Access::Control;
    circleCmd.api.cliOnly = QStringList{QStringLiteral("time-scale")};
    ApiParam directions = optionParam("directions", ParamType::Text);
    directions.choices = QStringList{QStringLiteral("cw"), QStringLiteral("ccw"), QStringLiteral("cw,ccw")};
    circleCmd.api.params = {optionParam("radius", ParamType::Number), optionParam("feed", ParamType::Number),
                            optionParam("centre", ParamType::Numbers), directions, optionParam("lead", ParamType::Number),
                            optionParam("samples", ParamType::Integer), optionParam("test", ParamType::File),
                            optionParam("out", ParamType::File)};
    circleCmd.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("radius"), 2},
                                        {QStringLiteral("feed"), 5}, {QStringLiteral("centre"), QJsonArray{15, 15}}};
    importCmd.api.access = Access::Compute;
    importCmd.api.params = {{QStringLiteral("export"), ParamType::File, tr("the interferometer software's CSV export"), true, {}, {}},
                            optionParam("sequence", ParamType::File, true), optionParam("out", ParamType::File),
                            optionParam("axis", ParamType::Axis)};
    importCmd.api.example = QJsonObject{{QStringLiteral("export"), QStringLiteral("resources/examples/stage-x-xl80.interferometer.csv")},
                                        {QStringLiteral("sequence"), QStringLiteral("resources/examples/stage-x-xl80.targets.csv")},
                                        {QStringLiteral("out"), QStringLiteral("x-imported.readings.csv")}};
    accuracy.subcommands = {run, analyzeCmd, circleCmd, importCmd};
    list.push_back(accuracy);
}

} // namespace app::cli
