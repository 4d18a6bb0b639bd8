// Nothing loaded from a file is changed silently. The step form's spin
// boxes clamped a file's volume −20 µL to 0 and its pump speed 900 µL/s to 500 while
// Problems listed the originals. The form shows the file's values, marked invalid, the
// recipe keeps them until the operator types another, and saving without an edit writes
// them back as they were.
#include "gui_window.h"

#include "widgets/common/number_field.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/plates/step_form.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

namespace {

/// The shown field of the step form whose text is `text`, or nullptr.
ui::NumberField* shownField(ui::StepForm* form, const QString& text)
{
    for (auto* f : form->findChildren<ui::NumberField*>())
        if (f->isVisible() && f->text() == text)
            return f;
    return nullptr;
}

QJsonObject firstStep(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("steps")).toArray().first().toObject();
}

} // namespace

TEST(TrustRecipeValues, AStepsOutOfRangeVolumeAndSpeedAreShownAsTheFileHasThemAndKeptUntilFixed)
{
    auto w = guitest::openReadyWindow(QSize(1366, 708));
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    ui::PlatesScreen* screen = w->platesScreen();
    screen->showTab(QStringLiteral("recipe"));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("odd-step.recipe.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"schema": "benchpilot.recipe", "version": 1, "name": "odd step",
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "aspirate", "plate": "samples", "wells": "A1", "volume_ul": -20, "speed_ul_s": 900}]})");
    f.close();
    ASSERT_TRUE(screen->openRecipe(path));
    ui::RecipeEditor* ed = screen->recipeEditor();
    ed->setCurrentStep(0);
    guitest::pump(30);
    auto* form = ed->findChild<ui::StepForm*>();
    ASSERT_NE(form, nullptr);

    ui::NumberField* volume = shownField(form, QStringLiteral("-20"));
    ui::NumberField* speed = shownField(form, QStringLiteral("900"));
    ASSERT_NE(volume, nullptr) << "the file's volume −20 µL is not shown as it is";
    ASSERT_NE(speed, nullptr) << "the file's speed 900 µL/s is not shown as it is";
    EXPECT_FALSE(volume->isValid());
    EXPECT_FALSE(speed->isValid());
    EXPECT_FALSE(volume->toolTip().isEmpty()) << "marked invalid without saying why";
    EXPECT_EQ(ed->recipe().steps[0].volumeUl, -20);
    EXPECT_EQ(ed->recipe().steps[0].speedUlS, std::optional<double>(900));
    EXPECT_FALSE(ed->isModified()) << "opening the file changed it";

    // Saved without an edit: the file's values go back as they came.
    const QString copy = dir.filePath(QStringLiteral("copy.recipe.json"));
    ASSERT_TRUE(screen->saveRecipe(copy));
    EXPECT_EQ(firstStep(copy).value(QStringLiteral("volume_ul")).toDouble(), -20);
    EXPECT_EQ(firstStep(copy).value(QStringLiteral("speed_ul_s")).toDouble(), 900);

    // Something typed that is not valid changes nothing; a valid number is the edit.
    volume->setFocus();
    volume->selectAll();
    QTest::keyClicks(volume, QStringLiteral("-3"));
    QMetaObject::invokeMethod(volume, "editingFinished");
    EXPECT_EQ(ed->recipe().steps[0].volumeUl, -20);
    EXPECT_FALSE(ed->isModified());
    volume->selectAll();
    QTest::keyClicks(volume, QStringLiteral("40"));
    QMetaObject::invokeMethod(volume, "editingFinished");
    EXPECT_EQ(ed->recipe().steps[0].volumeUl, 40);
    EXPECT_TRUE(volume->isValid());
    EXPECT_TRUE(ed->isModified());
    EXPECT_EQ(ed->recipe().steps[0].speedUlS, std::optional<double>(900)) << "fixing the volume changed the speed";
}
