// benchpilot-cli's tuning commands: tune (Ziegler–Nichols, ultimate
// gain or relay) on an instrument's axis or a model plant, step-test, gains.
// Gains are given and printed in continuous form (Kp, Ki in 1/s, Kd in s), the
// device's per-period form beside them in text output.
#include "cli_session.h"
#include "command.h"
#include "device/client/tuning_client.h"
#include "device/files/tuning_file.h"
#include "device/jobs/tuning/instrument_target.h"
#include "device/jobs/tuning/model_target.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "widgets/wording/wording.h"
#include "device/link/simulated_link.h"
#include "motion/control/tuning/tuning_rules.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <memory>

namespace app::cli {
namespace {

using namespace motion::control;

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }
QString num(double v) { return std::isfinite(v) ? QString::number(v, 'g', 6) : QStringLiteral("—"); }

QString describeGains(const DiscreteGains& g, double periodS)
{
    const ContinuousGains c = toContinuous(g, periodS);
    return tr("Kp %1, Ki %2 /s, Kd %3 s").arg(num(c.kp), num(c.kiPerS), num(c.kdS));
}

/// The step test's verdict (judgeStep) as a line: a limit cycle with its size and period.
QString verdictLine(StepOutcome o, const LimitCycle& lc, const QString& unit)
{
    switch (o) {
    case StepOutcome::Settled: return tr("  verdict: settled\n");
    case StepOutcome::DidNotSettle: return tr("  verdict: did not settle within 2 % of the step\n");
    case StepOutcome::Unstable: return tr("  verdict: unstable\n");
    case StepOutcome::LimitCycle:
        return tr("  verdict: never comes to rest: a limit cycle of ±%1 %2 every %3 s\n").arg(num(lc.amplitude), unit, num(lc.periodS));
    }
    return {};
}

/// Parses "Kp,Ki,Kd" in continuous form (or per period with `perPeriod`).
std::optional<DiscreteGains> parseGains(const QString& text, double periodS, bool perPeriod, QString* why)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3) {
        *why = tr("gains are three numbers Kp,Ki,Kd (got '%1')").arg(text);
        return std::nullopt;
    }
    double v[3];
    const char* names[3] = {"Kp", "Ki", "Kd"};
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        v[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok) {
            *why = tr("%1 '%2' is not a number").arg(QLatin1String(names[i]), parts[i]);
            return std::nullopt;
        }
    }
    // NaN, negative and absurd values go on to the device, which refuses them itself with its reason.
    return perPeriod ? DiscreteGains{v[0], v[1], v[2]} : toDiscrete(ContinuousGains{v[0], v[1], v[2]}, periodS);
}

QJsonObject continuousJson(const DiscreteGains& g, double periodS, bool withI = true, bool withD = true)
{
    const ContinuousGains c = toContinuous(g, periodS);
    QJsonObject o{{QStringLiteral("Kp"), c.kp}};
    if (withI)
        o[QStringLiteral("Ki")] = c.kiPerS;
    if (withD)
        o[QStringLiteral("Kd")] = c.kdS;
    return o;
}

/// Where a tuning command runs: a model plant (no instrument) or an axis.
struct Target {
    std::unique_ptr<dev::TuningTarget> target;
    dev::TuningClient* tuning = nullptr;
    int axis = -1;
    CliSession* session = nullptr;
};

