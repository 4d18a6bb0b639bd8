// benchpilot-cli grid-map run: the camera on a grid plate maps the XY stage
// (docs/accuracy.md, "Grid map by camera"): from the dot under the camera (or --start),
// --nodes C,R every --pitch mm (or a --test FILE), each dot found to a fraction of a
// pixel; the readings CSV and the result JSON (the grid map result file) written into
// --out. A run that stopped continues from its log there; a dot not found is that
// node's failure with its image kept.
#include "accuracy_cli.h"
#include "camera_cli.h"
#include "cli_session.h"
#include "command.h"

#include "device/camera/dot_reading_source.h"
#include "device/files/accuracy/grid/grid_map_result_file.h"
#include "device/files/accuracy/grid/grid_map_test_file.h"
#include "device/files/text_file.h"
#include "device/jobs/accuracy/grid_map_runner.h"
#include "device/link/simulated_link.h"
#include "widgets/report/accuracy_report.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

const std::vector<std::pair<QString, QString>> kGridOptionOf = {
    {QStringLiteral("pitch_mm"), QStringLiteral("--pitch")},       {QStringLiteral("nodes"), QStringLiteral("--nodes")},
    {QStringLiteral("plate_pitch_mm"), QStringLiteral("--plate-pitch")}, {QStringLiteral("feed_mm_s"), QStringLiteral("--feed")},
    {QStringLiteral("dwell_s"), QStringLiteral("--dwell")},         {QStringLiteral("start_mm"), QStringLiteral("--start")},
    {QStringLiteral("approach_mm"), QStringLiteral("--approach")},
};

/// The test from --test FILE, or from the options.
bool buildGridTest(Invocation& inv, motion::metrology::GridMapTest& out)
{
    if (inv.isSet(QStringLiteral("test"))) {
        for (const char* o : {"pitch", "nodes", "start", "plate-pitch", "feed", "dwell", "approach", "bidirectional"})
            if (inv.isSet(QLatin1String(o))) {
                inv.usage(tr("--test gives the whole test: leave out --%1").arg(QLatin1String(o)));
                return false;
            }
        const auto read = dev::files::accuracy::loadGridMapTestFile(inv.path(inv.value(QStringLiteral("test"))));
        if (reportProblems(inv, read.problems()) || !read.ok())
            return false;
        out = *read;
    } else {
        if (!inv.isSet(QStringLiteral("pitch")) || !inv.isSet(QStringLiteral("nodes"))) {
            inv.usage(tr("give --pitch MM and --nodes COLUMNS,ROWS, or --test FILE"));
            return false;
        }
        motion::metrology::GridMapTest t;
        QVector<double> pitch, nodes, start;
        if (!inv.numbers(QStringLiteral("pitch"), pitch) || !inv.numbers(QStringLiteral("nodes"), nodes, 2))
            return false;
        if (pitch.size() != 1 && pitch.size() != 2) {
            inv.usage(tr("--pitch '%1': one pitch in mm, or X,Y").arg(inv.value(QStringLiteral("pitch"))));
            return false;
        }
        t.pitchXMm = pitch.front();
        t.pitchYMm = pitch.back();
        for (double n : nodes)
            if (std::floor(n) != n) {
                inv.usage(tr("--nodes '%1': two whole numbers, COLUMNS,ROWS").arg(inv.value(QStringLiteral("nodes"))));
                return false;
            }
        t.columns = static_cast<int>(std::clamp(nodes[0], -1e6, 1e6));
        t.rows = static_cast<int>(std::clamp(nodes[1], -1e6, 1e6));
        if (inv.isSet(QStringLiteral("start"))) {
            if (!inv.numbers(QStringLiteral("start"), start, 2))
                return false;
            t.startXMm = start[0];
            t.startYMm = start[1];
        }
        if (!inv.number(QStringLiteral("plate-pitch"), t.platePitchMm, t.platePitchMm) || !inv.number(QStringLiteral("feed"), t.feedMmS, t.feedMmS)
            || !inv.number(QStringLiteral("dwell"), t.dwellS, t.dwellS) || !inv.number(QStringLiteral("approach"), t.approachMm, t.approachMm))
            return false;
        t.bidirectional = inv.isSet(QStringLiteral("bidirectional"));
        if (reportProblems(inv, motion::metrology::validate(t), kGridOptionOf))
            return false;
        out = t;
    }
    if (inv.isSet(QStringLiteral("stop-on-failure")))
        out.stopOnFailure = true;
    return true;
}

