#include "instrument_session.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/serial_transport.h"
#include "device/link/simulated_link.h"

namespace app {

InstrumentSession::InstrumentSession(proto::DeviceKind kind, const QString& name, QObject* parent)
    : QObject(parent), m_kind(kind), m_name(name), m_proxy(new dev::InstrumentProxy(this))
{
}

InstrumentSession::~InstrumentSession()
{
    if (m_benchPilot)
        m_benchPilot->setTransport(nullptr);
}

void InstrumentSession::disconnectLink()
{
    m_proxy->disconnectLink();
    if (m_benchPilot)
        m_benchPilot->setTransport(nullptr);
    if (m_link)
        m_link->deleteLater();
    m_link = nullptr;
}

dev::BenchPilotClient* InstrumentSession::benchPilotOn(dev::Transport* transport)
{
    if (!m_benchPilot) {
        m_benchPilot = new dev::BenchPilotClient;
        m_proxy->setBackend(m_benchPilot);
    }
    m_benchPilot->setTransport(transport);
    return m_benchPilot;
}

void InstrumentSession::connectTo(const ui::ConnectionChoice& choice)
{
    disconnectLink();
    m_choice = choice;
    dev::Transport* transport = nullptr;
    if (choice.simulator) {
        auto* sim = new dev::SimulatedLink(m_kind, choice.baud, this);
        transport = sim->hostEnd();
        m_link = sim;
    } else {
        auto* serial = new dev::SerialTransport(choice.port, choice.baud, this);
        transport = serial;
        m_link = serial;
    }
    benchPilotOn(transport)->connectLink();
}

} // namespace app
