// Tuning results as files (docs/tuning_results.md): round trips, every problem
// of a bad file at once with its position and field, the examples, atomic saves.
#include "device/english_words.h"
#include "device/files/tuning_file.h"
#include "motion/control/tuning/tuning_rules.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using motion::control::TuningResult;

namespace {

TuningResult relayResult()
{
    TuningResult r;
    r.target = "Stage X";
    r.unit = "mm";
    r.method = "relay";
    r.controlPeriodS = 0.001;
    r.ku = 4.27;
    r.tuS = 0.0052;
    r.kuDescribing = 3.68;
    r.tuRelayS = 0.006;
    r.refined = true;
    r.runs = 3;
    r.envelope = {0.05, 0.05, 2};
    r.relayAmplitude = 0.02;
    r.hysteresis = 0.001;
    r.points = {{1047.2, 0.256, -171.5}, {1256.6, 0.196, -193.2}};
    TuningResult::Verification v;
    v.rule = "zn-pid";
    v.gains = {2.56, 0.98, 1.66};
    v.metrics.riseTimeS = 0.0021;
    v.metrics.overshootPct = 64;
    v.metrics.settlingTimeS = std::nan("");  // never inside 2 % before the end: written as null
    v.metrics.iae = 3e-5;
    v.settledInside5umS = 0.027;
    v.outcome = "settled";
    r.verification = v;
    r.createdUtc = "2024-06-07T10:00:00Z";
    return r;
}

// From the build's idea of the source tree: a compiler cache may make __FILE__
// relative to another directory than the one the test runs in.
std::string sourceDir() { return std::string(BP_SOURCE_DIR) + "/"; }

} // namespace

TEST(TuningFile, WritesAndReadsBackTheSameDocument)
{
    const TuningResult r = relayResult();
    const std::string text = dev::files::tuningToJson(r);
    EXPECT_NE(text.find("\"schema\": \"benchpilot.tuning\""), std::string::npos);
    EXPECT_NE(text.find("\"zn-pid\""), std::string::npos);  // the rules table, for readers
    const auto back = dev::files::tuningFromJson(text);
    ASSERT_TRUE(back.result) << i18ntest::englishFormat(back.problems, "x.tuning.json");
    EXPECT_EQ(back.result->target, "Stage X");
    EXPECT_DOUBLE_EQ(back.result->ku, 4.27);
    ASSERT_TRUE(back.result->kuDescribing);
    EXPECT_DOUBLE_EQ(*back.result->kuDescribing, 3.68);
    ASSERT_EQ(back.result->points.size(), 2u);
    ASSERT_TRUE(back.result->verification);
    EXPECT_TRUE(std::isnan(back.result->verification->metrics.settlingTimeS));
    EXPECT_DOUBLE_EQ(back.result->verification->gains.kd, 1.66);
    EXPECT_EQ(dev::files::tuningToJson(*back.result), text);

    TuningResult ug;
    ug.target = "fopdt:K=2,tau=0.5,L=0.1";
    ug.method = "ultimate-gain";
    ug.controlPeriodS = 1e-4;
    ug.ku = 9.1;
    ug.tuS = 1.3;
    ug.step = 1;
    ug.envelope = {3, 3, 600};
    ug.trials = {{0.1, 0, 0, "no oscillation"}, {8.2, 0.73, 1.29, "decays"}, {9.1, 0.99, 1.3, "sustained"}};
    const auto ugBack = dev::files::tuningFromJson(dev::files::tuningToJson(ug));
    ASSERT_TRUE(ugBack.result) << i18ntest::englishFormat(ugBack.problems, "m.tuning.json");
    EXPECT_EQ(ugBack.result->trials.size(), 3u);
    EXPECT_EQ(dev::files::tuningToJson(*ugBack.result), dev::files::tuningToJson(ug));
}

TEST(TuningFile, ABadFileIsRefusedWithEveryProblemAndWhereItIs)
{
    const std::string text = R"({
  "schema": "benchpilot.tuning",
  "version": 1,
  "target": "Stage X",
  "method": "relay",
  "control_period_s": 0.001,
  "ku": -4,
  "tu_s": 0.005,
  "envelope": {"max_excursion": 0.05, "max_following_error": 0.05},
  "relay": {"amplitude": 0.02, "hysteresis": 0.001, "points": [{"omega_rad_s": 1, "gain": 1, "phase": -180}]},
  "verification": {"rule": "zn-ppp", "gains": {"kp": 1, "ki": 0, "kd": -1}},
  "kuu": 1
}
)";
    const auto r = dev::files::tuningFromJson(text);
    EXPECT_FALSE(r.result);
    const std::string p = i18ntest::englishFormat(r.problems, "bad.tuning.json");
    EXPECT_NE(p.find("bad.tuning.json:7:9: ku: must be"), std::string::npos) << p;
    EXPECT_NE(p.find("envelope.max_duration_s: is missing"), std::string::npos) << p;
    EXPECT_NE(p.find("relay.points[0].phase_deg: is missing"), std::string::npos) << p;
    EXPECT_NE(p.find("relay.points[0].phase"), std::string::npos) << p;
    EXPECT_NE(p.find("\"zn-ppp\" is not a rule"), std::string::npos) << p;
    EXPECT_NE(p.find("verification.gains.kd"), std::string::npos) << p;
    EXPECT_NE(p.find("kuu"), std::string::npos) << p;
    EXPECT_GE(std::count(p.begin(), p.end(), '\n'), 7);

    const std::string newer = i18ntest::englishFormat(dev::files::tuningFromJson(R"({"schema": "benchpilot.tuning", "version": 2})").problems, "n.json");
    EXPECT_NE(newer.find("written by a newer BenchPilot"), std::string::npos) << newer;
    const std::string other = i18ntest::englishFormat(dev::files::tuningFromJson(R"({"schema": "benchpilot.recipe", "version": 1})").problems, "o.json");
    EXPECT_NE(other.find("expected \"benchpilot.tuning\""), std::string::npos) << other;
    const std::string broken = i18ntest::englishFormat(dev::files::tuningFromJson("{\"schema\": ").problems, "b.json");
    EXPECT_NE(broken.find("b.json:1:"), std::string::npos) << broken;
}

