#include "device/files/recipes/recipe_loader.h"

#include "device/files/plates/labware_file.h"
#include "device/files/shipped_data.h"
#include "device/files/text_file.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace dev::files::plates {

namespace {
/// A file that cannot be read, as a problem of that file.
motion::msg::Problem unreadable(const QString& file, const motion::msg::Message& why)
{
    return motion::msg::Problem(QFileInfo(file).fileName().toStdString(), 0, 0, "", why);
}
} // namespace

int resolveLabware(const motion::plates::Recipe& recipe, const QString& baseDir, motion::plates::PlanContext& context, motion::msg::Problems* problems)
{
    int errors = 0;
    for (const motion::plates::RecipePlate& p : recipe.plates) {
        if (context.labware.count(p.labware))
            continue;
        if (auto lw = motion::plates::findBuiltinLabware(p.labware)) {
            context.labware[p.labware] = std::move(*lw);
            continue;
        }
        if (!isLabwareFile(p.labware))
            continue;  // the plan reports the unknown id with the recipe's position
        QString file = QDir(baseDir).filePath(QString::fromStdString(p.labware));
        // A recipe copied out of the examples still finds the labware shipped with them.
        if (!QFileInfo::exists(file))
            if (const QString shipped = dev::files::shippedLabwareFile(QString::fromStdString(p.labware)); !shipped.isEmpty())
                file = shipped;
        std::string text;
        motion::msg::Message error;
        if (!dev::files::readText(file, &text, &error)) {
            if (problems)
                problems->push_back(unreadable(file, error));
            ++errors;
            continue;
        }
        const LabwareRead lr = parseLabware(text);
        motion::msg::Problems found;
        dev::files::json::appendSorted(found, lr.problems, QFileInfo(file).fileName().toStdString());
        errors += motion::msg::errorCount(found);
        if (problems)
            problems->insert(problems->end(), found.begin(), found.end());
        if (lr.labware)
            context.labware[p.labware] = *lr.labware;
    }
    return errors;
}

LoadedRecipe loadRecipe(const QString& path, const motion::plates::Deck& deck, const std::vector<motion::plates::SlotCalibration>& calibration)
{
    LoadedRecipe out;
    out.path = path;
    out.context.deck = deck;
    for (const auto& c : calibration)
        if (deck.slot(c.slot))
            out.context.calibration[c.slot] = c.fit.transform;
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(path, &text, &error)) {
        out.problems.push_back(unreadable(path, error));
        out.errorCount = 1;
        return out;
    }
    RecipeRead read = parseRecipe(text);
    const std::string name = QFileInfo(path).fileName().toStdString();
    if (!read.recipe) {
        dev::files::json::appendSorted(out.problems, read.problems, name);
        out.errorCount = motion::msg::errorCount(out.problems);
        return out;
    }
    out.readable = read.wellFormed;
    out.recipe = *read.recipe;
    motion::msg::Problems labwareProblems;
    const int labwareErrors = resolveLabware(out.recipe, QFileInfo(path).absolutePath(), out.context, &labwareProblems);
    out.plan = motion::plates::planRecipe(out.recipe, out.context);
    placeProblems(read, out.plan.problems);
    dev::files::json::appendSorted(out.problems, read.problems, name);
    out.errorCount = motion::msg::errorCount(out.problems);
    out.problems.insert(out.problems.end(), labwareProblems.begin(), labwareProblems.end());
    out.errorCount += labwareErrors;
    return out;
}

} // namespace dev::files::plates
