#include "device/files/accuracy/load_text.h"

#include "device/files/text_file.h"

#include <QFileInfo>

namespace accuracyfiles {

std::optional<std::string> loadText(const QString& path, std::string& fileName, FileProblems& out)
{
    fileName = QFileInfo(path).fileName().toStdString();
    std::string text;
    QString error;
    if (files::readText(path, &text, &error))
        return text;
    out.push_back({fileName, 0, 0, "",
                   msg::make("file.unreadable", {msg::verbatim("file", path.toStdString()), msg::verbatim("detail", error.toStdString())}), false});
    return std::nullopt;
}

} // namespace accuracyfiles