TEST(TuningFile, TheExamplesLoad)
{
    const QDir dir(QString::fromStdString(sourceDir() + "resources/examples"));
    const QStringList names = dir.entryList({QStringLiteral("*.tuning.json")}, QDir::Files);
    ASSERT_GE(names.size(), 2) << "resources/examples should hold real tuning results";
    for (const QString& n : names) {
        dev::files::json::Problems problems;
        const auto r = dev::files::loadTuningFile(dir.filePath(n), &problems);
        ASSERT_TRUE(r) << i18ntest::englishFormat(problems, n.toStdString());
        EXPECT_GT(r->ku, 0);
        EXPECT_GT(r->tuS, 0);
    }
}

TEST(TuningFile, SavesAtomicallyAndLoadsBack)
{
    QTemporaryDir tmp;
    ASSERT_TRUE(tmp.isValid());
    const QString path = tmp.filePath(QStringLiteral("stage.tuning.json"));
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::saveTuningFile(path, relayResult(), &error)) << error;
    dev::files::json::Problems problems;
    const auto r = dev::files::loadTuningFile(path, &problems);
    ASSERT_TRUE(r) << i18ntest::englishFormat(problems, "stage.tuning.json");
    EXPECT_EQ(r->method, "relay");
    EXPECT_FALSE(dev::files::saveTuningFile(tmp.filePath(QStringLiteral("no/such/dir/x.json")), relayResult(), &error));
    EXPECT_EQ(error.id, "file.cannot_write");
    EXPECT_FALSE(dev::files::loadTuningFile(tmp.filePath(QStringLiteral("missing.json")), &problems));
    EXPECT_NE(i18ntest::englishFormat(problems, "x").find("missing.json"), std::string::npos) << i18ntest::englishFormat(problems, "x");
}

// The verification's verdict is kept with its limit cycle; a file written before there was
// a verdict reads as the step test judged it then (no settling time: did not settle).
TEST(TuningFile, AVerificationKeepsItsVerdictAndItsLimitCycle)
{
    TuningResult r = relayResult();
    r.verification->metrics.outcome = motion::control::StepOutcome::LimitCycle;
    r.verification->limitCycle = {true, 0.0025, 0.04, 4, 0.001};
    const std::string text = dev::files::tuningToJson(r);
    EXPECT_NE(text.find("\"verdict\": \"limit cycle\""), std::string::npos) << text;
    const auto back = dev::files::tuningFromJson(text);
    ASSERT_TRUE(back.result) << i18ntest::englishFormat(back.problems, "x.tuning.json");
    ASSERT_TRUE(back.result->verification);
    const auto& v = *back.result->verification;
    EXPECT_EQ(v.metrics.outcome, motion::control::StepOutcome::LimitCycle);
    ASSERT_TRUE(v.limitCycle.found);
    EXPECT_DOUBLE_EQ(v.limitCycle.amplitude, 0.0025);
    EXPECT_DOUBLE_EQ(v.limitCycle.periodS, 0.04);
    EXPECT_EQ(v.limitCycle.cycles, 4);
    EXPECT_EQ(dev::files::tuningToJson(*back.result), text);

    std::string old = dev::files::tuningToJson(relayResult());
    const std::string verdict = "\"verdict\": \"settled\"";
    const auto key = old.find(verdict);
    ASSERT_NE(key, std::string::npos) << old;
    const auto comma = old.rfind(',', key);
    old.erase(comma, key + verdict.size() - comma);
    ASSERT_EQ(old.find("verdict"), std::string::npos) << old;
    const auto read = dev::files::tuningFromJson(old);
    ASSERT_TRUE(read.result) << i18ntest::englishFormat(read.problems, "old.tuning.json");
    EXPECT_EQ(read.result->verification->metrics.outcome, motion::control::StepOutcome::DidNotSettle);
}
