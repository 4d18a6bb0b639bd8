#pragma once
// What a tuning session found, as people keep it (device/files/tuning_file.h
// writes it as JSON): the ultimate point, how it was measured, the rules table
// it gives, and the verification step test. Plain data.
#include "motion/control/experiment.h"
#include "motion/control/gains.h"
#include "motion/control/tuning/step_metrics.h"
#include "motion/control/tuning/step_verdict.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::control {

struct TuningResult {
    std::string target;          ///< "Stage X", or a plant spec ("fopdt:K=2,tau=0.5,L=0.1")
    std::string method;          ///< "ultimate-gain" or "relay"
    std::string unit;            ///< of positions and outputs ("mm"); "" for a model plant
    double controlPeriodS = 0;   ///< T of the loop the gains are for
    double ku = 0;
    double tuS = 0;
    std::optional<double> kuDescribing;  ///< relay: the classic describing-function estimate
    std::optional<double> tuRelayS;      ///< relay: the relay's own period
    bool refined = false;        ///< relay: Ku/Tu from the measured phase crossover
    int runs = 0;
    Envelope envelope;           ///< the operator's
    double step = 0;             ///< ultimate gain: each trial's step
    double relayAmplitude = 0;   ///< relay: d
    double hysteresis = 0;       ///< relay: ε
    struct Trial {
        double kp = 0;
        double ratio = 0;        ///< cycle-over-cycle amplitude ratio (0: no oscillation)
        double periodS = 0;
        std::string outcome;     ///< "decays", "sustained", "grows", "no oscillation", "hit the envelope"
    };
    std::vector<Trial> trials;   ///< ultimate gain
    struct Point {
        double omegaRadS = 0;
        double gain = 0;
        double phaseDeg = 0;
    };
    std::vector<Point> points;   ///< relay: every measured G(jω)
    struct Verification {
        std::string rule;        ///< rule id whose gains were tried
        DiscreteGains gains;
        StepMetrics metrics;     ///< judged as a step test is (judgeStep): its outcome says whether it came to rest
        LimitCycle limitCycle;   ///< the oscillation left at rest, if any
        double settledInside5umS = -1;  ///< when it entered ±5 µm (seed 002's band) for good; −1 never
        std::string outcome;     ///< end reason
    };
    std::optional<Verification> verification;
    std::string createdUtc;      ///< ISO 8601
    std::string note;
};

} // namespace motion::control
