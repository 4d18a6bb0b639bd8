#pragma once
// A scan's tile positions in the formats the stitching and acquisition tools read
// (docs/scan.md):
//  - Fiji/ImageJ Grid/Collection stitching "TileConfiguration.txt": `dim = 2`, then
//    `file; ; (x, y)` per tile, the image's top-left corner in pixels;
//  - a Micro-Manager position list (.pos): a Property Map 2.0 JSON document whose
//    StagePositions each hold one XY-stage device position in µm;
//  - CSV with planned, commanded and measured positions.
// The text functions are plain C++; writeExports adds the files (atomically).
#include "motion/plans/scan/scan_layout.h"
#include "motion/records/position_record.h"

#include "motion/message.h"

#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace dev::files::scan {

/// One record per tile, in visiting order: planned and commanded positions filled
/// in, labelled with the tile's file name; nothing measured yet.
std::vector<motion::PositionRecord> plannedRecords(const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout);

/// Where the stitcher should put a tile, in stage mm: the grating's reading at the
/// trigger (a compensated stage reports it at the work point already), or the planned
/// position before it is taken.
motion::scan::Point2 stitchPosition(const motion::scan::ScanPlan& plan, const motion::PositionRecord& record);

/// Stage millimetres → image pixels of the mosaic (the camera's rotation and y sense).
motion::scan::Point2 stageToPixels(const motion::scan::Camera& camera, motion::scan::Point2 stageMm);

std::string tileConfiguration(const motion::scan::ScanPlan& plan, const std::vector<motion::PositionRecord>& records);
std::string microManagerPositions(const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout);
std::string scanCsv(const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout,
                    const std::vector<motion::PositionRecord>& records);

/// File names inside the output folder.
constexpr const char* kTileConfigFile = "TileConfiguration.txt";
constexpr const char* kPositionsFile = "positions.pos";
constexpr const char* kCsvFile = "scan.csv";

/// Writes the three exports into `folder` (made if missing). `written` gets their paths.
bool writeExports(const QString& folder, const motion::scan::ScanPlan& plan, const motion::scan::ScanLayout& layout,
                  const std::vector<motion::PositionRecord>& records, QStringList* written, motion::msg::Message* error);

} // namespace dev::files::scan
