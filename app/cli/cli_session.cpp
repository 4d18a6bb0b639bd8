#include "cli_session.h"

#include "device/link/serial_transport.h"
#include "device/link/simulated_link.h"

#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cmath>

namespace cli {
namespace {
constexpr int kConnectTimeoutMs = 5000;

QString num(double v) { return QString::number(v, 'f', 4); }

/// Runs the event loop until `done` returns true or `timeoutMs` passes; false on timeout.
bool spinUntil(const std::function<bool()>& done, int timeoutMs)
{
    QEventLoop loop;
    QTimer tick;
    tick.setInterval(5);
    QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer limit;
    limit.setSingleShot(true);
    bool timedOut = false;
    QObject::connect(&limit, &QTimer::timeout, &loop, [&] {
        timedOut = true;
        loop.quit();
    });
    if (done())
        return true;
    tick.start();
    limit.start(timeoutMs);
    loop.exec();
    return !timedOut;
}
} // namespace

CliSession::CliSession(const LinkOptions& options, QTextStream& out, QTextStream& err)
    : m_opt(options), m_out(out), m_err(err), m_client(new dev::InstrumentClient(this))
{
    connect(m_client, &dev::InstrumentClient::eventReceived, this, [this](const dev::DeviceEvent& e) {
        using K = proto::EventKind;
        if (e.kind == K::LimitHit || e.kind == K::Fault || e.kind == K::EStop || e.kind == K::LostSteps
            || e.kind == K::JogExpired)
            if (!m_motionErrors.contains(e.text))  // one line per distinct problem, however often it repeats
                m_motionErrors << e.text;
    });
}

CliSession::~CliSession()
{
    m_client->setTransport(nullptr);
}

int CliSession::usage(const QString& message)
{
    m_err << "benchpilot-cli: " << message << "\n";
    m_err.flush();
    return Usage;
}

bool CliSession::connectDevice()
{
    dev::Transport* transport = nullptr;
    if (!m_opt.sim.isEmpty()) {
        auto* link = new dev::SimulatedLink(m_opt.sim == QLatin1String("stage") ? proto::DeviceKind::Stage : proto::DeviceKind::Analyzer,
                                            m_opt.baud, this);
        m_link = link;
        transport = link->hostEnd();
    } else {
        auto* serial = new dev::SerialTransport(m_opt.port, m_opt.baud, this);
        m_link = serial;
        transport = serial;
    }
    QString linkError;
    connect(m_client, &dev::InstrumentClient::linkError, this, [&linkError](const QString& m) {
        if (linkError.isEmpty())
            linkError = m;
    });
    m_client->setTransport(transport);
    m_client->connectLink();
    const bool finished = spinUntil(
        [this] {
            const auto s = m_client->state();
            return s == dev::LinkState::Ready || s == dev::LinkState::Disconnected || s == dev::LinkState::Lost;
        },
        kConnectTimeoutMs);
    if (finished && m_client->state() == dev::LinkState::Ready)
        return true;
    m_err << "benchpilot-cli: cannot connect to " << m_client->linkDescription() << ": "
          << (linkError.isEmpty() ? QStringLiteral("no answer within %1 s").arg(kConnectTimeoutMs / 1000) : linkError) << "\n";
    m_err.flush();
    return false;
}

int CliSession::run(const QString& command, const QStringList& args)
{
    static const QStringList known = {QStringLiteral("info"), QStringLiteral("status"), QStringLiteral("home"),
                                      QStringLiteral("move"), QStringLiteral("jog"), QStringLiteral("stop"),
                                      QStringLiteral("estop"), QStringLiteral("reset"), QStringLiteral("zero"),
                                      QStringLiteral("limits")};
    if (!known.contains(command))
        return usage(QStringLiteral("unknown command '%1' (try --help)").arg(command));
    const bool noArgs = command == QLatin1String("info") || command == QLatin1String("status") || command == QLatin1String("stop")
        || command == QLatin1String("estop") || command == QLatin1String("reset");
    if (noArgs && !args.isEmpty())
        return usage(QStringLiteral("%1 takes no arguments (got '%2')").arg(command, args.join(QLatin1Char(' '))));
    if (!connectDevice())
        return LinkTrouble;
    if (command == QLatin1String("info"))
        return cmdInfo();
    if (command == QLatin1String("status"))
        return cmdStatus();
    if (command == QLatin1String("home"))
        return cmdHome(args);
    if (command == QLatin1String("move"))
        return cmdMove(args);
    if (command == QLatin1String("jog"))
        return cmdJog(args);
    if (command == QLatin1String("stop"))
        return cmdStop();
    if (command == QLatin1String("estop"))
        return cmdEStop();
    if (command == QLatin1String("reset"))
        return cmdReset();
    if (command == QLatin1String("zero"))
        return cmdZero(args);
    return cmdLimits(args);
}

bool CliSession::parseAxes(const QString& text, quint8* mask)
{
    *mask = 0;
    const auto& id = m_client->identity();
    for (const QChar c : text) {
        if (c == QLatin1Char(',') || c == QLatin1Char(' '))
            continue;
        const int i = id.axisIndex(c);
        if (i < 0) {
            usage(QStringLiteral("axis '%1' does not exist on the %2 (axes: %3)").arg(c).arg(id.kindName()).arg([&] {
                QString s;
                for (const auto& a : id.axes)
                    s += a.letter;
                return s;
            }()));
            return false;
        }
        *mask = static_cast<quint8>(*mask | (1u << i));
    }
    return true;
}

int CliSession::request(const std::function<void(dev::InstrumentClient::Callback)>& send, const QString& what)
{
    bool done = false;
    std::optional<dev::RequestError> error;
    send([&](const std::optional<dev::RequestError>& e) {
        error = e;
        done = true;
    });
    spinUntil([&] { return done; }, 10000);
    if (!done) {
        m_err << "benchpilot-cli: " << what << ": no answer\n";
        m_err.flush();
        return LinkTrouble;
    }
    if (error) {
        m_err << "benchpilot-cli: " << error->message << "\n";
        m_err.flush();
        return error->kind == dev::RequestError::Kind::Device || error->kind == dev::RequestError::Kind::Invalid ? Refused : LinkTrouble;
    }
    return Ok;
}

int CliSession::waitUntilStill(const QString& what)
{
    // Two fresh status polls after the request was accepted, so "not moving" is news, not history.
    int fresh = 0;
    auto c = connect(m_client, &dev::InstrumentClient::statusChanged, this, [&fresh] { ++fresh; });
    const bool still = spinUntil(
        [&] {
            return m_client->state() != dev::LinkState::Ready || (fresh >= 2 && !m_client->status().anyMoving());
        },
        static_cast<int>(m_opt.timeoutS * 1000));
    disconnect(c);
    if (m_client->state() != dev::LinkState::Ready) {
        m_err << "benchpilot-cli: " << what << ": link lost while waiting\n";
        m_err.flush();
        return LinkTrouble;
    }
    if (!still) {
        m_client->stop();
        spinUntil([] { return false; }, 200);
        m_err << "benchpilot-cli: " << what << ": still moving after " << m_opt.timeoutS << " s; sent stop\n";
        m_err.flush();
        return Refused;
    }
    if (!m_motionErrors.isEmpty()) {
        m_err << "benchpilot-cli: " << what << ": " << m_motionErrors.join(QStringLiteral("; ")) << "\n";
        m_err.flush();
        printStatus();
        return Refused;
    }
    printStatus();
    return Ok;
}

void CliSession::printStatus()
{
    const auto& id = m_client->identity();
    const auto& st = m_client->status();
    if (m_opt.json) {
        QJsonObject axes;
        for (int i = 0; i < id.axes.size() && i < st.axes.size(); ++i) {
            const auto& a = st.axes[i];
            axes.insert(QString(id.axes[i].letter),
                        QJsonObject{{QStringLiteral("position"), a.commanded},
                                    {QStringLiteral("measured"), a.measured},
                                    {QStringLiteral("homed"), a.homed},
                                    {QStringLiteral("moving"), a.moving},
                                    {QStringLiteral("homing"), a.homing},
                                    {QStringLiteral("home_switch"), a.homeSwitch},
                                    {QStringLiteral("limit_switch"), a.limitSwitch},
                                    {QStringLiteral("unit"), id.axes[i].unitName()}});
        }
        QJsonObject root{{QStringLiteral("instrument"), id.kindName()},
                         {QStringLiteral("estop"), st.estop},
                         {QStringLiteral("fault"), st.fault},
                         {QStringLiteral("axes"), axes}};
        m_out << QJsonDocument(root).toJson(QJsonDocument::Compact) << "\n";
    } else {
        m_out << QStringLiteral("%1%2\n").arg(id.kindName(), st.estop ? QStringLiteral("  [E-STOP]") : QString());
        for (int i = 0; i < id.axes.size() && i < st.axes.size(); ++i) {
            const auto& a = st.axes[i];
            m_out << QStringLiteral("  %1  cmd %2  meas %3 %4  %5%6%7%8\n")
                         .arg(id.axes[i].letter)
                         .arg(num(a.commanded), 10)
                         .arg(num(a.measured), 10)
                         .arg(id.axes[i].unitName(), -2)
                         .arg(a.homed ? QStringLiteral("homed") : QStringLiteral("NOT HOMED"))
                         .arg(a.moving ? QStringLiteral(" moving") : QString())
                         .arg(a.homeSwitch ? QStringLiteral(" home-switch") : QString())
                         .arg(a.limitSwitch ? QStringLiteral(" limit-switch") : QString());
        }
    }
    m_out.flush();
}

int CliSession::cmdInfo()
{
    const auto& id = m_client->identity();
    if (m_opt.json) {
        QJsonArray axes;
        for (const auto& a : id.axes)
            axes.append(QJsonObject{{QStringLiteral("axis"), QString(a.letter)},
                                    {QStringLiteral("unit"), a.unitName()},
                                    {QStringLiteral("travel_min"), a.travelMin},
                                    {QStringLiteral("travel_max"), a.travelMax},
                                    {QStringLiteral("max_speed"), a.maxSpeed},
                                    {QStringLiteral("resolution"), a.resolution}});
        m_out << QJsonDocument(QJsonObject{{QStringLiteral("instrument"), id.kindName()},
                                           {QStringLiteral("model"), id.model},
                                           {QStringLiteral("firmware"), id.firmware},
                                           {QStringLiteral("protocol"), id.protocolVersion},
                                           {QStringLiteral("capabilities"), static_cast<qint64>(id.capabilities)},
                                           {QStringLiteral("link_baud"), static_cast<qint64>(id.linkBaud)},
                                           {QStringLiteral("axes"), axes}})
                     .toJson(QJsonDocument::Compact)
              << "\n";
    } else {
        m_out << id.model << " (" << id.kindName() << "), firmware " << id.firmware << ", protocol " << id.protocolVersion
              << "\n  link: " << m_client->linkDescription() << "\n";
        for (const auto& a : id.axes)
            m_out << "  " << a.letter << ": " << a.travelMin << " … " << a.travelMax << " " << a.unitName() << ", max "
                  << a.maxSpeed << " " << a.unitName() << "/s, resolution " << a.resolution << " " << a.unitName() << "\n";
    }
    m_out.flush();
    return Ok;
}

int CliSession::cmdStatus()
{
    // The status that arrived while connecting is current: print it as is.
    printStatus();
    return Ok;
}

int CliSession::cmdHome(const QStringList& args)
{
    quint8 mask = 0;
    if (!parseAxes(args.join(QString()), &mask))
        return Usage;
    if (int rc = request([&](auto cb) { m_client->home(mask, cb); }, QStringLiteral("home")))
        return rc;
    return waitUntilStill(QStringLiteral("home"));
}

int CliSession::cmdMove(const QStringList& args)
{
    QVector<QPair<int, double>> targets;
    bool relative = false;
    double speed = 0;
    const auto& id = m_client->identity();
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--relative")) {
            relative = true;
        } else if (a == QLatin1String("--speed")) {
            bool ok = false;
            speed = i + 1 < args.size() ? args[++i].toDouble(&ok) : 0;
            if (!ok || speed <= 0 || !std::isfinite(speed))
                return usage(QStringLiteral("--speed needs a positive number"));
        } else {
            const int eq = a.indexOf(QLatin1Char('='));
            if (eq != 1)
                return usage(QStringLiteral("move: expected AXIS=VALUE, got '%1'").arg(a));
            const int axis = id.axisIndex(a[0]);
            if (axis < 0)
                return usage(QStringLiteral("move: axis '%1' does not exist on the %2").arg(a[0]).arg(id.kindName()));
            bool ok = false;
            const double v = a.mid(2).toDouble(&ok);
            if (!ok || !std::isfinite(v))
                return usage(QStringLiteral("move: '%1' is not a number for axis %2").arg(a.mid(2)).arg(a[0]));
            targets.push_back({axis, v});
        }
    }
    if (targets.isEmpty())
        return usage(QStringLiteral("move: give at least one AXIS=VALUE"));
    if (int rc = request([&](auto cb) { m_client->move(targets, relative, speed, cb); }, QStringLiteral("move")))
        return rc;
    return waitUntilStill(QStringLiteral("move"));
}

