#pragma once
// Where a tuning job runs its experiments: an instrument's axis (the device
// runs them and keeps a capture) or a model plant (run in-process). The runner
// sees only this interface.
#include "motion/control/experiment.h"
#include "motion/control/tuning/oscillation.h"

#include <QObject>
#include <QString>

#include <functional>

namespace dev {

struct RunOutcome {
    bool ok = false;                   ///< a record came back (whatever ended the run)
    motion::msg::Message error;                ///< why not (tuning.target.*, request.*)
    bool linkLost = false;             ///< the link went away: resumable once it is back
    motion::control::Record record;
};

class TuningTarget : public QObject {
    Q_OBJECT
public:
    using Done = std::function<void(const RunOutcome&)>;
    explicit TuningTarget(QObject* parent = nullptr) : QObject(parent) {}

    virtual QString describe() const = 0;          ///< "Stage X", "fopdt:K=2,tau=0.5,L=0.1"
    virtual QString unit() const = 0;              ///< of positions: "mm", or "" for a model
    virtual double controlPeriodS() const = 0;
    virtual motion::control::InputModel inputModel() const = 0;
    virtual double noiseFloor() const = 0;         ///< smallest meaningful change of the output (a grating count)
    virtual bool ready() const = 0;                ///< can run now
    /// Why the Z-N methods cannot work on this target at all (a model plant whose
    /// phase never reaches −180°); empty when they can.
    virtual motion::msg::Message cannotTune() const { return {}; }
    /// A step test; a model starts it from rest, a device from where the axis stands.
    /// `trial`: a P-only trial of the ultimate-gain search, which a target may end
    /// as soon as it has shown enough cycles (`swing`: its noise floor for extrema).
    virtual void runStep(const motion::control::StepSpec& spec, bool trial, double swing, Done done) = 0;
    /// A relay or forced run; `continueRun` keeps a model plant where the last run left it.
    virtual void runRelay(const motion::control::RelaySpec& spec, bool continueRun, Done done) = 0;
    /// Ends the run in progress at once; its Done still comes, with what was captured.
    virtual void abort() = 0;

signals:
    /// Progress inside one run (a device's capture being read), 0–1.
    void runProgress(double fraction, const motion::msg::Message& what);
    /// A device test started / ended on the device (live telemetry is worth having
    /// only in between; after it the link is better left to reading the capture).
    void testRunning(bool running);
};

} // namespace dev
