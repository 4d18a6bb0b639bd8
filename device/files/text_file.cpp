#include "device/files/text_file.h"

#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>

namespace dev::files {

bool readText(const QString& path, std::string* text, QString* error, qint64 maxBytes)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = QCoreApplication::translate("files", "cannot open %1: %2").arg(path, f.errorString());
        return false;
    }
    if (f.size() > maxBytes) {
        if (error)
            *error = QCoreApplication::translate("files", "%1 is %2 MiB, more than the %3 MiB a BenchPilot file may be")
                         .arg(path)
                         .arg(f.size() / (1024.0 * 1024.0), 0, 'f', 1)
                         .arg(maxBytes / (1024 * 1024));
        return false;
    }
    const QByteArray bytes = f.readAll();
    if (f.error() != QFileDevice::NoError) {
        if (error)
            *error = QCoreApplication::translate("files", "cannot read %1: %2").arg(path, f.errorString());
        return false;
    }
    text->assign(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    return true;
}

bool writeAtomically(const QString& path, const std::string& text, QString* error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error)
            *error = QCoreApplication::translate("files", "cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    const qint64 n = static_cast<qint64>(text.size());
    if (f.write(text.data(), n) != n || !f.commit()) {
        if (error)
            *error = QCoreApplication::translate("files", "cannot write %1: %2").arg(path, f.errorString());
        f.cancelWriting();
        return false;
    }
    return true;
}

namespace {
motion::msg::Message fileProblem(const char* id, const QString& path, const QString& detail)
{
    return motion::msg::make(id, {motion::msg::verbatim("file", path.toStdString()), motion::msg::verbatim("detail", detail.toStdString())});
}
} // namespace

bool readText(const QString& path, std::string* text, motion::msg::Message* error, qint64 maxBytes)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = fileProblem("file.cannot_open", path, f.errorString());
        return false;
    }
    if (f.size() > maxBytes) {
        if (error)
            *error = motion::msg::make("file.too_large", {motion::msg::verbatim("file", path.toStdString()),
                                                  motion::msg::real("size", f.size() / (1024.0 * 1024.0)),
                                                  motion::msg::integer("max", maxBytes / (1024 * 1024), motion::msg::Unit::None)});
        return false;
    }
    const QByteArray bytes = f.readAll();
    if (f.error() != QFileDevice::NoError) {
        if (error)
            *error = fileProblem("file.cannot_read", path, f.errorString());
        return false;
    }
    text->assign(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    return true;
}

bool writeAtomically(const QString& path, const std::string& text, motion::msg::Message* error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error)
            *error = fileProblem("file.cannot_write", path, f.errorString());
        return false;
    }
    const qint64 n = static_cast<qint64>(text.size());
    if (f.write(text.data(), n) != n || !f.commit()) {
        if (error)
            *error = fileProblem("file.cannot_write", path, f.errorString());
        f.cancelWriting();
        return false;
    }
    return true;
}

} // namespace dev::files