int CliSession::cmdJog(const QStringList& args)
{
    if (args.size() != 3)
        return usage(QStringLiteral("jog: expected AXIS VELOCITY SECONDS"));
    const auto& id = m_client->identity();
    const int axis = args[0].size() == 1 ? id.axisIndex(args[0][0]) : -1;
    if (axis < 0)
        return usage(QStringLiteral("jog: axis '%1' does not exist on the %2").arg(args[0]).arg(id.kindName()));
    bool ok1 = false, ok2 = false;
    const double v = args[1].toDouble(&ok1);
    const double seconds = args[2].toDouble(&ok2);
    if (!ok1 || !std::isfinite(v) || std::abs(v) > id.axes[axis].maxSpeed)
        return usage(QStringLiteral("jog: velocity must be a number within ±%1 %2/s").arg(id.axes[axis].maxSpeed).arg(id.axes[axis].unitName()));
    if (!ok2 || seconds <= 0 || seconds > 600)
        return usage(QStringLiteral("jog: seconds must be in (0, 600]"));
    QString refused;
    auto c = connect(m_client, &dev::InstrumentClient::requestFailed, this, [&](const dev::RequestError& e) { refused = e.message; });
    m_client->startJog(axis, v);
    spinUntil([&] { return !refused.isEmpty() || m_client->state() != dev::LinkState::Ready; }, static_cast<int>(seconds * 1000));
    m_client->stopJog(axis);
    disconnect(c);
    if (!refused.isEmpty()) {
        m_err << "benchpilot-cli: " << refused << "\n";
        m_err.flush();
        return Refused;
    }
    return waitUntilStill(QStringLiteral("jog"));
}

