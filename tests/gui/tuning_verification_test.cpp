// The Z–N verification is judged as a step test is, and a loop that hunts at rest
// is said to. Found by hand: "completed, inside ±5 µm of the target from 25 ms"
// while the verification's trace swung ±2.5 µm for the whole second and the Step
// test tab said "did not settle". A model plant cannot hunt, so the target here
// runs one and adds what a quantised stage loop does on top: a steady ±2.5 µm
// swing, read in 0.5 µm grating counts.
#include "device/jobs/tuning/model_target.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "gui_wait.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/zn_panel.h"

#include <QTableWidget>

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr double kCountMm = 0.0005;

/// A model stage axis whose loop hunts ±`amplitudeMm` once a step test (not a trial) is under way.
class HuntingStage : public dev::ModelTarget {
public:
    HuntingStage(double amplitudeMm, double periodS)
        : dev::ModelTarget(*motion::control::parsePlant("fopdt:K=2,tau=0.5,L=0.1")), m_amplitude(amplitudeMm), m_period(periodS)
    {
    }
    QString describe() const override { return QStringLiteral("Stage X"); }
    QString unit() const override { return QStringLiteral("mm"); }
    double noiseFloor() const override { return kCountMm; }
    void runStep(const motion::control::StepSpec& spec, bool trial, double swing, Done done) override
    {
        if (trial)
            return ModelTarget::runStep(spec, trial, swing, std::move(done));
        ModelTarget::runStep(spec, trial, swing, [this, done](const dev::RunOutcome& out) {
            dev::RunOutcome hunted = out;
            auto& y = hunted.record.measured;
            for (std::size_t k = 0; k < y.size(); ++k) {
                const double t = static_cast<double>(k) * hunted.record.periodS;
                y[k] = std::round((y[k] + m_amplitude * std::sin(2 * 3.141592653589793 * t / m_period)) / kCountMm) * kCountMm;
            }
            done(hunted);
        });
    }

private:
    double m_amplitude, m_period;
};

struct TuningJob {
    dev::TuningRunner runner;
    bool finished = false, ok = false;
    motion::control::Record stepRecord;
    motion::control::StepVerdict stepVerdict;

    bool tune(dev::TuningTarget& target)
    {
        QObject::connect(&runner, &dev::TuningRunner::finished, &runner, [this](bool good, const motion::msg::Message&) {
            finished = true;
            ok = good;
        });
        QObject::connect(&runner, &dev::TuningRunner::stepTestDone, &runner,
                         [this](const motion::control::Record& r, const motion::control::StepVerdict& v, const motion::msg::Message&) {
                             stepRecord = r;
                             stepVerdict = v;
                         });
        dev::TuningRunner::ZnOptions o;
        o.method = motion::control::TuningMethod::Relay;
        o.envelope = {0.05, 0.05, 600};
        o.relayAmplitude = 0.005;
        o.hysteresis = 0.00002;
        o.verifyRule = "zn-pid";
        o.verifyStep = 0.01;  // 10 µm
        return runner.startZn(&target, o) && guitest::waitFor([this] { return finished; }, 20000) && ok;
    }
};

} // namespace

TEST(TuningVerification, ALoopThatHuntsAtRestIsSaidSoNotHiddenInsideTheBand)
{
    HuntingStage stage(0.0025, 0.04);
    TuningJob run;
    ASSERT_TRUE(run.tune(stage));
    const auto& r = run.runner.result();
    ASSERT_TRUE(r.verification);

    ui::ZnPanel panel;
    panel.showResult(r);
    const QString text = panel.resultText();
    EXPECT_FALSE(text.contains(QStringLiteral("inside ±5 µm of the target from"))) << "the swing is hidden behind the band: " << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("never comes to rest"))) << text.toStdString();
    // ±2.5 µm read in 0.5 µm counts: the mean swing of the counts is a little more.
    EXPECT_NEAR(r.verification->limitCycle.amplitude, 0.0025, 0.0003);
    EXPECT_NEAR(r.verification->limitCycle.periodS, 0.04, 0.001);
    EXPECT_TRUE(text.contains(QStringLiteral("a limit cycle of ±2.6 µm every 40 ms"))) << text.toStdString();

    // The Step test tab shows the same run with the same verdict.
    ui::StepTestPanel steps;
    steps.addResult(run.stepRecord, run.stepVerdict, QStringLiteral("verification"));
    QTableWidget* table = steps.metricsTable();
    ASSERT_EQ(table->columnCount(), 1);
    ASSERT_EQ(table->rowCount(), 9);
    EXPECT_EQ(table->item(2, 0)->text(), QStringLiteral("never: limit cycle"));
    EXPECT_EQ(table->item(8, 0)->text(), QStringLiteral("±2.6 µm every 40 ms"));
    EXPECT_EQ(r.verification->metrics.outcome, run.stepVerdict.metrics.outcome);
    EXPECT_EQ(r.verification->limitCycle.found, run.stepVerdict.limitCycle.found);
}

TEST(TuningVerification, ALoopThatComesToRestIsSettledWithNoCycle)
{
    HuntingStage stage(0, 0.04);
    TuningJob run;
    ASSERT_TRUE(run.tune(stage));
    const auto& r = run.runner.result();
    ASSERT_TRUE(r.verification);
    EXPECT_FALSE(r.verification->limitCycle.found);
    ui::ZnPanel panel;
    panel.showResult(r);
    EXPECT_FALSE(panel.resultText().contains(QStringLiteral("never comes to rest"))) << panel.resultText().toStdString();
    EXPECT_TRUE(panel.resultText().contains(QStringLiteral("inside ±5 µm of the target from"))) << panel.resultText().toStdString();
    ui::StepTestPanel steps;
    steps.addResult(run.stepRecord, run.stepVerdict, QStringLiteral("verification"));
    EXPECT_EQ(steps.metricsTable()->item(8, 0)->text(), QStringLiteral("none"));
}
