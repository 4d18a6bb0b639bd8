// The files BenchPilot ships beside its programs (share/benchpilot/, docs/install.md): a
// recipe copied out of the examples finds the labware it names by file name among the
// shipped labware, and a machine profile is found by its name among the shipped ones; a
// file the user has is always theirs first.
#include "device/files/plates/deck_file.h"
#include "device/files/recipes/recipe_loader.h"
#include "device/files/shipped_data.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QString kExamples = QStringLiteral(BP_SOURCE_DIR "/resources/examples");

/// A share/benchpilot/ of its own, with one labware file and one machine profile.
struct ShippedFolder {
    QTemporaryDir dir;
    ShippedFolder()
    {
        QDir(dir.path()).mkpath(QStringLiteral("labware"));
        QDir(dir.path()).mkpath(QStringLiteral("machines"));
        QFile::copy(kExamples + QStringLiteral("/reservoir-12.labware.json"), dir.filePath(QStringLiteral("labware/reservoir-12.labware.json")));
        QFile::copy(kExamples + QStringLiteral("/stage-grbl-uno.machine.json"), dir.filePath(QStringLiteral("machines/stage-grbl-uno.machine.json")));
        dev::files::setShippedDataDirectory(dir.path());
    }
    ~ShippedFolder() { dev::files::setShippedDataDirectory({}); }
};

TEST(ShippedData, ARecipeCopiedOutOfTheExamplesFindsTheShippedLabware)
{
    QTemporaryDir work;
    const QString recipe = work.filePath(QStringLiteral("transfer.recipe.json"));
    ASSERT_TRUE(QFile::copy(kExamples + QStringLiteral("/reagent-transfer.recipe.json"), recipe));
    {
        ShippedFolder shipped;
        const dev::files::plates::LoadedRecipe r = dev::files::plates::loadRecipe(recipe, dev::files::plates::builtinDeck(), {});
        EXPECT_TRUE(r.ok()) << r.errorCount;
        EXPECT_EQ(r.context.labware.count("reservoir-12.labware.json"), 1u);
    }
    // With nothing shipped, the same recipe cannot read the labware it names.
    dev::files::setShippedDataDirectory(work.filePath(QStringLiteral("nothing-here")));
    const dev::files::plates::LoadedRecipe alone = dev::files::plates::loadRecipe(recipe, dev::files::plates::builtinDeck(), {});
    dev::files::setShippedDataDirectory({});
    EXPECT_FALSE(alone.ok());
}

TEST(ShippedData, AMachineProfileIsFoundByItsName)
{
    ShippedFolder shipped;
    const QString expected = shipped.dir.filePath(QStringLiteral("machines/stage-grbl-uno.machine.json"));
    EXPECT_EQ(dev::files::resolveMachineProfile(QStringLiteral("stage-grbl-uno")), expected);
    EXPECT_EQ(dev::files::resolveMachineProfile(QStringLiteral("stage-grbl-uno.machine.json")), expected);
    // Not shipped, or a path: as typed, so opening it names what the user typed.
    EXPECT_EQ(dev::files::resolveMachineProfile(QStringLiteral("my-stage")), QStringLiteral("my-stage"));
    EXPECT_EQ(dev::files::resolveMachineProfile(QStringLiteral("profiles/stage-grbl-uno")), QStringLiteral("profiles/stage-grbl-uno"));
    // A file of that name in the working directory is the user's, and comes first.
    QTemporaryDir work;
    const QString here = QDir::currentPath();
    ASSERT_TRUE(QDir::setCurrent(work.path()));
    QFile own(QStringLiteral("stage-grbl-uno"));
    ASSERT_TRUE(own.open(QIODevice::WriteOnly));
    own.close();
    EXPECT_EQ(dev::files::resolveMachineProfile(QStringLiteral("stage-grbl-uno")), QStringLiteral("stage-grbl-uno"));
    QDir::setCurrent(here);
}

TEST(ShippedData, TheFolderIsFoundBesideTheProgramNotInTheSource)
{
    // The generated path is relative: bin/ to share/benchpilot/ as installed.
    EXPECT_FALSE(QDir::isAbsolutePath(QString::fromUtf8(dev::files::shippedDataFromProgram())));
    EXPECT_EQ(QString::fromUtf8(dev::files::shippedDataFromProgram()), QStringLiteral("../share/benchpilot"));
}

} // namespace
