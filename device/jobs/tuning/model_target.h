#pragma once
// A model plant as a tuning target: experiments run in-process on PlantSim,
// each delivered on the next event-loop turn so a screen stays responsive.
#include "device/jobs/tuning/tuning_target.h"
#include "motion/control/loop_sim.h"
#include "motion/control/plant.h"

#include <memory>

namespace dev {

class ModelTarget : public TuningTarget {
    Q_OBJECT
public:
    explicit ModelTarget(const motion::control::PlantSpec& plant, QObject* parent = nullptr);
    const motion::control::PlantSpec& plant() const { return m_spec; }

    QString describe() const override;
    QString unit() const override { return {}; }
    double controlPeriodS() const override { return m_spec.periodS; }
    motion::control::InputModel inputModel() const override { return motion::control::InputModel::Held; }
    double noiseFloor() const override { return 0; }
    bool ready() const override { return true; }
    motion::msg::Message cannotTune() const override;
    void runStep(const motion::control::StepSpec& spec, bool trial, double swing, Done done) override;
    void runRelay(const motion::control::RelaySpec& spec, bool continueRun, Done done) override;
    void abort() override { m_aborted = true; }

private:
    void deliver(motion::control::Experiment x, bool fromRest, motion::control::EarlyStop stop, Done done);

    motion::control::PlantSpec m_spec;
    std::unique_ptr<motion::control::PlantSim> m_sim;
    bool m_aborted = false;
};

} // namespace dev
