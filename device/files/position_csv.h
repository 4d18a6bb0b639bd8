#pragma once
// Measured positions as CSV (RFC 4180: comma-separated, a header line, fields
// with a comma, quote or line break quoted): one line per record, planned,
// commanded and measured per axis, the error in µm, the device time. Jobs add
// their own columns (a scan its tile's file, row and column). Plain C++.
#include "motion/records/position_record.h"

#include <string>
#include <vector>

namespace dev::files {

struct CsvColumn {
    std::string name;
    std::vector<std::string> cells;  ///< one per record
};

/// `axes` names the axes in record order ("XY"). Unmeasured records leave the
/// measured, error, time and settle cells empty.
std::string positionRecordsCsv(const std::vector<motion::PositionRecord>& records, const std::string& axes,
                               const std::vector<CsvColumn>& extra = {});

/// One CSV field, quoted when it needs to be.
std::string csvField(const std::string& text);

} // namespace dev::files