int CliSession::cmdStop()
{
    if (int rc = request([&](auto cb) { m_client->stop(0, cb); }, QStringLiteral("stop")))
        return rc;
    return waitUntilStill(QStringLiteral("stop"));
}

int CliSession::cmdEStop()
{
    if (int rc = request([&](auto cb) { m_client->estop(cb); }, QStringLiteral("estop")))
        return rc;
    m_motionErrors.clear();  // the E-stop event is the point here, not a failure
    spinUntil([] { return false; }, 150);
    printStatus();
    return Ok;
}

int CliSession::cmdReset()
{
    if (int rc = request([&](auto cb) { m_client->reset(cb); }, QStringLiteral("reset")))
        return rc;
    spinUntil([] { return false; }, 150);
    printStatus();
    return Ok;
}

int CliSession::cmdZero(const QStringList& args)
{
    quint8 mask = 0;
    if (args.isEmpty())
        return usage(QStringLiteral("zero: name the axes to zero, e.g. 'zero XY'"));
    if (!parseAxes(args.join(QString()), &mask))
        return Usage;
    if (int rc = request([&](auto cb) { m_client->setZero(mask, cb); }, QStringLiteral("zero")))
        return rc;
    spinUntil([] { return false; }, 150);
    printStatus();
    return Ok;
}

