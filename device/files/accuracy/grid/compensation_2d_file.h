#pragma once
// An XY stage's 2D compensation table as a file the host keeps: schema
// "benchpilot.compensation-2d", version 1 (docs/accuracy.md, "2D compensation
// table"), and its CSV export. The model is motion/metrology/grid/compensation_table_2d.h;
// the reader checks it as a device would.
#include "motion/checked.h"
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/grid/compensation_table_2d.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kCompensation2DSchema = "benchpilot.compensation-2d";
constexpr int kCompensation2DVersion = 1;

struct Compensation2DFile {
    motion::metrology::CompensationTable2D table;
    std::string source;  ///< free text: the map it was fitted from
};

std::string compensation2DToJson(const Compensation2DFile& f);

/// The value, or every problem why not (motion/checked.h).
using Compensation2DRead = motion::msg::Checked<Compensation2DFile>;
/// Plain C++: what the fuzzer drives.
Compensation2DRead compensation2DFromJson(std::string_view text, std::string_view fileName);
Compensation2DRead loadCompensation2DFile(const QString& path);
bool saveCompensation2DFile(const QString& path, const Compensation2DFile& f, motion::msg::Message* error);

/// `x_mm,y_mm,correction_x_um,correction_y_um`, a row per node, row by row.
std::string compensation2DToCsv(const motion::metrology::CompensationTable2D& t);

} // namespace dev::files::accuracy
