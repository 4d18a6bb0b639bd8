// bp-soak: both simulated instruments in one process, every kind of job at once, for a
// stretch of simulated time; reports memory, event-loop latency, lost telemetry, link
// trouble and jobs, and fails (exit 1) past the bounds in docs/testing.md ("Soak").
//   bp-soak [--sim-minutes 60] [--time-scale 100] [--seed 1] [--json FILE]
//           [--report-every 5] [--rate-hz 100] [--no-timing] [--verbose] [--examples DIR]
#include "soak_jobs.h"
#include "soak_probe.h"
#include "soak_rig.h"

#include "device/files/pattern_file.h"
#include "device/files/scan_plan_file.h"
#include "device/sim/sim_machine.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <cstdio>

namespace {

QCommandLineOption number(const char* name, const char* what, const char* fallback)
{
    QCommandLineOption o(QString::fromLatin1(name), QString::fromLatin1(what), QStringLiteral("n"));
    o.setDefaultValue(QString::fromLatin1(fallback));
    return o;
}

int setupFailed(const std::string& why)
{
    std::fprintf(stderr, "bp-soak: %s\n", why.c_str());
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress shows in a CTest log even when the soak is killed
    QCoreApplication::setApplicationName(QStringLiteral("bp-soak"));
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral("Soaks both simulated instruments (docs/testing.md, \"Soak\")."));
    p.addHelpOption();
    const auto minutes = number("sim-minutes", "simulated minutes to run", "60");
    const auto scale = number("time-scale", "simulated seconds per wall-clock second", "100");
    const auto seed = number("seed", "seeds the jobs' variations (jog speeds and times, pattern sizes)", "1");
    const auto every = number("report-every", "simulated minutes between rows of the table", "5");
    const auto rate = number("rate-hz", "telemetry rate the live plots ask for", "100");
    const auto latMax = number("latency-max-ms", "bound on the event loop's worst lateness (0: not judged)", "250");
    const auto latP99 = number("latency-p99-ms", "bound on its 99th percentile (0: not judged)", "50");
    const auto growthMb = number("growth-mb", "RSS growth allowed over the second half, MiB ...", "4");
    const auto growthPct = number("growth-percent", "... or this percentage of the half-way RSS, whichever is larger", "5");
    const QCommandLineOption noTiming(QStringLiteral("no-timing"),
                                      QStringLiteral("judge no latency and no memory growth (a short run on a busy machine)"));
    const QCommandLineOption verbose(QStringLiteral("verbose"), QStringLiteral("a line per job as it starts and ends"));
    const QCommandLineOption json(QStringLiteral("json"), QStringLiteral("also write the figures as JSON"), QStringLiteral("FILE"));
    QCommandLineOption examples(QStringLiteral("examples"), QStringLiteral("the example files' folder"), QStringLiteral("DIR"));
    examples.setDefaultValue(QStringLiteral(BP_SOURCE_DIR "/resources/examples"));
    p.addOptions({minutes, scale, seed, every, rate, latMax, latP99, growthMb, growthPct, noTiming, verbose, json, examples});
    p.process(app);

    const double simMinutes = p.value(minutes).toDouble();
    const double timeScale = p.value(scale).toDouble();
    const double reportMinutes = p.value(every).toDouble();
    if (!(simMinutes > 0) || !(timeScale > 0 && timeScale <= 1000) || !(reportMinutes > 0))
        return setupFailed("--sim-minutes and --report-every must be above 0, --time-scale in (0, 1000]");
    soak::Bounds bounds;
    bounds.latencyMaxMs = p.isSet(noTiming) ? 0 : p.value(latMax).toDouble();
    bounds.latencyP99Ms = p.isSet(noTiming) ? 0 : p.value(latP99).toDouble();
    bounds.growthMb = p.value(growthMb).toDouble();
    bounds.growthPercent = p.value(growthPct).toDouble();
    // Under 20 minutes the first half is all warm-up, and not every kind of job comes round.
    bounds.judgeGrowth = !p.isSet(noTiming) && simMinutes >= 20;
    bounds.everyKind = simMinutes >= 20;
    const std::uint64_t seedValue = p.value(seed).toULongLong();

