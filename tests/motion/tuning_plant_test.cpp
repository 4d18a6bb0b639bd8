// Model plants: parsing with errors that name the field, the exact simulation
// against closed-form step responses, and the analytic phase crossover.
#include "motion/numbers.h"
#include "motion/message_print.h"
#include "motion/control/plant.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::control;

namespace {
using motion::kPi;

PlantSpec parseOk(const char* text)
{
    const auto p = parsePlant(text);
    EXPECT_TRUE(p) << text << ": " << p.error();
    return p ? *p : PlantSpec{};
}

std::string parseError(const char* text)
{
    const auto p = parsePlant(text);
    EXPECT_FALSE(p) << text << " was accepted";
    return motion::msg::debugString(p.error());
}
} // namespace

TEST(TuningPlant, ParsesBothKindsAndWritesThemBack)
{
    const PlantSpec f = parseOk("fopdt:K=2,tau=0.5,L=0.1");
    EXPECT_EQ(f.kind, PlantSpec::Kind::Fopdt);
    EXPECT_DOUBLE_EQ(f.gain, 2);
    EXPECT_DOUBLE_EQ(f.tauS, 0.5);
    EXPECT_DOUBLE_EQ(f.delayS, 0.1);
    EXPECT_DOUBLE_EQ(f.periodS, 1e-4);  // 10 kHz unless told
    EXPECT_EQ(f.text(), "fopdt:K=2,tau=0.5,L=0.1");
    const PlantSpec l = parseOk(" lag: K=1.5 , tau=0.2, n=4, Ts=0.001 ");
    EXPECT_EQ(l.kind, PlantSpec::Kind::Lag);
    EXPECT_EQ(l.order, 4);
    EXPECT_DOUBLE_EQ(l.periodS, 0.001);
    EXPECT_EQ(l.text(), "lag:K=1.5,tau=0.2,n=4,Ts=0.001");
    EXPECT_EQ(parseOk(l.text().c_str()).text(), l.text());
}

TEST(TuningPlant, ParseErrorsNameTheField)
{
    EXPECT_NE(parseError("fopdt:K=2,tau=abc,L=0.1").find("tuning.plant.not_a_number{kind=\"fopdt\", field=\"tau\", text=\"abc\"}"), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=2,Tau=1,L=0.1").find("tuning.plant.unknown_field{kind=\"fopdt\", field=\"Tau\""), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=2,tau=1").find("tuning.plant.field_missing{kind=\"fopdt\", field=\"L\""), std::string::npos);
    EXPECT_NE(parseError("lag:K=1,tau=1,n=2.5").find("tuning.plant.order_invalid"), std::string::npos);
    EXPECT_NE(parseError("lag:K=1,tau=0,n=3").find("tuning.plant.not_positive{kind=\"lag\", field=\"tau\""), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=-1,tau=1,L=1").find("tuning.plant.not_positive{kind=\"fopdt\", field=\"K\""), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=1,K=2,tau=1,L=1").find("tuning.plant.field_twice{kind=\"fopdt\", field=\"K\"}"), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=1,tau=1,L=-0.5").find("tuning.plant.negative{kind=\"fopdt\", field=\"L\""), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=1,tau=1,L=1,Ts=0").find("tuning.plant.period_out_of_range"), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=1,tau=1,L").find("tuning.plant.no_value{kind=\"fopdt\", field=\"L\"}"), std::string::npos);
    EXPECT_NE(parseError("fopdt:K=1,,tau=1,L=1").find("tuning.plant.empty_field"), std::string::npos);
    EXPECT_NE(parseError("sopdt:K=1").find("tuning.plant.unknown_kind{kind=\"sopdt\"}"), std::string::npos);
    EXPECT_NE(parseError("fopdt").find("tuning.plant.no_fields"), std::string::npos);
}

