// At 1366 × 768 nothing is cut. The connection bar's identity
// was cut mid-letter without "…"; the recipe editor cut "Import Opentrons labware…" and
// the "▼" beside it, in English and more so in Chinese. Now the identity ends in "…"
// with the whole text in its tooltip, and every button and label of the recipe editor
// is whole at 1366 × 768 and at 1920 × 1080, in both languages: the plates table's column
// headers too, and a labware name too long for its box shows from its start.
#include "gui_window.h"

#include "widgets/common/elided_label.h"
#include "widgets/connection_bar.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/wording/translators.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QStyle>
#include <QLabel>
#include <QScrollArea>

#include <gtest/gtest.h>

namespace {

/// What of `root` is cut: a button or label narrower than its text needs, or hidden in
/// part by a scroll area's or the window's edge.
QStringList cutIn(QWidget* root)
{
    QStringList out;
    auto check = [&out](QWidget* wdg, const QString& text, int need) {
        if (!wdg->isVisible() || text.isEmpty())
            return;
        const QRect seen = wdg->visibleRegion().boundingRect();
        if (seen.isEmpty())
            return;  // scrolled out of view vertically: the page scrolls, it is not cut
        if (seen.width() < wdg->width())
            out << QStringLiteral("'%1' is cut at the side (%2 of %3 px shown)").arg(text).arg(seen.width()).arg(wdg->width());
        else if (wdg->width() < need)
            out << QStringLiteral("'%1' is squeezed (%2 px for %3)").arg(text).arg(wdg->width()).arg(need);
    };
    for (auto* b : root->findChildren<QAbstractButton*>())
        check(b, b->text(), b->minimumSizeHint().width());
    for (auto* l : root->findChildren<QLabel*>()) {
        if (qobject_cast<ui::ElidedLabel*>(l) || l->wordWrap())
            continue;  // these shorten or wrap their text themselves
        check(l, l->text(), l->fontMetrics().horizontalAdvance(l->text()));
    }
    // Column headers (a table's "Depth Z (mm)" was cut to "Depth Z (mm" at 1366 px).
    for (auto* h : root->findChildren<QHeaderView*>()) {
        if (!h->isVisible() || h->orientation() != Qt::Horizontal)
            continue;
        const int margin = 2 * h->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, h);
        for (int s = 0; s < h->count(); ++s) {
            const QString text = h->model()->headerData(s, Qt::Horizontal).toString();
            const int need = h->fontMetrics().horizontalAdvance(text) + margin;
            if (!h->isSectionHidden(s) && !text.isEmpty() && h->sectionSize(s) < need)
                out << QStringLiteral("header '%1' is squeezed (%2 px for %3)").arg(text).arg(h->sectionSize(s)).arg(need);
        }
    }
    // An editable combo with a name longer than its box shows the name's start (it showed
    // "ware.json"), and the whole name is in its tooltip.
    for (auto* c : root->findChildren<QComboBox*>()) {
        if (!c->isVisible() || !c->isEditable() || c->lineEdit()->hasFocus())
            continue;
        const QString text = c->currentText();
        if (c->lineEdit()->fontMetrics().horizontalAdvance(text) <= c->lineEdit()->width())
            continue;
        if (c->lineEdit()->cursorPosition() != 0)
            out << QStringLiteral("'%1' shows its end, not its start").arg(text);
        if (!c->toolTip().contains(text))
            out << QStringLiteral("'%1' is longer than its box and not in its tooltip").arg(text);
    }
    return out;
}

} // namespace

TEST(TrustLayout, TheConnectionBarsIdentityIsElidedWithItsWholeTextInTheTooltip)
{
    auto w = guitest::openReadyWindow(QSize(1366, 708));
    ASSERT_TRUE(w);
    guitest::pump(50);
    int elided = 0;
    const auto bars = w->findChildren<ui::ConnectionBar*>();
    ASSERT_EQ(bars.size(), 2);
    // A GRBL board names itself at length (build options, a profile's file name): longer
    // than the row's room even with no message beside it.
    bars[1]->showState(dev::LinkState::Ready, QStringLiteral("GRBL 1.1h ['$' for help] · [OPT:VNMHL,15,128] · profile "
                                                             "lab-3-bench-left-microscope-stage-2026-11-calibrated.machine.json · /dev/ttyUSB0 @ 115200 baud"));
    guitest::pump(50);
    for (ui::ConnectionBar* bar : bars) {
        QLabel* identity = nullptr;
        for (QLabel* l : bar->findChildren<QLabel*>())
            if (l->toolTip().contains(QStringLiteral(" — ")))
                identity = l;
        ASSERT_NE(identity, nullptr) << "no label shows the instrument's identity";
        const QString full = identity->toolTip();
        const int room = identity->contentsRect().width();
        const QFontMetrics fm = identity->fontMetrics();
        EXPECT_LE(fm.horizontalAdvance(identity->text()), room) << "cut without \"…\": " << identity->text().toStdString();
        if (fm.horizontalAdvance(full) > room) {
            EXPECT_TRUE(identity->text().endsWith(QChar(0x2026))) << identity->text().toStdString();
            ++elided;
        } else {
            EXPECT_EQ(identity->text(), full);
        }
    }
    EXPECT_GE(elided, 1) << "at 1366 px an identity this long has to be shortened somewhere";
}

TEST(TrustLayout, TheRecipeEditorIsWholeAtLaptopAndDesktopSizesInEnglishAndChinese)
{
    ui::words::Translators translators;
    QStringList failures;
    for (const QString& lang : {QStringLiteral("en"), QStringLiteral("zh_CN")}) {
        ASSERT_TRUE(translators.setLanguage(lang));
        for (const QSize& size : {QSize(1366, 708), QSize(1920, 1020)}) {
            auto w = guitest::openReadyWindow(size);
            ASSERT_TRUE(w);
            ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
            // The example's second step is a dispense with a source: the widest form there is.
            ASSERT_TRUE(w->platesScreen()->openRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/reagent-transfer.recipe.json")));
            w->platesScreen()->recipeEditor()->setCurrentStep(1);
            w->platesScreen()->showTab(QStringLiteral("recipe"));
            guitest::pump(50);
            const QString where = QStringLiteral("%1 %2×%3: ").arg(lang).arg(size.width()).arg(size.height());
            guitest::keepPicture(w.get(), QStringLiteral("recipe-%1-%2.png").arg(lang).arg(size.width()));
            for (const QString& c : cutIn(w->platesScreen()->recipeEditor()))
                failures << where + c;
            EXPECT_LE(w->width(), size.width()) << where.toStdString() << "the window grew";
        }
    }
    translators.setLanguage(QStringLiteral("en"));
    EXPECT_TRUE(failures.isEmpty()) << failures.join(QLatin1Char('\n')).toStdString();
}
