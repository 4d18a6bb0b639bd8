#include "device/link/simulated_link.h"

namespace dev {
namespace {
// A frozen event loop is caught up in one go, so a watchdog still trips at the
// right virtual time; past this the simulator gives up the lost time instead.
constexpr double kMaxCatchUpS = 5.0;
}

SimulatorHost::SimulatorHost(const dev::sim::MachineConfig& config, qint32 linkBaud, Transport* deviceEnd, QObject* parent)
    : SimulatorHost(std::make_unique<dev::sim::Firmware>(config, static_cast<std::uint32_t>(linkBaud > 0 ? linkBaud : 921600)),
                    deviceEnd, parent)
{
    m_firmware = static_cast<dev::sim::Firmware*>(m_device.get());
}

SimulatorHost::SimulatorHost(std::unique_ptr<dev::sim::SerialDevice> device, Transport* deviceEnd, QObject* parent)
    : QObject(parent), m_device(std::move(device)), m_end(deviceEnd)
{
    connect(m_end, &Transport::bytesReceived, this, [this](const QByteArray& b) {
        pump();  // bring the clock up to now before acting, so replies carry the right time
        m_device->receive(reinterpret_cast<const std::uint8_t*>(b.constData()), static_cast<std::size_t>(b.size()));
        flush();
    });
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(1);
    connect(&m_timer, &QTimer::timeout, this, &SimulatorHost::pump);
    // A device does not go away when its cable is pulled: it keeps running and
    // answers again once plugged back in. Without this the device end stayed
    // closed after LoopbackPair::replug() and a reconnecting host met silence.
    m_reopen.setSingleShot(true);
    m_reopen.setInterval(50);
    connect(&m_reopen, &QTimer::timeout, this, [this] {
        if (!m_end->isOpen())
            m_end->open();
    });
    connect(m_end, &Transport::lost, this, [this] {
        m_reopening = true;
        m_reopen.start();
    });
    connect(m_end, &Transport::failed, this, [this] {
        if (m_reopening)
            m_reopen.start();  // still unplugged: try again shortly
    });
    connect(m_end, &Transport::opened, this, [this] { m_reopening = false; });
    connect(m_end, &Transport::peerOpened, this, [this] {
        pump();  // the restart happens at the present time
        m_device->portOpened();
        flush();
    });
}

void SimulatorHost::start()
{
    m_end->open();
    m_wall.start();
    m_lastNs = 0;
    if (!m_manual)
        m_timer.start();
}

void SimulatorHost::setManualClock(bool manual)
{
    m_manual = manual;
    if (manual)
        m_timer.stop();
    else if (m_wall.isValid()) {
        m_lastNs = m_wall.nsecsElapsed();
        m_timer.start();
    }
}

void SimulatorHost::advance(double dtS)
{
    m_device->advance(dtS);
    flush();
}

void SimulatorHost::pump()
{
    if (m_manual || !m_wall.isValid())
        return;
    const qint64 now = m_wall.nsecsElapsed();
    double dt = double(now - m_lastNs) * 1e-9 * m_timeScale;
    m_lastNs = now;
    if (dt > kMaxCatchUpS)
        dt = kMaxCatchUpS;
    if (dt > 0)
        m_device->advance(dt);
    flush();
}

void SimulatorHost::flush()
{
    m_out.clear();
    m_device->drainOutput(m_out);
    if (!m_out.empty())
        m_end->write(QByteArray(reinterpret_cast<const char*>(m_out.data()), static_cast<qsizetype>(m_out.size())));
}

SimulatedLink::SimulatedLink(dev::proto::DeviceKind kind, qint32 baud, QObject* parent)
    : SimulatedLink(kind == dev::proto::DeviceKind::Stage ? dev::sim::stageConfig() : dev::sim::analyzerConfig(), baud, parent)
{
}

SimulatedLink::SimulatedLink(const dev::sim::MachineConfig& config, qint32 baud, QObject* parent)
    : QObject(parent), m_pair(new LoopbackPair(baud, this))
{
    m_host = new SimulatorHost(config, baud, m_pair->end(LoopbackPair::B), this);
    connect(m_host, &SimulatorHost::timeScaleChanged, m_pair, &LoopbackPair::setTimeScale);
    m_host->start();
}

SimulatedLink::SimulatedLink(std::unique_ptr<dev::sim::SerialDevice> device, qint32 baud, QObject* parent)
    : QObject(parent), m_pair(new LoopbackPair(baud, this))
{
    m_host = new SimulatorHost(std::move(device), m_pair->end(LoopbackPair::B), this);
    connect(m_host, &SimulatorHost::timeScaleChanged, m_pair, &LoopbackPair::setTimeScale);
    m_host->start();
}

} // namespace dev
