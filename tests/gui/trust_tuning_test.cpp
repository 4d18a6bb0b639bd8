// Trust on the Tuning screen, against the in-process stage:
// a gain typed as "-5" stays "-5", is shown invalid and never sent; a set far
// from the one in force asks first; a step test that diverges shows "unstable",
// never figures, and leaves the axis at rest under the gains it had before; and
// the screen speaks of what a person needs, not of the seeds' equation numbers.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "device/sim/sim_tuning.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/common/number_field.h"
#include "widgets/event_log.h"
#include "widgets/tuning/gains_panel.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/tuning/zn_panel.h"

#include <QAbstractButton>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

class TrustTuningTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1500, 950});
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
        ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
        t = w->tuningScreen();
        t->setConfirm([this](const QString& q) {
            questions << q;
            return answer;
        });
        ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
        ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
        ASSERT_TRUE(waitFor([&] { return !t->gains()->history().isEmpty(); }, 3000)) << t->statusText().toStdString();
    }
    dev::sim::SimMachine& stage() { return qobject_cast<dev::SimulatedLink*>(w->stage()->link())->machine(); }
    ui::NumberField* field(const char* name) { return t->gains()->findChild<ui::NumberField*>(QLatin1String(name)); }
    QPushButton* apply()
    {
        for (auto* b : t->gains()->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Apply"))
                return b;
        return nullptr;
    }
    void type(const char* name, const QString& text)
    {
        auto* e = field(name);
        ASSERT_NE(e, nullptr) << name;
        e->setFocus();
        e->selectAll();
        QTest::keyClicks(e, text);
    }
    std::unique_ptr<app::MainWindow> w;
    ui::TuningScreen* t = nullptr;
    QStringList questions;
    bool answer = false;
};

} // namespace

TEST_F(TrustTuningTest, ATypedMinusFiveStaysMinusFiveIsShownInvalidAndIsNeverSent)
{
    type("kpEdit", QStringLiteral("-5"));
    ui::NumberField* kp = field("kpEdit");
    EXPECT_EQ(kp->text(), QStringLiteral("-5")) << "a character was dropped";
    EXPECT_FALSE(kp->isValid());
    EXPECT_FALSE(kp->value().has_value());
    EXPECT_TRUE(kp->problem().contains(QStringLiteral("0 or more"))) << kp->problem().toStdString();
    EXPECT_EQ(kp->toolTip(), kp->problem());
    ASSERT_NE(apply(), nullptr);
    EXPECT_FALSE(apply()->isEnabled());
    EXPECT_FALSE(t->gains()->edited().has_value());
    QTest::mouseClick(apply(), Qt::LeftButton);
    pump(200);
    EXPECT_FLOAT_EQ(static_cast<float>(stage().tuning().gains(0).kp), 0.25f);
    type("kpEdit", QStringLiteral("abc"));
    EXPECT_TRUE(kp->problem().contains(QStringLiteral("not a number"))) << kp->problem().toStdString();
    type("kpEdit", QStringLiteral("0.3"));
    EXPECT_TRUE(kp->isValid());
    EXPECT_TRUE(apply()->isEnabled());
}

TEST_F(TrustTuningTest, GainsMoreThanThreeTimesAnActiveTermAskFirst)
{
    type("kpEdit", QStringLiteral("0.4"));  // 1.6 x: no question
    QTest::mouseClick(apply(), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 0.4) < 1e-6; }, 3000));
    EXPECT_TRUE(questions.isEmpty()) << questions.join(QLatin1Char('\n')).toStdString();

    type("kpEdit", QStringLiteral("5"));  // 12.5 x the Kp in force
    answer = false;
    QTest::mouseClick(apply(), Qt::LeftButton);
    pump(300);
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("Kp"))) << questions[0].toStdString();
    EXPECT_FLOAT_EQ(static_cast<float>(stage().tuning().gains(0).kp), 0.4f) << "sent although the operator said no";

    type("kdEdit", QStringLiteral("0.000005"));  // Kd 30 µs → 5 µs: under a third
    type("kpEdit", QStringLiteral("0.4"));
    QTest::mouseClick(apply(), Qt::LeftButton);
    pump(300);
    ASSERT_EQ(questions.size(), 2);
    EXPECT_TRUE(questions[1].contains(QStringLiteral("Kd"))) << questions[1].toStdString();

    answer = true;
    type("kpEdit", QStringLiteral("5"));
    type("kdEdit", QStringLiteral("3e-05"));
    QTest::mouseClick(apply(), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 5) < 1e-6; }, 3000));
    EXPECT_EQ(questions.size(), 3);
}

