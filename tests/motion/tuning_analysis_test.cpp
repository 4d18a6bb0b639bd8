// Step metrics, oscillation growth and period, exact frequency points, and the
// tuners' behaviour at their edges: envelopes, plants without an ultimate gain.
#include "motion/numbers.h"
#include "motion/message_print.h"
#include "motion/control/loop_sim.h"
#include "motion/control/tuning/model_tuning.h"
#include "motion/control/tuning/oscillation.h"
#include "motion/control/tuning/step_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace motion::control;

namespace {
using motion::kPi;

Record recordOf(double periodS, int n, double y0, double sp, const std::function<double(double)>& y)
{
    Record r;
    r.periodS = periodS;
    r.startPosition = y0;
    for (int k = 0; k < n; ++k)
        r.append(sp, y(k * periodS), 0);
    return r;
}
} // namespace

TEST(TuningStepMetrics, FirstOrderResponseHasTheTextbookNumbers)
{
    const double tau = 0.1;
    const Record r = recordOf(1e-4, 20000, 0, 2, [&](double t) { return 2 * (1 - std::exp(-t / tau)); });
    const StepMetrics m = stepMetrics(r);
    EXPECT_NEAR(m.riseTimeS, tau * std::log(9.0), 2e-4);   // 10 → 90 %
    EXPECT_NEAR(m.settlingTimeS, tau * std::log(50.0), 2e-4);  // into 2 %
    EXPECT_NEAR(m.overshootPct, 0, 1e-5);  // the tail mean sits a hair under 2: no real overshoot
    EXPECT_NEAR(m.steadyStateError, 0, 1e-6);
    EXPECT_NEAR(m.iae, 2 * tau, 1e-3);      // ∫ 2·e^{−t/τ} dt
    EXPECT_NEAR(m.ise, 4 * tau / 2, 1e-3);  // ∫ 4·e^{−2t/τ} dt
}

TEST(TuningStepMetrics, UnderdampedOvershootMatchesZeta)
{
    const double zeta = 0.3, wn = 20, wd = wn * std::sqrt(1 - zeta * zeta);
    const Record r = recordOf(1e-4, 40000, 0, 1, [&](double t) {
        return 1 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    });
    const StepMetrics m = stepMetrics(r);
    EXPECT_NEAR(m.overshootPct, 100 * std::exp(-zeta * kPi / std::sqrt(1 - zeta * zeta)), 0.05);
    // Its 37 % overshoot never leaves a ±50 % band once inside: it is in for good
    // from its first crossing of 0.5; a ±1 % band takes many cycles longer.
    double firstHalf = 0;
    for (std::size_t k = 0; k < r.size() && r.measured[k] < 0.5; ++k)
        firstHalf = static_cast<double>(k + 1) * r.periodS;
    EXPECT_NEAR(settledInsideS(r, 0.5), firstHalf, 1e-12);
    EXPECT_GT(settledInsideS(r, 0.01), 0.5);
}

TEST(TuningOscillation, RatioAndPeriodOfADampedSineDenseAndSparse)
{
    for (double samplesPerCycle : {300.0, 40.0, 3.6}) {
        for (double ratio : {0.7, 1.0, 1.15}) {
            const double T = 1e-3, P = samplesPerCycle * T;
            const double sigma = std::log(ratio) / P;
            std::vector<double> y;
            for (int k = 0; k < static_cast<int>(12 * samplesPerCycle); ++k) {
                const double t = k * T;
                y.push_back(5 + std::exp(sigma * t) * std::sin(2 * kPi * t / P + 0.3));
            }
            const auto a = analyzeOscillation(y, T, 0, 1e-6);
            ASSERT_TRUE(a.oscillating) << samplesPerCycle << " " << ratio;
            EXPECT_NEAR(a.ratio, ratio, 0.01 * ratio) << samplesPerCycle << " samples a cycle";
            EXPECT_NEAR(a.periodS, P, 0.005 * P) << samplesPerCycle << " samples a cycle";
            EXPECT_EQ(a.method, samplesPerCycle < 12 ? OscillationAnalysis::Method::DampedSineFit
                                                     : OscillationAnalysis::Method::Extrema);
        }
    }
}

