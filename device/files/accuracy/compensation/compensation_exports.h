#pragma once
// A compensation in the formats other tools read (docs/accuracy.md, "Exports"):
//
//  - CSV: nominal_mm,correction_up_um,correction_down_um, one row per nominal.
//  - LinuxCNC's joint compensation file (COMP_FILE in the [JOINT_n] section, its
//    docs/src/config/ini-config.adoc): one "nominal forward reverse" triplet a
//    line, separated by spaces, in machine units (mm here), nominals ascending, at
//    most 256 lines, nothing else in the file (LinuxCNC stops reading at the first
//    line that is not three numbers). COMP_FILE_TYPE 0: forward and reverse are the
//    positions the joint actually reaches moving in the positive and the negative
//    direction; LinuxCNC makes its correction nominal − actual. Type 1: they are
//    that correction itself (src/emc/motion/usrmotintf.cc, usrmotLoadComp). BenchPilot
//    writes type 0 as actual = nominal − correction, so both types make LinuxCNC
//    command exactly what BenchPilot would. LinuxCNC ignores BACKLASH when a
//    COMP_FILE is given: the backlash is in the two columns.
//
// A polynomial is sampled at the nominals given (by default 41 evenly over the
// range it was fitted on); a table at its own points.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/compensation/compensation_model.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

/// The table's own points, or 41 evenly spaced over a polynomial's valid range
/// (fewer on a range shorter than 80 µm, to keep them 2 µm apart).
std::vector<double> defaultNominals(const motion::metrology::CompensationModel& m);

std::string compensationCsv(const motion::metrology::CompensationModel& m, const std::vector<double>& nominalsMm = {});

enum class LinuxcncCompType { ActualPositions = 0, Corrections = 1 };

std::string linuxcncCompensation(const motion::metrology::CompensationModel& m, LinuxcncCompType type,
                                 const std::vector<double>& nominalsMm = {});

struct LinuxcncRead {
    std::optional<motion::metrology::CompensationModel> model;  ///< a per-direction table
    motion::msg::Problems problems;
};
/// A LinuxCNC compensation file of the given type, back to a per-direction table.
/// Stricter than LinuxCNC: a line that is not three numbers is an error here (there
/// it silently ends the table), and so are nominals out of order, over 256 lines.
LinuxcncRead linuxcncFromText(std::string_view text, std::string_view fileName, LinuxcncCompType type, const std::string& axis = "X");

/// Written all or nothing.
bool saveLinuxcncCompensation(const QString& path, const motion::metrology::CompensationModel& m, LinuxcncCompType type, motion::msg::Message* error);
bool saveCompensationCsv(const QString& path, const motion::metrology::CompensationModel& m, motion::msg::Message* error);

} // namespace dev::files::accuracy