QJsonObject gridResultJson(const QString& file)
{
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(file, &text, &error))
        return {};
    return QJsonDocument::fromJson(QByteArray::fromStdString(text)).object();
}

int runGridMap(Invocation& inv)
{
    motion::metrology::GridMapTest test;
    if (!buildGridTest(inv, test))
        return Usage;
    // Read before anything moves: a file that cannot be read stops the run before it starts.
    std::optional<motion::metrology::GridMapResult> before;
    if (inv.isSet(QStringLiteral("before"))) {
        const auto read = dev::files::accuracy::loadGridMapResultFile(inv.path(inv.value(QStringLiteral("before"))));
        if (reportProblems(inv, read.problems()) || !read.ok())
            return Usage;
        before = read->result;
    }
    double timeScale = 1;
    if (!inv.number(QStringLiteral("time-scale"), timeScale, 1.0))
        return Usage;
    if (inv.isSet(QStringLiteral("time-scale")) && (inv.link().sim.isEmpty() || inv.host().insideGui()))
        return inv.usage(timeScaleRefusal(inv));
    if (!(timeScale > 0 && timeScale <= 100))
        return inv.usage(tr("--time-scale must be from 0 to 100"));
    if (!inv.isSet(QStringLiteral("out")))
        return inv.usage(tr("give the folder for the run: --out DIR"));
    const QString folder = inv.path(inv.value(QStringLiteral("out")));
    if (timeScale != 1)
        inv.unpaceSimulatedLink();

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
            return reportFailure(inv, motion::msg::make("accuracy.run.not_homed", {motion::msg::verbatim("axis", "")}), Refused);
    }
    QVector<QPair<int, double>> at;
    if (inv.isSet(QStringLiteral("at")) && !session->parseTargets(inv.value(QStringLiteral("at")).split(QLatin1Char(','), Qt::SkipEmptyParts), &at))
        return Usage;
    if (!at.isEmpty()) {
        if (int rc = session->request([&](auto cb) { instrument->move(at, false, 0, cb); }, tr("move")))
            return rc;
        if (int rc = session->waitUntilStill(tr("move"), false))
            return rc;
    }
    QObject owner;
    auto camera = cameraFor(inv, session, inv.isSet(QStringLiteral("camera")) ? inv.value(QStringLiteral("camera")) : QStringLiteral("sim"),
                            "grid-plate");
    if (!camera)
        return Usage;
    camera->setParent(&owner);
    dev::camera::DotReadingOptions options;
    options.failedImagesFolder = folder;
    auto* source = new dev::camera::DotReadingSource(camera.release(), options, &owner);
    dev::jobs::GridMapRunner runner(instrument);
    motion::msg::Problems problems;
    if (!runner.prepare(test, source, folder, inv.isSet(QStringLiteral("restart")), &problems)) {
        if (inv.isSet(QStringLiteral("test")))
            problems = dev::files::accuracy::placeGridMapTestProblems(inv.path(inv.value(QStringLiteral("test"))), problems);
        reportProblems(inv, problems, kGridOptionOf);
        return Usage;
    }
    motion::msg::Message openProblem;
    bool opened = false;
    source->open([&](const motion::msg::Message& p) {
        openProblem = p;
        opened = true;
    });
    spinUntil([&] { return opened; }, 5000);
    if (!opened || !openProblem.empty())
        return reportFailure(inv, openProblem.empty() ? motion::msg::make("camera.not_open", {motion::msg::verbatim("source", "")}) : openProblem,
                             LinkTrouble);
    motion::msg::Message stopped;
    QObject::connect(&runner, &dev::jobs::GridMapRunner::problem, &runner, [&](const motion::msg::Message& m) { stopped = m; });
    QObject::connect(&runner, &dev::jobs::GridMapRunner::nodeFailed, &runner, [&](int, const motion::msg::Message& m) {
        if (!inv.json())
            inv.err() << "\n" << ui::words::text(m) << "\n";
    });
    QObject::connect(&runner, &dev::jobs::GridMapRunner::progress, &runner, [&](int visited, int total) {
        inv.host().progressed(QJsonObject{{QStringLiteral("nodes_visited"), visited}, {QStringLiteral("nodes"), total}});
        if (inv.json())
            return;
        inv.err() << tr("\r%1 of %2 nodes   ").arg(visited).arg(total);
        inv.err().flush();
    });
    if (runner.state() != dev::jobs::GridMapRunner::State::Finished) {
        motion::msg::Message why;
        if (!runner.start(&why))
            return reportFailure(inv, why, Refused);
        // A few seconds a node at most on the device's clock, the camera's time beside it.
        const double limitS = std::max(inv.link().timeoutS, 60 + runner.totalNodes() * (10.0 / timeScale + 5));
        const bool done = spinUntil([&] { return !runner.isActive(); }, static_cast<int>(std::min(24.0 * 3600, limitS) * 1000));
        if (!inv.json())
            inv.err() << "\n";
        if (!done) {
            runner.abort();
            return reportFailure(inv, motion::msg::make("accuracy.run.timed_out"), Refused);
        }
    } else if (!inv.json()) {
        inv.err() << tr("%1 holds a finished map of this test: its results follow, nothing was moved.").arg(QDir::toNativeSeparators(folder)) << "\n";
    }
    if (runner.state() != dev::jobs::GridMapRunner::State::Finished)
        return reportFailure(inv, stopped.empty() ? motion::msg::make("accuracy.run.aborted") : stopped, Refused);
    const QString resultFile = runner.basePath() + QStringLiteral(".grid-map-result.json");
    QStringList files = {runner.basePath() + QStringLiteral(".readings.csv")};
    if (QFileInfo::exists(resultFile))
        files << resultFile;
    if (!runner.result())
        return reportFailure(inv, stopped.empty() ? motion::msg::make("grid.run.incomplete", {motion::msg::integer("failed", runner.nodesFailed()),
                                                                                             motion::msg::integer("total", runner.totalNodes())})
                                                  : stopped,
                             Refused);
    // The report: this map, and beside it the map --before names (the same grid without
    // compensation), with the figures of both.
    ui::report::GridReportInput report;
    report.title = tr("Grid map of the XY stage");
    report.instrument = QStringLiteral("%1 (%2)").arg(instrument->identity().model, instrument->identity().family);
    report.source = source->describe();
    report.test = test;
    report.result = *runner.result();
    report.created = QDateTime::currentDateTime().toString(Qt::ISODate);
    report.before = before;
    if (ui::report::canRender()) {
        const QString pdf = runner.basePath() + QStringLiteral(".report.pdf");
        QString error;
        if (ui::report::writeGridReport(pdf, report, &error))
            files << pdf;
        else
            inv.report(error);
    }
    const QJsonObject result = gridResultJson(resultFile);
    if (inv.json()) {
        QJsonArray list;
        for (const QString& f : files)
            list.append(f);
        printJson(inv, QJsonObject{{QStringLiteral("ok"), true},
                                   {QStringLiteral("folder"), folder},
                                   {QStringLiteral("start_mm"), QJsonArray{nm6(runner.startXMm()), nm6(runner.startYMm())}},
                                   {QStringLiteral("placement"), result.value(QStringLiteral("placement"))},
                                   {QStringLiteral("figures"), result.value(QStringLiteral("figures"))},
                                   {QStringLiteral("nodes"), result.value(QStringLiteral("nodes"))},
                                   {QStringLiteral("files"), list}});
        return Ok;
    }
    const auto f = runner.result()->figures;
    inv.out() << tr("scale X %1 ppm, scale Y %2 ppm, squareness %3 µrad").arg(f.scaleXPpm, 0, 'f', 2).arg(f.scaleYPpm, 0, 'f', 2).arg(f.squarenessUrad, 0, 'f', 1)
              << "\n"
              << tr("straightness X %1 µm, straightness Y %2 µm").arg(f.straightnessXUm, 0, 'f', 2).arg(f.straightnessYUm, 0, 'f', 2) << "\n"
              << tr("error RMS %1 µm, max %2 µm; residual RMS %3 µm").arg(f.rmsErrorUm, 0, 'f', 2).arg(f.maxErrorUm, 0, 'f', 2).arg(f.rmsResidualUm, 0, 'f', 2)
              << "\n";
    if (f.maxReversalUm && f.meanReversalXUm && f.meanReversalYUm)
        inv.out() << tr("both directions, the map their mean; reversal max %1 µm, mean along X %2 µm, along Y %3 µm "
                        "(the lost motion a 2D table cannot correct)")
                         .arg(*f.maxReversalUm, 0, 'f', 2)
                         .arg(*f.meanReversalXUm, 0, 'f', 2)
                         .arg(*f.meanReversalYUm, 0, 'f', 2)
                  << "\n";
    for (const QString& file : files)
        inv.out() << tr("wrote %1").arg(file) << "\n";
    return Ok;
}

} // namespace

