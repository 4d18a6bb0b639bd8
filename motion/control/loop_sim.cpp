#include "motion/control/loop_sim.h"

#include <cmath>

namespace motion::control {

Record runExperiment(PlantSim& plant, Experiment x, const EarlyStop& earlyStop, long maxPeriods)
{
    Record r;
    r.periodS = plant.periodS();
    r.startPosition = x.startPosition();
    r.startOutput = x.startOutput();
    for (long k = 0; k < maxPeriods && x.running(); ++k) {
        const double y = plant.output();
        const double u = x.control(y);
        r.append(x.setpoint(), y, u);  // a trip keeps the sample that crossed the envelope
        if (!x.running())
            break;
        plant.step(u);
        if (earlyStop && x.running() && earlyStop(r))
            x.abort(EndReason::Completed);
    }
    if (x.running())
        x.abort(EndReason::Duration);
    r.reason = x.reason();
    r.tripValue = x.tripValue();
    r.tripLimit = x.tripLimit();
    return r;
}

Record simulatePid(const PlantSpec& spec, const DiscreteGains& gains, double step, double durationS)
{
    PlantSim plant(spec);
    IncrementalPid pid(gains);
    Record r;
    r.periodS = spec.periodS;
    const long n = std::lround(durationS / spec.periodS);
    r.setpoint.reserve(static_cast<std::size_t>(n));
    r.measured.reserve(static_cast<std::size_t>(n));
    r.output.reserve(static_cast<std::size_t>(n));
    for (long k = 0; k < n; ++k) {
        const double y = plant.output();
        pid.step(step - y);
        r.append(step, y, pid.output());
        plant.step(pid.output());
    }
    r.reason = EndReason::Completed;
    return r;
}

} // namespace motion::control
