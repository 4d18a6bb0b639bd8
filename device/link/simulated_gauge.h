#pragma once
// A simulated gauge in-process: dev::sim::SimGauge on the device end of a loopback pair,
// reading one axis' work point of an in-process simulator. What `--sim stage` gives
// an accuracy run in place of `benchpilot-sim --gauge PATH` (a pty of its own).
#include "device/link/loopback.h"
#include "device/link/simulated_link.h"
#include "device/sim/sim_gauge.h"

namespace dev {

class SimulatedGauge : public QObject {
    Q_OBJECT
public:
    /// `machine` must outlive this. `axis` is the index of the axis the gauge reads.
    SimulatedGauge(dev::sim::SimMachine& machine, int axis, const dev::sim::GaugeConfig& config = {}, QObject* parent = nullptr);

    Transport* hostEnd() { return m_pair->end(LoopbackPair::A); }
    LoopbackPair& pair() { return *m_pair; }
    dev::sim::SimGauge& gauge() { return *m_gauge; }
    int axis() const { return m_axis; }

private:
    LoopbackPair* m_pair;
    dev::sim::SimGauge* m_gauge;
    SimulatorHost* m_host;
    int m_axis;
};

} // namespace dev
