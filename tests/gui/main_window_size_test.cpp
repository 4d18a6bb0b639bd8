// The main window must fit the screens it is used on: lab PCs and laptops at
// 1366 × 768 are common, and a window taller than the screen hides its own
// status bar and the bottom of the screen's controls.
#include "gui_window.h"
#include "widgets/wording/translators.h"

#include <QLayout>
#include <QScrollArea>
#include <QScrollBar>

#include <gtest/gtest.h>

namespace {
/// How much more room than it has the screen's content needs (0, 0 when it fits unscrolled).
QSize shortOfRoom(QWidget* window, const QString& name)
{
    auto* scroll = window->findChild<QScrollArea*>(QStringLiteral("screenScroll_%1").arg(name));
    if (!scroll || !scroll->widget())
        return QSize(100000, 100000);
    const QSize need = scroll->widget()->minimumSizeHint().expandedTo(scroll->widget()->minimumSize());
    const QSize room = scroll->maximumViewportSize();
    return QSize(std::max(0, need.width() - room.width()), std::max(0, need.height() - room.height()));
}
} // namespace

// In English and in Chinese (Chinese text is often shorter but needs more height).
class MainWindowSize : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override { ASSERT_TRUE(translators.setLanguage(QString::fromLatin1(GetParam()))); }
    void TearDown() override { translators.setLanguage(QStringLiteral("en")); }
    ui::words::Translators translators;
};

TEST_P(MainWindowSize, EveryScreenFitsA1366x768Display)
{
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 708);
    w.show();
    const QStringList names = w.screenNames();
    ASSERT_GE(names.size(), 8) << "jog, plots, profiles, tuning, joystick, patterns, plates, scan";
    for (const QString& name : names) {
        ASSERT_TRUE(w.showScreen(name));
        w.layout()->activate();
        guitest::pump(20);
        const QSize min = w.minimumSizeHint().expandedTo(w.minimumSize());
        // Room for a title bar and a panel (about 60 px) on a 768-pixel display.
        EXPECT_LE(min.height(), 708) << name.toStdString() << " needs " << min.height() << " px";
        EXPECT_LE(min.width(), 1366) << name.toStdString() << " needs " << min.width() << " px";
        // Empty, every screen fits without scrolling.
        const QSize shortBy = shortOfRoom(&w, name);
        EXPECT_EQ(shortBy, QSize(0, 0)) << name.toStdString() << " is short of " << shortBy.width() << " × " << shortBy.height() << " px";
        // And the scroll area agrees: no scroll bar where the minimum fits. Tuning scrolled by
        // 90 px with room to spare, its word-wrapped labels sizing it to its preferred height.
        auto* scroll = w.findChild<QScrollArea*>(QStringLiteral("screenScroll_%1").arg(name));
        guitest::pump(20);
        if (shortBy == QSize(0, 0) && scroll) {
            EXPECT_FALSE(scroll->verticalScrollBar()->isVisible()) << name.toStdString() << " scrolls: " << scroll->widget()->height() << " px in "
                                                                   << scroll->viewport()->height();
            EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible()) << name.toStdString();
        }
    }
}

// The failure this catches: the empty screens fitted, but the window could not go narrower
// than 1401 px and widened itself to 1547 px once Ziegler–Nichols results were
// shown, pushing E-STOP off a 1366-pixel laptop screen. The screens in their busy
// states: tuning results, files with long names, a long error in the banner.
#include "widgets/message_banner.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/tuning/tuning_screen.h"

#include <QFile>
#include <QAbstractButton>
#include <QPushButton>
#include <QTemporaryDir>

namespace {
QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

/// A copy of an example under a name as long as people give their files.
QString longNamedCopy(const QTemporaryDir& dir, const char* name, const QString& suffix)
{
    const QString to = dir.filePath(QStringLiteral("2026-11-26 reagent transfer for the serum panel, second operator, "
                                                   "revised after the calibration of the plunger (copy 3)")
                                    + suffix);
    QFile::copy(example(name), to);
    return to;
}
} // namespace

