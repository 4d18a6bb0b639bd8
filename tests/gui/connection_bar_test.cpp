// The connection bar: a path typed into the port list is what
// connects (the pty benchpilot-sim serves), 115200 Bd is offered and chosen by default, and a
// machine profile can be chosen, remembered and cleared — the choice carries it to the session.
#include "widgets/connection_bar.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

namespace {

QComboBox* combo(ui::ConnectionBar& bar, int index) { return bar.findChildren<QComboBox*>().value(index); }

TEST(ConnectionBar, ATypedPathIsThePortThatConnects)
{
    ui::ConnectionBar bar(QStringLiteral("Stage"));
    QComboBox* source = combo(bar, 0);
    ASSERT_NE(source, nullptr);
    ASSERT_TRUE(source->isEditable());
    EXPECT_TRUE(bar.choice().simulator);
    source->lineEdit()->setText(QStringLiteral("/tmp/ttyBP-grbl"));
    const ui::ConnectionChoice c = bar.choice();
    EXPECT_FALSE(c.simulator);
    EXPECT_EQ(c.port, QStringLiteral("/tmp/ttyBP-grbl"));
    EXPECT_EQ(c.baud, 115200);
    // Return connects what was typed.
    QSignalSpy asked(&bar, &ui::ConnectionBar::connectRequested);
    QTest::keyClick(source->lineEdit(), Qt::Key_Return);
    ASSERT_TRUE(asked.wait(2000));
    QCoreApplication::processEvents();
    ASSERT_EQ(asked.count(), 1);
    EXPECT_EQ(asked.front().front().value<ui::ConnectionChoice>().port, QStringLiteral("/tmp/ttyBP-grbl"));
    // A remembered port is kept even when it is not there now.
    ui::ConnectionChoice remembered;
    remembered.simulator = false;
    remembered.port = QStringLiteral("/dev/ttyNOPE0");
    bar.setChoice(remembered);
    EXPECT_EQ(bar.choice().port, QStringLiteral("/dev/ttyNOPE0"));
}

TEST(ConnectionBar, OffersGrblsBaudRateAndAMachineProfile)
{
    ui::ConnectionBar bar(QStringLiteral("Analyzer"));
    EXPECT_TRUE(ui::ConnectionBar::baudRates().contains(115200));
    QComboBox* baud = combo(bar, 1);
    EXPECT_EQ(baud->currentText(), QStringLiteral("115200"));
    EXPECT_TRUE(bar.choice().profile.isEmpty());
    QSignalSpy wantsFile(&bar, &ui::ConnectionBar::profileFileRequested);
    QComboBox* profile = combo(bar, 2);
    ASSERT_NE(profile, nullptr);
    // The last entry asks for a file (the composition root shows the dialog) and keeps the choice.
    profile->setCurrentIndex(profile->count() - 1);
    emit profile->activated(profile->count() - 1);
    EXPECT_EQ(wantsFile.count(), 1);
    EXPECT_TRUE(bar.choice().profile.isEmpty());
    bar.addProfile(QStringLiteral("/profiles/stage-grbl-uno.machine.json"));
    EXPECT_EQ(bar.choice().profile, QStringLiteral("/profiles/stage-grbl-uno.machine.json"));
    EXPECT_EQ(profile->currentText(), QStringLiteral("stage-grbl-uno.machine.json"));
    EXPECT_EQ(bar.profiles(), QStringList{QStringLiteral("/profiles/stage-grbl-uno.machine.json")});
    // Back to the default wiring.
    ui::ConnectionChoice c = bar.choice();
    c.profile.clear();
    bar.setChoice(c);
    EXPECT_TRUE(bar.choice().profile.isEmpty());
    // Connected: nothing to change, and the controls say why.
    bar.showState(dev::LinkState::Ready, QStringLiteral("GRBL"));
    EXPECT_FALSE(profile->isEnabled());
    EXPECT_TRUE(profile->toolTip().contains(QStringLiteral("Disconnect"))) << profile->toolTip().toStdString();
}

} // namespace
