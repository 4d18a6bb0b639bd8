#include "device/link/simulated_gauge.h"

namespace dev {

SimulatedGauge::SimulatedGauge(dev::sim::SimMachine& machine, int axis, const dev::sim::GaugeConfig& config, QObject* parent)
    : QObject(parent), m_pair(new LoopbackPair(0, this)), m_axis(axis)
{
    auto gauge = std::make_unique<dev::sim::SimGauge>([&machine, axis] { return machine.workPointLogical(axis); }, config);
    m_gauge = gauge.get();
    m_host = new SimulatorHost(std::move(gauge), m_pair->end(LoopbackPair::B), this);
    // A gauge answers when asked and has no clock of its own to run.
    m_host->setManualClock(true);
    m_host->start();
}

} // namespace dev
