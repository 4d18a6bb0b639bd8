#include "device/files/shipped_data.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace dev::files {

namespace {
QString& overrideDirectory()
{
    static QString dir;
    return dir;
}

QString below(const QString& name)
{
    const QString base = shippedDataDirectory();
    return base.isEmpty() ? QString() : QDir(base).filePath(name);
}

/// A name with no folder in it: only those are looked up among the shipped files.
bool bareName(const QString& s) { return !s.isEmpty() && !s.contains(QLatin1Char('/')) && s != QLatin1String("..") && s != QLatin1String("."); }
} // namespace

void setShippedDataDirectory(const QString& directory) { overrideDirectory() = directory; }

QString shippedDataDirectory()
{
    if (!overrideDirectory().isEmpty())
        return overrideDirectory();
    if (!QCoreApplication::instance())
        return {};
    const QString dir = QDir(QCoreApplication::applicationDirPath()).filePath(QString::fromUtf8(shippedDataFromProgram()));
    return QFileInfo(dir).isDir() ? QDir::cleanPath(dir) : QString();
}

QString shippedExamplesDirectory() { return below(QStringLiteral("examples")); }
QString shippedLabwareDirectory() { return below(QStringLiteral("labware")); }
QString shippedMachinesDirectory() { return below(QStringLiteral("machines")); }

QString resolveMachineProfile(const QString& typed)
{
    if (QFileInfo::exists(typed) || !bareName(typed) || shippedMachinesDirectory().isEmpty())
        return typed;
    const QDir machines(shippedMachinesDirectory());
    for (const QString& name : {typed, typed + QStringLiteral(".machine.json")})
        if (QFileInfo(machines.filePath(name)).isFile())
            return machines.filePath(name);
    return typed;
}

QString shippedLabwareFile(const QString& fileName)
{
    if (!bareName(fileName) || shippedLabwareDirectory().isEmpty())
        return {};
    const QString file = QDir(shippedLabwareDirectory()).filePath(fileName);
    return QFileInfo(file).isFile() ? file : QString();
}

} // namespace dev::files
