// benchpilot-cli's instrument commands: info, status, home, move, jog, stop,
// estop, reset, zero, unlock, limits. Each connects, acts, waits until the machine is
// still where that is the point, and prints the result as text or JSON.
#include "cli_session.h"
#include "command.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// Commands that take no words after their options.
bool noArguments(Invocation& inv)
{
    if (inv.arguments().isEmpty())
        return true;
    inv.usage(tr("takes no arguments (got '%1')").arg(inv.arguments().join(QLatin1Char(' '))));
    return false;
}

/// The planner's profile as `info --json` names it; "unstated" when the device gave no limits.
QString profileName(dev::proto::MotionProfile p)
{
    switch (p) {
    case dev::proto::MotionProfile::Unstated: return QStringLiteral("unstated");
    case dev::proto::MotionProfile::Trapezoid: return QStringLiteral("trapezoid");
    case dev::proto::MotionProfile::JerkLimited: return QStringLiteral("jerk-limited");
    case dev::proto::MotionProfile::SeedSCurve: return QStringLiteral("seed-s-curve");
    }
    return QStringLiteral("unstated");
}

int info(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    const auto& id = s->instrument()->identity();
    if (inv.json()) {
        QJsonArray axes;
        for (const auto& a : id.axes) {
            QJsonObject o{{QStringLiteral("axis"), QString(a.letter)},
                          {QStringLiteral("unit"), a.unitName()},
                          {QStringLiteral("travel_min"), a.travelMin},
                          {QStringLiteral("travel_max"), a.travelMax},
                          {QStringLiteral("max_speed"), a.maxSpeed},
                          {QStringLiteral("resolution"), a.resolution}};
            if (id.reportsMotionLimits()) {  // per second², per second³ (0: jerk not limited), per second
                o[QStringLiteral("max_accel")] = a.maxAccel;
                o[QStringLiteral("max_jerk")] = a.maxJerk;
                o[QStringLiteral("default_speed")] = a.defaultSpeed;
            }
            axes.append(o);
        }
        QJsonArray features;
        const dev::Capabilities can = s->instrument()->capabilities();
        for (dev::Capability c : dev::allCapabilities())
            if (can.testFlag(c))
                features.append(QString::fromStdString(dev::capabilityKey(c)));
        inv.printJson(QJsonObject{{QStringLiteral("instrument"), id.kindName()},
                                  {QStringLiteral("model"), id.model},
                                  {QStringLiteral("firmware"), id.firmware},
                                  {QStringLiteral("family"), id.family},
                                  {QStringLiteral("protocol"), id.protocolVersion},
                                  {QStringLiteral("capabilities"), static_cast<qint64>(id.protocolCapabilities)},
                                  {QStringLiteral("features"), features},
                                  {QStringLiteral("motion_profile"), profileName(id.motionProfile)},
                                  {QStringLiteral("link_baud"), static_cast<qint64>(id.linkBaud)},
                                  {QStringLiteral("axes"), axes}});
    } else {
        inv.out() << id.model << " (" << id.kindName() << "), firmware " << id.firmware << ", " << id.family
                  << "\n  link: " << s->instrument()->linkDescription() << "\n";
        for (const auto& a : id.axes) {
            inv.out() << "  " << a.letter << ": " << a.travelMin << " … " << a.travelMax << " " << a.unitName() << ", max "
                      << a.maxSpeed << " " << a.unitName() << "/s, resolution " << a.resolution << " " << a.unitName();
            if (id.reportsMotionLimits())
                inv.out() << ", " << a.maxAccel << " " << a.unitName() << "/s²"
                          << (a.maxJerk > 0 ? QStringLiteral(", %1 %2/s³").arg(a.maxJerk).arg(a.unitName()) : QString());
            inv.out() << "\n";
        }
        if (!id.reportsMotionLimits())
            inv.out() << "  " << tr("planner limits: not reported (estimates assume the reference machine's)") << "\n";
    }
    inv.out().flush();
    return Ok;
}

int status(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    // The status that arrived while connecting is current: print it as is.
    s->printStatus();
    return Ok;
}

