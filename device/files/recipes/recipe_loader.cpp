#include "device/files/recipes/recipe_loader.h"

#include "device/files/plates/labware_file.h"
#include "device/files/text_file.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace platefiles {

QStringList formatProblems(const jsonio::Problems& problems, const QString& fileName, int* errors)
{
    QStringList out;
    const std::string name = fileName.toStdString();
    // In the order of the file, as a person reads it.
    std::vector<jsonio::Problem> sorted = problems.list();
    std::stable_sort(sorted.begin(), sorted.end(), [](const jsonio::Problem& a, const jsonio::Problem& b) {
        return a.position.line != b.position.line ? a.position.line < b.position.line : a.position.column < b.position.column;
    });
    for (const jsonio::Problem& p : sorted) {
        jsonio::Problems one;
        one.add(p.position, p.path, p.message);
        out << QString::fromStdString(one.format(name)).trimmed();
        if (errors && p.message.rfind("warning: ", 0) != 0)
            ++*errors;
    }
    return out;
}

int resolveLabware(const plates::Recipe& recipe, const QString& baseDir, plates::PlanContext& context, QStringList* messages)
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
        const QString file = QDir(baseDir).filePath(QString::fromStdString(p.labware));
        std::string text;
        QString error;
        if (!files::readText(file, &text, &error)) {
            if (messages)
                *messages << error;
            ++errors;
            continue;
        }
        const LabwareRead lr = parseLabware(text);
        if (messages)
            *messages << formatProblems(lr.problems, QFileInfo(file).fileName(), &errors);
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
    QString error;
    if (!files::readText(path, &text, &error)) {
        out.messages << error;
        out.errorCount = 1;
        return out;
    }
    RecipeRead read = parseRecipe(text);
    const QString name = QFileInfo(path).fileName();
    if (!read.recipe) {
        out.messages = formatProblems(read.problems, name, &out.errorCount);
        return out;
    }
    out.readable = read.wellFormed;
    out.recipe = *read.recipe;
    QStringList labwareMessages;
    const int labwareErrors = resolveLabware(out.recipe, QFileInfo(path).absolutePath(), out.context, &labwareMessages);
    out.plan = plates::planRecipe(out.recipe, out.context);
    placeProblems(read, out.plan.problems);
    out.messages = formatProblems(read.problems, name, &out.errorCount);
    out.messages << labwareMessages;
    out.errorCount += labwareErrors;
    return out;
}

} // namespace platefiles
