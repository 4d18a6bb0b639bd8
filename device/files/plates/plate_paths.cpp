#include "device/files/plates/plate_paths.h"

#include <QDir>
#include <QStandardPaths>

namespace dev::files::plates {

namespace {
QString base() { return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)).filePath(QStringLiteral("BenchPilot")); }
} // namespace

QString defaultCalibrationPath() { return QDir(base()).filePath(QStringLiteral("analyzer.calibration.json")); }

QString defaultRunLogDirectory() { return QDir(base()).filePath(QStringLiteral("runs")); }

} // namespace dev::files::plates
