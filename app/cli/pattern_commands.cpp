// benchpilot-cli pattern plan|run: a pattern from --shape and its options (or a pattern file),
// its segments printed without moving, or run on the instrument through its path queue with
// the contour error measured from telemetry (docs/patterns.md).
#include "cli_session.h"
#include "command.h"

#include "device/client/path_client.h"
#include "device/files/pattern_file.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/sim/machine_config.h"
#include "device/sim/path_queue.h"
#include "motion/plans/pattern.h"

#include "widgets/wording/wording.h"

#include <QFileInfo>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

QList<QCommandLineOption> patternOptions()
{
    return {option("shape", "line, rectangle, circle, arc, sine, cosine, spiral or raster", "SHAPE"),
            option("file", "a pattern file (*.pattern.json) instead of --shape", "FILE"),
            option("feed", "path speed, mm/s", "F"),
            option("from", "line: start, mm", "X,Y"),
            option("to", "line: end, mm", "X,Y"),
            option("corner", "rectangle, raster: lower-left corner, mm", "X,Y"),
            option("width", "rectangle, raster: width, mm", "MM"),
            option("height", "rectangle, raster: height, mm", "MM"),
            option("center", "circle, arc, spiral: centre, mm", "X,Y"),
            option("radius", "circle, arc: radius, mm", "MM"),
            option("start-deg", "circle, arc, spiral: start angle, degrees from +X", "DEG"),
            option("sweep-deg", "arc: angle swept, degrees (0–360)", "DEG"),
            option("dir", "rectangle, circle, arc, spiral: cw or ccw", "DIR"),
            option("origin", "sine, cosine: start of the wave's axis, mm", "X,Y"),
            option("amplitude", "sine, cosine: amplitude, mm", "MM"),
            option("wavelength", "sine, cosine: wavelength, mm", "MM"),
            option("length", "sine, cosine: length along the wave's axis, mm", "MM"),
            option("angle-deg", "sine, cosine: direction of the wave's axis, degrees", "DEG"),
            option("tolerance", "sine, cosine: largest chord deviation from the curve, mm", "MM"),
            option("start-radius", "spiral: radius it starts at, mm", "MM"),
            option("pitch", "spiral: radius gained per turn, mm", "MM"),
            option("turns", "spiral: whole or half turns", "N"),
            option("spacing", "raster: distance between passes, mm", "MM"),
            option("along", "raster: passes run along x or y", "AXIS"),
            option("z-height", "analyzer: Z height to work at (reached after XY, seed 000), mm", "MM")};
}

bool point(Invocation& inv, const char* name, motion::path::Vec2& into)
{
    const QString key = QString::fromLatin1(name);
    if (!inv.isSet(key))
        return true;
    QVector<double> v;
    if (!inv.numbers(key, v, 2))
        return false;
    into = {v[0], v[1]};
    return true;
}

bool num(Invocation& inv, const char* name, double& into)
{
    const QString key = QString::fromLatin1(name);
    return !inv.isSet(key) || inv.number(key, into);
}

bool direction(Invocation& inv, bool& clockwise)
{
    if (!inv.isSet(QStringLiteral("dir")))
        return true;
    const QString d = inv.value(QStringLiteral("dir"));
    if (d != QLatin1String("cw") && d != QLatin1String("ccw")) {
        inv.usage(tr("--dir must be cw or ccw (got '%1')").arg(d));
        return false;
    }
    clockwise = d == QLatin1String("cw");
    return true;
}

