// Whole-file reads and all-or-nothing writes.
#include "device/files/text_file.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

TEST(TextFile, WritesAtomicallyAndReadsBack)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("a.json"));
    QString error;
    ASSERT_TRUE(dev::files::writeAtomically(path, "{\"x\": 1}\n", &error)) << error.toStdString();
    ASSERT_TRUE(dev::files::writeAtomically(path, "{\"x\": 2}\n", &error)) << error.toStdString();
    std::string text;
    ASSERT_TRUE(dev::files::readText(path, &text, &error));
    EXPECT_EQ(text, "{\"x\": 2}\n");
    // No temporary file is left beside it.
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("a.json")});
}

TEST(TextFile, FailuresNameTheFile)
{
    QTemporaryDir dir;
    QString error;
    std::string text;
    EXPECT_FALSE(dev::files::readText(dir.filePath(QStringLiteral("missing.json")), &text, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("missing.json"))) << error.toStdString();
    EXPECT_FALSE(dev::files::writeAtomically(dir.filePath(QStringLiteral("no/such/dir/a.json")), "x", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("a.json"))) << error.toStdString();
    const QString big = dir.filePath(QStringLiteral("big.json"));
    ASSERT_TRUE(dev::files::writeAtomically(big, std::string(2000, ' '), &error));
    EXPECT_FALSE(dev::files::readText(big, &text, &error, 1000));
    EXPECT_TRUE(error.contains(QStringLiteral("big.json"))) << error.toStdString();
}
