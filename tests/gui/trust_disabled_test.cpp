// The failure this catches: "Go" stayed disabled until homing with no hint why, and the go-to field
// was cut to "tar…". A greyed control says why in its tooltip.
#include "gui_window.h"

#include "widgets/jog_screen.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>

#include <gtest/gtest.h>

using guitest::waitFor;

namespace {
/// Every control of the Jog screen that is shown greyed without a reason in its tooltip.
QStringList silentlyDisabled(QWidget* screen, const QString& reason)
{
    QStringList out;
    QList<QWidget*> controls;
    for (auto* b : screen->findChildren<QAbstractButton*>())
        controls << b;
    for (auto* e : screen->findChildren<QLineEdit*>())
        if (!qobject_cast<QComboBox*>(e->parentWidget()))
            controls << e;
    for (auto* c : screen->findChildren<QComboBox*>())
        controls << c;
    for (QWidget* c : controls)
        if (c->isVisible() && !c->isEnabled() && !c->toolTip().contains(reason)) {
            const auto* b = qobject_cast<QAbstractButton*>(c);
            out << QStringLiteral("%1 '%2': %3").arg(QLatin1String(c->metaObject()->className()), b ? b->text() : QString(), c->toolTip());
        }
    return out;
}
} // namespace

TEST(TrustDisabled, GreyedJogControlsSayWhy)
{
    auto w = guitest::openReadyWindow(QSize(1366, 708));
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    ui::JogScreen* jog = w->jogScreen(0);
    guitest::pump(100);

    // Not homed: Go says to home first.
    QList<QPushButton*> gos;
    for (auto* b : jog->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Go"))
            gos << b;
    ASSERT_FALSE(gos.isEmpty());
    for (auto* go : gos) {
        EXPECT_FALSE(go->isEnabled());
        EXPECT_TRUE(go->toolTip().startsWith(QStringLiteral("Home "))) << go->toolTip().toStdString();
    }
    // The go-to field shows its whole placeholder.
    for (auto* e : jog->findChildren<QLineEdit*>()) {
        if (!e->placeholderText().isEmpty() && e->isVisible()) {
            EXPECT_GE(e->width(), e->fontMetrics().horizontalAdvance(e->placeholderText()) + 8)
                << "'" << e->placeholderText().toStdString() << "' in " << e->width() << " px";
        }
    }

    // E-stop: everything that moves is greyed, and each says so.
    w->emergencyStop();
    ASSERT_TRUE(waitFor([&] { return w->analyzer()->instrument()->status().estop; }, 3000));
    guitest::pump(50);
    const QStringList silent = silentlyDisabled(jog, QStringLiteral("E-STOP"));
    EXPECT_TRUE(silent.isEmpty()) << silent.join(QLatin1Char('\n')).toStdString();
    w->resetEStop();
    ASSERT_TRUE(waitFor([&] { return !w->analyzer()->instrument()->status().estop; }, 3000));
    guitest::pump(50);
    for (auto* go : gos)
        EXPECT_TRUE(go->toolTip().startsWith(QStringLiteral("Home "))) << "the reason went with the E-stop: " << go->toolTip().toStdString();

    // No link: the same, with the reason for that.
    w->analyzer()->disconnectLink();
    ASSERT_TRUE(waitFor([&] { return !w->analyzer()->instrument()->isReady(); }, 3000));
    guitest::pump(50);
    const QStringList silent2 = silentlyDisabled(jog, QStringLiteral("Connect"));
    EXPECT_TRUE(silent2.isEmpty()) << silent2.join(QLatin1Char('\n')).toStdString();
}