int home(Invocation& inv)
{
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    quint8 mask = 0;
    if (!s->parseAxes(inv.arguments().join(QString()), &mask))
        return Usage;
    if (int rc = s->request([&](auto cb) { s->instrument()->home(mask, cb); }, tr("home")))
        return rc;
    return s->waitUntilStill(tr("home"));
}

int move(Invocation& inv)
{
    double speed = 0;
    if (!inv.number(QStringLiteral("speed"), speed, 0.0))
        return Usage;
    if (inv.isSet(QStringLiteral("speed")) && !(speed > 0))
        return inv.usage(tr("--speed needs a positive number"));
    const QStringList words = inv.arguments();
    if (words.isEmpty())
        return inv.usage(tr("give at least one AXIS=VALUE"));
    for (const QString& a : words)
        if (a.indexOf(QLatin1Char('=')) != 1)
            return inv.usage(tr("expected AXIS=VALUE, got '%1'").arg(a));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    QVector<QPair<int, double>> targets;
    if (!s->parseTargets(words, &targets))
        return Usage;
    const bool relative = inv.isSet(QStringLiteral("relative"));
    if (int rc = s->request([&](auto cb) { s->instrument()->move(targets, relative, speed, cb); }, tr("move")))
        return rc;
    return s->waitUntilStill(tr("move"));
}