TEST_F(TrustTuningTest, ADivergingStepTestSaysUnstableAndLeavesTheAxisAtRestUnderThePreviousGains)
{
    auto* s = w->stage()->instrument();
    s->home(0);
    pump(300);
    ASSERT_TRUE(waitFor([&] { return !s->status().anyMoving() && s->status().axes[0].homed; }, 40000));
    s->move({{0, 50}}, false);
    pump(200);
    ASSERT_TRUE(waitFor([&] { return !s->status().anyMoving(); }, 10000));
    answer = true;
    type("kpEdit", QStringLiteral("12"));  // far above the loop's ultimate gain: it runs away
    QTest::mouseClick(apply(), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 12) < 1e-6; }, 3000));
    // The step test runs the set the screen has in force: wait for the device's reply, not only its change.
    ASSERT_TRUE(waitFor([&] { return std::abs(t->gains()->inForce().kp - 12) < 1e-6; }, 3000));
    QTest::mouseClick(t->stepTests()->findChild<QPushButton*>(QStringLiteral("runStepTest")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return t->stepTests()->runs() == 1 && !t->runner()->busy(); }, 15000)) << t->statusText().toStdString();
    auto* table = t->stepTests()->metricsTable();
    for (int row : {0, 1, 2}) {
        bool isNumber = false;
        table->item(row, 0)->text().toDouble(&isNumber);
        EXPECT_FALSE(isNumber) << "row " << row << " shows a figure for a response that diverged: " << table->item(row, 0)->text().toStdString();
        EXPECT_EQ(table->item(row, 0)->text(), QStringLiteral("unstable"));
    }
    // Back under the set before Kp 12, at rest, and the screen shows it.
    ASSERT_TRUE(waitFor([&] { return std::abs(stage().tuning().gains(0).kp - 0.25) < 1e-6; }, 3000));
    ASSERT_TRUE(waitFor([&] { return std::abs(t->gains()->inForce().kp - 0.25) < 1e-6; }, 3000));
    pump(300);
    const double here = s->status().axes[0].measured;
    pump(500);
    EXPECT_NEAR(s->status().axes[0].measured, here, 0.005);
    EXPECT_FALSE(s->status().anyMoving());
    EXPECT_NEAR(here, 50, 0.5);
    bool said = false;
    for (int i = 0; i < w->eventLog()->rowCount(); ++i)
        said = said || w->eventLog()->rowText(i).contains(QStringLiteral("stopped at"));
    EXPECT_TRUE(said) << "the event log does not say where the axis stopped";
}

TEST_F(TrustTuningTest, TheScreenSpeaksOfGainsNotOfSeedEquationsOrTables)
{
    t->assistant()->showResult([] {
        motion::control::TuningResult r;
        r.target = "Stage X";
        r.method = "relay";
        r.controlPeriodS = 0.001;
        r.ku = 2;
        r.tuS = 0.05;
        r.runs = 3;
        r.unit = "mm";
        motion::control::TuningResult::Verification v;
        v.rule = "zn-pid";
        v.outcome = "settled";
        v.settledInside5umS = 0.01;
        r.verification = v;
        return r;
    }());
    QStringList seen;
    for (auto* l : t->findChildren<QLabel*>())
        seen << l->text();
    for (auto* table : t->findChildren<QTableWidget*>()) {
        for (int c = 0; c < table->columnCount(); ++c)
            if (auto* h = table->horizontalHeaderItem(c))
                seen << h->text();
        for (int r = 0; r < table->rowCount(); ++r)
            for (int c = 0; c < table->columnCount(); ++c)
                if (auto* i = table->item(r, c))
                    seen << i->text();
    }
    for (const QString& text : seen)
        for (const QString& jargon : {QStringLiteral("seed"), QStringLiteral("Table 1"), QStringLiteral("eq. ")})
            EXPECT_FALSE(text.contains(jargon)) << text.toStdString();
}

// On the Tuning screen, results opened during a run would
// replace the ones the running assistant fills in. Held while it runs.
TEST_F(TrustTuningTest, OpeningResultsIsHeldWhileATuningRunIsUnderWay)
{
    ASSERT_TRUE(t->setModelPlant(QStringLiteral("fopdt:K=2,tau=0.5,L=0.1")));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Model plant")));
    ASSERT_TRUE(t->startAssistant());
    ASSERT_TRUE(t->runner()->busy());
    QPushButton* open = nullptr;
    for (auto* b : t->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Open results…"))
            open = b;
    ASSERT_NE(open, nullptr);
    EXPECT_FALSE(open->isEnabled());
    EXPECT_FALSE(t->loadResults(QStringLiteral("/nonexistent/any.tuning.json")));
    EXPECT_TRUE(t->statusText().contains(QStringLiteral("under way"))) << t->statusText().toStdString();
    t->abort();
    ASSERT_TRUE(waitFor([&] { return !t->runner()->busy(); }, 10000));
    EXPECT_TRUE(open->isEnabled());
}
