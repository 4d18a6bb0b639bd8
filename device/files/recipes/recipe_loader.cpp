#include "device/files/recipes/recipe_loader.h"

#include "device/files/plates/labware_file.h"
#include "device/files/shipped_data.h"
#include "device/files/text_file.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace platefiles {

namespace {
/// A file that cannot be read, as a problem of that file.
msg::Problem unreadable(const QString& file, const msg::Message& why)
{
    return msg::Problem(QFileInfo(file).fileName().toStdString(), 0, 0, "", why);
}
} // namespace

int resolveLabware(const plates::Recipe& recipe, const QString& baseDir, plates::PlanContext& context, msg::Problems* problems)
{
    int errors = 0;
    for (const plates::RecipePlate& p : recipe.plates) {
        if (context.labware.count(p.labware))
            continue;
        if (auto lw = plates::findBuiltinLabware(p.labware)) {
            context.labware[p.labware] = std::move(*lw);
            continue;
        }
        if (!isLabwareFile(p.labware))
            continue;  // the plan reports the unknown id with the recipe's position
        QString file = QDir(baseDir).filePath(QString::fromStdString(p.labware));
        // A recipe copied out of the examples still finds the labware shipped with them.
        if (!QFileInfo::exists(file))
            if (const QString shipped = files::shippedLabwareFile(QString::fromStdString(p.labware)); !shipped.isEmpty())
                file = shipped;
        std::string text;
        msg::Message error;
        if (!files::readText(file, &text, &error)) {
            if (problems)
                problems->push_back(unreadable(file, error));
            ++errors;
            continue;
        }
        const LabwareRead lr = parseLabware(text);
        msg::Problems found;
        jsonio::appendSorted(found, lr.problems, QFileInfo(file).fileName().toStdString());
        errors += msg::errorCount(found);
        if (problems)
            problems->insert(problems->end(), found.begin(), found.end());
        if (lr.labware)
            context.labware[p.labware] = *lr.labware;
    }
    return errors;
}

LoadedRecipe loadRecipe(const QString& path, const plates::Deck& deck, const std::vector<plates::SlotCalibration>& calibration)
{
    LoadedRecipe out;
    out.path = path;
    out.context.deck = deck;
    for (const auto& c : calibration)
        if (deck.slot(c.slot))
            out.context.calibration[c.slot] = c.fit.transform;
    std::string text;
    msg::Message error;
    if (!files::readText(path, &text, &error)) {
        out.problems.push_back(unreadable(path, error));
        out.errorCount = 1;
        return out;
    }
    RecipeRead read = parseRecipe(text);
    const std::string name = QFileInfo(path).fileName().toStdString();
    if (!read.recipe) {
        jsonio::appendSorted(out.problems, read.problems, name);
        out.errorCount = msg::errorCount(out.problems);
        return out;
    }
    out.readable = read.wellFormed;
    out.recipe = *read.recipe;
    msg::Problems labwareProblems;
    const int labwareErrors = resolveLabware(out.recipe, QFileInfo(path).absolutePath(), out.context, &labwareProblems);
    out.plan = plates::planRecipe(out.recipe, out.context);
    placeProblems(read, out.plan.problems);
    jsonio::appendSorted(out.problems, read.problems, name);
    out.errorCount = msg::errorCount(out.problems);
    out.problems.insert(out.problems.end(), labwareProblems.begin(), labwareProblems.end());
    out.errorCount += labwareErrors;
    return out;
}

} // namespace platefiles
