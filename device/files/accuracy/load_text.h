#pragma once
// Reading a whole file for the accuracy readers: its text, or the reason it cannot be
// read (file.cannot_open, file.too_large, file.cannot_read). The readers then name
// problems by the file's name, not its path.
#include "device/files/accuracy/file_problem.h"

#include <QString>

#include <optional>
#include <string>

namespace dev::files::accuracy {

std::optional<std::string> loadText(const QString& path, std::string& fileName, motion::msg::Problems& out);

} // namespace dev::files::accuracy
