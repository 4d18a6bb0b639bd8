// Both tuning methods against the analytic phase crossover over a wide, seeded
// population of FOPDT and lag plants (what the tuning must get right first), and the
// classic describing-function estimate beside the refined one.
#include "motion/message_print.h"
#include "motion/control/tuning/model_tuning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace motion::control;

namespace {

/// The test population: FOPDT from lag- to delay-dominant, lags of order 3–8.
/// Every Tu is at least 200 control periods of the 10 kHz loop, so the loop's
/// own sampling moves the crossover by under 1°.
std::vector<PlantSpec> population(int fopdtCount, int lagCount, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    auto logUniform = [&](double lo, double hi) {
        return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
    };
    std::vector<PlantSpec> out;
    for (int i = 0; i < fopdtCount; ++i) {
        PlantSpec p;
        p.kind = PlantSpec::Kind::Fopdt;
        p.gain = logUniform(0.2, 5);
        p.tauS = logUniform(0.05, 5);
        p.delayS = std::max(0.01, p.tauS * logUniform(0.05, 5));
        p.order = 1;
        out.push_back(p);
    }
    for (int i = 0; i < lagCount; ++i) {
        PlantSpec p;
        p.kind = PlantSpec::Kind::Lag;
        p.gain = logUniform(0.2, 5);
        p.tauS = logUniform(0.01, 2);
        p.order = 3 + static_cast<int>(rng() % 6);
        out.push_back(p);
    }
    return out;
}

ModelTuningOptions optionsFor(const PlantSpec& p, TuningMethod m)
{
    ModelTuningOptions o;
    o.method = m;
    o.step = 1;
    o.envelope = {3, 3, 2000};
    // What a person would choose knowing the plant's gain roughly: a relay that
    // moves the output by a fraction of the envelope.
    o.relayAmplitude = 0.3 / p.gain;
    // Above the (here: numerical) noise, well below the cycle's amplitude. With
    // none, a relay started exactly on its setpoint may chatter at the loop rate.
    o.hysteresis = 0.002;
    return o;
}

struct Errors {
    std::vector<double> ku, tu;
    double maxKu() const { return ku.empty() ? 0 : *std::max_element(ku.begin(), ku.end()); }
    double maxTu() const { return tu.empty() ? 0 : *std::max_element(tu.begin(), tu.end()); }
};

} // namespace

/// 50 plants in 10 shards of 5: each shard stays well inside a test's time
/// limit even unoptimised under the sanitizers, and every build tests them all.
constexpr int kShards = 10;
const std::vector<PlantSpec>& plants()
{
    static const std::vector<PlantSpec> all = population(30, 20, 20240607);
    return all;
}

class TuningAccuracy : public ::testing::TestWithParam<int> {};

TEST_P(TuningAccuracy, BothMethodsFindKuAndTuWithinFivePercentOverManyPlants)
{
    const std::size_t per = plants().size() / kShards;
    Errors ug, relay, classic;
    for (std::size_t i = static_cast<std::size_t>(GetParam()) * per; i < static_cast<std::size_t>(GetParam() + 1) * per; ++i) {
        const PlantSpec& p = plants()[i];
        const auto want = ultimatePoint(p);
        ASSERT_TRUE(want) << p.text();
        for (TuningMethod m : {TuningMethod::UltimateGain, TuningMethod::Relay}) {
            const ModelTuning t = tuneModel(p, optionsFor(p, m));
            ASSERT_TRUE(t.ok) << p.text() << ": " << t.error;
            const double eKu = std::abs(t.ku / want->ku - 1), eTu = std::abs(t.tuS / want->tuS - 1);
            EXPECT_LT(eKu, 0.05) << p.text() << (m == TuningMethod::Relay ? " relay" : " ultimate gain") << ": Ku " << t.ku
                                 << " against " << want->ku;
            EXPECT_LT(eTu, 0.05) << p.text() << (m == TuningMethod::Relay ? " relay" : " ultimate gain") << ": Tu " << t.tuS
                                 << " against " << want->tuS;
            Errors& e = m == TuningMethod::Relay ? relay : ug;
            e.ku.push_back(eKu);
            e.tu.push_back(eTu);
            if (m == TuningMethod::Relay) {
                EXPECT_TRUE(t.relay->refined) << p.text() << ": " << t.error;
                classic.ku.push_back(std::abs(t.relay->kuDescribing / want->ku - 1));
                classic.tu.push_back(std::abs(t.relay->tuRelayS / want->tuS - 1));
            }
        }
    }
    std::printf("plants %zu–%zu: max |error| Ku / Tu — ultimate gain %.2f %% / %.2f %%, relay refined %.2f %% / %.2f %%, "
                "relay classic DF %.1f %% / %.1f %%\n",
                GetParam() * per, (GetParam() + 1) * per - 1, 100 * ug.maxKu(), 100 * ug.maxTu(), 100 * relay.maxKu(),
                100 * relay.maxTu(), 100 * classic.maxKu(), 100 * classic.maxTu());
}

INSTANTIATE_TEST_SUITE_P(Shards, TuningAccuracy, ::testing::Range(0, kShards));