int jog(Invocation& inv)
{
    const QStringList words = inv.arguments();
    // Without SECONDS only where a caller can hold a jog open (the API): it runs until
    // device.stop or until that caller loses control.
    const bool held = words.size() == 2 && inv.host().canHoldJog();
    if (words.size() != 3 && !held)
        return inv.usage(tr("expected AXIS VELOCITY SECONDS"));
    bool ok1 = false, ok2 = false;
    const double v = words[1].toDouble(&ok1);
    const double seconds = held ? 0 : words[2].toDouble(&ok2);
    if (!ok1 || !std::isfinite(v))
        return inv.usage(tr("velocity '%1' is not a number").arg(words[1]));
    if (!held && (!ok2 || seconds <= 0 || seconds > 600))
        return inv.usage(tr("seconds must be in (0, 600]"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    const auto& id = s->instrument()->identity();
    const int axis = words[0].size() == 1 ? id.axisIndex(words[0][0]) : -1;
    if (axis < 0)
        return inv.usage(tr("axis '%1' does not exist on the %2").arg(words[0]).arg(::ui::words::term(dev::instrumentTerm(id.kind))));
    if (std::abs(v) > id.axes[axis].maxSpeed)
        return inv.usage(tr("velocity must be within ±%1 %2/s").arg(id.axes[axis].maxSpeed).arg(id.axes[axis].unitName()));
    QString refused;
    dev::Instrument* c = s->instrument();
    auto conn = QObject::connect(c, &dev::Instrument::requestFailed, s, [&](const dev::RequestError& e) {
        refused = ::ui::words::text(e.message);
        s->noteRefusal(e);
    });
    if (held) {
        inv.host().holdJog(*s, axis, v);
        // The device's answer (a refusal: not homed past a limit, E-stop) comes within a poll or two.
        spinUntil([&] { return !refused.isEmpty() || c->state() != dev::LinkState::Ready; }, 150);
        QObject::disconnect(conn);
        if (!refused.isEmpty())
            return inv.refused(refused);
        s->printStatus();
        return Ok;
    }
    // The caller losing control (the API's lease) stops the jog, as releasing a jog key does.
    const auto lost = inv.host().onLostControl([c, axis] { c->stopJog(axis); });
    const auto abortHook = inv.host().onAbort([c, axis] { c->stopJog(axis); });
    c->startJog(axis, v);
    spinUntil([&] { return !refused.isEmpty() || c->state() != dev::LinkState::Ready || !c->isJogging(axis); },
              static_cast<int>(seconds * 1000));
    c->stopJog(axis);
    QObject::disconnect(conn);
    if (!refused.isEmpty())
        return inv.refused(refused);
    return s->waitUntilStill(tr("jog"));
}

/// The worse of two exit codes (link trouble over a refusal over a usage error).
int worse(int a, int b) { return std::max(a, b); }

/// Sends a halt (`send`) to every session before waiting for any answer, so that a slow
/// link never holds up another machine's halt; then waits for each. `halted` gets the
/// sessions that accepted it. Returns the worst exit code.
int haltEach(const QVector<CliSession*>& sessions, const std::function<void(CliSession*, dev::Instrument::Callback)>& send,
             const QString& what, QVector<CliSession*>* halted)
{
    std::vector<std::shared_ptr<CliSession::PendingRequest>> pending;
    for (CliSession* s : sessions)
        pending.push_back(s->sendRequest([s, &send](dev::Instrument::Callback cb) { send(s, std::move(cb)); }));
    int rc = Ok;
    for (int i = 0; i < sessions.size(); ++i) {
        const int answered = sessions[i]->awaitAnswer(pending[static_cast<std::size_t>(i)], what);
        if (answered == Ok)
            *halted << sessions[i];
        rc = worse(rc, answered);
    }
    return rc;
}

/// What a halt reached. One instrument: its status, as `status` prints it (with --json,
/// "halted" names it too). Several (inside the GUI, none named): each one's status in
/// turn; with --json {"halted": [names], "instruments": [statuses]}.
void printHalted(Invocation& inv, const QVector<CliSession*>& halted, int asked)
{
    if (!inv.json()) {
        for (CliSession* s : halted)
            s->printStatus();
        return;
    }
    QJsonArray names, statuses;
    for (CliSession* s : halted) {
        names.append(s->instrument()->identity().kindName());
        statuses.append(s->statusJson());
    }
    QJsonObject o = asked == 1 && !halted.isEmpty() ? halted.first()->statusJson() : QJsonObject{{QStringLiteral("instruments"), statuses}};
    o.insert(QStringLiteral("halted"), names);
    inv.printJson(o);
}

int stop(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    const QVector<CliSession*> sessions = inv.haltSessions();
    if (sessions.isEmpty())
        return LinkTrouble;
    QVector<CliSession*> halted;
    int rc = haltEach(sessions, [](CliSession* s, dev::Instrument::Callback cb) { s->instrument()->stop(0, std::move(cb)); }, tr("stop"),
                      &halted);
    QVector<CliSession*> shown;
    for (CliSession* s : halted) {
        rc = worse(rc, s->waitUntilStill(tr("stop"), false));
        if (s->instrument()->isReady())
            shown << s;
    }
    if (!shown.isEmpty())
        printHalted(inv, shown, static_cast<int>(sessions.size()));
    return rc;
}

/// Lets a status poll arrive after a request whose effect is immediate, then prints it.
int settleAndPrint(CliSession* s)
{
    spinUntil([] { return false; }, 150);
    s->printStatus();
    return Ok;
}

int estop(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    const QVector<CliSession*> sessions = inv.haltSessions();
    if (sessions.isEmpty())
        return LinkTrouble;
    QVector<CliSession*> halted;
    const int rc = haltEach(sessions, [](CliSession* s, dev::Instrument::Callback cb) { s->instrument()->estop(std::move(cb)); },
                            tr("estop"), &halted);
    for (CliSession* s : sessions)
        s->takeMotionErrors();  // the E-stop event is the point here, not a failure
    if (halted.isEmpty())
        return rc;
    spinUntil([] { return false; }, 150);  // a status poll after the latch, so the printed status shows it
    printHalted(inv, halted, static_cast<int>(sessions.size()));
    return rc;
}

int reset(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    if (int rc = s->request([&](auto cb) { s->instrument()->reset(cb); }, tr("reset")))
        return rc;
    return settleAndPrint(s);
}

int zero(Invocation& inv)
{
    if (inv.arguments().isEmpty())
        return inv.usage(tr("name the axes to zero, e.g. 'zero XY'"));
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    quint8 mask = 0;
    if (!s->parseAxes(inv.arguments().join(QString()), &mask))
        return Usage;
    if (int rc = s->request([&](auto cb) { s->instrument()->setZero(mask, cb); }, tr("zero")))
        return rc;
    return settleAndPrint(s);
}

int unlock(Invocation& inv)
{
    if (!noArguments(inv))
        return Usage;
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    if (!s->instrument()->status().positionLost) {
        s->report(tr("nothing to unlock: the instrument trusts its position"));
        s->printStatus();
        return Ok;
    }
    // The operator's word, said out loud: the controller's own idea of where it is becomes the truth.
    s->report(tr("unlocking: the position the controller believes is taken as true; home the axes when you can"));
    if (int rc = s->request([&](auto cb) { s->instrument()->unlock(cb); }, tr("unlock")))
        return rc;
    return settleAndPrint(s);
}

int limits(Invocation& inv)
{
    struct Change {
        QString text;
        double lo, hi;
    };
    QVector<Change> changes;
    for (const QString& a : inv.arguments()) {
        // AXIS=MIN:MAX
        const int eq = a.indexOf(QLatin1Char('='));
        const int colon = a.indexOf(QLatin1Char(':'));
        bool ok1 = false, ok2 = false;
        const double lo = colon > eq ? a.mid(eq + 1, colon - eq - 1).toDouble(&ok1) : 0;
        const double hi = colon > eq ? a.mid(colon + 1).toDouble(&ok2) : 0;
        if (eq != 1 || !ok1 || !ok2)
            return inv.usage(tr("expected AXIS=MIN:MAX, got '%1'").arg(a));
        changes.push_back({a, lo, hi});
    }
    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    const auto& id = s->instrument()->identity();
    for (const Change& c : changes) {
        const int axis = id.axisIndex(c.text[0]);
        if (axis < 0)
            return inv.usage(tr("axis '%1' does not exist on the %2").arg(c.text[0]).arg(::ui::words::term(dev::instrumentTerm(id.kind))));
        if (int rc = s->request([&](auto cb) { s->instrument()->setSoftLimits(axis, c.lo, c.hi, cb); }, tr("limits")))
            return rc;
    }
    const auto& lim = s->instrument()->softLimits();
    if (inv.json()) {
        QJsonObject o;
        for (int i = 0; i < id.axes.size() && i < lim.size(); ++i)
            o.insert(QString(id.axes[i].letter), QJsonArray{lim[i].min, lim[i].max});
        inv.printJson(QJsonObject{{QStringLiteral("soft_limits"), o}});
    } else {
        for (int i = 0; i < id.axes.size() && i < lim.size(); ++i)
            inv.out() << "  " << id.axes[i].letter << ": " << lim[i].min << " … " << lim[i].max << " " << id.axes[i].unitName() << "\n";
    }
    inv.out().flush();
    return Ok;
}

} // namespace

void addDeviceCommands(std::vector<Command>& list)
{
    const QCommandLineOption relative(QStringLiteral("relative"), tr("targets are distances from where the axes are"));
    const QCommandLineOption speed(QStringLiteral("speed"), tr("path speed in the unit of the first axis named, per second"),
                                   QStringLiteral("V"));
    auto api = [](const char* method, Access access, QList<ApiParam> params = {}, QJsonObject example = {}) {
        ApiSpec a;
        a.method = QString::fromLatin1(method);
        a.access = access;
        a.params = std::move(params);
        a.example = std::move(example);
        return a;
    };
    const QJsonObject stage{{QStringLiteral("instrument"), QStringLiteral("stage")}};
    auto withStage = [&stage](std::initializer_list<std::pair<QString, QJsonValue>> more) {
        QJsonObject o = stage;
        for (const auto& [k, v] : more)
            o.insert(k, v);
        return o;
    };
    list.push_back({QStringLiteral("info"), tr("device identity, axes, travel, resolution"), {}, {}, {}, info, {},
                    api("device.info", Access::Read, {}, stage)});
    list.push_back({QStringLiteral("status"), tr("positions (commanded and measured), homed, moving, switches"), {}, {}, {}, status, {},
                    api("device.status", Access::Read, {}, stage)});
    list.push_back({QStringLiteral("home"), tr("home the axes (all when none given), wait until done"), QStringLiteral("[AXES]"),
                    tr("The analyzer lifts Z first. AXES are letters, e.g. 'XY'."), {}, home, {},
                    api("device.home", Access::Control,
                        {{QStringLiteral("axes"), ParamType::Axes, tr("the axes to home, e.g. \"XY\"; all when left out"), false, {}, {}}},
                        withStage({{QStringLiteral("axes"), QStringLiteral("X")}}))});
    list.push_back({QStringLiteral("move"), tr("move and wait until done (mm, µL for P)"), QStringLiteral("AXIS=VALUE..."),
                    tr("Absolute moves need homed axes; targets beyond the soft limits are refused by the device."),
                    {relative, speed}, move, {},
                    api("device.move", Access::Control,
                        {{QStringLiteral("targets"), ParamType::AxisValues, tr("axis → target, e.g. {\"X\": 10, \"Y\": 5}"), true, {}, {}},
                         {QStringLiteral("speed"), ParamType::Number, {}, false, QStringLiteral("speed"), {}}},
                        withStage({{QStringLiteral("targets"), QJsonObject{{QStringLiteral("X"), 10}, {QStringLiteral("Y"), 5}}},
                                   {QStringLiteral("relative"), true}}))});
    list.push_back({QStringLiteral("jog"), tr("velocity jog for SECONDS, then stop and wait until still"),
                    QStringLiteral("AXIS VELOCITY SECONDS"),
                    tr("The jog is refreshed while it runs; if this program dies the device stops the axis by itself."), {}, jog, {},
                    api("device.jog", Access::Control,
                        {{QStringLiteral("axis"), ParamType::Axis, tr("the axis letter"), true, {}, {}},
                         {QStringLiteral("velocity"), ParamType::Number, tr("axis units per second, signed"), true, {}, {}},
                         {QStringLiteral("seconds"), ParamType::Number,
                          tr("jog this long, then stop and wait until still; without it the jog runs until device.stop, "
                             "or until the lease or the connection ends"),
                          false, {}, {}}},
                        withStage({{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 2}, {QStringLiteral("seconds"), 0.5}}))});
    list.push_back({QStringLiteral("stop"), tr("decelerate all axes to rest"), {}, {}, {}, stop, {}, api("device.stop", Access::Safety, {}, stage)});
    list.push_back({QStringLiteral("estop"), tr("halt at once and latch the E-stop"), {}, {}, {}, estop, {},
                    api("device.estop", Access::Safety, {}, stage)});
    list.push_back({QStringLiteral("reset"), tr("clear the E-stop latch"), {}, {}, {}, reset, {}, api("device.reset", Access::Control, {}, stage)});
    list.push_back({QStringLiteral("zero"), tr("make the current position zero"), QStringLiteral("AXES"),
                    tr("On a GRBL controller without homing ($22=0) this takes the present position as home, on your word: "
                       "absolute moves are allowed after it."),
                    {}, zero, {},
                    api("device.zero", Access::Control,
                        {{QStringLiteral("axes"), ParamType::Axes, tr("the axes to zero, e.g. \"XY\""), true, {}, {}}},
                        withStage({{QStringLiteral("axes"), QStringLiteral("XY")}}))});
    list.push_back({QStringLiteral("unlock"), tr("accept the position a controller believes after an alarm (GRBL's $X)"), {},
                    tr("After an alarm that lost the position (a reset while moving, an E-stop, a hard limit) a GRBL controller "
                       "refuses motion until it is homed or unlocked. Unlocking takes its idea of the position as true: home "
                       "when you can."),
                    {}, unlock, {}, api("device.unlock", Access::Control, {}, stage)});
    ApiSpec limitsApi = api("device.limits", Access::Control,
                            {{QStringLiteral("limits"), ParamType::AxisRanges, tr("axis → [min, max] to set; shows them when left out"), false, {}, {}}},
                            withStage({{QStringLiteral("limits"), QJsonObject{{QStringLiteral("X"), QJsonArray{0, 50}}}}}));
    limitsApi.readsWithoutArguments = true;
    list.push_back({QStringLiteral("limits"), tr("show or set soft limits"), QStringLiteral("[AXIS=MIN:MAX...]"), {}, {}, limits, {}, limitsApi});
}

} // namespace app::cli
