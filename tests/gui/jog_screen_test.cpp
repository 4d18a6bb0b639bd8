// The Jog screen driven as a person would: buttons, keys, E-stop, against the
// in-process simulators.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "app/gui/screenshot.h"
#include "gui_wait.h"
#include "widgets/event_log.h"
#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"

#include <QDir>
#include <QImage>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

app::MainWindowOptions testOptions()
{
    app::MainWindowOptions o;
    o.persistSettings = false;
    o.confirmDialogs = false;
    return o;
}

QList<QToolButton*> buttonsWithText(QWidget* root, const QString& text)
{
    QList<QToolButton*> out;
    for (auto* b : root->findChildren<QToolButton*>())
        if (b->text() == text)
            out << b;
    return out;
}

QPushButton* pushButton(QWidget* root, const QString& text)
{
    for (auto* b : root->findChildren<QPushButton*>())
        if (b->text() == text)
            return b;
    return nullptr;
}

class JogScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = std::make_unique<app::MainWindow>(testOptions());
        w->resize(1500, 900);
        w->show();
        ASSERT_TRUE(waitFor([&] { return w->analyzer()->instrument()->isReady() && w->stage()->instrument()->isReady(); }, 5000));
    }
    dev::Instrument* analyzer() { return w->analyzer()->instrument(); }
    std::unique_ptr<app::MainWindow> w;
};

TEST_F(JogScreenTest, HoldButtonMovesTheAxisAndReleaseStopsIt)
{
    ui::JogScreen* jog = w->jogScreen(0);
    const auto holdPlus = buttonsWithText(jog, QStringLiteral("▶▶"));
    ASSERT_EQ(holdPlus.size(), 4);  // X, Y, Z, P
    const double before = analyzer()->status().axes[0].commanded;
    QTest::mousePress(holdPlus[0], Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return analyzer()->status().axes[0].commanded > before + 0.5; }, 3000));
    EXPECT_TRUE(analyzer()->status().axes[0].moving);
    QTest::mouseRelease(holdPlus[0], Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !analyzer()->status().axes[0].moving; }, 3000));
    const double stoppedAt = analyzer()->status().axes[0].commanded;
    pump(300);
    EXPECT_DOUBLE_EQ(analyzer()->status().axes[0].commanded, stoppedAt) << "the axis crept on after release";
    EXPECT_NEAR(analyzer()->status().axes[1].commanded, 0.0, 1e-6) << "Y moved though only X was held";
}

TEST_F(JogScreenTest, StepButtonMovesByTheChosenStep)
{
    ui::JogScreen* jog = w->jogScreen(0);
    const auto plus = buttonsWithText(jog, QStringLiteral("+"));
    ASSERT_EQ(plus.size(), 4);
    const double before = analyzer()->status().axes[1].commanded;
    QTest::mouseClick(plus[1], Qt::LeftButton);  // Y, default preset 1 mm
    ASSERT_TRUE(waitFor([&] { return analyzer()->status().axes[1].commanded > before + 0.999 && !analyzer()->status().axes[1].moving; }, 4000));
    EXPECT_NEAR(analyzer()->status().axes[1].commanded - before, 1.0, 1e-6);
}

TEST_F(JogScreenTest, ArrowKeyHoldsJogAndKeyReleaseStops)
{
    ui::JogScreen* jog = w->jogScreen(0);
    w->activateWindow();
    jog->setFocus();
    const double before = analyzer()->status().axes[0].commanded;
    QTest::keyPress(jog, Qt::Key_Left);
    ASSERT_TRUE(waitFor([&] { return analyzer()->status().axes[0].commanded < before - 0.3; }, 3000));
    QTest::keyRelease(jog, Qt::Key_Left);
    ASSERT_TRUE(waitFor([&] { return !analyzer()->status().axes[0].moving; }, 3000));
    EXPECT_FALSE(analyzer()->isJogging(0));
}