TEST(TuningOscillation, ARelayCycleOfAFractionalNumberOfSamplesIsStable)
{
    // What the simulated stage does under a relay: a cycle 5.5 control periods
    // long, sampled, so successive periods alternate by half a sample or more.
    const double T = 1e-3, P = 5.5 * T, d = 0.02;
    Record r;
    r.periodS = T;
    for (int k = 0; k < 200; ++k) {
        const double ph = 2 * kPi * k * T / P + 0.3;
        const double y = 0.01 * (std::sin(ph) + 0.3 * std::sin(3 * ph));
        r.append(0, y, std::cos(ph) > 0 ? d : -d);
    }
    const auto a = analyzeRelay(r, d, 1e-4, InputModel::Sampled);
    ASSERT_TRUE(a.ok) << a.problem;
    EXPECT_NEAR(a.periodS, P, 0.005 * P);
    EXPECT_EQ(a.cycles % 2, 0) << "an odd number of alternating cycles biases the period";
}

TEST(TuningOscillation, ForcedSquareWaveMeasuresTheExactFrequencyResponse)
{
    const PlantSpec p{PlantSpec::Kind::Lag, 1.3, 0.05, 0, 4, 1e-4};
    PlantSim sim(p);
    RelaySpec s;
    s.amplitude = 0.2;
    s.forcedPeriodS = 0.4;
    s.cycles = 6;
    s.envelope = {10, 10, 100};
    const Record r = runExperiment(sim, Experiment::relay(s, 0, 0, p.periodS));
    EXPECT_EQ(r.reason, EndReason::Completed);
    const FrequencyPoint fp = analyzeForced(r, 4000, 2, InputModel::Held);
    const auto want = frequencyResponse(p, fp.omegaRadS);
    EXPECT_NEAR(fp.gain() / std::abs(want), 1, 1e-4);
    EXPECT_NEAR(std::remainder(std::arg(fp.g) - std::arg(want), 2 * kPi), 0, 1e-4);
}

TEST(TuningEnvelope, TheStepTestTripsOnTheLimitItCrossesAndSaysByHowMuch)
{
    const PlantSpec p{PlantSpec::Kind::Fopdt, 1, 0.05, 0.02, 1, 1e-4};
    PlantSim sim(p);
    StepSpec s;
    s.step = 1;
    s.gains = {4, 0.002, 0};  // far above this plant's Ku ≈ 2.6: it grows
    s.runS = 5;
    s.envelope = {1.5, 3, 10};
    const Record r = runExperiment(sim, Experiment::stepTest(s, 0, 0, p.periodS));
    EXPECT_EQ(r.reason, EndReason::Excursion);
    EXPECT_NEAR(r.tripLimit, 1.5, 1e-12);
    EXPECT_GT(r.tripValue, 1.5);
    EXPECT_LT(r.tripValue, 1.5 + 0.01);  // caught within one control period
    for (double y : r.measured)
        EXPECT_LE(std::abs(y), r.tripValue + 1e-12);
}

TEST(TuningEnvelope, UltimateGainTrialsNeverLeaveTheOperatorsEnvelope)
{
    const PlantSpec p{PlantSpec::Kind::Fopdt, 2, 0.1, 0.05, 1, 1e-4};
    ModelTuningOptions o;
    o.envelope = {1.5, 1.5, 60};
    o.step = 0.5;
    const ModelTuning t = tuneModel(p, o);
    ASSERT_TRUE(t.ok) << t.error;
    bool someTripped = false;
    for (const Record& r : t.runs) {
        someTripped = someTripped || isEnvelopeTrip(r.reason);
        for (double y : r.measured)
            EXPECT_LE(std::abs(y - r.startPosition), 0.6 * 1.5 + 0.01) << "a trial left its own (60 %) envelope";
    }
    EXPECT_TRUE(someTripped) << "no trial was stopped by its envelope: the test did not test it";
}

TEST(TuningModel, PlantsWithoutAnUltimateGainAreRefusedWithTheReason)
{
    for (const char* spec : {"lag:K=1,tau=0.1,n=2", "fopdt:K=1,tau=0.1,L=0"}) {
        for (TuningMethod m : {TuningMethod::UltimateGain, TuningMethod::Relay}) {
            ModelTuningOptions o;
            o.method = m;
            const ModelTuning t = tuneModel(*parsePlant(spec), o);
            EXPECT_FALSE(t.ok);
            EXPECT_TRUE(t.runs.empty()) << "it tried anyway";
            EXPECT_EQ(t.error.id, "tuning.model.no_ultimate_gain") << t.error;
        }
    }
}

