#include "instrument_session.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/backends/grbl/client/grbl_client.h"
#include "device/link/serial_transport.h"
#include "device/link/simulated_link.h"

namespace app {

InstrumentSession::InstrumentSession(dev::proto::DeviceKind kind, const QString& name, QObject* parent)
    : QObject(parent), m_kind(kind), m_name(name), m_proxy(new dev::InstrumentProxy(this))
{
}

InstrumentSession::~InstrumentSession()
{
    stopProbe();
    if (m_benchPilot)
        m_benchPilot->setTransport(nullptr);
    if (m_grbl)
        m_grbl->setTransport(nullptr);
}

void InstrumentSession::disconnectLink()
{
    stopProbe();
    m_proxy->disconnectLink();
    if (m_benchPilot)
        m_benchPilot->setTransport(nullptr);
    if (m_grbl)
        m_grbl->setTransport(nullptr);
    if (m_link && m_link != m_sim)
        m_link->deleteLater();  // the simulator stays powered: only its cable is out
    m_link = nullptr;
}

void InstrumentSession::dropSimulator()
{
    if (m_sim)
        m_sim->deleteLater();
    m_sim = nullptr;
}

dev::BenchPilotClient* InstrumentSession::benchPilotOn(dev::Transport* transport)
{
    if (!m_benchPilot || m_proxy->backend() != m_benchPilot) {  // none yet, or a GRBL backend took over
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
    if (choice.simulator) {
        // The same simulator again when only the cable was out; a new one for another wire speed.
        if (!m_sim || m_simBaud != choice.baud) {
            dropSimulator();
            m_sim = new dev::SimulatedLink(m_kind, choice.baud, this);
            m_simBaud = choice.baud;
        }
        m_link = m_sim;
        benchPilotOn(m_sim->hostEnd())->connectLink();
        return;
    }
    dropSimulator();  // another instrument was chosen
    auto* serial = new dev::SerialTransport(choice.port, choice.baud, this);
    m_link = serial;
    connectPort(serial, choice);
}

} // namespace app
