// The Tuning screen driven as a person would, against the in-process simulators:
// targets, gains with Apply/Revert and their history, step tests with metrics,
// the Z-N assistant on a model plant with "Use these", results saved and opened.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "device/sim/sim_tuning.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/tuning/gains_panel.h"
#include "widgets/tuning/response_plot.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/tuning/zn_panel.h"

#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

class TuningScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1500, 950});
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
        ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
        t = w->tuningScreen();
        ASSERT_NE(t, nullptr);
    }
    dev::sim::SimMachine& stage() { return qobject_cast<dev::SimulatedLink*>(w->stage()->link())->machine(); }
    QPushButton* button(QWidget* root, const QString& text)
    {
        for (auto* b : root->findChildren<QPushButton*>())
            if (b->text() == text && b->isVisible())
                return b;
        return nullptr;
    }
    void setEdit(const char* name, const QString& text)
    {
        auto* e = t->gains()->findChild<QLineEdit*>(QLatin1String(name));
        ASSERT_NE(e, nullptr) << name;
        e->selectAll();
        QTest::keyClicks(e, text);
    }
    std::unique_ptr<app::MainWindow> w;
    ui::TuningScreen* t = nullptr;
};

} // namespace

TEST_F(TuningScreenTest, OffersTheStagesAxesAndAModelPlantNotTheAnalyzer)
{
    ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
    EXPECT_EQ(t->targetNames(), (QStringList{QStringLiteral("Stage X"), QStringLiteral("Stage Y"), QStringLiteral("Model plant")}));
    // Found in the Xvfb session: the screen, built before the stage had answered, stayed on
    // the model plant it had fallen back to. A fallback nobody chose gives way to the stage.
    EXPECT_EQ(t->currentTarget().toStdString(), "Stage X");
    QString error;
    EXPECT_FALSE(t->setModelPlant(QStringLiteral("fopdt:K=2,tau=-1,L=0.1"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("tau"))) << error.toStdString();
    EXPECT_TRUE(t->setModelPlant(QStringLiteral("lag:K=1,tau=0.05,n=2")));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Model plant")));
    EXPECT_TRUE(t->assistant()->resultText().contains(QStringLiteral("no finite ultimate gain"))) << t->assistant()->resultText().toStdString();
    EXPECT_FALSE(t->startAssistant());
}

TEST_F(TuningScreenTest, GainsApplyRevertAndKeepAHistoryOnTheStage)
{
    ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
    ASSERT_TRUE(waitFor([&] { return !t->gains()->history().isEmpty(); }, 3000)) << t->currentTarget().toStdString() << " " << t->statusText().toStdString();
    EXPECT_NEAR(t->gains()->inForce().kp, 0.25, 1e-6);
    // Continuous form on screen: the stage's ki = 0.5 per 1 ms period is Ki = 500 /s.
    EXPECT_EQ(t->gains()->findChild<QLineEdit*>(QStringLiteral("kiEdit"))->text(), QStringLiteral("500"));
    setEdit("kpEdit", QStringLiteral("0.4"));
    QTest::mouseClick(button(t->gains(), QStringLiteral("Apply")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 0.4) < 1e-6; }, 3000));
    ASSERT_TRUE(waitFor([&] { return t->gains()->history().size() == 2; }, 3000));
    EXPECT_EQ(t->gains()->history().back().source, QStringLiteral("edited"));
    QTest::mouseClick(button(t->gains(), QStringLiteral("Revert")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 0.25) < 1e-6; }, 3000));
    ASSERT_TRUE(waitFor([&] { return t->gains()->history().size() == 3; }, 3000));
    QStringList sources;
    for (const auto& h : t->gains()->history())
        sources << h.source;
    EXPECT_TRUE(t->gains()->history().back().source.startsWith(QStringLiteral("reverted"))) << sources.join(QStringLiteral(" | ")).toStdString();
    EXPECT_EQ(t->gains()->findChild<QTableWidget*>(QStringLiteral("gainsHistory"))->rowCount(), 3);
}

