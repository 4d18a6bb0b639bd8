// The main window must fit the screens it is used on: lab PCs and laptops at
// 1366 × 768 are common, and a window taller than the screen hides its own
// status bar and the bottom of the screen's controls.
#include "gui_window.h"

#include <QLayout>

#include <gtest/gtest.h>

TEST(MainWindowSize, EveryScreenFitsA1366x768Display)
{
    app::MainWindow w(guitest::testWindowOptions());
    w.show();
    const QStringList names = w.screenNames();
    ASSERT_GE(names.size(), 8) << "jog, plots, profiles, tuning, joystick, patterns, plates, scan";
    for (const QString& name : names) {
        ASSERT_TRUE(w.showScreen(name));
        w.layout()->activate();
        const QSize min = w.minimumSizeHint().expandedTo(w.minimumSize());
        // Room for a title bar and a panel (about 60 px) on a 768-pixel display.
        EXPECT_LE(min.height(), 708) << name.toStdString() << " needs " << min.height() << " px";
        EXPECT_LE(min.width(), 1366) << name.toStdString() << " needs " << min.width() << " px";
    }
}
