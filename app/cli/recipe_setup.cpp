#include "recipe_setup.h"

#include "device/files/plates/calibration_file.h"
#include "device/files/plates/deck_file.h"
#include "device/files/plates/plate_paths.h"
#include "device/files/text_file.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace app::cli {
namespace {
QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }
} // namespace

QList<QCommandLineOption> recipeSetupOptions()
{
    return {QCommandLineOption(QStringLiteral("deck"), tr("the deck definition (default: the built-in analyzer deck)"), QStringLiteral("FILE")),
            QCommandLineOption(QStringLiteral("calibration"),
                               tr("slot calibration (default: the one the GUI keeps, %1); \"none\" for the nominal slots")
                                   .arg(dev::files::plates::defaultCalibrationPath()),
                               QStringLiteral("FILE"))};
}

int loadSetup(Invocation& inv, RecipeSetup* setup)
{
    const QStringList args = inv.arguments();
    if (args.size() != 1)
        return inv.usage(tr("name one recipe file"));
    std::string text;
    motion::msg::Message error;
    if (inv.isSet(QStringLiteral("deck"))) {
        const QString deckPath = inv.path(inv.value(QStringLiteral("deck")));
        if (!dev::files::readText(deckPath, &text, &error))
            return inv.usage(ui::words::text(error));
        const dev::files::plates::DeckRead d = dev::files::plates::parseDeck(text);
        if (!d.deck)
            return inv.usage(ui::words::fileProblems(d.problems, QFileInfo(deckPath).fileName()).join(QLatin1Char('\n')));
        setup->deck = *d.deck;
    } else {
        setup->deck = dev::files::plates::builtinDeck();
    }
    const QString cal = inv.isSet(QStringLiteral("calibration")) ? inv.path(inv.value(QStringLiteral("calibration")))
                                                                 : dev::files::plates::defaultCalibrationPath();
    if (inv.value(QStringLiteral("calibration")) != QLatin1String("none") && (inv.isSet(QStringLiteral("calibration")) || QFileInfo::exists(cal))) {
        if (!dev::files::readText(cal, &text, &error))
            return inv.usage(ui::words::text(error));
        const dev::files::plates::CalibrationRead c = dev::files::plates::parseCalibration(text);
        if (!c.ok())
            return inv.usage(ui::words::fileProblems(c.problems, QFileInfo(cal).fileName()).join(QLatin1Char('\n')));
        setup->calibration = c.calibrations;
        setup->calibrationPath = cal;
    }
    setup->loaded = dev::files::plates::loadRecipe(inv.path(args.front()), setup->deck, setup->calibration);
    return 0;
}

int reportInvalid(Invocation& inv, const dev::files::plates::LoadedRecipe& loaded)
{
    for (const QString& m : ui::words::problems(loaded.problems))
        inv.err() << m << "\n";
    inv.err().flush();
    return Usage;
}

} // namespace app::cli
