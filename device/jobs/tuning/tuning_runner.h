#pragma once
// The tuning job: the Ziegler–Nichols assistant (ultimate-gain search or relay
// autotune, then the rules table and an automatic verification step test) and
// plain step tests, on any TuningTarget. One run at a time; every run can be
// aborted; a lost link interrupts the job (the device holds the axis under its
// gains by itself) and resume() runs the interrupted experiment again once the
// link is back. Trial gains only ever travel inside a test: the operator's
// gains change only when a person applies a row of the rules table.
#include "device/jobs/tuning/tuning_target.h"
#include "motion/control/tuning/model_tuning.h"
#include "motion/control/tuning/tuning_result.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace dev {

class TuningRunner : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Running, Interrupted, Done, Failed, Aborted };

    struct ZnOptions {
        motion::control::TuningMethod method = motion::control::TuningMethod::UltimateGain;
        motion::control::Envelope envelope{0.05, 0.05, 2};  ///< the operator's limits (target units, s)
        double trialShare = 0.6;     ///< trials run inside this share of the envelope
        double step = 0.01;          ///< ultimate gain: each trial's setpoint step
        double trialS = 0.3;         ///< ultimate gain on a device: each trial's length
        double startKp = 0.1;
        double kpMax = 100;
        double relayAmplitude = 0.005;  ///< d
        double hysteresis = 0.001;      ///< ε
        int relayCycles = 20;
        bool refine = true;
        std::string verifyRule = "zn-pid";  ///< rule whose gains the verification step test tries ("" none)
        double verifyStep = 0.01;
        double settleBand = 0.001;   ///< verification: the device's settle band
    };

    explicit TuningRunner(QObject* parent = nullptr);

    /// Starts the assistant; false (with a message) if it cannot start.
    bool startZn(TuningTarget* target, const ZnOptions& options);
    /// A single step test with the gains in `spec` (trial gains: the operator's stay).
    bool startStepTest(TuningTarget* target, const motion::control::StepSpec& spec, const motion::msg::Message& label);
    void abort();
    /// After Interrupted: runs the interrupted experiment again. False if it cannot yet.
    bool resume();

    State state() const { return m_state; }
    bool busy() const { return m_state == State::Running; }
    /// The last assistant's findings (valid once ultimateFound was emitted).
    const motion::control::TuningResult& result() const { return m_result; }
    TuningTarget* target() const { return m_target; }

    /// The verification test's gains for a rule, in the target's discrete form.
    static motion::control::DiscreteGains ruleGains(const std::string& ruleId, double ku, double tuS, double periodS);
    /// How a step on `target` is judged: its grating count, and seed 002's ±5 µm on a stage (mm).
    static motion::control::StepJudging judging(const TuningTarget& target);

signals:
    void stateChanged(dev::TuningRunner::State state);
    /// fraction 0–1 of the job (an estimate while the search runs), and what it does now with an ETA.
    void progress(double fraction, const motion::msg::Message& text);
    /// Every experiment's record: kind 0 trial, 1 relay, 2 forced run, 3 step test / verification.
    void recordArrived(const motion::control::Record& record, const motion::msg::Message& label, int kind);
    void ultimateFound(double ku, double tuS);
    /// A step test or the verification, judged by motion::control::judgeStep (the same rules for both).
    void stepTestDone(const motion::control::Record& record, const motion::control::StepVerdict& verdict, const motion::msg::Message& label);
    /// The job ended: ok, and a message for the operator (tuning.run.*; labels are tuning.label.*).
    void finished(bool ok, const motion::msg::Message& message);
    /// Something the operator should read now (link lost, E-stop, …).
    void message(const motion::msg::Message& text);

private:
    void setState(State s);
    void next();
    void runTrial(double kp);
    void runRelay(const motion::control::RelaySpec& spec);
    void runVerification();
    void onRun(const RunOutcome& out, int kind, const motion::msg::Message& label);
    bool endedBadly(const motion::control::Record& r, const motion::msg::Message& label);
    void concludeSearch();
    void fail(const motion::msg::Message& why);
    void reportProgress(const motion::msg::Message& what);
    int remainingRunsEstimate() const;

    QPointer<TuningTarget> m_target;
    State m_state = State::Idle;
    ZnOptions m_options;
    std::optional<motion::control::UltimateGainSearch> m_search;
    std::optional<motion::control::RelayAutotune> m_relay;
    bool m_stepOnly = false;
    bool m_verifying = false;
    bool m_abortRequested = false;
    double m_sign = 1;
    double m_currentKp = 0;
    double m_swing = 0;
    std::function<void()> m_pending;   ///< issues the current experiment (again, on resume)
    motion::control::TuningResult m_result;
    int m_runsDone = 0;
    double m_runSeconds = 0;           ///< wall time of runs so far, for the ETA
    QElapsedTimer m_runClock;
};

/// The state's term for people ("tuning.state.running"), worded by ui::words::term.
const char* stateTerm(TuningRunner::State s);

} // namespace dev

Q_DECLARE_METATYPE(dev::TuningRunner::State)