/// The pattern the options describe; nullopt after a usage message. Fields not given keep the
/// shape's defaults (a file's values, with --file).
std::optional<motion::plans::Pattern> patternFrom(Invocation& inv)
{
    motion::plans::Pattern p;
    if (inv.isSet(QStringLiteral("file"))) {
        dev::files::json::Problems problems;
        if (!dev::files::loadPatternFile(inv.path(inv.value(QStringLiteral("file"))), &p, &problems)) {
            inv.usage(ui::words::fileProblems(problems, QFileInfo(inv.value(QStringLiteral("file"))).fileName()).join(QLatin1Char('\n')));
            return std::nullopt;
        }
    } else if (!inv.isSet(QStringLiteral("shape"))) {
        inv.usage(tr("give --shape (line, rectangle, circle, arc, sine, cosine, spiral, raster) or --file"));
        return std::nullopt;
    }
    if (inv.isSet(QStringLiteral("shape"))) {
        const auto s = motion::plans::shapeFromName(inv.value(QStringLiteral("shape")).toStdString());
        if (!s) {
            inv.usage(tr("--shape '%1' is not one of line, rectangle, circle, arc, sine, cosine, spiral, raster")
                          .arg(inv.value(QStringLiteral("shape"))));
            return std::nullopt;
        }
        p.shape = *s;
    }
    bool ok = num(inv, "feed", p.feedMmS) && point(inv, "from", p.line.startMm) && point(inv, "to", p.line.endMm);
    using S = motion::plans::PatternShape;
    switch (p.shape) {
    case S::Rectangle:
        ok = ok && point(inv, "corner", p.rectangle.cornerMm) && num(inv, "width", p.rectangle.widthMm)
            && num(inv, "height", p.rectangle.heightMm) && direction(inv, p.rectangle.clockwise);
        break;
    case S::Circle:
        ok = ok && point(inv, "center", p.circle.centerMm) && num(inv, "radius", p.circle.radiusMm)
            && num(inv, "start-deg", p.circle.startDeg) && direction(inv, p.circle.clockwise);
        break;
    case S::Arc:
        ok = ok && point(inv, "center", p.arc.centerMm) && num(inv, "radius", p.arc.radiusMm) && num(inv, "start-deg", p.arc.startDeg)
            && num(inv, "sweep-deg", p.arc.sweepDeg) && direction(inv, p.arc.clockwise);
        break;
    case S::Sine:
    case S::Cosine:
        ok = ok && point(inv, "origin", p.wave.originMm) && num(inv, "amplitude", p.wave.amplitudeMm)
            && num(inv, "wavelength", p.wave.wavelengthMm) && num(inv, "length", p.wave.lengthMm)
            && num(inv, "angle-deg", p.wave.angleDeg) && num(inv, "tolerance", p.wave.toleranceMm);
        break;
    case S::Spiral:
        ok = ok && point(inv, "center", p.spiral.centerMm) && num(inv, "start-radius", p.spiral.startRadiusMm)
            && num(inv, "pitch", p.spiral.pitchMm) && num(inv, "turns", p.spiral.turns) && num(inv, "start-deg", p.spiral.startDeg)
            && direction(inv, p.spiral.clockwise);
        break;
    case S::Raster:
        ok = ok && point(inv, "corner", p.raster.cornerMm) && num(inv, "width", p.raster.widthMm)
            && num(inv, "height", p.raster.heightMm) && num(inv, "spacing", p.raster.spacingMm);
        if (ok && inv.isSet(QStringLiteral("along"))) {
            const QString a = inv.value(QStringLiteral("along"));
            if (a != QLatin1String("x") && a != QLatin1String("y")) {
                inv.usage(tr("--along must be x or y (got '%1')").arg(a));
                return std::nullopt;
            }
            p.raster.alongY = a == QLatin1String("y");
        }
        break;
    case S::Line: break;
    }
    if (ok && inv.isSet(QStringLiteral("z-height"))) {
        double z = 0;
        ok = inv.number(QStringLiteral("z-height"), z);
        p.zMm = z;
    }
    if (!ok)
        return std::nullopt;
    const auto problems = motion::plans::validate(p);
    if (!problems.empty()) {
        inv.usage(ui::words::problems(problems).join(QStringLiteral("; ")));
        return std::nullopt;
    }
    return p;
}

QJsonArray pointJson(motion::path::Vec2 p) { return QJsonArray{p.x, p.y}; }