    // What it runs: the examples a user starts from.
    const QString dir = p.value(examples);
    motion::scan::ScanPlan scanPlan;
    dev::files::json::Problems problems;
    if (!dev::files::scan::loadPlan(dir + QStringLiteral("/well-centre.scan.json"), &scanPlan, &problems))
        return setupFailed("cannot read well-centre.scan.json in " + dir.toStdString());
    motion::plans::Pattern sinePattern;
    if (!dev::files::loadPatternFile(dir + QStringLiteral("/stage-sine-chords.pattern.json"), &sinePattern, &problems))
        return setupFailed("cannot read stage-sine-chords.pattern.json in " + dir.toStdString());
    const QStringList recipes{dir + QStringLiteral("/sampling-96.recipe.json"), dir + QStringLiteral("/reagent-transfer.recipe.json")};
    QTemporaryDir temp;
    if (!temp.isValid())
        return setupFailed("no temporary folder");

    soak::Station analyzer(dev::proto::DeviceKind::Analyzer, timeScale);
    soak::Station stage(dev::proto::DeviceKind::Stage, timeScale);
    dev::tele::TelemetryHub hub;
    hub.addInstrument(0, QStringLiteral("Analyzer"), &analyzer.client);
    hub.addInstrument(1, QStringLiteral("Stage"), &stage.client);
    soak::PlotConsumer plots(hub, p.value(rate).toInt());
    std::string why;
    if (!analyzer.connectAndHome(60000, &why) || !stage.connectAndHome(60000, &why))
        return setupFailed(why);
    plots.want();

    soak::Tally tally;
    tally.verbose = p.isSet(verbose);
    soak::AnalyzerWork analyzerWork(analyzer, tally, timeScale, seedValue * 2 + 1, recipes, temp.path());
    soak::StageWork stageWork(stage, tally, timeScale, seedValue * 2 + 2, scanPlan, motion::plans::plan(sinePattern), temp.path());
    soak::Probe probe({&analyzer, &stage}, hub, plots, tally);
    const std::vector<std::string> kinds{"plate", "scan", "line", "arc", "sine", "jog"};

    std::printf("bp-soak: %.0f simulated minutes at %gx, seed %llu, plots at %d Hz on %zu channels\n", simMinutes, timeScale,
                static_cast<unsigned long long>(seedValue), p.value(rate).toInt(), plots.channels());
    std::printf("(lat_* in ms: how late a %d ms timer came in the period ending on the row; other columns are totals)\n",
                soak::Probe::kProbeMs);
    soak::Probe::printHeader(stdout);
    probe.start();
    soak::Probe::printRow(stdout, probe.periods().back());
    analyzerWork.begin();
    stageWork.begin();

    // The soak ends once the slower clock has run its time and the jobs under way have
    // finished (a job cut at the end would be neither done nor failed). The wall limit is
    // for a soak that hangs: five times the nominal time and two minutes more.
    const double targetS = simMinutes * 60;
    const double wallLimitS = targetS / timeScale * 5 + 120;
    double nextRowS = reportMinutes * 60;
    bool stopping = false, hung = false;
    QElapsedTimer wall;
    wall.start();
    QTimer check;
    check.setInterval(20);
    QObject::connect(&check, &QTimer::timeout, &app, [&] {
        const double t = probe.simS();
        if (t >= nextRowS && !stopping) {
            soak::Probe::printRow(stdout, probe.snapshot());
            nextRowS += reportMinutes * 60;
        }
        if (t >= targetS && !stopping) {
            stopping = true;
            analyzerWork.finishUp();
            stageWork.finishUp();
        }
        // Idle before the time is up: both links went (the works start nothing without one).
        if (analyzerWork.idle() && stageWork.idle())
            app.quit();
        if (wall.elapsed() > wallLimitS * 1000) {
            hung = true;
            app.quit();
        }
    });
    check.start();
    app.exec();
    soak::Probe::printRow(stdout, probe.snapshot());

