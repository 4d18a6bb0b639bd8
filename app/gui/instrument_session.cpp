#include "instrument_session.h"

#include "device/link/serial_transport.h"
#include "device/link/simulated_link.h"

namespace app {

InstrumentSession::InstrumentSession(proto::DeviceKind kind, const QString& name, QObject* parent)
    : QObject(parent), m_kind(kind), m_name(name), m_client(new dev::InstrumentClient(this))
{
}

InstrumentSession::~InstrumentSession() { m_client->setTransport(nullptr); }

void InstrumentSession::disconnectLink()
{
    m_client->disconnectLink();
    m_client->setTransport(nullptr);
    if (m_link)
        m_link->deleteLater();
    m_link = nullptr;
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
    m_client->setTransport(transport);
    m_client->connectLink();
}

} // namespace app
