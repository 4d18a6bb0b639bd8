#include "motion_commands.h"

#include "motion/any_profile.h"
#include "motion/blocks.h"
#include "motion/can_frame.h"
#include "motion/chords.h"
#include "motion/interpolation.h"
#include "motion/step_timing.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cli {

namespace {

constexpr int kExitUsage = 1;
constexpr int kExitRefused = 2;
constexpr std::int64_t kMaxPoints = 2000000;  ///< keeps a typo in --step from printing gigabytes

/// Options of one command: every option takes one value; --joint may repeat.
class Options {
public:
    Options(QString command, QTextStream& err) : m_command(std::move(command)), m_err(err) {}

    bool parse(const QStringList& args, const QSet<QString>& allowed)
    {
        for (int i = 0; i < args.size(); ++i) {
            const QString& name = args[i];
            if (!name.startsWith(QLatin1String("--")) || !allowed.contains(name))
                return fail(QStringLiteral("unknown option '%1' (options: %2)").arg(name, sortedNames(allowed)));
            if (i + 1 >= args.size())
                return fail(QStringLiteral("%1 needs a value").arg(name));
            m_values.insert(name, args[++i]);
        }
        return true;
    }

    bool has(const QString& name) const { return m_values.contains(name); }
    QString text(const QString& name, const QString& fallback = {}) const { return m_values.value(name, fallback); }
    QStringList all(const QString& name) const
    {
        QStringList v = m_values.values(name);
        std::reverse(v.begin(), v.end());  // QMultiMap returns the latest first
        return v;
    }

    /// A number; `fallback` when absent and not required. Reports the option and value on error.
    bool number(const QString& name, double& value, std::optional<double> fallback = std::nullopt)
    {
        if (!has(name)) {
            if (!fallback)
                return fail(QStringLiteral("%1 is required").arg(name));
            value = *fallback;
            return true;
        }
        bool ok = false;
        value = text(name).toDouble(&ok);
        if (!ok || !std::isfinite(value))
            return fail(QStringLiteral("%1 '%2' is not a number").arg(name, text(name)));
        return true;
    }

    /// Comma-separated numbers ("30,40"), exactly `count` of them when count > 0.
    bool numbers(const QString& name, QVector<double>& values, int count = 0)
    {
        if (!has(name))
            return fail(QStringLiteral("%1 is required").arg(name));
        values.clear();
        for (const QString& part : text(name).split(QLatin1Char(','))) {
            bool ok = false;
            const double v = part.trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(v))
                return fail(QStringLiteral("%1 '%2': '%3' is not a number").arg(name, text(name), part));
            values << v;
        }
        if (count > 0 && values.size() != count)
            return fail(QStringLiteral("%1 '%2' needs %3 comma-separated numbers").arg(name, text(name)).arg(count));
        return true;
    }

    int usage(const QString& message)
    {
        fail(message);
        return kExitUsage;
    }
    int refused(const QString& message)
    {
        fail(message);
        return kExitRefused;
    }

    bool fail(const QString& message)
    {
        m_err << "benchpilot-cli " << m_command << ": " << message << "\n";
        m_err.flush();
        return false;
    }

private:
    static QString sortedNames(const QSet<QString>& names)
    {
        QStringList l(names.begin(), names.end());
        l.sort();
        return l.join(QLatin1Char(' '));
    }

    QString m_command;
    QTextStream& m_err;
    QMultiMap<QString, QString> m_values;
};

/// The option a person typed for a motion-library field, so refusals name what they can change.
QString optionForField(const std::string& message)
{
    static const std::pair<const char*, const char*> kFields[] = {
        {"vMaxMmS", "--vmax"},     {"aMaxMmS2", "--amax"},     {"jMaxMmS3", "--jmax"},
        {"accelTimeS", "--accel-time"}, {"startSpeedMmS", "--start-speed"}, {"plateauMm", "--plateau"},
        {"distanceMm", "--distance"}};
    for (const auto& [field, option] : kFields)
        if (message.find(field) != std::string::npos)
            return QString::fromLatin1(option) + QStringLiteral(": ");
    return {};
}

void printJson(QTextStream& out, const QJsonObject& object)
{
    out << QJsonDocument(object).toJson(QJsonDocument::Compact) << "\n";
    out.flush();
}

QJsonArray samplesJson(const std::vector<motion::ProfileSample>& samples)
{
    QJsonArray a;
    for (const auto& s : samples)
        a.append(QJsonObject{{"t", s.t}, {"s", s.s}, {"v", s.v}, {"a", s.a}, {"j", s.j}});
    return a;
}

