// Every text a screen shows went through translation: with a pseudo-translation of
// every context installed before the window is built, no label, button, tab, column
// header, combo item, placeholder or tooltip may still read as plain English. The
// screens listed in kPending still build some texts outside tr() or before the
// language is known; issue 17's phase 2 reworks them (retranslateUi) and moves them
// to kChecked. The walk prints what it found on every screen either way.
#include "gui_window.h"

#include "../device/pseudo_translation.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTabWidget>
#include <QTableWidget>

#include <gtest/gtest.h>

namespace {

/// Visible texts of `root` and its visible children that still read as English.
QStringList englishOn(QWidget* root)
{
    QStringList out;
    auto check = [&out](const QString& where, const QString& text) {
        for (const QString& w : i18ntest::untranslated(text))
            out << QStringLiteral("%1: \"%2\" in \"%3\"").arg(where, w, text.left(80));
    };
    QList<QWidget*> all = root->findChildren<QWidget*>();
    all.prepend(root);
    for (QWidget* w : all) {
        if (!w->isVisibleTo(root->window()))
            continue;
        const QString name = QString::fromLatin1(w->metaObject()->className());
        check(name + QStringLiteral(" tooltip"), w->toolTip());
        if (auto* l = qobject_cast<QLabel*>(w))
            check(name, l->text());
        if (auto* b = qobject_cast<QAbstractButton*>(w))
            check(name, b->text());
        if (auto* g = qobject_cast<QGroupBox*>(w))
            check(name, g->title());
        if (auto* e = qobject_cast<QLineEdit*>(w))
            check(name + QStringLiteral(" placeholder"), e->placeholderText());
        if (auto* c = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < c->count(); ++i)
                check(name, c->itemText(i));
        if (auto* t = qobject_cast<QTabWidget*>(w))
            for (int i = 0; i < t->count(); ++i)
                check(name, t->tabText(i));
        if (auto* t = qobject_cast<QTableWidget*>(w))
            for (int c = 0; c < t->columnCount(); ++c)
                if (t->horizontalHeaderItem(c))
                    check(name + QStringLiteral(" header"), t->horizontalHeaderItem(c)->text());
        if (auto* l = qobject_cast<QListWidget*>(w))
            for (int i = 0; i < l->count(); ++i)
                check(name, l->item(i)->text());
    }
    return out;
}

// Screens whose every text goes through translation today (checked).
const QStringList kChecked = {};
// The rest, for issue 17's phase 2 (reported, not failed).
const QStringList kPending = {QStringLiteral("jog"),      QStringLiteral("plots"),    QStringLiteral("profiles"),
                              QStringLiteral("tuning"),   QStringLiteral("joystick"), QStringLiteral("patterns"),
                              QStringLiteral("plates"),   QStringLiteral("scan"),     QStringLiteral("calibration")};

TEST(I18nWalk, TheWindowsOwnTextsAndEveryScreenGoThroughTranslation)
{
    const i18ntest::PseudoTranslation pseudo({});
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 768);
    w.show();
    QApplication::processEvents();
    QStringList failures;
    for (const QString& screen : w.screenNames()) {
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
        const QStringList found = englishOn(&w);
        if (!found.isEmpty())
            std::printf("[i18n walk] %s: %lld texts not translated, e.g. %s\n", qPrintable(screen), static_cast<long long>(found.size()),
                        qPrintable(found.first()));
        if (kChecked.contains(screen))
            failures << found;
        else
            EXPECT_TRUE(kPending.contains(screen)) << screen.toStdString() << " is in neither list";
    }
    EXPECT_TRUE(failures.isEmpty()) << failures.join(QLatin1Char('\n')).toStdString();
}

TEST(I18nWalk, TheWalkFindsATextThatDidNotGoThroughTranslation)
{
    const i18ntest::PseudoTranslation pseudo({});
    QWidget root;
    auto* l = new QLabel(QStringLiteral("Plain English here"), &root);
    (void)l;
    root.show();
    EXPECT_FALSE(englishOn(&root).isEmpty());
    l->setText(QCoreApplication::translate("ui::Test", "Plain English here"));
    EXPECT_TRUE(englishOn(&root).isEmpty()) << englishOn(&root).join(QLatin1Char('\n')).toStdString();
}

} // namespace
