// One rule for long moves on every screen. Scan once asked nothing before a
// 45 mm approach while Jog and Patterns asked; now Scan asks too (and No leaves the stage
// where it is), and the long-move question offers "Don't ask again this session": ticked
// with Yes, the next long move — on any screen — goes without asking. Destructive
// questions (homing, aborting, disconnecting) never offer it. The real dialogs are
// answered here as an operator would click them.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/jobs/scan_runner.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/axis_row.h"
#include "widgets/jog_screen.h"
#include "widgets/scan/scan_screen.h"

#include <QApplication>
#include <QCheckBox>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

/// Clicks the window's question boxes as they come up: records each, ticks its waiver
/// when asked to, and answers Yes or Cancel.
class Operator : public QObject {
public:
    struct Seen {
        QString text;
        bool offersWaiver;
    };
    Operator()
    {
        m_timer.setInterval(20);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || !box->isVisible() || box == m_last)
                return;
            m_last = box;
            seen.push_back({box->text(), box->checkBox() != nullptr});
            if (box->checkBox() && tickWaiver)
                box->checkBox()->setChecked(true);
            box->button(yes ? QMessageBox::Yes : QMessageBox::Cancel)->click();
        });
        m_timer.start();
    }
    std::vector<Seen> seen;
    bool yes = true;
    bool tickWaiver = false;

private:
    QTimer m_timer;
    QPointer<QMessageBox> m_last;
};

class TrustLongMoveTest : public ::testing::Test {
protected:
    /// The window with its dialogs (`dialogs`) or without, the stage homed with its clock sped up.
    void open(bool dialogs)
    {
        auto o = guitest::testWindowOptions();
        o.confirmDialogs = dialogs;
        w = std::make_unique<app::MainWindow>(o);
        w->resize(1500, 950);
        w->show();
        ASSERT_TRUE(waitFor([&] { return stage()->isReady(); }, 5000));
        auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
        ASSERT_NE(link, nullptr);
        link->host().setTimeScale(10);
        stage()->home(0);
        ASSERT_TRUE(waitFor([&] { return stage()->status().axes.size() >= 2 && stage()->status().axes[0].homed && stage()->status().axes[1].homed
                                         && !stage()->status().anyMoving(); }, 30000));
        link->host().setTimeScale(1);
    }
    dev::Instrument* stage() { return w->stage()->instrument(); }
    /// A scan of a few 1 mm tiles at least 40 mm from where the stage is: short to take, long to reach.
    void planAFarScan()
    {
        const double x = stage()->status().axes[0].commanded, y = stage()->status().axes[1].commanded;
        const double at = (x < 50 && y < 50) ? 60 : 5;
        motion::scan::ScanPlan p;
        p.region.cornerA = {at, at};
        p.region.cornerB = {at + 1.8, at + 1.8};
        p.camera.source = motion::scan::FieldSource::Direct;
        p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1;
        p.exposureS = 0.01;
        w->scanScreen()->setPlan(p);
        w->scanScreen()->setOutputFolder(dir.path());
        pump(100);  // the screen replans on a short timer
    }
    QTemporaryDir dir;
    std::unique_ptr<app::MainWindow> w;
};

} // namespace

TEST_F(TrustLongMoveTest, ScanAsksBeforeALongApproachAndNoLeavesTheStageWhereItIs)
{
    open(false);
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    planAFarScan();
    QStringList asked;
    w->scanScreen()->setConfirm([&](const QString& q) {
        asked << q;
        return false;
    });
    const double x = stage()->status().axes[0].commanded, y = stage()->status().axes[1].commanded;
    EXPECT_FALSE(w->scanScreen()->run());
    ASSERT_EQ(asked.size(), 1) << "a 40 mm approach went without asking";
    EXPECT_TRUE(asked[0].contains(QStringLiteral("starting with a move to"))) << asked[0].toStdString();
    pump(300);
    EXPECT_FALSE(stage()->status().anyMoving()) << "the stage moved although the operator said no";
    EXPECT_EQ(stage()->status().axes[0].commanded, x);
    EXPECT_EQ(stage()->status().axes[1].commanded, y);
    EXPECT_NE(w->scanScreen()->runner()->state(), dev::jobs::ScanRunner::State::Running);
}

TEST_F(TrustLongMoveTest, DontAskAgainWithYesLetsTheNextLongMoveOfTheSessionGoWithoutAsking)
{
    open(true);
    Operator op;
    op.tickWaiver = true;
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    planAFarScan();
    ASSERT_TRUE(w->scanScreen()->run());
    ASSERT_EQ(op.seen.size(), 1u) << "the long approach was not asked";
    EXPECT_TRUE(op.seen[0].offersWaiver) << "a long move offers \"Don't ask again this session\"";
    ASSERT_TRUE(waitFor([&] { return w->scanScreen()->runner()->state() == dev::jobs::ScanRunner::State::Finished; }, 60000));
    ASSERT_TRUE(waitFor([&] { return !stage()->status().anyMoving(); }, 5000));

    // Another screen, another long move: not asked again this session.
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    w->showInstrument(1);
    auto rows = w->jogScreen(1)->findChildren<ui::AxisRow*>();
    ASSERT_FALSE(rows.isEmpty());
    const double from = stage()->status().axes[0].commanded;
    const double to = from > 50 ? from - 45 : from + 45;
    emit rows[0]->goToRequested(0, to);
    pump(100);
    EXPECT_EQ(op.seen.size(), 1u) << "asked again after \"Don't ask again this session\": " << op.seen.back().text.toStdString();
    EXPECT_TRUE(waitFor([&] { return std::abs(stage()->status().axes[0].commanded - from) > 0.5; }, 3000)) << "the move did not go";
}

TEST_F(TrustLongMoveTest, DestructiveQuestionsNeverOfferDontAskAgain)
{
    open(true);
    Operator op;
    op.yes = false;
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    w->showInstrument(1);
    QPushButton* home = guitest::button(w->jogScreen(1), QObject::tr("Home all"));
    ASSERT_NE(home, nullptr);
    home->click();
    ASSERT_EQ(op.seen.size(), 1u) << "Home all did not ask";
    EXPECT_FALSE(op.seen[0].offersWaiver) << "homing offered \"Don't ask again\": " << op.seen[0].text.toStdString();
    pump(200);
    EXPECT_FALSE(stage()->status().anyMoving()) << "homed although the operator said no";
}
