// benchpilot-cli tune, step-test and gains, called in-process: the JSON shapes
// docs/tuning.md gives, Ku/Tu against the closed form, and refusals that say why.
#include "cli_in_process.h"
#include "motion/control/plant.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {
itest::CliResult run(const QStringList& args) { return itest::runCliInProcess(args); }
QStringList words(const char* text) { return itest::splitWords(text); }
} // namespace

TEST(TuningCli, TunePrintsKuTuAndTheRulesInTheIssuesShape)
{
    for (const char* method : {"zn", "relay"}) {
        const auto r = run(words("tune --method") << QString::fromLatin1(method)
                                                  << words("--plant fopdt:K=2,tau=0.5,L=0.1 --relay-amplitude 0.15 --json"));
        ASSERT_EQ(r.code, 0) << method << ": " << r.err.toStdString();
        const QJsonObject j = r.json();
        EXPECT_EQ(j.keys(), (QStringList{QStringLiteral("Ku"), QStringLiteral("Tu"), QStringLiteral("rules")}));
        const auto want = motion::control::ultimatePoint(*motion::control::parsePlant("fopdt:K=2,tau=0.5,L=0.1"));
        EXPECT_NEAR(j["Ku"].toDouble(), want->ku, 0.05 * want->ku) << method;
        EXPECT_NEAR(j["Tu"].toDouble(), want->tuS, 0.05 * want->tuS) << method;
        const QJsonObject rules = j["rules"].toObject();
        EXPECT_EQ(rules["zn-p"].toObject().keys(), QStringList{QStringLiteral("Kp")});
        EXPECT_EQ(rules["zn-pi"].toObject().keys(), (QStringList{QStringLiteral("Ki"), QStringLiteral("Kp")}));
        EXPECT_EQ(rules["zn-pid"].toObject().keys(), (QStringList{QStringLiteral("Kd"), QStringLiteral("Ki"), QStringLiteral("Kp")}));
        // Continuous form, seed 002 Table 1: Kp = 0.6 Ku, Ki = 2 Kp/Tu [1/s], Kd = Kp Tu/8 [s].
        const double ku = j["Ku"].toDouble(), tu = j["Tu"].toDouble();
        const QJsonObject pid = rules["zn-pid"].toObject();
        EXPECT_NEAR(pid["Kp"].toDouble(), 0.6 * ku, 1e-9);
        EXPECT_NEAR(pid["Ki"].toDouble(), 2 * 0.6 * ku / tu, 1e-6);
        EXPECT_NEAR(pid["Kd"].toDouble(), 0.6 * ku * tu / 8, 1e-9);
        for (const char* id : {"tl-pi", "tl-pid", "pessen", "some-overshoot", "no-overshoot"})
            EXPECT_TRUE(rules.contains(QLatin1String(id))) << id;
    }
}

TEST(TuningCli, APlantWithoutAnUltimateGainIsRefusedWithTheReason)
{
    const auto r = run(words("tune --method relay --plant lag:K=1,tau=0.2,n=2 --json"));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no finite ultimate gain"))) << r.err.toStdString();
    const auto bad = run(words("tune --method zn --plant fopdt:K=1,tau=x,L=1"));
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(bad.err.contains(QStringLiteral("tau must be a number"))) << bad.err.toStdString();
    EXPECT_EQ(run(words("tune --method pid --plant fopdt:K=1,tau=1,L=1")).code, 1);
    EXPECT_EQ(run(words("tune --method zn")).code, 1);
}

TEST(TuningCli, StepTestOnTheSimulatedStagePrintsItsMetrics)
{
    const auto r = run(words("--sim stage step-test --axis X --size 0.01 --json"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject j = r.json();
    for (const char* key : {"rise_time_s", "overshoot_pct", "settling_time_s", "steady_state_error", "iae", "ise", "peak_output",
                            "settled_inside_5um_s", "gains", "outcome"})
        EXPECT_TRUE(j.contains(QLatin1String(key))) << key;
    EXPECT_NEAR(j["gains"].toObject()["Kp"].toDouble(), 0.25, 1e-6);
    EXPECT_NEAR(j["gains"].toObject()["Ki"].toDouble(), 500, 1e-3);  // the seed's ki = 0.5 per 1 ms period
    EXPECT_GT(j["overshoot_pct"].toDouble(), 0);
    EXPECT_LT(j["settled_inside_5um_s"].toDouble(), 0.1);
}

TEST(TuningCli, GainsShowAndSetAndTheDeviceRefusesBadOnes)
{
    const auto shown = run(words("--sim stage --json gains X=0.3,400,2e-5"));
    ASSERT_EQ(shown.code, 0) << shown.err.toStdString();
    const QJsonObject x = shown.json()["axes"].toObject()["X"].toObject();
    EXPECT_NEAR(x["Kp"].toDouble(), 0.3, 1e-6);
    EXPECT_NEAR(x["ki"].toDouble(), 0.4, 1e-6);  // per period, beside the continuous form
    EXPECT_NEAR(x["control_period_s"].toDouble(), 0.001, 1e-12);
    const auto refused = run(words("--sim stage gains X=nan,1,1"));
    EXPECT_EQ(refused.code, 2);
    EXPECT_TRUE(refused.err.contains(QStringLiteral("the previous ones stay"))) << refused.err.toStdString();
    EXPECT_TRUE(refused.err.contains(QStringLiteral("NaN"))) << refused.err.toStdString();
    EXPECT_EQ(run(words("--sim analyzer gains")).code, 2);
}
