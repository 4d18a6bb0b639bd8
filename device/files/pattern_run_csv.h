#pragma once
// A pattern run as CSV (docs/patterns.md): one row per telemetry sample judged during the run,
// commanded and measured XY, where along the path it was judged and its contour error.
#include "device/jobs/pattern_runner.h"

#include <QString>

#include <string>
#include <vector>

namespace dev::files {

/// Header: time_s,commanded_x_mm,commanded_y_mm,measured_x_mm,measured_y_mm,path_mm,contour_um,segment
std::string patternRunCsv(const std::vector<dev::jobs::PatternRunSample>& samples);
/// Atomic write; false with a sentence naming the file otherwise.
bool savePatternRunCsv(const QString& path, const std::vector<dev::jobs::PatternRunSample>& samples, motion::msg::Message* error);

} // namespace dev::files