    const soak::Figures& first = probe.periods().front();
    const soak::Figures& last = probe.periods().back();
    std::printf("\nsoak: %.1f simulated minutes in %.1f s wall: %.1fx (%gx asked)\n", last.simS / 60, last.wallS,
                last.wallS > 0 ? last.simS / last.wallS : 0.0, timeScale);
    std::printf("memory: RSS %.1f MiB at start, %.1f at the end, %.1f at most; heap in use %.1f -> %.1f MiB\n",
                first.rssKb / 1024.0, last.rssKb / 1024.0, probe.rssMaxKb() / 1024.0, first.heapKb / 1024.0, last.heapKb / 1024.0);
    std::printf("event loop: %.1f ms late at worst, %.1f ms at the 99th percentile (%llu ticks of %d ms)\n", probe.latencyMaxMs(),
                probe.latencyP99Ms(), static_cast<unsigned long long>(probe.latencyTicks()), soak::Probe::kProbeMs);
    std::printf("telemetry: %llu samples; lost %llu (clients %llu, hub %llu, firmware dropped %llu batches)\n",
                static_cast<unsigned long long>(last.samples), static_cast<unsigned long long>(last.lost()),
                static_cast<unsigned long long>(last.lostSamples), static_cast<unsigned long long>(last.hubLostSamples),
                static_cast<unsigned long long>(last.droppedBatches));
    std::printf("link: %llu errors; %llu retransmits, %llu late replies; %llu jogs expired on the device\n",
                static_cast<unsigned long long>(last.linkErrors), static_cast<unsigned long long>(last.retransmits),
                static_cast<unsigned long long>(last.lateReplies), static_cast<unsigned long long>(last.jogExpired));
    std::printf("jobs:");
    for (const auto& [kind, c] : tally.byKind)
        std::printf(" %s %llu done/%llu failed;", kind.c_str(), static_cast<unsigned long long>(c.done), static_cast<unsigned long long>(c.failed));
    std::printf("\npatterns: %llu queue underruns, worst contour error %.2f um\n", static_cast<unsigned long long>(tally.patternUnderruns),
                tally.maxContourUm);
    std::printf("plots: %llu frames over %zu channels, stores %.1f KiB\n", static_cast<unsigned long long>(last.plotFrames), plots.channels(),
                static_cast<double>(last.storeBytes) / 1024.0);
    for (const auto& f : tally.failures)
        std::printf("  job failure: %s\n", f.c_str());
    for (soak::Station* s : {&analyzer, &stage})
        for (const auto& m : s->trouble.firstMessages)
            std::printf("  %s\n", m.c_str());

    std::vector<std::string> failures = probe.verdict(bounds, kinds);
    if (hung)
        failures.insert(failures.begin(), "did not finish within " + std::to_string(static_cast<int>(wallLimitS)) + " s of wall time");
    QJsonObject out = probe.json(bounds, kinds);
    out.insert(QStringLiteral("sim_minutes_asked"), simMinutes);
    out.insert(QStringLiteral("time_scale_asked"), timeScale);
    out.insert(QStringLiteral("time_scale_achieved"), last.wallS > 0 ? last.simS / last.wallS : 0.0);
    out.insert(QStringLiteral("seed"), static_cast<qint64>(seedValue));
    out.insert(QStringLiteral("passed"), failures.empty());
    if (p.isSet(json)) {
        QFile f(p.value(json));
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(QJsonDocument(out).toJson()) < 0)
            std::fprintf(stderr, "bp-soak: cannot write %s\n", qPrintable(p.value(json)));
    }
    if (failures.empty()) {
        std::printf("PASSED\n");
        return 0;
    }
    for (const auto& f : failures)
        std::printf("FAILED: %s\n", f.c_str());
    return 1;
}
