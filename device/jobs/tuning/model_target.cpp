#include "device/jobs/tuning/model_target.h"

#include "motion/control/tuning/model_tuning.h"

#include <QPointer>
#include <QTimer>

namespace dev {

using namespace motion::control;

ModelTarget::ModelTarget(const PlantSpec& plant, QObject* parent) : TuningTarget(parent), m_spec(plant) {}

QString ModelTarget::describe() const { return QString::fromStdString(m_spec.text()); }

motion::msg::Message ModelTarget::cannotTune() const
{
    const motion::msg::Message why = whyNoUltimateGain(m_spec);
    return why.empty() ? motion::msg::Message() : motion::msg::make("tuning.model.no_ultimate_gain", {motion::msg::verbatim("plant", m_spec.text()), motion::msg::nested("cause", why)});
}

void ModelTarget::runStep(const StepSpec& spec, bool trial, double swing, Done done)
{
    deliver(Experiment::stepTest(spec, 0, 0, m_spec.periodS), true, trial ? trialEarlyStop(swing) : EarlyStop{}, std::move(done));
}

void ModelTarget::runRelay(const RelaySpec& spec, bool continueRun, Done done)
{
    deliver(Experiment::relay(spec, 0, 0, m_spec.periodS), !continueRun, {}, std::move(done));
}

void ModelTarget::deliver(Experiment x, bool fromRest, EarlyStop stop, Done done)
{
    m_aborted = false;
    QPointer<ModelTarget> self(this);
    // Runs on the next turn: a model run takes milliseconds, and the caller's
    // bookkeeping (progress, plots) sees it like a device's asynchronous run.
    QTimer::singleShot(0, this, [self, x, fromRest, stop, done] {
        if (!self)
            return;
        RunOutcome out;
        if (self->m_aborted) {
            out.error = motion::msg::make("tuning.target.aborted");
            return done(out);
        }
        if (fromRest || !self->m_sim)
            self->m_sim = std::make_unique<PlantSim>(self->m_spec);
        out.record = runExperiment(*self->m_sim, x, stop);
        out.ok = true;
        done(out);
    });
}

} // namespace dev