TEST_F(JogScreenTest, EscapeIsEStopFromAnyScreenAndResetClearsIt)
{
    ui::JogScreen* jog = w->jogScreen(0);
    const auto holdPlus = buttonsWithText(jog, QStringLiteral("▶▶"));
    QTest::mousePress(holdPlus[2], Qt::LeftButton);  // Z
    ASSERT_TRUE(waitFor([&] { return analyzer()->status().axes[2].moving; }, 3000));
    w->showScreen(w->screenNames().last());  // E-stop must work whatever screen is showing
    QTest::keyClick(w.get(), Qt::Key_Escape);
    ASSERT_TRUE(waitFor([&] { return analyzer()->status().estop && !analyzer()->status().axes[2].moving; }, 3000));
    QTest::mouseRelease(holdPlus[2], Qt::LeftButton);
    const double frozen = analyzer()->status().axes[2].commanded;
    pump(200);
    EXPECT_DOUBLE_EQ(analyzer()->status().axes[2].commanded, frozen);
    EXPECT_EQ(w->banner()->level(), ui::MessageBanner::Level::Error);

    // While latched, motion is refused with a reason the operator sees.
    std::optional<dev::RequestError> refusal;
    analyzer()->jogStep(0, 1.0, 0, [&](const auto& e) { refusal = e; });
    ASSERT_TRUE(waitFor([&] { return refusal.has_value(); }, 2000));
    EXPECT_EQ(refusal->code, dev::proto::ErrorCode::EStopActive);

    QPushButton* reset = pushButton(w.get(), QObject::tr("Reset E-stop"));
    ASSERT_NE(reset, nullptr);
    ASSERT_TRUE(waitFor([&] { return reset->isVisible(); }, 2000));
    QTest::mouseClick(reset, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !analyzer()->status().estop; }, 2000));
    // The E-stop's message and the refusal it caused end with the latch: nothing on the strip still says E-stop.
    for (const QString& t : w->banner()->texts())
        EXPECT_FALSE(t.contains(QStringLiteral("E-STOP")) || t.contains(QStringLiteral("latched"))) << t.toStdString();
    EXPECT_TRUE(w->banner()->text().contains(QStringLiteral("E-stop cleared"))) << w->banner()->text().toStdString();
    bool eventLogged = false;
    for (int r = 0; r < w->eventLog()->rowCount(); ++r)
        eventLogged = eventLogged || w->eventLog()->rowText(r).contains(QStringLiteral("E-stop"));
    EXPECT_TRUE(eventLogged);
}

TEST_F(JogScreenTest, GoToIsOnlyOfferedOnHomedAxes)
{
    ui::JogScreen* jog = w->jogScreen(1);
    w->showInstrument(1);
    QList<QPushButton*> gos;
    for (auto* b : jog->findChildren<QPushButton*>())
        if (b->text() == QObject::tr("Go"))
            gos << b;
    ASSERT_EQ(gos.size(), 2);
    pump(200);
    EXPECT_FALSE(gos[0]->isEnabled()) << "absolute move offered on an unhomed axis";
    w->stage()->instrument()->home(0);
    ASSERT_TRUE(waitFor([&] { return w->stage()->instrument()->status().axes[0].homed && w->stage()->instrument()->status().axes[1].homed; }, 30000));
    pump(200);
    EXPECT_TRUE(gos[0]->isEnabled());
}

TEST(Screenshot, WritesTheRequestedScreenToAPng)
{
    QTemporaryDir dir;
    app::ScreenshotRequest r;
    r.file = dir.filePath(QStringLiteral("jog.png"));
    r.screen = QStringLiteral("jog");
    r.instrument = QStringLiteral("stage");
    r.settleMs = 100;
    ASSERT_EQ(app::takeScreenshot(r), 0);
    QImage img(r.file);
    ASSERT_FALSE(img.isNull());
    EXPECT_EQ(img.width(), 1600);
    r.screen = QStringLiteral("no-such-screen");
    EXPECT_NE(app::takeScreenshot(r), 0);
}

} // namespace
