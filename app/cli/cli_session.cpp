#include "cli_session.h"

#include "device/sim/machine_config.h"
#include "fiber.h"

#include "widgets/wording/wording.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/serial_transport.h"
#include "device/link/simulated_link.h"
#include "device/sim/machine_config.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cmath>

namespace app::cli {
namespace {
// A safety net only: the client ends a connect itself (the device silent for its silence
// limit, or no whole answer within its give-up while damaged frames show a device talking),
// and the CLI must not cut that patience short. It did, at 5 s: at 1 % of bytes damaged one
// home in thirty ended "no answer within 5 s" while the client was still getting through.
constexpr int kConnectTimeoutMs = dev::BenchPilotClient::kConnectGiveUpMs + 2000;
constexpr int kGrblConnectTimeoutMs = 9000;

QString num(double v) { return QString::number(v, 'f', 4); }
} // namespace

bool spinUntil(const std::function<bool()>& done, int timeoutMs)
{
    if (Fiber* fiber = Fiber::current())
        return fiber->waitUntil(done, timeoutMs);
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

CliSession::CliSession(Invocation& inv, const LinkOptions& options)
    : m_inv(inv), m_opt(options), m_client(nullptr), m_ownProxy(new dev::InstrumentProxy(this))
{
    m_client = m_ownProxy;
    watchMotionErrors();
}

CliSession::CliSession(Invocation& inv, dev::Instrument* instrument) : m_inv(inv), m_opt(inv.link()), m_client(instrument)
{
    watchMotionErrors();
}

void CliSession::watchMotionErrors()
{
    connect(m_client, &dev::Instrument::eventReceived, this, [this](const dev::DeviceEvent& e) {
        using K = dev::proto::EventKind;
        if (e.kind == K::LimitHit || e.kind == K::Fault || e.kind == K::EStop || e.kind == K::LostSteps
            || e.kind == K::JogExpired)
            if (const QString said = ui::words::eventDetail(e); !m_motionErrors.contains(said))  // one line per distinct problem
                m_motionErrors << said;
    });
}

CliSession::~CliSession()
{
    if (m_wantedTelemetry && m_telemetryWish)
        m_telemetryWish({}, 0);
    if (m_benchPilot)
        m_benchPilot->setTransport(nullptr);
}

void CliSession::wantTelemetry(const QVector<dev::proto::ChannelRef>& channels, int rateHz)
{
    m_wantedTelemetry = !channels.isEmpty();
    if (m_telemetryWish)
        m_telemetryWish(channels, rateHz);
    else
        m_client->subscribe(channels, rateHz);
}

void CliSession::report(const QString& message) { m_inv.report(message); }

QStringList CliSession::takeMotionErrors()
{
    QStringList e;
    e.swap(m_motionErrors);
    return e;
}

bool CliSession::connectDevice()
{
    QString linkError;
    // Only while connecting: the lambda holds a reference to this frame's string
    // (ASan caught a later link error writing into the dead frame).
    const auto watch = connect(m_client, &dev::Instrument::linkError, this, [&linkError](const motion::msg::Message& m) {
        if (linkError.isEmpty())
            linkError = ui::words::text(m);
    });
    if (!m_opt.sim.isEmpty()) {
        dev::SimulatedLink* link = nullptr;
        if (m_opt.stageErrors && m_opt.sim == QLatin1String("stage")) {
            dev::sim::MachineConfig config = dev::sim::stageConfig();
            dev::sim::applyStageErrors(config, *m_opt.stageErrors);
            link = new dev::SimulatedLink(config, m_opt.baud, this);
        } else {
            link = new dev::SimulatedLink(m_opt.sim == QLatin1String("stage") ? dev::proto::DeviceKind::Stage : dev::proto::DeviceKind::Analyzer,
                                          m_opt.baud, this);
        }
        m_link = link;
        m_benchPilot = new dev::BenchPilotClient;
        m_ownProxy->setBackend(m_benchPilot);
        m_benchPilot->setTransport(link->hostEnd());
    } else {
        auto* serial = new dev::SerialTransport(m_opt.port, m_opt.baud, this);
        m_link = serial;
        if (!choosePortBackend(serial)) {
            disconnect(watch);
            return false;
        }
    }
    m_client->connectLink();
    // A GRBL controller answers within its own connect timeout, after its identification ($I, $$, $#).
    const bool grbl = m_ownProxy->backend() != m_benchPilot;
    const bool finished = spinUntil(
        [this] {
            const auto s = m_client->state();
            return s == dev::LinkState::Ready || s == dev::LinkState::Disconnected || s == dev::LinkState::Lost;
        },
        grbl ? kGrblConnectTimeoutMs : kConnectTimeoutMs);
    disconnect(watch);
    if (finished && m_client->state() == dev::LinkState::Ready)
        return true;
    report(QCoreApplication::translate("app::cli", "cannot connect to %1: %2")
               .arg(m_client->linkDescription(),
                    linkError.isEmpty() ? QCoreApplication::translate("app::cli", "no answer within %1 s").arg(kConnectTimeoutMs / 1000)
                                        : linkError));
    return false;
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
            report(QCoreApplication::translate("app::cli", "axis '%1' does not exist on the %2 (axes: %3)").arg(c).arg(ui::words::term(dev::instrumentTerm(id.kind))).arg([&] {
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

bool CliSession::parseTargets(const QStringList& words, QVector<QPair<int, double>>* targets)
{
    const auto& id = m_client->identity();
    targets->clear();
    for (const QString& a : words) {
        if (a.indexOf(QLatin1Char('=')) != 1) {
            report(QCoreApplication::translate("app::cli", "expected AXIS=VALUE, got '%1'").arg(a));
            return false;
        }
        const int axis = id.axisIndex(a[0]);
        if (axis < 0) {
            report(QCoreApplication::translate("app::cli", "axis '%1' does not exist on the %2").arg(a[0]).arg(ui::words::term(dev::instrumentTerm(id.kind))));
            return false;
        }
        bool ok = false;
        const double v = a.mid(2).toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            report(QCoreApplication::translate("app::cli", "'%1' is not a number for axis %2").arg(a.mid(2)).arg(a[0]));
            return false;
        }
        targets->push_back({axis, v});
    }
    return true;
}

int CliSession::request(const std::function<void(dev::Instrument::Callback)>& send, const QString& what)
{
    return awaitAnswer(sendRequest(send), what);
}

std::shared_ptr<CliSession::PendingRequest> CliSession::sendRequest(const std::function<void(dev::Instrument::Callback)>& send)
{
    // Shared with the callback: an answer that comes after the wait gave up has somewhere to go.
    auto pending = std::make_shared<PendingRequest>();
    send([pending](const std::optional<dev::RequestError>& e) {
        pending->error = e;
        pending->done = true;
    });
    return pending;
}

int CliSession::awaitAnswer(const std::shared_ptr<PendingRequest>& pending, const QString& what)
{
    spinUntil([&] { return pending->done; }, 10000);
    if (!pending->done) {
        report(QCoreApplication::translate("app::cli", "%1: no answer").arg(what));
        return LinkTrouble;
    }
    if (const auto& error = pending->error) {
        if (error->kind == dev::RequestError::Kind::Device)
            m_lastRefusal = error;
        report(ui::words::text(error->message));
        return error->kind == dev::RequestError::Kind::Device || error->kind == dev::RequestError::Kind::Invalid ? Refused : LinkTrouble;
    }
    return Ok;
}

bool CliSession::waitUntilHomed(quint8 mask)
{
    int fresh = 0;
    auto c = connect(m_client, &dev::Instrument::statusChanged, this, [&fresh] { ++fresh; });
    const bool homed = spinUntil(
        [&] {
            if (m_client->state() != dev::LinkState::Ready)
                return true;
            if (fresh < 2)
                return false;
            const auto& axes = m_client->status().axes;
            for (int i = 0; i < axes.size(); ++i)
                if ((mask & (1u << i)) && (!axes[i].homed || axes[i].moving))
                    return false;
            return !m_client->status().anyMoving();
        },
        static_cast<int>(m_opt.timeoutS * 1000));
    disconnect(c);
    return homed && m_client->state() == dev::LinkState::Ready;
}

int CliSession::waitUntilStill(const QString& what, bool printStatusAfter)
{
    // Asked to stop (the API's call.cancel or the GUI's Abort): the machine decelerates
    // and the wait ends as the motion does.
    const auto abortHook = m_inv.host().onAbort([this] { m_client->stop(); });
    // Two fresh status polls after the request was accepted, so "not moving" is news, not history.
    int fresh = 0;
    auto c = connect(m_client, &dev::Instrument::statusChanged, this, [&fresh] { ++fresh; });
    QString why;  // the client's own words for a lost link: silence, a vanished port, …
    auto w = connect(m_client, &dev::Instrument::linkError, this, [&why](const motion::msg::Message& m) {
        if (why.isEmpty())
            why = ui::words::text(m);
    });
    const bool still = spinUntil(
        [&] {
            return m_client->state() != dev::LinkState::Ready || (fresh >= 2 && !m_client->status().anyMoving());
        },
        static_cast<int>(m_opt.timeoutS * 1000));
    disconnect(c);
    disconnect(w);
    if (m_client->state() != dev::LinkState::Ready) {
        report(why.isEmpty() ? QCoreApplication::translate("app::cli", "%1: link lost while waiting").arg(what)
                             : QCoreApplication::translate("app::cli", "%1: link lost while waiting: %2").arg(what, why));
        return LinkTrouble;
    }
    if (!still) {
        m_client->stop();
        spinUntil([] { return false; }, 200);
        report(QCoreApplication::translate("app::cli", "%1: still moving after %2 s; sent stop").arg(what).arg(m_opt.timeoutS));
        return Refused;
    }
    if (!m_motionErrors.isEmpty()) {
        report(QStringLiteral("%1: %2").arg(what, m_motionErrors.join(QStringLiteral("; "))));
        if (printStatusAfter)
            printStatus();
        return Refused;
    }
    if (printStatusAfter)
        printStatus();
    return Ok;
}

QJsonObject CliSession::statusJson() const
{
    const auto& id = m_client->identity();
    const auto& st = m_client->status();
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
    return QJsonObject{{QStringLiteral("instrument"), id.kindName()},
                       {QStringLiteral("estop"), st.estop},
                       {QStringLiteral("fault"), st.fault},
                       {QStringLiteral("axes"), axes}};
}

void CliSession::printStatus()
{
    const auto& id = m_client->identity();
    const auto& st = m_client->status();
    if (m_opt.json) {
        m_inv.printJson(statusJson());
        return;
    }
    {
        QTextStream& out = m_inv.out();
        out << QStringLiteral("%1%2\n").arg(ui::words::term(dev::instrumentTerm(id.kind)), st.estop ? QStringLiteral("  [%1]").arg(QCoreApplication::translate("app::cli", "E-STOP")) : QString());
        if (st.positionLost)
            out << "  " << QCoreApplication::translate("app::cli", "[ALARM] the controller does not trust its position: home, or `unlock` on your word")
                << "\n";
        for (int i = 0; i < id.axes.size() && i < st.axes.size(); ++i) {
            const auto& a = st.axes[i];
            // English stays exactly as it was (people's scripts read it); --lang words it.
            auto t = [](const char* s) { return QCoreApplication::translate("app::cli", s); };
            out << QStringLiteral("  %1  %2 %3  %4 %5 %6  %7%8%9%10\n")
                         .arg(id.axes[i].letter)
                         .arg(t(QT_TRANSLATE_NOOP("app::cli", "cmd")))
                         .arg(num(a.commanded), 10)
                         .arg(t(QT_TRANSLATE_NOOP("app::cli", "meas")))
                         .arg(num(a.measured), 10)
                         .arg(id.axes[i].unitName(), -2)
                         .arg(a.homed ? t(QT_TRANSLATE_NOOP("app::cli", "homed")) : t(QT_TRANSLATE_NOOP("app::cli", "NOT HOMED")))
                         .arg(a.moving ? QLatin1Char(' ') + t(QT_TRANSLATE_NOOP("app::cli", "moving")) : QString())
                         .arg(a.homeSwitch ? QLatin1Char(' ') + t(QT_TRANSLATE_NOOP("app::cli", "home-switch")) : QString())
                         .arg(a.limitSwitch ? QLatin1Char(' ') + t(QT_TRANSLATE_NOOP("app::cli", "limit-switch")) : QString());
        }
        out.flush();
    }
}

} // namespace app::cli
