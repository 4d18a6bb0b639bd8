#pragma once
// Reading the examples and the built-in deck in device tests.
#include "device/english_words.h"
#include "device/files/plates/deck_file.h"

#include <QDir>
#include <QFile>

#include <string>

namespace platestest {

inline QString examplePath(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

inline std::string readExample(const char* name)
{
    QFile f(examplePath(name));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll().toStdString();
}

/// Messages of a problem list, one per line, for assertions.
inline std::string text(const dev::files::json::Problems& p) { return i18ntest::englishFormat(p, "f.json"); }

} // namespace platestest
