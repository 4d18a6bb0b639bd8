// The Patterns screen's Run / Pause / Abort driven through its buttons and their keys (F5, F6,
// F8) on the simulated stage: a pause brings the machine to rest on the path and holds it there,
// resume finishes the pattern, abort stops and leaves the screen ready for the next run.
#include "device/jobs/pattern_runner.h"
#include "patterns_fixture.h"
#include "widgets/patterns/pattern_screen.h"

#include <QPushButton>
#include <QRegularExpression>

#include "widgets/message_banner.h"

#include <cmath>

using guitest::MotionScreensTest;
using guitest::pump;
using guitest::waitFor;
using State = dev::jobs::PatternRunner::State;

namespace {

class PatternRunControls : public MotionScreensTest {
protected:
    static constexpr double kLengthMm = 5.0;
    const motion::path::Vec2 from{0.5, 0.5}, to{3.5, 4.5};  // 5 mm at 1.5 mm/s: over 3 s

    /// The stage homed, the Patterns screen on show with the line in its form, the buttons found.
    void SetUp() override
    {
        MotionScreensTest::SetUp();
        ASSERT_TRUE(homeStage());
        ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
        p = w->motionScreens()->patterns();
        p->setInstrument(1);
        motion::plans::Pattern pat;
        pat.shape = motion::plans::PatternShape::Line;
        pat.feedMmS = 1.5;
        pat.line = {from, to};
        p->setPattern(pat);
        for (QPushButton* b : p->findChildren<QPushButton*>()) {
            if (b->text() == QStringLiteral("Run"))
                runButton = b;
            else if (b->text() == QStringLiteral("Pause"))
                pauseButton = b;
            else if (b->text() == QStringLiteral("Abort"))
                abortButton = b;
        }
        ASSERT_TRUE(runButton && pauseButton && abortButton);
        ASSERT_TRUE(waitFor([&] { return runButton->isEnabled(); }, 2000));
        EXPECT_FALSE(pauseButton->isEnabled());
        EXPECT_FALSE(abortButton->isEnabled());
    }
    dev::jobs::PatternRunner* runner() { return p->runner(); }
    motion::path::Vec2 measured()
    {
        const auto& a = stage()->status().axes;
        return {a[0].measured, a[1].measured};
    }
    motion::path::Vec2 commanded()
    {
        const auto& a = stage()->status().axes;
        return {a[0].commanded, a[1].commanded};
    }
    /// Distance along the line and off it (mm) of a point.
    std::pair<double, double> onLine(motion::path::Vec2 q) const
    {
        const double ux = (to.x - from.x) / kLengthMm, uy = (to.y - from.y) / kLengthMm;
        const double dx = q.x - from.x, dy = q.y - from.y;
        return {dx * ux + dy * uy, std::fabs(dx * uy - dy * ux)};
    }
    bool atRest()
    {
        const auto& a = stage()->status().axes;
        return !a[0].moving && !a[1].moving;
    }
    /// Running and at least `mm` along the line.
    bool runningPast(double mm) { return runner()->state() == State::Running && onLine(measured()).first > mm; }
    /// The buttons as they must be once a run has ended, whichever way.
    void expectReadyForTheNextRun()
    {
        EXPECT_TRUE(runButton->isEnabled());
        EXPECT_FALSE(pauseButton->isEnabled());
        EXPECT_FALSE(abortButton->isEnabled());
        EXPECT_EQ(pauseButton->text(), QStringLiteral("Pause"));
    }
    ui::PatternScreen* p = nullptr;
    QPushButton* runButton = nullptr;
    QPushButton* pauseButton = nullptr;
    QPushButton* abortButton = nullptr;
};

}  // namespace

TEST_F(PatternRunControls, PauseHoldsTheMachineOnThePathAndResumeFinishesThePattern)
{
    QTest::keyClick(w.get(), Qt::Key_F5);  // Run
    ASSERT_TRUE(waitFor([&] { return runningPast(1.0); }, 10000)) << p->statusText().toStdString();
    EXPECT_FALSE(runButton->isEnabled());
    EXPECT_TRUE(pauseButton->isEnabled());
    EXPECT_TRUE(abortButton->isEnabled());

    QTest::mouseClick(pauseButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Paused; }, 5000)) << p->statusText().toStdString();
    EXPECT_EQ(pauseButton->text(), QStringLiteral("Resume"));
    EXPECT_TRUE(pauseButton->isEnabled());
    EXPECT_FALSE(runButton->isEnabled());
    ASSERT_TRUE(waitFor([&] { return atRest(); }, 3000));
    const auto held = measured();
    const auto [along, off] = onLine(held);
    EXPECT_GT(along, 1.0);
    EXPECT_LT(along, kLengthMm - 0.1) << "the pause came too late to hold anywhere but the end";
    EXPECT_LT(off, 0.005) << "the machine left the path to stop";
    const auto heldRef = commanded();
    pump(500);
    EXPECT_EQ(runner()->state(), State::Paused);
    EXPECT_EQ(commanded().x, heldRef.x) << "a paused run crept on";
    EXPECT_EQ(commanded().y, heldRef.y) << "a paused run crept on";
    EXPECT_NEAR(measured().x, held.x, 0.002);  // the grating's count may flicker by one
    EXPECT_NEAR(measured().y, held.y, 0.002);

    QTest::keyClick(w.get(), Qt::Key_F6);  // Resume
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Done; }, 15000)) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return atRest(); }, 3000));
    EXPECT_NEAR(stage()->status().axes[0].commanded, to.x, 0.001);
    EXPECT_NEAR(stage()->status().axes[1].commanded, to.y, 0.001);
    expectReadyForTheNextRun();
}

