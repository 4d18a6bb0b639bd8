// The Profiles screen, offscreen: kinds, limits, curves, move time and the step table.
#include "widgets/profiles_screen.h"

#include <gtest/gtest.h>

#include <qcustomplot.h>

#include <QApplication>
#include <QComboBox>
#include "widgets/common/number_field.h"
#include <QLabel>
#include <QTableView>
#include <QTest>

namespace {

QApplication& app()
{
    static int argc = 1;
    static char name[] = "profiles_screen_test";
    static char* argv[] = {name, nullptr};
    static QApplication* instance = qobject_cast<QApplication*>(QCoreApplication::instance());
    if (!instance)
        instance = new QApplication(argc, argv);
    return *instance;
}

ui::NumberField* field(ui::ProfilesScreen& s, const char* name)
{
    auto* box = s.findChild<ui::NumberField*>(QString::fromLatin1(name));
    EXPECT_NE(box, nullptr) << name;
    return box;
}

void settle()
{
    QTest::qWait(150);  // the screen coalesces edits on a 60 ms timer
}

}  // namespace

TEST(ProfilesScreen, JerkLimitedDefaultShowsCurvesTimeAndTable)
{
    app();
    ui::ProfilesScreen screen;
    screen.resize(1200, 800);
    screen.show();
    settle();
    field(screen, "distance")->setValue(120);
    field(screen, "vmax")->setValue(100);
    field(screen, "amax")->setValue(1000);
    field(screen, "jmax")->setValue(10000);
    field(screen, "step")->setValue(0.01);
    settle();
    EXPECT_NEAR(screen.moveTimeS(), 1.4, 1e-9);
    EXPECT_TRUE(screen.findChild<QLabel*>(QStringLiteral("moveTime"))->text().contains(QLatin1String("1.4000")));
    EXPECT_EQ(screen.stepTableRows(), 12000);
    auto* velocity = screen.findChild<QCustomPlot*>(QStringLiteral("plotVelocity"));
    ASSERT_NE(velocity, nullptr);
    EXPECT_GT(velocity->graph(0)->dataCount(), 100);
    EXPECT_NEAR(velocity->yAxis->range().upper, 100, 20);
    // The seed's 72 MHz / 50 µs split is visible in the table.
    auto* table = screen.findChild<QTableView*>(QStringLiteral("stepTable"));
    ASSERT_NE(table, nullptr);
    const QString whole = table->model()->index(6000, 2).data().toString();
    const QString ticks = table->model()->index(6000, 1).data().toString();
    EXPECT_EQ(ticks, QStringLiteral("7200"));  // 100 mm/s at 0.01 mm/step = 10 kHz = 7200 ticks
    EXPECT_EQ(whole, QStringLiteral("2"));
}

TEST(ProfilesScreen, KindChoosesWhichLimitsApplyAndBadLimitsExplainThemselves)
{
    app();
    ui::ProfilesScreen screen;
    screen.show();
    auto* kind = screen.findChild<QComboBox*>(QStringLiteral("kind"));
    ASSERT_NE(kind, nullptr);
    kind->setCurrentIndex(0);  // seed S-curve: acceleration time, no jerk field
    settle();
    EXPECT_TRUE(field(screen, "accelTime")->isVisible());
    EXPECT_FALSE(field(screen, "jmax")->isVisible());
    field(screen, "distance")->setValue(30);
    field(screen, "vmax")->setValue(37.5);
    field(screen, "accelTime")->setValue(0.1);
    settle();
    EXPECT_NEAR(screen.moveTimeS(), 0.9, 1e-9);  // seed 000 Table 2, x axis to 30 mm

    kind->setCurrentIndex(3);
    field(screen, "jmax")->setValue(0);
    settle();
    EXPECT_LT(screen.moveTimeS(), 0);
    auto* error = screen.findChild<QLabel*>(QStringLiteral("error"));
    ASSERT_NE(error, nullptr);
    EXPECT_TRUE(error->isVisible());
    EXPECT_TRUE(error->text().contains(QLatin1String("jMaxMmS3 = 0"))) << error->text().toStdString();
    EXPECT_EQ(screen.stepTableRows(), 0);
}

TEST(ProfilesScreen, HugeTablesAreRefusedWithAHint)
{
    app();
    ui::ProfilesScreen screen;
    field(screen, "distance")->setValue(1000);
    field(screen, "step")->setValue(0.0001);
    settle();
    EXPECT_EQ(screen.stepTableRows(), 0);
    EXPECT_TRUE(screen.findChild<QLabel*>(QStringLiteral("tableSummary"))->text().contains(QLatin1String("too many")));
    EXPECT_GT(screen.moveTimeS(), 0);
}
