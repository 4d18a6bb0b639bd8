#include "device/files/accuracy/accuracy_run_folders.h"

#include <QDir>
#include <QFileInfo>

namespace dev::files::accuracy {

namespace {

QString numbered(const QString& base, int n)
{
    QString b = QDir::cleanPath(base);
    return n <= 1 ? b : QStringLiteral("%1-%2").arg(b).arg(n);
}

} // namespace

QStringList runFolders(const QString& base)
{
    QStringList out;
    for (int n = 1; n < 10000 && QFileInfo(numbered(base, n)).isDir(); ++n)
        out << numbered(base, n);
    return out;
}

QString latestRunFolder(const QString& base)
{
    const QStringList all = runFolders(base);
    return all.isEmpty() ? QDir::cleanPath(base) : all.back();
}

QString nextRunFolder(const QString& base) { return numbered(base, static_cast<int>(runFolders(base).size()) + 1); }

} // namespace dev::files::accuracy
