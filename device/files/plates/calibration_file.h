#pragma once
// Slot calibrations kept between runs (benchpilot.calibration, docs/plates.md):
// the taught points of each slot. The fit is written for the person reading the
// file and recomputed from the points on reading, so the two cannot disagree.
#include "device/files/json_fields.h"
#include "motion/plans/plates/calibration.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::plates {

constexpr const char* kCalibrationSchema = "benchpilot.calibration";
constexpr int kCalibrationVersion = 1;

struct CalibrationRead {
    std::string deck;                              ///< the deck id it was taught on
    std::vector<motion::plates::SlotCalibration> calibrations;
    dev::files::json::Problems problems;
    bool ok() const { return problems.empty(); }
};

CalibrationRead parseCalibration(std::string_view text);
std::string writeCalibration(const std::string& deckId, const std::vector<motion::plates::SlotCalibration>& calibrations);

/// The transforms a plan uses, by slot id.
std::map<std::string, motion::plates::PlateTransform> calibrationTransforms(const std::vector<motion::plates::SlotCalibration>& calibrations);

} // namespace dev::files::plates