/// The path limits a simulated instrument runs with (the device's defaults).
motion::path::PathLimits simLimits(const QString& instrument)
{
    const dev::sim::MachineConfig c = instrument == QLatin1String("analyzer") ? dev::sim::analyzerConfig() : dev::sim::stageConfig();
    motion::path::PathLimits l;
    l.accelMmS2 = dev::sim::PathQueue::kDefaultAccelShare * std::min(c.axes[0].maxAccel, c.axes[1].maxAccel);
    l.junctionDeviationMm = dev::sim::PathQueue::kDefaultJunctionDeviationMm;
    l.maxSpeedMmS = std::min(c.axes[0].maxSpeed, c.axes[1].maxSpeed);
    return l;
}

/// The options-only check and the pattern both subcommands start from; nullopt after a usage message.
std::optional<motion::plans::Pattern> commandPattern(Invocation& inv)
{
    if (!inv.arguments().isEmpty()) {
        inv.usage(tr("takes options only (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
        return std::nullopt;
    }
    return patternFrom(inv);
}

int plan(Invocation& inv)
{
    const auto p = commandPattern(inv);
    if (!p)
        return Usage;
    const auto path = motion::plans::plan(*p);
    const QString instrument = inv.link().sim.isEmpty() ? QStringLiteral("stage") : inv.link().sim;
    const auto limits = simLimits(instrument);
    const auto est = motion::path::estimatePath(path, limits);
    const auto box = motion::plans::boundsOf(path);
    QJsonArray segments;
    for (std::size_t k = 0; k < path.size(); ++k) {
        const auto& s = path[k];
        QJsonObject o{{QStringLiteral("index"), static_cast<qint64>(k)},
                      {QStringLiteral("kind"), QString::fromLatin1(motion::path::segmentKindName(s.kind))},
                      {QStringLiteral("start_mm"), pointJson(s.start)},
                      {QStringLiteral("end_mm"), pointJson(s.end)},
                      {QStringLiteral("feed_mm_s"), s.feedMmS},
                      {QStringLiteral("length_mm"), motion::path::lengthMm(s)},
                      {QStringLiteral("entry_mm_s"), est.blocks[k].entryMmS},
                      {QStringLiteral("exit_mm_s"), est.blocks[k].exitMmS}};
        if (s.isArc())
            o.insert(QStringLiteral("center_mm"), pointJson(s.center));
        segments.append(o);
    }
    const QJsonObject result{{QStringLiteral("shape"), QString::fromLatin1(motion::plans::shapeName(p->shape))},
                             {QStringLiteral("segments"), segments},
                             {QStringLiteral("segment_count"), static_cast<qint64>(path.size())},
                             {QStringLiteral("length_mm"), est.lengthMm},
                             {QStringLiteral("estimated_s"), est.durationS},
                             {QStringLiteral("timed_for"), instrument},
                             {QStringLiteral("bounds_mm"), QJsonArray{box.minX, box.minY, box.maxX, box.maxY}}};
    if (inv.json()) {
        inv.printJson(result);
    } else {
        inv.out() << tr("%1: %2 segments, %3 mm, about %4 s on the %5 simulator's limits\n")
                         .arg(QString::fromLatin1(motion::plans::shapeName(p->shape)))
                         .arg(path.size())
                         .arg(est.lengthMm, 0, 'f', 3)
                         .arg(est.durationS, 0, 'f', 2)
                         .arg(instrument);
        for (std::size_t k = 0; k < path.size(); ++k) {
            const auto& s = path[k];
            inv.out() << QStringLiteral("  %1 %2 (%3, %4) → (%5, %6)").arg(k).arg(QString::fromLatin1(motion::path::segmentKindName(s.kind)))
                             .arg(s.start.x, 0, 'f', 4).arg(s.start.y, 0, 'f', 4).arg(s.end.x, 0, 'f', 4).arg(s.end.y, 0, 'f', 4);
            if (s.isArc())
                inv.out() << QStringLiteral(" about (%1, %2)").arg(s.center.x, 0, 'f', 4).arg(s.center.y, 0, 'f', 4);
            inv.out() << QStringLiteral(", %1 mm/s\n").arg(s.feedMmS);
        }
    }
    inv.out().flush();
    return Ok;
}

int run(Invocation& inv)
{
    const auto p = commandPattern(inv);
    if (!p)
        return Usage;
    const auto path = motion::plans::plan(*p);
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    dev::Instrument* c = s->instrument();
    if (inv.isSet(QStringLiteral("home-first"))) {
        if (int rc = s->request([&](auto cb) { c->home(0, cb); }, tr("home")))
            return rc;
        // Quietly: the run's result is the one line this command prints.
        if (!s->waitUntilHomed(static_cast<quint8>((1u << c->identity().axes.size()) - 1)))
            return inv.refused(tr("homing did not finish"));
    }
    dev::PathClient* paths = c->paths();
    if (!paths || !c->capabilities().testFlag(dev::Capability::PathQueue))
        return inv.refused(ui::words::text(c->whyNot(dev::Capability::PathQueue)));
    dev::jobs::PatternRunner runner(c);
    bool limits = false;
    paths->refreshLimits([&](const auto&) { limits = true; });
    spinUntil([&] { return limits; }, 3000);
    std::vector<motion::msg::Message> problems;
    QObject::connect(&runner, &dev::jobs::PatternRunner::message, &runner, [&](const motion::msg::Message& m, bool problem) {
        if (problem)
            problems.push_back(m);
    });
    QObject::connect(c, &dev::Instrument::telemetryReceived, &runner,
                     [&](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, *c, b); });
    s->wantTelemetry(dev::jobs::patternChannels(), 250);
    dev::jobs::PatternRunner::Options o;
    o.zMm = p->zMm;
    if (!runner.start(path, o)) {
        QStringList why;
        bool notHomed = false;
        for (const motion::msg::Message& m : problems) {
            why << ui::words::text(m);
            notHomed = notHomed || m.id == "pattern.run.not_homed";
        }
        if (!inv.link().sim.isEmpty() && !inv.host().insideGui() && notHomed)
            why << tr("(every --sim command starts a fresh simulator: add --home-first)");
        return inv.refused(why.join(QLatin1Char(' ')));
    }
    const auto abortHook = inv.host().onAbort([&runner] { runner.abort(); });  // the API's cancel
    const bool finished = spinUntil([&] { return !runner.busy(); }, static_cast<int>(inv.link().timeoutS * 1000));
    if (!finished) {
        runner.abort();
        spinUntil([&] { return !runner.busy(); }, 3000);
        return inv.refused(tr("the pattern did not finish within --timeout %1 s: aborted").arg(inv.link().timeoutS));
    }
    const auto sum = runner.summary();
    const QJsonObject result{{QStringLiteral("shape"), QString::fromLatin1(motion::plans::shapeName(p->shape))},
                             {QStringLiteral("instrument"), c->identity().kindName()},
                             {QStringLiteral("state"), ui::words::englishTerm(dev::jobs::PatternRunner::stateTerm(runner.state()))},
                             {QStringLiteral("complete"), sum.complete},
                             {QStringLiteral("segments"), static_cast<qint64>(path.size())},
                             {QStringLiteral("segments_done"), static_cast<qint64>(runner.segmentsDone())},
                             {QStringLiteral("length_mm"), motion::path::pathLengthMm(path)},
                             {QStringLiteral("max_contour_um"), sum.maxContourMm * 1e3},
                             {QStringLiteral("rms_contour_um"), sum.rmsContourMm * 1e3},
                             {QStringLiteral("max_contour_at_mm"), sum.maxAtPathMm},
                             {QStringLiteral("duration_s"), sum.durationS},
                             {QStringLiteral("samples"), static_cast<qint64>(sum.samples)},
                             {QStringLiteral("sample_rate_hz"), c->subscribedRateHz()},
                             {QStringLiteral("underruns"), sum.underruns}};
    if (inv.json())
        inv.printJson(result);
    else
        inv.out() << tr("%1 on the %2: %3 of %4 segments in %5 s; contour error max %6 µm, RMS %7 µm (%8 samples at %9 Hz)\n")
                         .arg(QString::fromLatin1(motion::plans::shapeName(p->shape)), ui::words::term(dev::instrumentTerm(c->identity().kind)))
                         .arg(runner.segmentsDone())
                         .arg(path.size())
                         .arg(sum.durationS, 0, 'f', 2)
                         .arg(sum.maxContourMm * 1e3, 0, 'f', 2)
                         .arg(sum.rmsContourMm * 1e3, 0, 'f', 2)
                         .arg(sum.samples)
                         .arg(c->subscribedRateHz());
    inv.out().flush();
    if (!sum.complete)
        return inv.refused(problems.empty() ? tr("the pattern did not complete") : ui::words::text(problems.back()));
    return Ok;
}

} // namespace

