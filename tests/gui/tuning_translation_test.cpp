// What the tuning screens show from motion/'s plain keys (how a run ended, a
// trial's outcome, where a rule comes from) reaches the person translated: with
// a stand-in translation installed, none of it is left in English.
#include "widgets/wording/wording.h"
#include "motion/control/tuning/tuning_result.h"
#include "motion/control/tuning/tuning_rules.h"
#include "widgets/tuning/zn_panel.h"

#include "../device/pseudo_translation.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QTableWidget>

#include "widgets/common/number_field.h"

#include <gtest/gtest.h>

using motion::control::EndReason;
using motion::control::TuningResult;

TEST(TuningTranslation, OutcomesAndEndReasonsAreTranslatedByKey)
{
    const i18ntest::PseudoTranslation translated({QStringLiteral("ui::words::TuningWords")});
    EXPECT_EQ(ui::words::tuningOutcome("decays"), QStringLiteral("décáys"));
    EXPECT_EQ(ui::words::tuningOutcome("sustained"), QStringLiteral("sústáínéd"));
    EXPECT_EQ(ui::words::tuningOutcome("hit the envelope"), QStringLiteral("hít thé énvélópé"));
    EXPECT_EQ(ui::words::term(motion::control::endReasonTerm(EndReason::Excursion)), QStringLiteral("máx éxcúrsíón crósséd"));
    EXPECT_EQ(ui::words::tuningOutcome(motion::control::endReasonName(EndReason::Settled)), QStringLiteral("séttléd"))
        << "a verification stores its end reason's name";
}

/// A relay result on the stage's X, verified with Ziegler–Nichols PID ending for `reason`.
TuningResult relayResult(EndReason reason)
{
    TuningResult r;
    r.target = "Stage X";
    r.method = "relay";
    r.controlPeriodS = 0.001;
    r.ku = 2;
    r.tuS = 0.5;
    r.runs = 3;
    TuningResult::Verification v;
    v.rule = "zn-pid";
    v.outcome = motion::control::endReasonName(reason);
    r.verification = v;
    return r;
}

TEST(TuningTranslation, TheZnPanelShowsTheVerificationAndTheRuleSourcesTranslated)
{
    const TuningResult r = relayResult(EndReason::Settled);

    const i18ntest::PseudoTranslation translated({QStringLiteral("ui::words::TuningWords"), QStringLiteral("ui::ZnPanel")});
    ui::ZnPanel panel;
    panel.showResult(r);
    const QString text = panel.resultText();
    EXPECT_TRUE(text.contains(QStringLiteral("séttléd"))) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("settled"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Zíéglér–Níchóls PÍD"))) << "the rule by its (translated) name, not its id: " << text.toStdString();
    QTableWidget* rules = panel.rulesTable();
    const auto& all = motion::control::tuningRules();
    ASSERT_EQ(rules->rowCount(), static_cast<int>(all.size()));
    for (int row = 0; row < rules->rowCount(); ++row) {
        const QString source = rules->item(row, 0)->toolTip();
        EXPECT_NE(source, QString::fromUtf8(all[static_cast<std::size_t>(row)].source)) << "row " << row << " is still in English";
        EXPECT_FALSE(source.isEmpty());
    }
    EXPECT_TRUE(rules->item(0, 0)->toolTip().contains(QStringLiteral("sééd 002 Táblé 1 (Zíéglér & Níchóls 1942)")))
        << rules->item(0, 0)->toolTip().toStdString();
}

// Seen in a Chinese screenshot: "超调量 nan %". A verification that did not settle in its band
// has no overshoot to give, and says so.
TEST(TuningTranslation, AVerificationWithoutAnOvershootSaysItWasNotMeasured)
{
    TuningResult r = relayResult(EndReason::Completed);
    r.verification->metrics.overshootPct = std::numeric_limits<double>::quiet_NaN();
    ui::ZnPanel panel;
    panel.showResult(r);
    const QString text = panel.resultText();
    EXPECT_TRUE(text.contains(QStringLiteral("overshoot not measured"))) << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("nan"), Qt::CaseInsensitive)) << text.toStdString();
    r.verification->metrics.overshootPct = 12.5;
    panel.showResult(r);
    EXPECT_TRUE(panel.resultText().contains(QStringLiteral("overshoot 12.5 %"))) << panel.resultText().toStdString();
}

// Seen in the retaken screenshot at 1366 × 768: short of room, the panel squeezed its first
// three spin boxes thin. They keep the height they need; the rules table takes the shortfall.
TEST(ZnPanelLayout, ShortOfRoomTheSpinBoxesKeepTheirHeight)
{
    ui::ZnPanel panel;
    panel.resize(800, 380);
    panel.show();
    QCoreApplication::processEvents();
    const auto spins = panel.findChildren<ui::NumberField*>();
    ASSERT_GE(spins.size(), 3);
    for (ui::NumberField* s : spins) {
        if (s->isVisible()) {
            EXPECT_GE(s->height(), s->sizeHint().height()) << s->objectName().toStdString();
        }
    }
}