/// --kind and the limits shared by `profile` and `steptable`.
bool readRequest(Options& o, motion::ProfileRequest& r)
{
    const QString kindName = o.text(QStringLiteral("--kind"), QStringLiteral("jerk-limited"));
    const auto kind = motion::profileKindFromName(kindName.toStdString());
    if (!kind)
        return o.usage(QStringLiteral("--kind '%1' is not one of seed-scurve, trapezoid, exponential, jerk-limited").arg(kindName));
    r.kind = *kind;
    return o.number(QStringLiteral("--vmax"), r.vMaxMmS) && o.number(QStringLiteral("--amax"), r.aMaxMmS2, 0.0)
           && o.number(QStringLiteral("--jmax"), r.jMaxMmS3, 0.0) && o.number(QStringLiteral("--accel-time"), r.accelTimeS, 0.0)
           && o.number(QStringLiteral("--start-speed"), r.startSpeedMmS, 0.0)
           && o.number(QStringLiteral("--plateau"), r.plateauMm, 0.0);
}

const QSet<QString> kRequestOptions = {QStringLiteral("--kind"), QStringLiteral("--distance"), QStringLiteral("--vmax"),
                                       QStringLiteral("--amax"), QStringLiteral("--jmax"), QStringLiteral("--accel-time"),
                                       QStringLiteral("--start-speed"), QStringLiteral("--plateau")};