/// The pattern options with their JSON types (points are [x, y], lengths numbers).
QList<ApiParam> patternParams()
{
    QList<ApiParam> p;
    for (const char* point : {"from", "to", "corner", "center", "origin"})
        p << optionParam(point, ParamType::Numbers);
    for (const char* number : {"feed", "width", "height", "radius", "start-deg", "sweep-deg", "amplitude", "wavelength", "length",
                               "angle-deg", "tolerance", "start-radius", "pitch", "turns", "spacing", "z-height"})
        p << optionParam(number, ParamType::Number);
    ApiParam file = optionParam("file", ParamType::File);
    p << file;
    ApiParam shape = optionParam("shape", ParamType::Text);
    shape.choices = QStringList{QStringLiteral("line"), QStringLiteral("rectangle"), QStringLiteral("circle"), QStringLiteral("arc"),
                                QStringLiteral("sine"), QStringLiteral("cosine"), QStringLiteral("spiral"), QStringLiteral("raster")};
    p << shape;
    return p;
}

void addPatternCommands(std::vector<Command>& list)
{
    Command pattern;
    pattern.name = QStringLiteral("pattern");
    pattern.summary = tr("plan a pattern (line, rectangle, circle, arc, sine, cosine, spiral, raster) or run it and measure the contour error");
    pattern.description = tr("Shape options not given keep the pattern's defaults (docs/patterns.md). "
                             "--file reads a *.pattern.json; shape options then change it.");
    Command planCmd{QStringLiteral("plan"), tr("print the segments, length and estimated time without moving"), {},
                    tr("Timed on the limits of the simulator --sim names (the stage when none)."), patternOptions(), plan, {}};
    planCmd.api.access = Access::Compute;
    planCmd.api.instrumentParam = true;
    planCmd.api.params = patternParams();
    planCmd.api.example = QJsonObject{{QStringLiteral("shape"), QStringLiteral("circle")}, {QStringLiteral("radius"), 2},
                                      {QStringLiteral("center"), QJsonArray{50, 50}}, {QStringLiteral("feed"), 5}};
    QList<QCommandLineOption> runOptions = patternOptions();
    runOptions << option("home-first", "home every axis before the run (a fresh --sim simulator is not homed)");
    Command runCmd{QStringLiteral("run"), tr("run the pattern on the instrument; print max and RMS contour error (µm) and duration"), {},
                   tr("Moves to the pattern's start (XY, then Z on the analyzer), streams the segments into the device's path "
                      "queue and judges the measured XY from telemetry against the path. Exit 2 if it is refused or does not complete."),
                   runOptions, run, {}};
    runCmd.api.access = Access::Control;
    runCmd.api.params = patternParams();
    runCmd.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("shape"), QStringLiteral("circle")},
                                     {QStringLiteral("radius"), 1}, {QStringLiteral("center"), QJsonArray{50, 50}},
                                     {QStringLiteral("feed"), 5}};
    pattern.subcommands = {planCmd, runCmd};
    list.push_back(pattern);
}

} // namespace app::cli