void addGridMapCommands(std::vector<Command>& list)
{
    Command grid{QStringLiteral("grid-map"), tr("the XY stage mapped by the camera on a grid plate: scale, squareness, straightness"),
                 QString(), QString(), {}, {}, {}};
    QList<QCommandLineOption> options{
        option("camera", "sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR (see camera list)", "SOURCE", "sim"),
        option("test", "a grid map test file (*.grid-map-test.json) instead of the options below", "file"),
        option("pitch", "between nodes, in mm: one pitch, or X,Y; a whole multiple of the plate's pitch", "mm"),
        option("nodes", "how many nodes, COLUMNS,ROWS (at least 3 each)", "c,r"),
        option("start", "the first node X,Y in mm (default: the dot nearest the image centre where the stage stands)", "x,y"),
        option("plate-pitch", "the plate's certified dot pitch in mm", "mm", "1"),
        option("feed", "feed between nodes in mm/s", "mm/s", "10"),
        option("dwell", "wait after arriving, in s", "s", "0.2"),
        option("approach", "the lead-in before each row (from below; from above in the reverse pass), in mm", "mm", "0.05"),
        option("bidirectional", "read every node twice: forward from -X -Y, then in reverse order from +X +Y; the map is "
                                "their mean and each node gets its reversal"),
        option("stop-on-failure", "stop the run at a dot the camera cannot find (default: it is that node's failure and the run goes on)"),
        option("out", "folder for the run log, the readings CSV, the result JSON and the PDF report", "dir"),
        option("before", "a grid map result of the same grid without compensation: shown beside this one in the report", "file"),
        option("restart", "keep another test's run log in --out aside and start afresh"),
        option("home", "home X and Y first"),
        option("at", "move here first, e.g. X=20,Y=20: over the plate's first dot", "AXIS=MM[,AXIS=MM]"),
        option("time-scale", "with --sim: run the simulator's clock this many times faster", "k", "1")};
    options << cameraOptions("grid-plate");
    Command run{QStringLiteral("run"), tr("map the stage on a grid plate with the camera"), QString(),
                tr("Starts at the dot nearest the image centre where the stage stands (or --start), visits the nodes row by row, "
                   "each approached from below (with --bidirectional, then again in reverse order from above), finds each dot to "
                   "a fraction of a pixel, and writes the readings CSV and the result JSON into --out. A run that stopped "
                   "continues from its log there without reading a node twice."),
                options, &runGridMap, {}};
    run.api.method = QStringLiteral("grid_map.run");
    run.api.access = Access::Control;
    run.api.cliOnly = QStringList{QStringLiteral("time-scale")};
    run.api.params = {optionParam("test", ParamType::File),    optionParam("pitch", ParamType::Numbers),
                      optionParam("nodes", ParamType::Numbers), optionParam("start", ParamType::Numbers),
                      optionParam("plate-pitch", ParamType::Number), optionParam("feed", ParamType::Number),
                      optionParam("dwell", ParamType::Number),  optionParam("approach", ParamType::Number),
                      optionParam("out", ParamType::File),      optionParam("before", ParamType::File),
                      optionParam("camera-seed", ParamType::Integer)};
    run.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("camera"), QStringLiteral("sim")},
                                  {QStringLiteral("pitch"), QJsonArray{10}},           {QStringLiteral("nodes"), QJsonArray{3, 3}},
                                  {QStringLiteral("at"), QStringLiteral("X=20,Y=20")}, {QStringLiteral("home"), true},
                                  {QStringLiteral("out"), QStringLiteral("grid-run")}};
    grid.subcommands = {run};
    list.push_back(grid);
}

} // namespace app::cli