TEST(TuningModel, UltimateGainSearchGivesUpAtKpMaxOnALoopThatNeverOscillates)
{
    // Driving the planner directly with a plant the model tuner would have refused.
    const PlantSpec p{PlantSpec::Kind::Lag, 1, 0.05, 0, 2, 1e-4};
    UltimateGainOptions uo;
    uo.kpMax = 50;
    uo.swing = 1e-6;
    UltimateGainSearch search(uo);
    int trials = 0;
    while (auto kp = search.nextKp()) {
        PlantSim sim(p);
        StepSpec s;
        s.step = 1;
        s.gains = {*kp, 0, 0};
        s.runS = 20;
        s.envelope = {5, 5, 21};
        search.report(*kp, runExperiment(sim, Experiment::stepTest(s, 0, 0, p.periodS), trialEarlyStop(1e-6)));
        ASSERT_LT(++trials, 40) << "the search loops";
    }
    EXPECT_FALSE(search.result());
    EXPECT_EQ(motion::msg::debugString(search.failure()), "tuning.ultimate.decays_up_to{kp=50}") << search.failure();
}

TEST(TuningModel, RelayReportsTheClassicEstimateBesideTheRefinedOne)
{
    // A pure dead time: the relay's output is a square wave, the describing
    // function reads Ku = 4/(π·K) against the true 1/K (27 % high).
    ModelTuningOptions o;
    o.method = TuningMethod::Relay;
    o.relayAmplitude = 0.5;
    o.hysteresis = 0.001;
    const ModelTuning t = tuneModel(*parsePlant("fopdt:K=2,tau=0,L=0.05"), o);
    ASSERT_TRUE(t.ok) << t.error;
    EXPECT_NEAR(t.relay->kuDescribing, 4 / (kPi * 2), 0.01 * 4 / (kPi * 2));
    EXPECT_NEAR(t.ku, 0.5, 0.005);
    EXPECT_NEAR(t.tuS, 0.1, 0.001);
    EXPECT_TRUE(t.relay->refined);
}

// The failure this catches: a response that diverged until the envelope tripped showed
// "overshoot 0 %, settling 6 ms" read off its last samples.
TEST(TuningStepMetrics, ATrippedOrUnsettledResponseHasNoSettlingFigures)
{
    // Runs away until the envelope trips at 0.2, then the capture holds where it stopped.
    Record grows = recordOf(1e-3, 120, 0, 0.05, [](double t) { return std::min(0.2, 0.05 * std::exp(t / 0.02) - 0.05); });
    grows.reason = EndReason::Excursion;
    const StepMetrics u = stepMetrics(grows);
    EXPECT_EQ(u.outcome, StepOutcome::Unstable);
    EXPECT_TRUE(std::isnan(u.overshootPct)) << u.overshootPct;
    EXPECT_TRUE(std::isnan(u.settlingTimeS)) << u.settlingTimeS;
    EXPECT_TRUE(std::isnan(u.riseTimeS));
    EXPECT_TRUE(std::isnan(u.steadyStateError));
    EXPECT_GT(u.iae, 0);  // the integrals are still what happened
    EXPECT_FALSE(std::isnan(stepFigures(grows).settlingTimeS)) << "the raw figures are the lie this guards against";

    Record hunts = recordOf(1e-3, 1000, 0, 1, [](double t) { return 1 + 0.5 * std::sin(60 * t); });
    hunts.reason = EndReason::Completed;
    const StepMetrics h = stepMetrics(hunts);
    EXPECT_EQ(h.outcome, StepOutcome::DidNotSettle);
    EXPECT_TRUE(std::isnan(h.overshootPct));

    Record fine = recordOf(1e-4, 20000, 0, 2, [](double t) { return 2 * (1 - std::exp(-t / 0.1)); });
    fine.reason = EndReason::Settled;
    EXPECT_EQ(stepMetrics(fine).outcome, StepOutcome::Settled);
}
