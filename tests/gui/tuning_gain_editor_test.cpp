// The gain editor read key by key, as an operator types: what the screen says
// (the discrete gains, Ti and Td, the reason a set cannot be applied, Apply and
// Revert) follows the text in the field after every key, never the one before.
#include "widgets/common/number_field.h"
#include "widgets/tuning/gains_panel.h"

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

namespace {

class GainEditorTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        // The stage's gains at power-up: Kp 0.25, Ki 500 /s, Kd 30 µs on a 1 ms loop.
        panel.setTarget(QStringLiteral("Stage X"), 1e-3, true, {0.25, 0.5, 0.03}, QStringLiteral("read from the device"));
        panel.show();
        panel.activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(&panel)) << "focus moves only in an active window";
    }
    ui::NumberField* field(const char* name) { return panel.findChild<ui::NumberField*>(QLatin1String(name)); }
    QString label(const char* name) { return panel.findChild<QLabel*>(QLatin1String(name))->text(); }
    QPushButton* button(const char* name) { return panel.findChild<QPushButton*>(QLatin1String(name)); }
    /// Replaces the field's text by typing `text` key by key.
    void retype(const char* name, const QString& text)
    {
        ui::NumberField* f = field(name);
        f->setFocus();
        f->selectAll();
        QTest::keyClicks(f, text);
    }
    ui::GainsPanel panel;
};

} // namespace

TEST_F(GainEditorTest, AValidEntryAfterAnInvalidOneIsReadAtOnce)
{
    retype("kpEdit", QStringLiteral("abc"));
    EXPECT_TRUE(label("gainsNote").contains(QStringLiteral("“abc” is not a number"))) << label("gainsNote").toStdString();
    EXPECT_FALSE(button("gainsApply")->isEnabled());
    retype("kpEdit", QStringLiteral("2"));
    EXPECT_FALSE(label("gainsNote").contains(QStringLiteral("abc"))) << "the message is one key behind: " << label("gainsNote").toStdString();
    EXPECT_TRUE(button("gainsApply")->isEnabled()) << "Apply stays disabled for a valid Kp";
    EXPECT_EQ(label("kpDiscrete"), QStringLiteral("kp = 2"));
}

TEST_F(GainEditorTest, BackspaceIsShownAtOnce)
{
    retype("kpEdit", QStringLiteral("20"));
    EXPECT_EQ(label("kpDiscrete"), QStringLiteral("kp = 20"));
    QTest::keyClick(field("kpEdit"), Qt::Key_Backspace);
    ASSERT_EQ(field("kpEdit")->text(), QStringLiteral("2"));
    EXPECT_EQ(label("kpDiscrete"), QStringLiteral("kp = 2")) << "the field shows 2";
    // Ti = Kp/Ki = 2 / 500 /s.
    EXPECT_TRUE(label("gainsNote").startsWith(QStringLiteral("Ti = Kp/Ki = 4 ms"))) << label("gainsNote").toStdString();
    const auto g = panel.edited();
    ASSERT_TRUE(g.has_value());
    EXPECT_DOUBLE_EQ(g->kp, 2);
}

TEST_F(GainEditorTest, ANumberBeingTypedIsNotAnErrorUntilTheOperatorLeavesTheField)
{
    ui::NumberField* kp = field("kpEdit");
    retype("kpEdit", QStringLiteral("-"));
    EXPECT_TRUE(kp->isIncomplete());
    EXPECT_FALSE(kp->value().has_value());
    EXPECT_FALSE(label("gainsNote").contains(QStringLiteral("not a number"))) << label("gainsNote").toStdString();
    EXPECT_FALSE(kp->toolTip().contains(QStringLiteral("not a number"))) << kp->toolTip().toStdString();
    EXPECT_FALSE(kp->property("invalid").toBool()) << "marked red after the first key";
    EXPECT_FALSE(button("gainsApply")->isEnabled()) << "nothing is sent while it is no number";

    QTest::keyClick(kp, Qt::Key_5);
    EXPECT_TRUE(label("gainsNote").contains(QStringLiteral("0 or more"))) << label("gainsNote").toStdString();
    EXPECT_TRUE(kp->property("invalid").toBool());

    // Left as "-": now it is an error, and says so.
    retype("kpEdit", QStringLiteral("-"));
    kp->clearFocus();
    EXPECT_FALSE(kp->isIncomplete());
    EXPECT_TRUE(label("gainsNote").contains(QStringLiteral("“-” is not a number"))) << label("gainsNote").toStdString();
    EXPECT_TRUE(kp->property("invalid").toBool());

    // An exponent on its way: "1e" is no error while typing, "1e-3" is a number.
    retype("kdEdit", QStringLiteral("1e"));
    EXPECT_TRUE(field("kdEdit")->isIncomplete());
    QTest::keyClicks(field("kdEdit"), QStringLiteral("-3"));
    EXPECT_TRUE(field("kdEdit")->isValid());
}

TEST_F(GainEditorTest, RevertTakesBackEditsNotYetApplied)
{
    QSignalSpy applied(&panel, &ui::GainsPanel::applyRequested);
    QSignalSpy reverted(&panel, &ui::GainsPanel::revertRequested);
    EXPECT_FALSE(button("gainsRevert")->isEnabled()) << "nothing to take back yet";
    retype("kpEdit", QStringLiteral("0.4"));
    EXPECT_TRUE(button("gainsRevert")->isEnabled()) << "Revert stays disabled while an edit is not applied";
    QTest::mouseClick(button("gainsRevert"), Qt::LeftButton);
    EXPECT_EQ(field("kpEdit")->text(), QStringLiteral("0.25"));
    EXPECT_EQ(applied.count(), 0);
    EXPECT_EQ(reverted.count(), 0) << "taking back an edit sends nothing";
    EXPECT_FALSE(button("gainsRevert")->isEnabled());

    // Something that is no number is taken back too.
    retype("kiEdit", QStringLiteral("abc"));
    EXPECT_TRUE(button("gainsRevert")->isEnabled());
    QTest::mouseClick(button("gainsRevert"), Qt::LeftButton);
    EXPECT_EQ(field("kiEdit")->text(), QStringLiteral("500"));
    EXPECT_TRUE(button("gainsApply")->isEnabled());
}
