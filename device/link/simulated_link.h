#pragma once
// The simulator running in-process: the reference firmware on one end of a
// loopback pair, the host's transport on the other. Virtual time follows the
// wall clock (times a scale), so everything a person sees happens in real time.
#include "device/link/loopback.h"
#include "device/protocol/messages_path.h"
#include "device/sim/firmware.h"
#include "device/sim/serial_device.h"

#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace dev {

/// Drives a simulated device (the BenchPilot firmware, or any dev::sim::SerialDevice such as the
/// GRBL personality) from the device end of any transport.
class SimulatorHost : public QObject {
    Q_OBJECT
public:
    SimulatorHost(const dev::sim::MachineConfig& config, qint32 linkBaud, Transport* deviceEnd, QObject* parent = nullptr);
    SimulatorHost(std::unique_ptr<dev::sim::SerialDevice> device, Transport* deviceEnd, QObject* parent = nullptr);

    /// The BenchPilot firmware; only for a host made with a MachineConfig.
    dev::sim::Firmware& firmware() { return *m_firmware; }
    dev::sim::SerialDevice& device() { return *m_device; }
    /// Virtual seconds per wall-clock second. The firmware budgets telemetry per
    /// virtual second of its link; over a SimulatedLink the wire runs at the same
    /// scale (LoopbackPair::setTimeScale), so a sped-up device never sends more
    /// than its wire carries and its replies do not queue behind samples.
    void setTimeScale(double scale)
    {
        m_timeScale = scale;
        // A quiet host is judged on its own clock: 1 s of wall time is `scale` s here. So
        // are its jog refreshes (every 50 ms of its time), or no jog holds above 4x.
        if (m_firmware) {
            m_firmware->setHostSilenceLimitS(dev::proto::kPathHostSilenceMs / 1000.0 * std::max(1.0, scale));
            m_firmware->machine().setJogWatchdogTripS(dev::sim::SimMachine::kJogWatchdogTripS * std::max(1.0, scale));
        }
        emit timeScaleChanged(scale);
    }
    double timeScale() const { return m_timeScale; }
    /// Stops the clock; `advance()` then moves virtual time by hand (deterministic tests).
    void setManualClock(bool manual);
    void advance(double dtS);
    void start();

signals:
    void timeScaleChanged(double scale);

private:
    void pump();
    void flush();

    std::unique_ptr<dev::sim::SerialDevice> m_device;
    dev::sim::Firmware* m_firmware = nullptr;  ///< m_device, when it is the BenchPilot firmware
    Transport* m_end;
    QTimer m_timer;
    QTimer m_reopen;          ///< after the link was lost: retries opening until the cable is back
    bool m_reopening = false;
    QElapsedTimer m_wall;
    qint64 m_lastNs = 0;
    double m_timeScale = 1.0;
    bool m_manual = false;
    std::vector<std::uint8_t> m_out;
};

/// Loopback pair + simulator host: hand `hostEnd()` to a BenchPilotClient.
class SimulatedLink : public QObject {
    Q_OBJECT
public:
    SimulatedLink(dev::proto::DeviceKind kind, qint32 baud, QObject* parent = nullptr);
    SimulatedLink(const dev::sim::MachineConfig& config, qint32 baud, QObject* parent = nullptr);
    /// Any simulated device on the device end: the GRBL personality (dev::sim::GrblFirmware).
    SimulatedLink(std::unique_ptr<dev::sim::SerialDevice> device, qint32 baud, QObject* parent = nullptr);

    Transport* hostEnd() { return m_pair->end(LoopbackPair::A); }
    LoopbackPair& pair() { return *m_pair; }
    SimulatorHost& host() { return *m_host; }
    /// The BenchPilot firmware's machine; only for a link made with a kind or a MachineConfig.
    dev::sim::SimMachine& machine() { return m_host->firmware().machine(); }

private:
    LoopbackPair* m_pair;
    SimulatorHost* m_host;
};

} // namespace dev