int runProfile(const QStringList& args, QTextStream& out, QTextStream& err)
{
    Options o(QStringLiteral("profile"), err);
    QSet<QString> allowed = kRequestOptions;
    allowed << QStringLiteral("--dt");
    motion::ProfileRequest request;
    QVector<double> distances;
    double dt = 0;
    if (!o.parse(args, allowed) || !readRequest(o, request) || !o.numbers(QStringLiteral("--distance"), distances)
        || !o.number(QStringLiteral("--dt"), dt, 0.01))
        return kExitUsage;
    if (dt <= 0)
        return o.usage(QStringLiteral("--dt '%1' must be > 0").arg(o.text(QStringLiteral("--dt"))));
    if (distances.size() > motion::kMaxAxes)
        return o.usage(QStringLiteral("--distance '%1' has %2 axes; at most %3")
                          .arg(o.text(QStringLiteral("--distance"))).arg(distances.size()).arg(motion::kMaxAxes));
    QJsonObject json{{"kind", QString::fromLatin1(motion::profileKindName(request.kind))}};
    if (distances.size() == 1) {
        const auto profile = motion::planProfile(distances[0], request);
        if (!profile)
            return o.usage(optionForField(profile.error) + QString::fromStdString(profile.error));
        const auto samples = motion::sampleProfile(*profile, dt);
        if (samples.empty())
            return o.usage(QStringLiteral("--dt '%1' gives too many samples for a %2 s move").arg(o.text(QStringLiteral("--dt"))).arg(profile->duration()));
        json.insert("duration", profile->duration());
        json.insert("distance", profile->distance());
        json.insert("samples", samplesJson(samples));
    } else {
        const auto move = motion::planSynchronized(distances.constData(), int(distances.size()), request);
        if (!move)
            return o.usage(optionForField(move.error) + QString::fromStdString(move.error));
        const double T = move->duration();
        if (T / dt > 1e6)
            return o.usage(QStringLiteral("--dt '%1' gives too many samples for a %2 s move").arg(o.text(QStringLiteral("--dt"))).arg(T));
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
    printJson(out, json);
    return 0;
}

QJsonArray pointsJson(const std::vector<motion::GridPoint>& grid, double step, double x0, double y0)
{
    QJsonArray points;
    for (const auto& p : grid)
        points.append(QJsonArray{x0 + p.x * step, y0 + p.y * step});
    return points;
}

int runInterpolate(const QStringList& args, QTextStream& out, QTextStream& err)
{
    Options o(QStringLiteral("interpolate"), err);
    if (!o.parse(args, {QStringLiteral("--shape"), QStringLiteral("--from"), QStringLiteral("--to"), QStringLiteral("--start"),
                        QStringLiteral("--center"), QStringLiteral("--dir"), QStringLiteral("--step"),
                        QStringLiteral("--amplitude"), QStringLiteral("--wavelength"), QStringLiteral("--length"),
                        QStringLiteral("--tolerance")}))
        return kExitUsage;
    const QString shape = o.text(QStringLiteral("--shape"));
    double step = 0;
    if (!o.number(QStringLiteral("--step"), step, shape == QLatin1String("sine") || shape == QLatin1String("cosine") ? std::optional(0.001) : std::nullopt))
        return kExitUsage;
    if (!(step > 0))
        return o.usage(QStringLiteral("--step '%1' must be > 0").arg(o.text(QStringLiteral("--step"))));
    const auto tooMany = [&](double steps) {
        return o.usage(QStringLiteral("--step '%1' gives %2 steps; at most %3").arg(o.text(QStringLiteral("--step"))).arg(steps, 0, 'f', 0).arg(kMaxPoints));
    };
    QJsonObject json{{"shape", shape}, {"step", step}};
    std::vector<motion::GridPoint> grid;
    double maxErrorMm = 0, x0 = 0, y0 = 0;
    if (shape == QLatin1String("line")) {
        QVector<double> from{0, 0}, to;
        if ((o.has(QStringLiteral("--from")) && !o.numbers(QStringLiteral("--from"), from, 2)) || !o.numbers(QStringLiteral("--to"), to, 2))
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
        if (!o.numbers(QStringLiteral("--start"), start, 2) || !o.numbers(QStringLiteral("--center"), center, 2)
            || !o.numbers(QStringLiteral("--to"), to, 2))
            return kExitUsage;
        const QString dir = o.text(QStringLiteral("--dir"));
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
                              .arg(o.text(QStringLiteral("--to")))
                              .arg(std::fabs(std::hypot(double(e.x), double(e.y)) - r) * step)
                              .arg(o.text(QStringLiteral("--start")), o.text(QStringLiteral("--center"))));
        grid = *pts;
        x0 = center[0];
        y0 = center[1];
        for (const auto& p : grid)
            maxErrorMm = std::max(maxErrorMm, std::fabs(std::hypot(double(p.x), double(p.y)) - r) * step);
    } else if (shape == QLatin1String("sine") || shape == QLatin1String("cosine")) {
        double amplitude = 0, wavelength = 0, length = 0, tolerance = 0;
        if (!o.number(QStringLiteral("--amplitude"), amplitude) || !o.number(QStringLiteral("--wavelength"), wavelength)
            || !o.number(QStringLiteral("--length"), length) || !o.number(QStringLiteral("--tolerance"), tolerance))
            return kExitUsage;
        for (const auto& [name, v] : {std::pair{QStringLiteral("--wavelength"), wavelength}, std::pair{QStringLiteral("--length"), length},
                                      std::pair{QStringLiteral("--tolerance"), tolerance}})
            if (!(v > 0))
                return o.usage(QStringLiteral("%1 '%2' must be > 0").arg(name, o.text(name)));
        if ((length + 2 * std::fabs(amplitude) * length / wavelength * 4) / step > kMaxPoints)
            return tooMany((length + 8 * std::fabs(amplitude) * length / wavelength) / step);
        const bool cosine = shape == QLatin1String("cosine");
        const auto chords = motion::sineChords(amplitude, wavelength, length, tolerance, cosine);
        if (chords.size() > std::size_t(kMaxPoints))
            return o.usage(QStringLiteral("--tolerance '%1' needs %2 chords").arg(o.text(QStringLiteral("--tolerance"))).arg(chords.size()));
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
    printJson(out, json);
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

int runStepTable(const QStringList& args, QTextStream& out, QTextStream& err)
{
    Options o(QStringLiteral("steptable"), err);
    QSet<QString> allowed = kRequestOptions;
    allowed << QStringLiteral("--step") << QStringLiteral("--clock-hz") << QStringLiteral("--interrupt-us")
            << QStringLiteral("--min-rate") << QStringLiteral("--max-rate") << QStringLiteral("--total-steps")
            << QStringLiteral("--start-rate") << QStringLiteral("--top-rate") << QStringLiteral("--accel")
            << QStringLiteral("--decel") << QStringLiteral("--plateau-steps");
    motion::StepTimerConfig timer;
    double interruptUs = 50;
    if (!o.parse(args, allowed) || !o.number(QStringLiteral("--clock-hz"), timer.clockHz, 72e6)
        || !o.number(QStringLiteral("--interrupt-us"), interruptUs, 50.0) || !o.number(QStringLiteral("--min-rate"), timer.minRateHz, 80.0)
        || !o.number(QStringLiteral("--max-rate"), timer.maxRateHz, 20000.0))
        return kExitUsage;
    timer.interruptPeriodS = interruptUs * 1e-6;
    if (!(timer.clockHz > 0) || !(interruptUs > 0) || !(timer.minRateHz > 0) || !(timer.maxRateHz >= timer.minRateHz))
        return o.usage(QStringLiteral("--clock-hz, --interrupt-us, --min-rate must be > 0 and --max-rate >= --min-rate"));
    timer.firstMatchTicks = std::uint32_t(std::llround(timer.interruptPeriodS * timer.clockHz / 2));
    std::vector<double> instants;
    QJsonObject extra;
    if (o.has(QStringLiteral("--total-steps"))) {
        // Seed 001's own move, in steps, with its v += a·t0 iteration.
        motion::Seed001Move m;
        double total = 0, plateau = 0;
        if (!o.number(QStringLiteral("--total-steps"), total) || !o.number(QStringLiteral("--start-rate"), m.startRateHz)
            || !o.number(QStringLiteral("--top-rate"), m.topRateHz) || !o.number(QStringLiteral("--accel"), m.accelHzS)
            || !o.number(QStringLiteral("--decel"), m.decelHzS, m.accelHzS) || !o.number(QStringLiteral("--plateau-steps"), plateau, 0.0))
            return kExitUsage;
        m.totalSteps = std::llround(total);
        m.plateauSteps = std::llround(plateau);
        if (m.totalSteps < 1 || m.totalSteps > kMaxPoints)
            return o.usage(QStringLiteral("--total-steps '%1' must be 1 … %2").arg(o.text(QStringLiteral("--total-steps"))).arg(kMaxPoints));
        const auto profile = motion::seed001Profile(m);
        if (!profile || !(m.startRateHz > 0))
            return o.usage(QStringLiteral("--start-rate '%1' --top-rate '%2' --accel '%3' --decel '%4' --plateau-steps '%5': need 0 < start <= top, accel/decel > 0, plateau >= 0")
                              .arg(o.text(QStringLiteral("--start-rate")), o.text(QStringLiteral("--top-rate")), o.text(QStringLiteral("--accel")),
                                   o.text(QStringLiteral("--decel")), o.text(QStringLiteral("--plateau-steps"))));
        instants = motion::seed001StepInstantsS(m);
        const auto exact = motion::stepInstantsS(*profile, 1.0);
        extra.insert("exact_duration", exact.empty() ? 0.0 : exact.back());
        extra.insert("seed_iteration_error", instants.back() - (exact.empty() ? 0.0 : exact.back()));
    } else {
        motion::ProfileRequest request;
        double distance = 0, stepMm = 0;
        if (!readRequest(o, request) || !o.number(QStringLiteral("--distance"), distance) || !o.number(QStringLiteral("--step"), stepMm))
            return kExitUsage;
        if (!(stepMm > 0) || std::fabs(distance) / stepMm > kMaxPoints)
            return o.usage(QStringLiteral("--step '%1' must be > 0 and give at most %2 steps").arg(o.text(QStringLiteral("--step"))).arg(kMaxPoints));
        const auto profile = motion::planProfile(distance, request);
        if (!profile)
            return o.usage(optionForField(profile.error) + QString::fromStdString(profile.error));
        instants = motion::stepInstantsS(*profile, stepMm);
        extra.insert("kind", QString::fromLatin1(motion::profileKindName(request.kind)));
        extra.insert("duration", profile->duration());
    }
    QJsonObject json = tableJson(motion::buildStepTable(instants, timer), timer.clockHz);
    for (auto it = extra.begin(); it != extra.end(); ++it)
        json.insert(it.key(), it.value());
    printJson(out, json);
    return 0;
}

int runBlocks(const QStringList& args, QTextStream& out, QTextStream& err)
{
    Options o(QStringLiteral("blocks"), err);
    double vMax = 0;
    if (!o.parse(args, {QStringLiteral("--joint"), QStringLiteral("--vmax")}) || !o.number(QStringLiteral("--vmax"), vMax, 32767.0))
        return kExitUsage;
    const QStringList joints = o.all(QStringLiteral("--joint"));
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
            return o.refused(QStringLiteral("--joint '%1': %2").arg(joints[j], QString::fromStdString(plan.error)));
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
    printJson(out, QJsonObject{{"joints", jointsJson}, {"frames", frames}});
    return 0;
}

}  // namespace

std::optional<int> runMotionCommand(const QString& command, const QStringList& args, QTextStream& out, QTextStream& err)
{
    if (command == QLatin1String("profile"))
        return runProfile(args, out, err);
    if (command == QLatin1String("interpolate"))
        return runInterpolate(args, out, err);
    if (command == QLatin1String("steptable"))
        return runStepTable(args, out, err);
    if (command == QLatin1String("blocks"))
        return runBlocks(args, out, err);
    return std::nullopt;
}

}  // namespace cli