/// Homes the axis (sped-up clock on the in-process simulator) and moves it to
/// the middle of its travel, so an envelope fits inside the soft limits.
int homeAndCentre(Invocation& inv, CliSession* s, int axis)
{
    auto* sim = qobject_cast<dev::SimulatedLink*>(s->link());
    dev::Instrument* c = s->instrument();
    if (sim) {
        // The clock runs 20× for homing: no telemetry, or the paced link would overflow.
        c->subscribe({}, 0);
        sim->host().setTimeScale(20);
    }
    int rc = Ok;
    if (!c->status().axes.value(axis).homed) {
        inv.report(tr("homing the axis first"));
        rc = s->request([&](auto cb) { c->home(static_cast<quint8>(1u << axis), cb); }, tr("home"));
        if (!rc && !spinUntil([&] { return c->status().axes.value(axis).homed && !c->status().anyMoving(); }, 60000))
            rc = inv.refused(tr("homing did not finish"));
    }
    if (!rc) {
        const auto& a = c->identity().axes[axis];
        rc = s->request([&](auto cb) { c->move({{axis, 0.5 * (a.travelMin + a.travelMax)}}, false, 0, cb); }, tr("move"));
        spinUntil([&] { return false; }, 200);
        if (!rc && !spinUntil([&] { return !c->status().anyMoving(); }, 30000))
            rc = inv.refused(tr("the axis did not come to rest"));
    }
    if (sim)
        sim->host().setTimeScale(1);  // tests run in real time: the device's host watchdog is in its time
    return rc;
}

