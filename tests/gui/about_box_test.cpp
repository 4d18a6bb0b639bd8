// Help → About BenchPilot: the version, the Qt the program runs on, its licence and the
// libraries it is made of with theirs; in Chinese when the screens are, and reworded
// when the language changes while it is open.
#include "app/gui/about_dialog.h"

#include "widgets/wording/translators.h"

#include <QApplication>
#include <QDir>
#include <QLabel>
#include <QMainWindow>
#include <QMenuBar>

#include <gtest/gtest.h>

namespace {

QString shownText(app::AboutDialog* box)
{
    QString all;
    for (auto* l : box->findChildren<QLabel*>())
        all += l->text();
    return all;
}

TEST(AboutBox, SaysTheVersionTheQtTheLicenceAndTheLibraries)
{
    QMainWindow window;
    auto* help = new app::HelpMenu(&window);
    window.menuBar()->addMenu(help);
    window.show();
    EXPECT_EQ(help->title(), QStringLiteral("&Help"));
    help->aboutAction()->trigger();
    auto* box = window.findChild<app::AboutDialog*>();
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->isVisible());
    EXPECT_EQ(box->windowTitle(), QStringLiteral("About BenchPilot"));
    const QString text = shownText(box);
    for (const QString& want : {QStringLiteral("BenchPilot " BP_VERSION), QString::fromLatin1(qVersion()), QStringLiteral("GPL-3.0-or-later"),
                                QStringLiteral("QCustomPlot"), QStringLiteral("Eigen"), QStringLiteral("MPL-2.0"), QStringLiteral("LGPL-3.0"),
                                QStringLiteral("NO WARRANTY")})
        EXPECT_TRUE(text.contains(want)) << want.toStdString() << " not in: " << text.toStdString();
    // BP_GUI_SHOTS=DIR keeps a picture of the box for a person to look at.
    if (const QString folder = qEnvironmentVariable("BP_GUI_SHOTS"); !folder.isEmpty())
        box->grab().save(QDir(folder).filePath(QStringLiteral("about_box.png")));
    // A second click brings the same box forward rather than a second one.
    help->aboutAction()->trigger();
    EXPECT_EQ(window.findChildren<app::AboutDialog*>().size(), 1);
}

TEST(AboutBox, IsInChineseWhenTheScreensAre)
{
    QMainWindow window;
    auto* help = new app::HelpMenu(&window);
    window.menuBar()->addMenu(help);
    help->aboutAction()->trigger();
    auto* box = window.findChild<app::AboutDialog*>();
    ASSERT_NE(box, nullptr);
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(help->title(), QStringLiteral("帮助(&H)"));
    EXPECT_EQ(box->windowTitle(), QStringLiteral("关于 BenchPilot"));
    const QString text = shownText(box);
    EXPECT_TRUE(text.contains(QStringLiteral("自由软件"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("GPL-3.0-or-later"))) << text.toStdString();
    translators.setLanguage(QStringLiteral("en"));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(box->windowTitle(), QStringLiteral("About BenchPilot"));
}

} // namespace