TEST_F(PatternRunControls, AbortStopsOnThePathAndTheNextRunCanStartAndBeAbortedWhilePaused)
{
    QTest::mouseClick(runButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runningPast(1.0); }, 10000)) << p->statusText().toStdString();
    QTest::keyClick(w.get(), Qt::Key_F8);  // Abort
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Aborted; }, 5000)) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return atRest(); }, 3000));
    const auto [along, off] = onLine(measured());
    EXPECT_LT(along, kLengthMm - 0.1) << "the abort came too late to stop anywhere but the end";
    EXPECT_LT(off, 0.005);
    expectReadyForTheNextRun();

    // Run again (it goes back to the start first), pause with F6, then abort the paused run.
    QTest::mouseClick(runButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runner()->busy(); }, 2000)) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return runningPast(0.5); }, 15000)) << p->statusText().toStdString();
    QTest::keyClick(w.get(), Qt::Key_F6);
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Paused && atRest(); }, 5000)) << p->statusText().toStdString();
    const auto held = commanded();
    QTest::mouseClick(abortButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Aborted; }, 5000)) << p->statusText().toStdString();
    pump(300);
    EXPECT_EQ(commanded().x, held.x) << "aborting a paused run moved the machine";
    EXPECT_EQ(commanded().y, held.y) << "aborting a paused run moved the machine";
    expectReadyForTheNextRun();
}

// The failure this catches: the status said "segment 2 of 4, 15.7 mm done" while the stage was at
// 17.6 mm in segment 3, and an aborted run's summary said "time 0.0 s".
TEST_F(PatternRunControls, StatusSaysWhereTheMachineIsAndAnAbortedRunKeepsItsTime)
{
    QTest::mouseClick(runButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runningPast(2.0); }, 10000)) << p->statusText().toStdString();
    pump(150);  // a few samples more
    const double along = onLine(measured()).first;
    const QString status = p->statusText();
    EXPECT_TRUE(status.contains(QStringLiteral("segment 1 of 1"))) << status.toStdString();
    const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("([0-9]+[.,][0-9]) mm done")).match(status);
    ASSERT_TRUE(m.hasMatch()) << status.toStdString();
    EXPECT_NEAR(QString(m.captured(1)).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(), along, 0.4)
        << status.toStdString() << " with the stage " << along << " mm along the line";

    QTest::mouseClick(abortButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !runner()->busy(); }, 5000));
    EXPECT_GT(runner()->summary().durationS, 1.0) << "an aborted run after more than 1.3 s";
    EXPECT_FALSE(runner()->summary().complete);
}

// The failure this catches: after a pulled cable the button said "Continue" while the message said
// "press Resume".
TEST_F(PatternRunControls, TheButtonAfterALostLinkSaysTheWordTheMessageUses)
{
    QTest::mouseClick(runButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runningPast(1.0); }, 10000)) << p->statusText().toStdString();
    w->stage()->disconnectLink();
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Interrupted; }, 5000));
    pump(50);
    QString said;
    for (const QString& t : w->banner()->texts())
        if (t.contains(QStringLiteral("Resume")) || t.contains(QStringLiteral("Continue")))
            said = t;
    ASSERT_TRUE(said.contains(QStringLiteral("press "))) << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("press ") + pauseButton->text())) << said.toStdString() << " / button "
                                                                                << pauseButton->text().toStdString();
}

// A pattern loaded while one runs would replace the path on screen with
// one the machine is not following. Load… is held back, saying why, until the run ends.
TEST_F(PatternRunControls, LoadIsHeldBackWhileAPatternRuns)
{
    QPushButton* load = guitest::button(p, QStringLiteral("Load…"));
    ASSERT_NE(load, nullptr);
    EXPECT_TRUE(load->isEnabled());
    QTest::mouseClick(runButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runningPast(0.5); }, 10000)) << p->statusText().toStdString();
    EXPECT_FALSE(load->isEnabled()) << "Load… offered while a pattern runs";
    EXPECT_FALSE(load->toolTip().isEmpty()) << "held back without saying why";
    QTest::mouseClick(abortButton, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return runner()->state() == State::Aborted; }, 5000)) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return load->isEnabled(); }, 3000)) << "Load… still held after the run";
}