TEST_P(MainWindowSize, EveryScreenInItsBusyStatesFitsA1366x768DisplayWithEStopShown)
{
    auto w = guitest::openReadyWindow(QSize(1366, 708));
    ASSERT_TRUE(w);
    QTemporaryDir dir;
    ASSERT_TRUE(w->tuningScreen()->loadResults(longNamedCopy(dir, "stage-x-relay.tuning.json", QStringLiteral(".tuning.json"))));
    ASSERT_TRUE(w->tuningScreen()->hasResult());
    ASSERT_TRUE(w->platesScreen()->openRecipe(longNamedCopy(dir, "reagent-transfer.recipe.json", QStringLiteral(".recipe.json"))));
    w->banner()->show(ui::MessageBanner::Level::Error,
                      QStringLiteral("Stage: the controller no longer trusts its position (an alarm, an E-stop or a reset while it "
                                     "was moving). Home it, or Unlock on the Jog screen to take the position it believes."));
    for (const QString& name : w->screenNames()) {
        ASSERT_TRUE(w->showScreen(name));
        w->layout()->activate();
        guitest::pump(30);
        const QSize min = w->minimumSizeHint().expandedTo(w->minimumSize());
        EXPECT_LE(min.width(), 1366) << name.toStdString() << " needs " << min.width() << " px";
        EXPECT_LE(min.height(), 708) << name.toStdString() << " needs " << min.height() << " px";
        EXPECT_LE(w->width(), 1366) << name.toStdString() << ": the window grew itself to " << w->width() << " px";
        EXPECT_LE(w->height(), 708) << name.toStdString() << ": the window grew itself to " << w->height() << " px";
        // No button cut at the side ("Resum…" on the Plates run panel, "Import Opentrons
        // labw…" in the recipe editor).
        if (name == QLatin1String("plates"))
            w->platesScreen()->showTab(QStringLiteral("run"));
        guitest::pump(20);
        for (QAbstractButton* b : w->findChildren<QAbstractButton*>()) {
            const QRegion seen = b->visibleRegion();
            if (b->isVisible() && !seen.isEmpty()) {
                EXPECT_EQ(seen.boundingRect().width(), b->width())
                    << name.toStdString() << ": '" << b->text().toStdString() << "' is cut at the side";
            }
        }
        // Tall content may scroll; nothing scrolls sideways.
        EXPECT_EQ(shortOfRoom(w.get(), name).width(), 0) << name.toStdString() << " scrolls sideways";
        const QRect estop(w->estopButton()->mapTo(w.get(), QPoint(0, 0)), w->estopButton()->size());
        EXPECT_TRUE(QRect(0, 0, 1366, 708).contains(estop)) << name.toStdString() << ": E-STOP is off the screen";
    }
}

INSTANTIATE_TEST_SUITE_P(Languages, MainWindowSize, ::testing::Values("en", "zh_CN"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param[0] == 'e' ? "English" : "Chinese"); });

// A screen held without its height-for-width still scrolls when what it needs grows past the
// room (results shown, a long list), and stops when it shrinks back.
TEST(MainWindowScroll, AScreenScrollsOnlyWhileItsMinimumDoesNotFit)
{
    auto w = guitest::openReadyWindow(QSize(1366, 768));
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
    guitest::pump(100);
    auto* scroll = w->findChild<QScrollArea*>(QStringLiteral("screenScroll_tuning"));
    QWidget* screen = w->tuningScreen();
    ASSERT_TRUE(scroll && screen);
    EXPECT_FALSE(scroll->verticalScrollBar()->isVisible());
    EXPECT_EQ(screen->height(), scroll->viewport()->height()) << "the screen fills its room";
    screen->setMinimumHeight(scroll->viewport()->height() + 300);
    guitest::pump(100);
    EXPECT_TRUE(scroll->verticalScrollBar()->isVisible());
    EXPECT_EQ(screen->height(), scroll->viewport()->height() + 300);
    screen->setMinimumHeight(0);
    guitest::pump(100);
    EXPECT_FALSE(scroll->verticalScrollBar()->isVisible());
    EXPECT_EQ(screen->height(), scroll->viewport()->height());
}
