#pragma once
// The scan plan file (docs/scan.md): "schema": "benchpilot.scan-plan", version 1.
// Read with every problem at once, each with its line, column and field, the
// plan's own rules (motion/plans/scan/scan_plan.h validate) included; written in
// a fixed member order. The text functions are plain C++ (fuzzed); loadPlan and
// savePlan add the file.
#include "device/files/json.h"
#include "device/files/json_fields.h"
#include "motion/plans/scan/scan_plan.h"

#include <QString>

#include <optional>
#include <string_view>

namespace dev::files::scan {

constexpr const char* kPlanSchema = "benchpilot.scan-plan";
constexpr int kPlanVersion = 1;

struct PlanReadResult {
    std::optional<motion::scan::ScanPlan> plan;  ///< only when there is no problem
    dev::files::json::Problems problems;
};

PlanReadResult parsePlan(std::string_view text);
dev::files::json::Value planToJson(const motion::scan::ScanPlan& plan);
std::string writePlan(const motion::scan::ScanPlan& plan);

/// Where `path` ("region.vertices_mm[3]", "overlap[0]") stands in the document, or
/// the nearest enclosing value that is there (a field left to its default).
dev::files::json::Position locate(const dev::files::json::Value& root, const std::string& path);

/// False with every problem in `problems` (ui::words::fileProblems words them, with the
/// file, line and column).
bool loadPlan(const QString& path, motion::scan::ScanPlan* plan, dev::files::json::Problems* problems);
bool savePlan(const QString& path, const motion::scan::ScanPlan& plan, motion::msg::Message* error);

} // namespace dev::files::scan
