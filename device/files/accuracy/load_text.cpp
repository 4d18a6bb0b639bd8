#include "device/files/accuracy/load_text.h"

#include "device/files/text_file.h"

#include <QFileInfo>

namespace dev::files::accuracy {

std::optional<std::string> loadText(const QString& path, std::string& fileName, motion::msg::Problems& out)
{
    fileName = QFileInfo(path).fileName().toStdString();
    std::string text;
    motion::msg::Message error;  // file.cannot_open, file.too_large, file.cannot_read {file, detail}
    if (dev::files::readText(path, &text, &error))
        return text;
    out.push_back({fileName, 0, 0, "", error});
    return std::nullopt;
}

} // namespace dev::files::accuracy