TEST_F(TuningScreenTest, AStepTestOnTheStageAddsAResponseAndItsMetrics)
{
    auto* s = w->stage()->instrument();
    s->home(0);
    pump(300);
    ASSERT_TRUE(waitFor([&] { return !s->status().anyMoving() && s->status().axes[0].homed; }, 40000));
    ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
    ASSERT_TRUE(waitFor([&] { return !t->gains()->history().isEmpty(); }, 3000));
    s->move({{0, 50}}, false);
    pump(200);
    ASSERT_TRUE(waitFor([&] { return !s->status().anyMoving(); }, 10000));
    QTest::mouseClick(t->stepTests()->findChild<QPushButton*>(QStringLiteral("runStepTest")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return t->stepTests()->runs() == 1; }, 10000)) << t->statusText().toStdString();
    auto* table = t->stepTests()->metricsTable();
    ASSERT_EQ(table->columnCount(), 1);                           // one column a run, beside the plot
    EXPECT_NE(table->item(1, 0)->text(), QStringLiteral("—"));      // an overshoot was measured
    EXPECT_NE(table->item(7, 0)->text(), QStringLiteral("never"));  // inside seed 002's ±5 µm
    EXPECT_EQ(t->stepTests()->plot()->runCount(), 1);
}

TEST_F(TuningScreenTest, AssistantOnAModelFillsTheRulesAndUseTheseAppliesARow)
{
    ASSERT_TRUE(t->setModelPlant(QStringLiteral("fopdt:K=2,tau=0.5,L=0.1")));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Model plant")));
    auto o = t->assistant()->options();
    o.method = motion::control::TuningMethod::Relay;
    o.relayAmplitude = 0.15;
    t->assistant()->setOptions(o);
    QTest::mouseClick(t->assistant()->findChild<QPushButton*>(QStringLiteral("znStart")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return t->hasResult() && !t->runner()->busy(); }, 20000)) << t->statusText().toStdString();
    const auto want = motion::control::ultimatePoint(*motion::control::parsePlant("fopdt:K=2,tau=0.5,L=0.1"));
    EXPECT_NEAR(t->lastResult().ku, want->ku, 0.05 * want->ku);
    EXPECT_EQ(t->assistant()->rulesTable()->rowCount(), 8);
    EXPECT_TRUE(t->assistant()->resultText().contains(QStringLiteral("Classic describing function")));
    auto* use = t->assistant()->findChild<QPushButton*>(QStringLiteral("use_tl-pid"));
    ASSERT_NE(use, nullptr);
    const int before = t->gains()->history().size();
    QTest::mouseClick(use, Qt::LeftButton);
    ASSERT_EQ(t->gains()->history().size(), before + 1);
    EXPECT_TRUE(t->gains()->history().back().source.contains(QStringLiteral("Tyreus"))) << t->gains()->history().back().source.toStdString();
    const auto tl = dev::TuningRunner::ruleGains("tl-pid", t->lastResult().ku, t->lastResult().tuS, 1e-4);
    EXPECT_NEAR(t->gains()->inForce().kp, tl.kp, 1e-9);

    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("model.tuning.json"));
    ASSERT_TRUE(t->saveResults(path)) << t->statusText().toStdString();
    const double ku = t->lastResult().ku;
    ASSERT_TRUE(t->loadResults(path)) << t->statusText().toStdString();
    EXPECT_DOUBLE_EQ(t->lastResult().ku, ku);
    EXPECT_FALSE(t->loadResults(tmp.filePath(QStringLiteral("none.tuning.json"))));
    EXPECT_TRUE(t->statusText().contains(QStringLiteral("none.tuning.json"))) << t->statusText().toStdString();
}

TEST_F(TuningScreenTest, EscapeInAGainFieldStillStopsEverything)
{
    ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
    auto* kp = t->gains()->findChild<QLineEdit*>(QStringLiteral("kpEdit"));
    ASSERT_NE(kp, nullptr);
    w->activateWindow();
    kp->setFocus();
    QTest::keyClick(kp, Qt::Key_Escape);
    EXPECT_TRUE(waitFor([&] { return stage().estopActive(); }, 3000)) << "the tuning screen swallowed Esc";
}
