#include "soak_rig.h"

#include <QEventLoop>
#include <QPointer>

#include <memory>

namespace soak {
namespace {
/// Messages kept word for word per instrument; the rest are only counted.
constexpr std::size_t kKeptMessages = 8;
} // namespace

Station::Station(dev::proto::DeviceKind kind, double timeScale)
    : link(kind, 0), name(kind == dev::proto::DeviceKind::Stage ? "stage" : "analyzer")
{
    // Unpaced: the firmware budgets telemetry per virtual second of its link, so a paced
    // UART under a sped-up clock would carry K times its rate (SimulatorHost::setTimeScale).
    link.host().setTimeScale(timeScale);
    connect(&client, &dev::Instrument::linkError, this, [this](const motion::msg::Message& m) {
        ++trouble.linkErrorSignals;
        note("link error: " + motion::msg::debugString(m));
    });
    connect(&client, &dev::Instrument::requestFailed, this, [this](const dev::RequestError& e) {
        ++trouble.refusals;
        note("request failed: " + motion::msg::debugString(e.message));
    });
    connect(&client, &dev::Instrument::eventReceived, this, [this](const dev::DeviceEvent& e) {
        // Counted, not quoted: a fault only in sum (the simulator scales its trip with its clock).
        if (e.kind == dev::proto::EventKind::JogExpired)
            ++trouble.jogExpired;
    });
    connect(&client, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (s == dev::LinkState::Lost || s == dev::LinkState::Disconnected) {
            ++trouble.linkDrops;
            note(std::string("link state ") + dev::linkStateKey(s));
        }
    });
    client.setTransport(link.hostEnd());
}

Station::~Station() { client.setTransport(nullptr); }

void Station::note(const std::string& what)
{
    if (trouble.firstMessages.size() < kKeptMessages)
        trouble.firstMessages.push_back(std::string(name) + ": " + what);
}

bool Station::connectAndHome(int timeoutMs, std::string* why)
{
    QEventLoop loop;
    QTimer limit;
    limit.setSingleShot(true);
    QObject::connect(&limit, &QTimer::timeout, &loop, &QEventLoop::quit);
    limit.start(timeoutMs);
    auto conn = connect(&client, &dev::Instrument::stateChanged, &loop, [&](dev::LinkState s) {
        if (s == dev::LinkState::Ready || s == dev::LinkState::Disconnected || s == dev::LinkState::Lost)
            loop.quit();
    });
    client.connectLink();
    if (client.state() != dev::LinkState::Ready)
        loop.exec();
    disconnect(conn);
    if (client.state() != dev::LinkState::Ready) {
        *why = std::string(name) + " did not connect";
        return false;
    }
    // Callbacks may come after this returns (a timeout): they share their state, not the stack.
    struct Homing {
        bool answered = false, refused = false, homed = false;
        std::string why;
        QPointer<QEventLoop> loop;
    };
    auto h = std::make_shared<Homing>();
    h->loop = &loop;
    client.home(0, [h](const std::optional<dev::RequestError>& e) {
        h->answered = true;
        h->refused = e.has_value();
        if (e)
            h->why = "refused to home: " + motion::msg::debugString(e->message);
    });
    // Homed: every axis says so and none moves, on a reading asked for after the reply.
    QTimer poll;
    poll.setInterval(5);
    QObject::connect(&poll, &QTimer::timeout, &loop, [this, h] {
        if (h->refused || client.state() != dev::LinkState::Ready) {
            h->loop->quit();
            return;
        }
        if (!h->answered)
            return;
        client.readStatus([h](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& st) {
            if (e || st.axes.isEmpty() || h->homed)
                return;
            for (const auto& a : st.axes)
                if (!a.homed || a.moving || a.homing)
                    return;
            h->homed = true;
            if (h->loop)
                h->loop->quit();
        });
    });
    poll.start();
    loop.exec();
    if (!h->homed)
        *why = std::string(name) + " " + (h->why.empty() ? std::string("did not finish homing") : h->why);
    return h->homed;
}

void whenStill(dev::Instrument* client, QObject* context, std::function<void(bool)> then, int triesLeft)
{
    QPointer<QObject> guard(context);
    client->readStatus([client, guard, then, triesLeft](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& st) {
        if (!guard)
            return;
        if (e || triesLeft <= 0) {
            then(false);
            return;
        }
        if (!st.anyMoving()) {
            then(true);
            return;
        }
        QTimer::singleShot(2, guard, [client, guard, then, triesLeft] { whenStill(client, guard, then, triesLeft - 1); });
    });
}

PlotConsumer::PlotConsumer(dev::tele::TelemetryHub& hub, int rateHz) : m_hub(hub), m_rateHz(rateHz), m_columns(kColumns)
{
    m_frame.setSingleShot(true);
    m_frame.setInterval(kFrameMs);
    connect(&m_frame, &QTimer::timeout, this, &PlotConsumer::redraw);
    // Never a redraw per batch: at most one frame per kFrameMs (PlotsScreen::scheduleRedraw).
    connect(&m_hub, &dev::tele::TelemetryHub::dataArrived, this, [this] {
        if (!m_frame.isActive())
            m_frame.start();
    });
}

void PlotConsumer::want()
{
    m_keys.clear();
    for (int instrument : m_hub.instruments())
        m_keys += m_hub.availableChannels(instrument);
    m_hub.setWanted(QStringLiteral("soak-plots"), m_keys, m_rateHz);
}

std::size_t PlotConsumer::storeBytes() const
{
    std::size_t bytes = 0;
    for (const auto& key : m_keys)
        if (const dev::tele::ChannelStore* s = m_hub.store(key))
            bytes += s->memoryBytes();
    return bytes;
}

void PlotConsumer::redraw()
{
    ++m_frames;
    if (m_keys.isEmpty())
        return;
    for (int k = 0; k < kShownChannels; ++k) {
        const dev::tele::ChannelKey& key = m_keys[(m_firstShown + k) % m_keys.size()];
        const dev::tele::ChannelStore* s = m_hub.store(key);
        if (!s || s->empty()) {
            ++m_emptyReads;
            continue;
        }
        const double t1 = s->lastTime();
        s->decimate(t1 - m_hub.windowS(), t1, kColumns, m_columns.data());
    }
    m_firstShown = (m_firstShown + kShownChannels) % m_keys.size();
}

} // namespace soak
