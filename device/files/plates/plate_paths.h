#pragma once
// Where the plate files that are not the user's documents live, shared by the
// GUI and the CLI so both see the same calibration: under the user's data
// directory (XDG_DATA_HOME, ~/.local/share on Linux), in BenchPilot/.
#include <QString>

namespace dev::files::plates {

/// The analyzer's slot calibration, kept between runs.
QString defaultCalibrationPath();
/// Where run logs go when the user names none.
QString defaultRunLogDirectory();

} // namespace dev::files::plates