int CliSession::cmdLimits(const QStringList& args)
{
    const auto& id = m_client->identity();
    for (const QString& a : args) {
        // AXIS=MIN:MAX
        const int eq = a.indexOf(QLatin1Char('='));
        const int colon = a.indexOf(QLatin1Char(':'));
        const int axis = eq == 1 ? id.axisIndex(a[0]) : -1;
        bool ok1 = false, ok2 = false;
        const double lo = colon > eq ? a.mid(eq + 1, colon - eq - 1).toDouble(&ok1) : 0;
        const double hi = colon > eq ? a.mid(colon + 1).toDouble(&ok2) : 0;
        if (axis < 0 || !ok1 || !ok2)
            return usage(QStringLiteral("limits: expected AXIS=MIN:MAX, got '%1'").arg(a));
        if (int rc = request([&](auto cb) { m_client->setSoftLimits(axis, lo, hi, cb); }, QStringLiteral("limits")))
            return rc;
    }
    const auto& lim = m_client->softLimits();
    if (m_opt.json) {
        QJsonObject o;
        for (int i = 0; i < id.axes.size() && i < lim.size(); ++i)
            o.insert(QString(id.axes[i].letter), QJsonArray{lim[i].min, lim[i].max});
        m_out << QJsonDocument(QJsonObject{{QStringLiteral("soft_limits"), o}}).toJson(QJsonDocument::Compact) << "\n";
    } else {
        for (int i = 0; i < id.axes.size() && i < lim.size(); ++i)
            m_out << "  " << id.axes[i].letter << ": " << lim[i].min << " … " << lim[i].max << " " << id.axes[i].unitName() << "\n";
    }
    m_out.flush();
    return Ok;
}

} // namespace cli