TEST(TuningPlant, FopdtSimulationIsExactAtTheSamples)
{
    // A dead time of 12.5 control periods: the half period is split inside a step.
    const PlantSpec p = parseOk("fopdt:K=2,tau=0.05,L=0.00125");
    PlantSim sim(p);
    for (int k = 0; k < 2000; ++k) {
        const double t = k * p.periodS;
        const double want = t < p.delayS ? 0.0 : p.gain * (1 - std::exp(-(t - p.delayS) / p.tauS));
        ASSERT_NEAR(sim.output(), want, 1e-12) << "k=" << k;
        sim.step(1.0);
    }
}

TEST(TuningPlant, LagCascadeIsExactAtTheSamples)
{
    const PlantSpec p = parseOk("lag:K=0.7,tau=0.02,n=4");
    PlantSim sim(p);
    for (int k = 0; k < 3000; ++k) {
        const double x = k * p.periodS / p.tauS;
        double sum = 0, term = 1;
        for (int m = 0; m < 4; ++m) {
            sum += term;
            term *= x / (m + 1);
        }
        ASSERT_NEAR(sim.output(), 0.7 * (1 - std::exp(-x) * sum), 1e-12) << "k=" << k;
        sim.step(1.0);
    }
}

TEST(TuningPlant, PureDeadTimeDelaysTheHeldInput)
{
    const PlantSpec p = parseOk("fopdt:K=3,tau=0,L=0.0005");
    PlantSim sim(p);
    for (int k = 0; k < 20; ++k) {
        EXPECT_DOUBLE_EQ(sim.output(), k > 5 ? 3.0 * (k - 6) : 0.0) << "k=" << k;
        sim.step(k);
    }
}

TEST(TuningPlant, UltimatePointSolvesThePhaseCrossover)
{
    const PlantSpec f = parseOk("fopdt:K=2,tau=0.5,L=0.1");
    const auto u = ultimatePoint(f);
    ASSERT_TRUE(u);
    EXPECT_NEAR(std::atan(u->omegaRadS * 0.5) + u->omegaRadS * 0.1, kPi, 1e-12);
    EXPECT_NEAR(u->ku, std::sqrt(1 + std::pow(u->omegaRadS * 0.5, 2)) / 2, 1e-12);
    EXPECT_NEAR(std::arg(frequencyResponse(f, u->omegaRadS)), -kPi, 1e-9);  // ±π: on the negative real axis
    EXPECT_NEAR(std::abs(frequencyResponse(f, u->omegaRadS)) * u->ku, 1, 1e-12);
    // Pure dead time: ω = π/L, Ku = 1/K.
    const auto d = ultimatePoint(parseOk("fopdt:K=4,tau=0,L=0.2"));
    ASSERT_TRUE(d);
    EXPECT_NEAR(d->tuS, 0.4, 1e-12);
    EXPECT_NEAR(d->ku, 0.25, 1e-12);
    // n equal lags: ω = tan(π/n)/τ, Ku = 1/(K·cos(π/n)^n); n = 3 gives Ku = 8/K.
    const auto l = ultimatePoint(parseOk("lag:K=2,tau=0.1,n=3"));
    ASSERT_TRUE(l);
    EXPECT_NEAR(l->omegaRadS, std::tan(kPi / 3) / 0.1, 1e-9);
    EXPECT_NEAR(l->ku, 4.0, 1e-9);
}

TEST(TuningPlant, PlantsThatNeverLag180DegreesHaveNoUltimateGain)
{
    EXPECT_FALSE(ultimatePoint(parseOk("lag:K=1,tau=1,n=2")));
    EXPECT_FALSE(ultimatePoint(parseOk("lag:K=1,tau=1,n=1")));
    EXPECT_FALSE(ultimatePoint(parseOk("fopdt:K=1,tau=1,L=0")));
    EXPECT_EQ(motion::msg::debugString(whyNoUltimateGain(parseOk("lag:K=1,tau=1,n=2"))), "tuning.plant.lag_no_ku{order=2, phase=180°}");
    EXPECT_TRUE(whyNoUltimateGain(parseOk("lag:K=1,tau=1,n=3")).empty());
}