/// The instrument of the global options, with its tuning client.
int openInstrument(Invocation& inv, Target& t)
{
    if (inv.link().sim.isEmpty() && inv.link().port.isEmpty() && !inv.host().insideGui())
        return inv.usage(tr("give --sim stage or --port PATH"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    t.session = s;
    t.tuning = s->instrument()->tuning();
    if (!t.tuning || !t.tuning->hasGains())
        return inv.refused(ui::words::text(s->instrument()->whyNot(dev::Capability::PidGains)));
    return Ok;
}

/// --plant, or the instrument of the global options with --axis.
int openTarget(Invocation& inv, Target& t, bool needsAxis)
{
    if (inv.isSet(QStringLiteral("plant"))) {
        if (!inv.link().sim.isEmpty() || !inv.link().port.isEmpty())
            return inv.usage(tr("give either --plant or an instrument (--sim/--port with --axis), not both"));
        const auto p = parsePlant(inv.value(QStringLiteral("plant")).toStdString());
        if (!p)
            return inv.usage(tr("--plant: %1").arg(ui::words::text(p.error())));
        t.target = std::make_unique<dev::ModelTarget>(*p);
        return Ok;
    }
    const QString letter = inv.value(QStringLiteral("axis"));
    if (needsAxis && letter.size() != 1)
        return inv.usage(tr("give --axis X (a closed-loop axis) or --plant SPEC"));
    if (int rc = openInstrument(inv, t))
        return rc;
    CliSession* s = t.session;
    if (!needsAxis)
        return Ok;
    t.axis = s->instrument()->identity().axisIndex(letter[0].toUpper());
    if (t.axis < 0)
        return inv.usage(tr("axis '%1' does not exist on the %2").arg(letter, ui::words::term(dev::instrumentTerm(s->instrument()->identity().kind))));
    if (inv.isSet(QStringLiteral("home")) || qobject_cast<dev::SimulatedLink*>(s->link()))
        if (int rc = homeAndCentre(inv, s, t.axis))
            return rc;
    auto target = std::make_unique<dev::InstrumentTarget>(t.tuning, t.axis, s->instrument()->identity().kindName());
    // The loop period comes with the gains.
    bool read = false;
    std::optional<dev::RequestError> err;
    t.tuning->getGains(t.axis, [&](const auto& e, const dev::AxisGains& g) {
        err = e;
        if (!e)
            target->setControlPeriodS(g.controlPeriodS);
        read = true;
    });
    spinUntil([&] { return read; }, 5000);
    if (err)
        return err->kind == dev::RequestError::Kind::Device ? inv.refused(ui::words::text(err->message)) : inv.linkTrouble(ui::words::text(err->message));
    t.target = std::move(target);
    return Ok;
}

bool readEnvelope(Invocation& inv, Envelope& e)
{
    return inv.number(QStringLiteral("max-excursion"), e.maxExcursion, e.maxExcursion)
        && inv.number(QStringLiteral("max-following-error"), e.maxFollowingError, e.maxFollowingError)
        && inv.number(QStringLiteral("max-duration"), e.maxDurationS, e.maxDurationS);
}

/// Starts the runner with `start` and runs it until it finishes; returns the exit
/// code and says what went wrong.
int runToEnd(Invocation& inv, dev::TuningRunner& runner, const std::function<bool()>& start, double timeoutS)
{
    bool done = false, ok = false;
    QString message;
    QObject::connect(&runner, &dev::TuningRunner::finished, &runner, [&](bool good, const motion::msg::Message& m) {
        done = true;
        ok = good;
        message = ui::words::text(m);
    });
    QObject::connect(&runner, &dev::TuningRunner::message, &runner, [&](const motion::msg::Message& m) { inv.report(ui::words::text(m)); });
    if (!start())
        return inv.refused(message.isEmpty() ? tr("could not start") : message);
    const auto abortHook = inv.host().onAbort([&runner] { runner.abort(); });  // the API's cancel: the axis stops under its gains
    if (!spinUntil([&] { return done || runner.state() == dev::TuningRunner::State::Interrupted; }, static_cast<int>(timeoutS * 1000))) {
        runner.abort();
        spinUntil([&] { return done; }, 3000);
        return inv.refused(tr("no result within %1 s (--timeout): aborted; the axis is stopped").arg(timeoutS));
    }
    if (runner.state() == dev::TuningRunner::State::Interrupted)
        return inv.linkTrouble(tr("the link was lost; the device ended the test and holds the axis under its gains"));
    if (!ok)
        return inv.refused(message);
    return Ok;
}

int tune(Invocation& inv)
{
    const QString method = inv.value(QStringLiteral("method"));
    if (method != QLatin1String("zn") && method != QLatin1String("relay"))
        return inv.usage(tr("--method must be zn (ultimate gain) or relay"));
    if (!inv.arguments().isEmpty())
        return inv.usage(tr("takes no arguments (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
    const bool model = inv.isSet(QStringLiteral("plant"));
    dev::TuningRunner::ZnOptions o;
    o.method = method == QLatin1String("relay") ? TuningMethod::Relay : TuningMethod::UltimateGain;
    o.envelope = model ? Envelope{3, 3, 600} : Envelope{0.05, 0.05, 2};
    o.step = model ? 1 : 0.02;
    o.relayAmplitude = model ? 0.2 : 0.02;
    o.hysteresis = model ? 0.002 : 0.001;
    o.startKp = model ? 0.1 : 0.25;
    o.kpMax = model ? 1000 : 100;
    o.verifyRule = inv.value(QStringLiteral("verify")).toStdString();
    if (!o.verifyRule.empty() && !findRule(o.verifyRule))
        return inv.usage(tr("--verify: no rule '%1'").arg(QString::fromStdString(o.verifyRule)));
    if (!readEnvelope(inv, o.envelope) || !inv.number(QStringLiteral("relay-amplitude"), o.relayAmplitude, o.relayAmplitude)
        || !inv.number(QStringLiteral("hysteresis"), o.hysteresis, o.hysteresis) || !inv.number(QStringLiteral("step"), o.step, o.step))
        return Usage;
    o.verifyStep = o.step;
    o.refine = !inv.isSet(QStringLiteral("no-refine"));
    Target t;
    if (int rc = openTarget(inv, t, true))
        return rc;
    if (model)
        o.trialS = o.envelope.maxDurationS;
    dev::TuningRunner runner;
    if (int rc = runToEnd(inv, runner, [&] { return runner.startZn(t.target.get(), o); }, inv.link().timeoutS))
        return rc;
    const TuningResult& r = runner.result();
    if (inv.isSet(QStringLiteral("save"))) {
        motion::msg::Message error;
        if (!dev::files::saveTuningFile(inv.path(inv.value(QStringLiteral("save"))), r, &error))
            return inv.refused(ui::words::text(error));
    }
    if (inv.json()) {
        QJsonObject rules;
        for (const auto& rule : tuningRules())
            rules[QLatin1String(rule.id)] =
                continuousJson(toDiscrete(applyRule(rule, r.ku, r.tuS), r.controlPeriodS), r.controlPeriodS, rule.tiPerTu > 0, rule.tdPerTu > 0);
        inv.printJson(QJsonObject{{QStringLiteral("Ku"), r.ku}, {QStringLiteral("Tu"), r.tuS}, {QStringLiteral("rules"), rules}});
    } else {
        inv.out() << QString::fromStdString(r.target) << ": Ku = " << num(r.ku) << ", Tu = " << num(r.tuS) << " s ("
                  << (o.method == TuningMethod::Relay ? tr("relay") : tr("ultimate gain")) << ", " << r.runs << tr(" runs") << ")\n";
        if (r.kuDescribing)
            inv.out() << tr("  classic describing function: Ku = %1, Tu = %2 s%3\n")
                             .arg(num(*r.kuDescribing), num(r.tuRelayS.value_or(0)), r.refined ? tr(" (refined above)") : QString());
        inv.out() << tr("  rule                       Kp          Ki [1/s]    Kd [s]      | per period T = %1 s: kp, ki, kd\n").arg(num(r.controlPeriodS));
        for (const auto& rule : tuningRules()) {
            const auto c = applyRule(rule, r.ku, r.tuS);
            const auto d = toDiscrete(c, r.controlPeriodS);
            inv.out() << "  " << QString::fromLatin1(rule.id).leftJustified(26) << " " << num(c.kp).leftJustified(11) << " "
                      << num(c.kiPerS).leftJustified(11) << " " << num(c.kdS).leftJustified(11) << " | " << num(d.kp) << ", " << num(d.ki)
                      << ", " << num(d.kd) << "\n";
        }
        if (r.verification) {
            inv.out() << tr("  verified with %1: overshoot %2 %, %3\n")
                             .arg(QString::fromStdString(r.verification->rule), num(r.verification->metrics.overshootPct),
                                  ui::words::tuningOutcome(r.verification->outcome));
            inv.out() << verdictLine(r.verification->metrics.outcome, r.verification->limitCycle, QString::fromStdString(r.unit));
        }
    }
    inv.out().flush();
    return Ok;
}

int stepTest(Invocation& inv)
{
    if (!inv.arguments().isEmpty())
        return inv.usage(tr("takes no arguments (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
    double size = 0;
    if (!inv.number(QStringLiteral("size"), size, 0.01))
        return Usage;
    if (!(size != 0) || !std::isfinite(size))
        return inv.usage(tr("--size must be a non-zero number (mm on an instrument, signed for the direction)"));
    const bool model = inv.isSet(QStringLiteral("plant"));
    Envelope env = model ? Envelope{3 * std::abs(size), 2 * std::abs(size), 600} : Envelope{std::max(0.05, 3 * std::abs(size)), std::max(0.05, 2 * std::abs(size)), 2};
    if (!readEnvelope(inv, env))
        return Usage;
    Target t;
    if (int rc = openTarget(inv, t, true))
        return rc;
    StepSpec s;
    s.step = size;
    s.envelope = env;
    const double T = t.target->controlPeriodS();
    if (inv.isSet(QStringLiteral("gains"))) {
        QString why;
        const auto g = parseGains(inv.value(QStringLiteral("gains")), T, inv.isSet(QStringLiteral("per-period")), &why);
        if (!g)
            return inv.usage(tr("--gains: %1").arg(why));
        s.gains = *g;
    } else if (t.tuning) {
        bool read = false;
        std::optional<dev::RequestError> err;
        t.tuning->getGains(t.axis, [&](const auto& e, const dev::AxisGains& g) {
            err = e;
            s.gains = g.gains;
            read = true;
        });
        spinUntil([&] { return read; }, 5000);
        if (err)
            return inv.refused(ui::words::text(err->message));
    } else {
        return inv.usage(tr("a model plant has no gains of its own: give --gains Kp,Ki,Kd"));
    }
    if (model) {
        s.runS = 0.99 * env.maxDurationS;
    } else {
        s.settleBand = std::max(2 * t.target->noiseFloor(), 0.02 * std::abs(size));
        s.settleHoldS = 0.05;
        s.runS = std::min(1.0, 0.9 * env.maxDurationS);
    }
    dev::TuningRunner runner;
    Record record;
    StepMetrics m;
    StepVerdict verdict;
    QObject::connect(&runner, &dev::TuningRunner::stepTestDone, &runner, [&](const Record& r, const StepVerdict& v, const motion::msg::Message&) {
        record = r;
        verdict = v;
        m = v.metrics;
    });
    if (int rc = runToEnd(inv, runner, [&] { return runner.startStepTest(t.target.get(), s, motion::msg::make("tuning.label.step_test")); }, inv.link().timeoutS))
        return rc;
    const bool mm = t.target->unit() == QLatin1String("mm");
    const double in5 = mm ? verdict.insideTargetBandS : std::nan("");
    auto opt = [](double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); };
    if (inv.json()) {
        QJsonObject o{{QStringLiteral("target"), t.target->describe()},
                      {QStringLiteral("step"), size},
                      {QStringLiteral("gains"), continuousJson(s.gains, T)},
                      {QStringLiteral("outcome"), QString::fromLatin1(endReasonName(record.reason))},
                      {QStringLiteral("rise_time_s"), opt(m.riseTimeS)},
                      {QStringLiteral("overshoot_pct"), opt(m.overshootPct)},
                      {QStringLiteral("settling_time_s"), opt(m.settlingTimeS)},
                      {QStringLiteral("steady_state_error"), opt(m.steadyStateError)},
                      {QStringLiteral("iae"), opt(m.iae)},
                      {QStringLiteral("ise"), opt(m.ise)},
                      {QStringLiteral("peak_output"), opt(m.peakOutput)},
                      {QStringLiteral("unit"), t.target->unit()},
                      {QStringLiteral("verdict"), QString::fromLatin1(stepOutcomeName(m.outcome))}};
        if (mm)
            o[QStringLiteral("settled_inside_5um_s")] = opt(in5);
        if (verdict.limitCycle.found)
            o[QStringLiteral("limit_cycle")] = QJsonObject{{QStringLiteral("amplitude"), verdict.limitCycle.amplitude},
                                                           {QStringLiteral("period_s"), verdict.limitCycle.periodS}};
        inv.printJson(o);
    } else {
        const QString u = t.target->unit();
        inv.out() << t.target->describe() << tr(": step %1 %2 with ").arg(num(size), u) << describeGains(s.gains, T) << " — "
                  << ui::words::term(endReasonTerm(record.reason)) << "\n"
                  << tr("  rise 10–90 %: %1 s, overshoot %2 %, settling (2 %): %3 s\n").arg(num(m.riseTimeS), num(m.overshootPct), num(m.settlingTimeS))
                  << tr("  steady-state error %1 %4, IAE %2 %4·s, ISE %3 %4²·s, peak output %5 %4\n")
                         .arg(num(m.steadyStateError), num(m.iae), num(m.ise), u, num(m.peakOutput));
        if (mm)
            inv.out() << (std::isnan(in5) ? tr("  never inside seed 002's ±5 µm band\n") : tr("  inside seed 002's ±5 µm band from %1 s\n").arg(num(in5)));
        inv.out() << verdictLine(m.outcome, verdict.limitCycle, u);
    }
    inv.out().flush();
    (void)opt;
    return Ok;
}

int gains(Invocation& inv)
{
    Target t;
    if (int rc = openInstrument(inv, t))
        return rc;
    dev::Instrument* c = t.session->instrument();
    const auto& id = c->identity();
    const bool perPeriod = inv.isSet(QStringLiteral("per-period"));
    auto read = [&](int axis, dev::AxisGains& out) -> std::optional<dev::RequestError> {
        bool done = false;
        std::optional<dev::RequestError> err;
        t.tuning->getGains(axis, [&](const auto& e, const dev::AxisGains& g) {
            err = e;
            out = g;
            done = true;
        });
        spinUntil([&] { return done; }, 5000);
        return err;
    };
    // Set first (AXIS=Kp,Ki,Kd ...), then show every axis.
    for (const QString& a : inv.arguments()) {
        const int eq = a.indexOf(QLatin1Char('='));
        const int axis = eq == 1 ? id.axisIndex(a[0].toUpper()) : -1;
        if (axis < 0)
            return inv.usage(tr("expected AXIS=Kp,Ki,Kd with a closed-loop axis, got '%1'").arg(a));
        dev::AxisGains now;
        if (const auto e = read(axis, now))
            return inv.refused(ui::words::text(e->message));
        QString why;
        const auto g = parseGains(a.mid(2), now.controlPeriodS, perPeriod, &why);
        if (!g)
            return inv.usage(tr("%1: %2").arg(a, why));
        if (int rc = t.session->request([&](auto cb) { t.tuning->setGains(axis, *g, inv.isSet(QStringLiteral("save")), cb); }, tr("set gains")))
            return rc;
    }
    QJsonObject axes;
    for (int axis : t.tuning->tunableAxes()) {
        dev::AxisGains g;
        if (const auto e = read(axis, g))
            return inv.refused(ui::words::text(e->message));
        const QString letter(id.axes[axis].letter);
        if (inv.json()) {
            QJsonObject o = continuousJson(g.gains, g.controlPeriodS);
            o[QStringLiteral("kp")] = g.gains.kp;
            o[QStringLiteral("ki")] = g.gains.ki;
            o[QStringLiteral("kd")] = g.gains.kd;
            o[QStringLiteral("control_period_s")] = g.controlPeriodS;
            o[QStringLiteral("saved")] = continuousJson(g.saved, g.controlPeriodS);
            axes[letter] = o;
        } else {
            inv.out() << letter << ": " << describeGains(g.gains, g.controlPeriodS) << tr("  (per period T = %1 s: kp %2, ki %3, kd %4)")
                                                                                          .arg(num(g.controlPeriodS), num(g.gains.kp), num(g.gains.ki), num(g.gains.kd))
                      << (g.gains != g.saved ? tr("; power-up set differs") : QString()) << "\n";
        }
    }
    if (inv.json())
        inv.printJson(QJsonObject{{QStringLiteral("axes"), axes}});
    inv.out().flush();
    return Ok;
}

} // namespace

void addTuningCommands(std::vector<Command>& list)
{
    const QCommandLineOption plant(QStringLiteral("plant"), tr("a model plant instead of an instrument: fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=.."),
                                   QStringLiteral("SPEC"));
    const QCommandLineOption axis(QStringLiteral("axis"), tr("the instrument's closed-loop axis"), QStringLiteral("X"));
    const QCommandLineOption home(QStringLiteral("home"), tr("home the axis and move it to mid-travel first (always done on the in-process simulator)"));
    const QCommandLineOption excursion(QStringLiteral("max-excursion"), tr("envelope: the furthest from the start (mm; plant units)"), QStringLiteral("E"));
    const QCommandLineOption following(QStringLiteral("max-following-error"), tr("envelope: the largest |setpoint − position|"), QStringLiteral("F"));
    const QCommandLineOption duration(QStringLiteral("max-duration"), tr("envelope: the longest a test may run, s"), QStringLiteral("S"));
    const QCommandLineOption perPeriod(QStringLiteral("per-period"), tr("gains are eq. 2's per-period kp,ki,kd, not Kp, Ki [1/s], Kd [s]"));
    const QList<ApiParam> envelopeParams{optionParam("max-excursion", ParamType::Number), optionParam("max-following-error", ParamType::Number),
                                         optionParam("max-duration", ParamType::Number), optionParam("axis", ParamType::Axis)};
    auto tuningApi = [&](const char* method, QList<ApiParam> params, QJsonObject example) {
        ApiSpec a;
        a.method = QString::fromLatin1(method);
        a.access = Access::Control;
        a.params = envelopeParams + params;
        a.example = std::move(example);
        return a;
    };
    ApiParam methodParam = optionParam("method", ParamType::Text);
    methodParam.choices = QStringList{QStringLiteral("zn"), QStringLiteral("relay")};
    list.push_back({QStringLiteral("tune"), tr("find Ku and Tu (Ziegler–Nichols) and print the tuning rules"), {},
                    tr("--method zn raises Kp trial by trial (P only) until the oscillation neither grows nor decays; "
                       "--method relay runs Åström and Hägglund's relay, then refines to the measured phase crossover. "
                       "Trials run inside 60 % of the envelope. Ki and Kd are printed in continuous form (1/s, s)."),
                    {QCommandLineOption(QStringLiteral("method"), tr("zn (ultimate gain) or relay"), QStringLiteral("M")), plant, axis, home,
                     QCommandLineOption(QStringLiteral("relay-amplitude"), tr("relay: d, of the controller output (mm; plant units)"), QStringLiteral("D")),
                     QCommandLineOption(QStringLiteral("hysteresis"), tr("relay: ε (mm; plant units)"), QStringLiteral("E")),
                     QCommandLineOption(QStringLiteral("step"), tr("zn: each trial's setpoint step (mm; plant units)"), QStringLiteral("S")),
                     QCommandLineOption(QStringLiteral("no-refine"), tr("relay: only the classic describing-function estimate")),
                     QCommandLineOption(QStringLiteral("verify"), tr("run a step test with this rule's gains afterwards (zn-pid, tl-pi, …)"), QStringLiteral("RULE")),
                     QCommandLineOption(QStringLiteral("save"), tr("write the results to a .tuning.json file"), QStringLiteral("FILE")), excursion,
                     following, duration},
                    tune, {},
                    tuningApi("tuning.tune",
                              {methodParam, optionParam("relay-amplitude", ParamType::Number), optionParam("hysteresis", ParamType::Number),
                               optionParam("step", ParamType::Number), optionParam("save", ParamType::File)},
                              QJsonObject{{QStringLiteral("method"), QStringLiteral("relay")},
                                          {QStringLiteral("plant"), QStringLiteral("fopdt:K=2,tau=0.5,L=0.1")},
                                          {QStringLiteral("relay_amplitude"), 0.15}})});
    list.push_back({QStringLiteral("step-test"), tr("a step on one axis under given (or the axis' own) gains; print its metrics"), {},
                    tr("--size in mm (signed: the direction). --gains Kp,Ki,Kd are tried for this test only: the axis' own gains stay."),
                    {QCommandLineOption(QStringLiteral("size"), tr("step size, mm (plant units); negative steps down"), QStringLiteral("MM")),
                     QCommandLineOption(QStringLiteral("gains"), tr("Kp,Ki,Kd for this test (Ki in 1/s, Kd in s)"), QStringLiteral("Kp,Ki,Kd")), perPeriod,
                     plant, axis, home, excursion, following, duration},
                    stepTest, {},
                    tuningApi("tuning.step_test", {optionParam("size", ParamType::Number), optionParam("gains", ParamType::Numbers)},
                              QJsonObject{{QStringLiteral("plant"), QStringLiteral("fopdt:K=2,tau=0.5,L=0.1")}, {QStringLiteral("size"), 1},
                                          {QStringLiteral("gains"), QJsonArray{1.2, 2.5, 0.05}}})});
    list.push_back({QStringLiteral("gains"), tr("show or set the PID gains of the closed-loop axes"), QStringLiteral("[AXIS=Kp,Ki,Kd...]"),
                    tr("Kp, Ki in 1/s, Kd in s (per period with --per-period). The device refuses NaN, negative and absurd "
                       "values with its reason and keeps the gains it had."),
                    {perPeriod, QCommandLineOption(QStringLiteral("save"), tr("also keep them as the device's power-up gains"))}, gains, {}, [] {
                        ApiSpec a;
                        a.method = QStringLiteral("tuning.gains");
                        a.access = Access::Control;
                        a.readsWithoutArguments = true;
                        a.params = {{QStringLiteral("gains"), ParamType::AxisValues, tr("axis → [Kp, Ki, Kd] to set; shows them when left out"), false, {}, {}}};
                        a.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}};
                        return a;
                    }()});
}

} // namespace app::cli
