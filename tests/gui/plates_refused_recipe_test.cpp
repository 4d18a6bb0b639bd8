// A recipe whose plates section is wrong is refused at Open. The operator is told every
// reason, each with its line and column as the CLI prints them, in the Problems pane;
// the banner only says the file was refused and where to look, with the file's name as
// it is; the pane does not go on showing the verdict on the recipe before.
#include "app/gui/main_window.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/message_banner.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"

#include <QFile>
#include <QGroupBox>
#include <QListWidget>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using guitest::pump;

namespace {

/// The rows of the recipe editor's Problems pane.
QStringList problemRows(ui::RecipeEditor* editor)
{
    QStringList rows;
    for (auto* box : editor->findChildren<QGroupBox*>())
        if (box->title() == QObject::tr("Problems"))
            if (auto* list = box->findChild<QListWidget*>())
                for (int i = 0; i < list->count(); ++i)
                    rows << list->item(i)->text();
    return rows;
}

// Plate 1 in a slot the deck does not have, plate 2 without its labware.
const char* kBadPlates = R"({
  "schema": "benchpilot.recipe",
  "version": 1,
  "name": "bad plates",
  "plates": [
    {"name": "assay", "slot": "9", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 69},
    {"name": "reagents", "slot": "2", "safe_z_mm": 38, "depth_z_mm": 68}
  ],
  "steps": [
    {"type": "wash", "station": "wash", "volume_ul": 100, "cycles": 1}
  ]
}
)";

TEST(PlatesRefusedRecipe, EveryErrorIsListedWithItsPlaceAndTheBannerPointsThere)
{
    auto w = guitest::openReadyWindow({1500, 950});
    ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    ui::PlatesScreen* screen = w->platesScreen();
    ui::RecipeEditor* editor = screen->recipeEditor();
    ASSERT_TRUE(screen->openRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/reagent-transfer.recipe.json")));
    pump(50);
    ASSERT_TRUE(screen->plan().ok()) << "the recipe before validates";
    const QStringList verdictBefore = problemRows(editor);
    const std::string before = editor->recipe().name;

    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad-plates.recipe.json"));
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(kBadPlates);
    f.close();
    w->banner()->dismiss();
    EXPECT_FALSE(screen->openRecipe(bad));
    pump(50);

    EXPECT_EQ(editor->recipe().name, before) << "a refused file leaves the recipe on screen as it was";
    const QStringList rows = problemRows(editor);
    const QString all = rows.join(QLatin1Char('\n'));
    EXPECT_FALSE(rows.contains(QObject::tr("The recipe validates."))) << all.toStdString();
    for (const QString& row : verdictBefore)
        EXPECT_FALSE(rows.contains(row)) << "the verdict on the recipe before stays: " << row.toStdString();
    ASSERT_FALSE(rows.isEmpty());
    EXPECT_TRUE(rows.front().startsWith(QStringLiteral("bad-plates.recipe.json "))) << "the pane says which file these are of";
    // Both errors, each with its line and column, as `benchpilot-cli recipe validate` prints them.
    EXPECT_TRUE(all.contains(QStringLiteral("bad-plates.recipe.json:6:31: plates[0].slot: "))) << all.toStdString();
    EXPECT_TRUE(all.contains(QStringLiteral("bad-plates.recipe.json:7:5: plates[1]"))) << all.toStdString();

    const QString banner = w->banner()->text();
    EXPECT_FALSE(banner.contains(QLatin1Char('\n'))) << "a banner shows one line: " << banner.toStdString();
    EXPECT_FALSE(banner.contains(QStringLiteral("plates[0]"))) << "the list is the pane's: " << banner.toStdString();
    EXPECT_TRUE(banner.startsWith(QStringLiteral("bad-plates.recipe.json "))) << "the file's name as it is: " << banner.toStdString();
    EXPECT_TRUE(banner.contains(QObject::tr("Problems"))) << banner.toStdString();

    // An edit of the recipe on screen shows its own verdict again.
    editor->edit(QStringLiteral("rename"), [](motion::plates::Recipe& r) { r.name = "renamed"; });
    pump(50);
    EXPECT_EQ(problemRows(editor), verdictBefore);
}

// A file that opens but does not validate (its form is right, a slot is wrong): its
// problems too carry their line and column while the recipe on screen is that file.
TEST(PlatesRefusedRecipe, AnOpenedRecipesProblemsCarryTheirPlaceUntilItIsEdited)
{
    auto w = guitest::openReadyWindow({1500, 950});
    ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    ui::PlatesScreen* screen = w->platesScreen();
    ui::RecipeEditor* editor = screen->recipeEditor();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad-slot.recipe.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(kBadPlates).replace(R"("slot": "2", )", R"("slot": "2", "labware": "sbs-96", )"));
    f.close();
    ASSERT_TRUE(screen->openRecipe(path));
    pump(50);
    EXPECT_FALSE(screen->plan().ok());
    QString all = problemRows(editor).join(QLatin1Char('\n'));
    EXPECT_TRUE(all.contains(QStringLiteral("bad-slot.recipe.json:6:31: plates[0].slot: "))) << all.toStdString();

    editor->edit(QStringLiteral("rename"), [](motion::plates::Recipe& r) { r.name = "renamed"; });
    pump(50);
    all = problemRows(editor).join(QLatin1Char('\n'));
    EXPECT_TRUE(all.startsWith(QStringLiteral("plates[0].slot: "))) << "an edited recipe's lines are no longer the file's: " << all.toStdString();
}

} // namespace
