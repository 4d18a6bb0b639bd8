#include "command.h"

#include "motion/any_profile.h"
#include "motion/blocks.h"
#include "motion/can_frame.h"
#include "motion/chords.h"
#include "motion/interpolation.h"
#include "motion/step_timing.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace app::cli {

namespace {

constexpr int kExitUsage = 1;
constexpr std::int64_t kMaxPoints = 2000000;  ///< keeps a typo in --step from printing gigabytes

/// The option a person typed for a motion-library field, so refusals name what they can change.
/// The option a planning message is about, from its `field` argument.
QString optionForField(const motion::msg::Message& m)
{
    const std::string message = m.text("field");
    static const std::pair<const char*, const char*> kFields[] = {
        {"vMaxMmS", "--vmax"},     {"aMaxMmS2", "--amax"},     {"jMaxMmS3", "--jmax"},
        {"accelTimeS", "--accel-time"}, {"startSpeedMmS", "--start-speed"}, {"plateauMm", "--plateau"},
        {"distanceMm", "--distance"}};
    for (const auto& [field, option] : kFields)
        if (message.find(field) != std::string::npos)
            return QString::fromLatin1(option) + QStringLiteral(": ");
    return {};
}

QJsonArray samplesJson(const std::vector<motion::ProfileSample>& samples)
{
    QJsonArray a;
    for (const auto& s : samples)
        a.append(QJsonObject{{"t", s.t}, {"s", s.s}, {"v", s.v}, {"a", s.a}, {"j", s.j}});
    return a;
}

/// --kind and the limits shared by `profile` and `steptable`.
bool readRequest(Invocation& o, motion::ProfileRequest& r)
{
    const QString kindName = o.value(QStringLiteral("kind"));
    const auto kind = motion::profileKindFromName(kindName.toStdString());
    if (!kind) {
        o.usage(QStringLiteral("--kind '%1' is not one of seed-scurve, trapezoid, exponential, jerk-limited").arg(kindName));
        return false;
    }
    r.kind = *kind;
    return o.number(QStringLiteral("vmax"), r.vMaxMmS) && o.number(QStringLiteral("amax"), r.aMaxMmS2, 0.0)
           && o.number(QStringLiteral("jmax"), r.jMaxMmS3, 0.0) && o.number(QStringLiteral("accel-time"), r.accelTimeS, 0.0)
           && o.number(QStringLiteral("start-speed"), r.startSpeedMmS, 0.0)
           && o.number(QStringLiteral("plateau"), r.plateauMm, 0.0);
}


int runProfile(Invocation& o)
{
    motion::ProfileRequest request;
    QVector<double> distances;
    double dt = 0;
    if (!readRequest(o, request) || !o.numbers(QStringLiteral("distance"), distances)
        || !o.number(QStringLiteral("dt"), dt, 0.01))
        return kExitUsage;
    if (dt <= 0)
        return o.usage(QStringLiteral("--dt '%1' must be > 0").arg(o.value(QStringLiteral("dt"))));
    if (distances.size() > motion::kMaxAxes)
        return o.usage(QStringLiteral("--distance '%1' has %2 axes; at most %3")
                          .arg(o.value(QStringLiteral("distance"))).arg(distances.size()).arg(motion::kMaxAxes));
    QJsonObject json{{"kind", QString::fromLatin1(motion::profileKindName(request.kind))}};
    if (distances.size() == 1) {
        const auto profile = motion::planProfile(distances[0], request);
        if (!profile)
            return o.usage(optionForField(profile.error()) + ui::words::text(profile.error()));
        const auto samples = motion::sampleProfile(*profile, dt);
        if (samples.empty())
            return o.usage(QStringLiteral("--dt '%1' gives too many samples for a %2 s move").arg(o.value(QStringLiteral("dt"))).arg(profile->duration()));
        json.insert("duration", profile->duration());
        json.insert("distance", profile->distance());
        json.insert("samples", samplesJson(samples));
    } else {
        const auto move = motion::planSynchronized(distances.constData(), int(distances.size()), request);
        if (!move)
            return o.usage(optionForField(move.error()) + ui::words::text(move.error()));
        const double T = move->duration();
        if (T / dt > 1e6)
            return o.usage(QStringLiteral("--dt '%1' gives too many samples for a %2 s move").arg(o.value(QStringLiteral("dt"))).arg(T));
        QJsonArray axes;
        for (int i = 0; i < move->axisCount(); ++i) {
            std::vector<motion::ProfileSample> samples;
            for (double t = 0; t < T; t += dt)
                samples.push_back(move->axisAt(i, t));
            samples.push_back(move->axisAt(i, T));
            axes.append(QJsonObject{{"axis", i}, {"distance", move->distanceMm(i)}, {"samples", samplesJson(samples)}});
        }
        json.insert("duration", T);
        json.insert("axes", axes);
    }
    o.printJson(json);
    return 0;
}

QJsonArray pointsJson(const std::vector<motion::GridPoint>& grid, double step, double x0, double y0)
{
    QJsonArray points;
    for (const auto& p : grid)
        points.append(QJsonArray{x0 + p.x * step, y0 + p.y * step});
    return points;
}

int runInterpolate(Invocation& o)
{
    const QString shape = o.value(QStringLiteral("shape"));
    double step = 0;
    if (!o.number(QStringLiteral("step"), step, shape == QLatin1String("sine") || shape == QLatin1String("cosine") ? std::optional(0.001) : std::nullopt))
        return kExitUsage;
    if (!(step > 0))
        return o.usage(QStringLiteral("--step '%1' must be > 0").arg(o.value(QStringLiteral("step"))));
    const auto tooMany = [&](double steps) {
        return o.usage(QStringLiteral("--step '%1' gives %2 steps; at most %3").arg(o.value(QStringLiteral("step"))).arg(steps, 0, 'f', 0).arg(kMaxPoints));
    };
    QJsonObject json{{"shape", shape}, {"step", step}};
    std::vector<motion::GridPoint> grid;
    double maxErrorMm = 0, x0 = 0, y0 = 0;
    if (shape == QLatin1String("line")) {
        QVector<double> from{0, 0}, to;
        if ((o.isSet(QStringLiteral("from")) && !o.numbers(QStringLiteral("from"), from, 2)) || !o.numbers(QStringLiteral("to"), to, 2))
            return kExitUsage;
        const double xe = std::round((to[0] - from[0]) / step), ye = std::round((to[1] - from[1]) / step);
        if (std::fabs(xe) + std::fabs(ye) > kMaxPoints)
            return tooMany(std::fabs(xe) + std::fabs(ye));
        grid = motion::interpolateLinePoints(std::int64_t(xe), std::int64_t(ye));
        x0 = from[0];
        y0 = from[1];
        const double len = std::hypot(xe, ye);
        for (const auto& p : grid)
            if (len > 0)
                maxErrorMm = std::max(maxErrorMm, std::fabs(double(p.x) * ye - double(p.y) * xe) / len * step);
    } else if (shape == QLatin1String("arc")) {
        QVector<double> start, center, to;
        if (!o.numbers(QStringLiteral("start"), start, 2) || !o.numbers(QStringLiteral("center"), center, 2)
            || !o.numbers(QStringLiteral("to"), to, 2))
            return kExitUsage;
        const QString dir = o.value(QStringLiteral("dir"));
        if (dir != QLatin1String("cw") && dir != QLatin1String("ccw"))
            return o.usage(QStringLiteral("--dir '%1' must be cw or ccw").arg(dir));
        const motion::GridPoint s{std::llround((start[0] - center[0]) / step), std::llround((start[1] - center[1]) / step)};
        const motion::GridPoint e{std::llround((to[0] - center[0]) / step), std::llround((to[1] - center[1]) / step)};
        const double r = std::hypot(double(s.x), double(s.y));
        if (8 * r > kMaxPoints)
            return tooMany(8 * r);
        const auto pts = motion::interpolateArcPoints(s, e, dir == QLatin1String("ccw"));
        if (!pts)
            return o.usage(QStringLiteral("--to '%1' is %2 mm from the circle through --start '%3' around --center '%4' "
                                         "(at most half a step, radius at least two steps)")
                              .arg(o.value(QStringLiteral("to")))
                              .arg(std::fabs(std::hypot(double(e.x), double(e.y)) - r) * step)
                              .arg(o.value(QStringLiteral("start")), o.value(QStringLiteral("center"))));
        grid = *pts;
        x0 = center[0];
        y0 = center[1];
        for (const auto& p : grid)
            maxErrorMm = std::max(maxErrorMm, std::fabs(std::hypot(double(p.x), double(p.y)) - r) * step);
    } else if (shape == QLatin1String("sine") || shape == QLatin1String("cosine")) {
        double amplitude = 0, wavelength = 0, length = 0, tolerance = 0;
        if (!o.number(QStringLiteral("amplitude"), amplitude) || !o.number(QStringLiteral("wavelength"), wavelength)
            || !o.number(QStringLiteral("length"), length) || !o.number(QStringLiteral("tolerance"), tolerance))
            return kExitUsage;
        for (const auto& [name, v] : {std::pair{QStringLiteral("--wavelength"), wavelength}, std::pair{QStringLiteral("--length"), length},
                                      std::pair{QStringLiteral("--tolerance"), tolerance}})
            if (!(v > 0))
                return o.usage(QStringLiteral("%1 '%2' must be > 0").arg(name, o.value(name.mid(2))));
        if ((length + 2 * std::fabs(amplitude) * length / wavelength * 4) / step > kMaxPoints)
            return tooMany((length + 8 * std::fabs(amplitude) * length / wavelength) / step);
        const bool cosine = shape == QLatin1String("cosine");
        const auto chords = motion::sineChords(amplitude, wavelength, length, tolerance, cosine);
        if (chords.size() > std::size_t(kMaxPoints))
            return o.usage(QStringLiteral("--tolerance '%1' needs %2 chords").arg(o.value(QStringLiteral("tolerance"))).arg(chords.size()));
        grid = motion::interpolatePolyline(chords, step);
        std::vector<motion::PointMm> mm;
        mm.reserve(grid.size());
        for (const auto& p : grid)
            mm.push_back({p.x * step, p.y * step});
        const double k = 2 * 3.14159265358979323846 / wavelength;
        maxErrorMm = motion::maxDistanceToGraphMm(
            mm, [&](double x) { return amplitude * (cosine ? std::cos(k * x) : std::sin(k * x)); }, tolerance + 2 * step);
        json.insert("chords", int(chords.size()) - 1);
    } else {
        return o.usage(QStringLiteral("--shape '%1' is not one of line, arc, sine, cosine").arg(shape));
    }
    json.insert("steps", qint64(grid.size()) - 1);
    json.insert("max_contour_error", maxErrorMm);
    json.insert("points", pointsJson(grid, step, x0, y0));
    o.printJson(json);
    return 0;
}

QJsonObject tableJson(const motion::StepTable& t, double clockHz)
{
    QJsonArray entries;
    for (const auto& e : t.entries)
        entries.append(QJsonObject{{"period_ticks", qint64(e.periodTicks)}, {"whole_periods", qint64(e.wholePeriods)},
                                   {"match", e.matchTicks}, {"zero_corrected", e.zeroCorrected}, {"clamped", e.clamped}});
    return QJsonObject{{"clock_hz", clockHz},
                       {"interrupt_ticks", qint64(t.interruptTicks)},
                       {"steps", qint64(t.entries.size())},
                       {"ideal_duration", t.idealDurationS},
                       {"table_duration", t.tableDurationS},
                       {"time_error", t.timeErrorS},
                       {"clamped", t.clampedCount},
                       {"zero_corrections", t.zeroCorrections},
                       {"max_whole_periods", qint64(t.maxWholePeriods)},
                       {"entries", entries}};
}

int runStepTable(Invocation& o)
{
    motion::StepTimerConfig timer;
    double interruptUs = 50;
    if (!o.number(QStringLiteral("clock-hz"), timer.clockHz, 72e6)
        || !o.number(QStringLiteral("interrupt-us"), interruptUs, 50.0) || !o.number(QStringLiteral("min-rate"), timer.minRateHz, 80.0)
        || !o.number(QStringLiteral("max-rate"), timer.maxRateHz, 20000.0))
        return kExitUsage;
    timer.interruptPeriodS = interruptUs * 1e-6;
    if (!(timer.clockHz > 0) || !(interruptUs > 0) || !(timer.minRateHz > 0) || !(timer.maxRateHz >= timer.minRateHz))
        return o.usage(QStringLiteral("--clock-hz, --interrupt-us, --min-rate must be > 0 and --max-rate >= --min-rate"));
    timer.firstMatchTicks = std::uint32_t(std::llround(timer.interruptPeriodS * timer.clockHz / 2));
    std::vector<double> instants;
    QJsonObject extra;
    if (o.isSet(QStringLiteral("total-steps"))) {
        // Seed 001's own move, in steps, with its v += a·t0 iteration.
        motion::Seed001Move m;
        double total = 0, plateau = 0;
        if (!o.number(QStringLiteral("total-steps"), total) || !o.number(QStringLiteral("start-rate"), m.startRateHz)
            || !o.number(QStringLiteral("top-rate"), m.topRateHz) || !o.number(QStringLiteral("accel"), m.accelHzS)
            || !o.number(QStringLiteral("decel"), m.decelHzS, m.accelHzS) || !o.number(QStringLiteral("plateau-steps"), plateau, 0.0))
            return kExitUsage;
        m.totalSteps = std::llround(total);
        m.plateauSteps = std::llround(plateau);
        if (m.totalSteps < 1 || m.totalSteps > kMaxPoints)
            return o.usage(QStringLiteral("--total-steps '%1' must be 1 … %2").arg(o.value(QStringLiteral("total-steps"))).arg(kMaxPoints));
        const auto profile = motion::seed001Profile(m);
        if (!profile || !(m.startRateHz > 0))
            return o.usage(QStringLiteral("--start-rate '%1' --top-rate '%2' --accel '%3' --decel '%4' --plateau-steps '%5': need 0 < start <= top, accel/decel > 0, plateau >= 0")
                              .arg(o.value(QStringLiteral("start-rate")), o.value(QStringLiteral("top-rate")), o.value(QStringLiteral("accel")),
                                   o.value(QStringLiteral("decel")), o.value(QStringLiteral("plateau-steps"))));
        instants = motion::seed001StepInstantsS(m);
        const auto exact = motion::stepInstantsS(*profile, 1.0);
        extra.insert("exact_duration", exact.empty() ? 0.0 : exact.back());
        extra.insert("seed_iteration_error", instants.back() - (exact.empty() ? 0.0 : exact.back()));
    } else {
        motion::ProfileRequest request;
        double distance = 0, stepMm = 0;
        if (!readRequest(o, request) || !o.number(QStringLiteral("distance"), distance) || !o.number(QStringLiteral("step"), stepMm))
            return kExitUsage;
        if (!(stepMm > 0) || std::fabs(distance) / stepMm > kMaxPoints)
            return o.usage(QStringLiteral("--step '%1' must be > 0 and give at most %2 steps").arg(o.value(QStringLiteral("step"))).arg(kMaxPoints));
        const auto profile = motion::planProfile(distance, request);
        if (!profile)
            return o.usage(optionForField(profile.error()) + ui::words::text(profile.error()));
        instants = motion::stepInstantsS(*profile, stepMm);
        extra.insert("kind", QString::fromLatin1(motion::profileKindName(request.kind)));
        extra.insert("duration", profile->duration());
    }
    QJsonObject json = tableJson(motion::buildStepTable(instants, timer), timer.clockHz);
    for (auto it = extra.begin(); it != extra.end(); ++it)
        json.insert(it.key(), it.value());
    o.printJson(json);
    return 0;
}

int runBlocks(Invocation& o)
{
    double vMax = 0;
    if (!o.number(QStringLiteral("vmax"), vMax, 32767.0))
        return kExitUsage;
    const QStringList joints = o.values(QStringLiteral("joint"));
    if (joints.isEmpty())
        return o.usage(QStringLiteral("--joint is required: S:V2:t0_ms,S:V2:t0_ms,… per joint, repeat for more joints"));
    if (joints.size() > motion::kMaxCanJoints)
        return o.usage(QStringLiteral("%1 --joint options; the CAN ID holds joints 0 … %2").arg(joints.size()).arg(motion::kMaxCanJoints - 1));
    std::vector<std::vector<motion::Block>> blocks;
    QJsonArray jointsJson;
    for (int j = 0; j < joints.size(); ++j) {
        std::vector<motion::Block> list;
        QJsonArray wire;
        for (const QString& item : joints[j].split(QLatin1Char(','))) {
            const QStringList f = item.split(QLatin1Char(':'));
            bool ok[3] = {false, false, false};
            const qlonglong s = f.value(0).toLongLong(&ok[0]);
            const int v2 = f.value(1).toInt(&ok[1]);
            const int t0 = f.value(2).toInt(&ok[2]);
            if (f.size() != 3 || !ok[0] || !ok[1] || !ok[2] || s < INT32_MIN || s > INT32_MAX || v2 < INT16_MIN || v2 > INT16_MAX
                || t0 < 0 || t0 > UINT16_MAX)
                return o.usage(QStringLiteral("--joint '%1': block '%2' must be S:V2:t0 with int32 S, int16 V2, uint16 t0 (ms)").arg(joints[j], item));
            list.push_back({std::int32_t(s), std::int16_t(v2), std::uint16_t(t0)});
            wire.append(QJsonObject{{"S", s}, {"V2", v2}, {"t0_ms", t0}});
        }
        const auto plan = motion::planJointBlocks(list, vMax, j);
        if (!plan)
            return o.refused(QStringLiteral("--joint '%1': %2").arg(joints[j], ui::words::text(plan.error())));
        QJsonArray planned;
        for (const auto& p : plan->blocks)
            planned.append(QJsonObject{{"source", p.sourceIndex}, {"steps", qint64(p.steps) * p.direction},
                                       {"v1", p.startSpeedStepsS * p.direction}, {"v2", p.endSpeedStepsS * p.direction},
                                       {"t0", p.durationS}, {"shape", QString::fromLatin1(motion::blockShapeName(p.shape))},
                                       {"t1", p.rampTimeS}, {"t2", p.cruiseTimeS}, {"a", p.accelStepsS2 * p.direction}});
        jointsJson.append(QJsonObject{{"joint", j}, {"blocks", wire}, {"planned", planned}, {"splits", plan->splitCount}});
        blocks.push_back(std::move(list));
    }
    QJsonArray frames;
    for (const auto& f : motion::interleaveBlockFrames(blocks))
        frames.append(QString::fromStdString(motion::canFrameToHex(f)));
    o.printJson(QJsonObject{{"joints", jointsJson}, {"frames", frames}});
    return 0;
}

/// Motion-library commands take options only.
std::function<int(Invocation&)> optionsOnly(int (*run)(Invocation&))
{
    return [run](Invocation& inv) {
        if (!inv.arguments().isEmpty())
            return inv.usage(QStringLiteral("takes options only (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
        return run(inv);
    };
}

QCommandLineOption opt(const char* name, const char* description, const char* valueName = "X", const char* fallback = nullptr)
{
    return option(name, description, valueName, fallback);
}

QList<QCommandLineOption> profileLimits()
{
    return {opt("kind", "seed-scurve, trapezoid, exponential or jerk-limited", "KIND", "jerk-limited"),
            opt("distance", "move length in mm; comma-separated for a synchronized multi-axis move", "MM"),
            opt("vmax", "maximum speed, mm/s", "V"),
            opt("amax", "maximum acceleration, mm/s² (trapezoid, exponential, jerk-limited)", "A"),
            opt("jmax", "maximum jerk, mm/s³ (jerk-limited)", "J"),
            opt("accel-time", "seed 000 acceleration time, s (seed-scurve)", "S"),
            opt("start-speed", "start/stop speed, mm/s (trapezoid, exponential)", "V"),
            opt("plateau", "seed 001 start and end plateau, mm (trapezoid)", "MM")};
}

} // namespace

void addMotionCommands(std::vector<Command>& list)
{
    auto tr = [](const char* t) { return QCoreApplication::translate("app::cli", t); };
    QList<QCommandLineOption> profile = profileLimits();
    profile << opt("dt", "sample period of the output, s", "S", "0.01");
    auto compute = [](const char* method, QList<ApiParam> params, QJsonObject example) {
        ApiSpec a;
        a.method = QString::fromLatin1(method);
        a.access = Access::Compute;
        a.params = std::move(params);
        a.example = std::move(example);
        return a;
    };
    auto number = [](const char* name) { return optionParam(name, ParamType::Number); };
    auto numbers = [](const char* name) { return optionParam(name, ParamType::Numbers); };
    const QList<ApiParam> limitParams{numbers("distance"), number("vmax"), number("amax"), number("jmax"), number("accel-time"),
                                      number("start-speed"), number("plateau")};
    list.push_back({QStringLiteral("profile"), tr("plan a motion profile and print s, v, a, j samples (JSON)"), {},
                    tr("See docs/motion.md for the profiles and the seeds they come from."), profile, optionsOnly(runProfile), {},
                    compute("motion.profile", limitParams + QList<ApiParam>{number("dt")},
                            QJsonObject{{QStringLiteral("kind"), QStringLiteral("trapezoid")}, {QStringLiteral("distance"), QJsonArray{2}},
                                        {QStringLiteral("vmax"), 10}, {QStringLiteral("amax"), 100}, {QStringLiteral("dt"), 0.1}})});
    list.push_back({QStringLiteral("interpolate"), tr("point-by-point line or arc, or sine/cosine by chords (JSON)"), {},
                    tr("line: --to X,Y [--from X,Y]; arc: --start, --center, --to, --dir cw|ccw; "
                       "sine|cosine: --amplitude, --wavelength, --length, --tolerance. All need --step (mm)."),
                    {opt("shape", "line, arc, sine or cosine", "SHAPE"), opt("from", "line start, mm", "X,Y"),
                     opt("to", "line or arc end, mm", "X,Y"), opt("start", "arc start, mm", "X,Y"),
                     opt("center", "arc centre, mm", "X,Y"), opt("dir", "arc direction: cw or ccw", "DIR"),
                     opt("step", "one step of the machine, mm", "MM"), opt("amplitude", "sine/cosine amplitude, mm", "MM"),
                     opt("wavelength", "sine/cosine wavelength, mm", "MM"), opt("length", "sine/cosine length along X, mm", "MM"),
                     opt("tolerance", "largest chord deviation from the curve, mm", "MM")},
                    optionsOnly(runInterpolate), {},
                    compute("motion.interpolate",
                            {numbers("from"), numbers("to"), numbers("start"), numbers("center"), number("step"), number("amplitude"),
                             number("wavelength"), number("length"), number("tolerance")},
                            QJsonObject{{QStringLiteral("shape"), QStringLiteral("line")}, {QStringLiteral("to"), QJsonArray{0.5, 0.25}},
                                        {QStringLiteral("step"), 0.1}})});
    QList<QCommandLineOption> steps = profileLimits();
    steps << opt("step", "one step of the motor, mm", "MM") << opt("clock-hz", "timer clock, Hz", "HZ", "72000000")
          << opt("interrupt-us", "interrupt period, µs", "US", "50") << opt("min-rate", "slowest step rate, Hz", "HZ", "80")
          << opt("max-rate", "fastest step rate, Hz", "HZ", "20000")
          << opt("total-steps", "seed 001's own move: total steps (with --start-rate, --top-rate, --accel)", "N")
          << opt("start-rate", "seed 001: start step rate, Hz", "HZ") << opt("top-rate", "seed 001: top step rate, Hz", "HZ")
          << opt("accel", "seed 001: acceleration, Hz/s", "HZ_S") << opt("decel", "seed 001: deceleration, Hz/s (default: --accel)", "HZ_S")
          << opt("plateau-steps", "seed 001: start and end plateau, steps", "N");
    list.push_back({QStringLiteral("steptable"), tr("seed 001 step-period table of a profile or of seed 001's own move (JSON)"), {},
                    tr("Whole interrupt periods plus a remainder per step, with the zero-match correction."), steps,
                    optionsOnly(runStepTable), {},
                    compute("motion.steptable",
                            limitParams + QList<ApiParam>{number("step"), number("clock-hz"), number("interrupt-us"), number("min-rate"),
                                                          number("max-rate"), number("total-steps"), number("start-rate"), number("top-rate"),
                                                          number("accel"), number("decel"), number("plateau-steps")},
                            QJsonObject{{QStringLiteral("total_steps"), 20}, {QStringLiteral("start_rate"), 500}, {QStringLiteral("top_rate"), 2000},
                                        {QStringLiteral("accel"), 100000}})});
    list.push_back({QStringLiteral("blocks"), tr("plan seed 004 blocks per joint and pack them into CAN frames (JSON)"), {},
                    tr("--joint S:V2:t0_ms,S:V2:t0_ms,… once per joint."),
                    {opt("joint", "one joint's blocks S:V2:t0_ms,…; repeat for more joints", "BLOCKS"),
                     opt("vmax", "largest speed, steps/s", "V", "32767")},
                    optionsOnly(runBlocks), {},
                    compute("motion.blocks",
                            {{QStringLiteral("joint"), ParamType::Text,
                              tr("one joint's blocks \"S:V2:t0_ms,…\"; an array of such strings for several joints"), true,
                              QStringLiteral("joint"), {}},
                             number("vmax")},
                            QJsonObject{{QStringLiteral("joint"), QJsonArray{QStringLiteral("100:200:500")}}})});
}

} // namespace app::cli
