#pragma once
// What all three programs print for --version: the GNU layout (name and version,
// copyright, licence, warranty), which help2man turns into the man pages' COPYRIGHT
// section. Left in English, as the licence's own name is.
#include <string>

namespace app {

/// The licence the programs are distributed under: QCustomPlot, which the GUI
/// links, is GPL-3.0-or-later, so the whole is too (LICENSE, docs/install.md).
inline constexpr const char* kLicenceSpdx = "GPL-3.0-or-later";

inline std::string versionText(const char* program)
{
    return std::string(program) + " " BP_VERSION "\n"
           "Copyright (C) 2026 The BenchPilot authors.\n"
           "License GPL-3.0-or-later: GNU GPL version 3 or later <https://www.gnu.org/licenses/gpl-3.0.html>.\n"
           "This is free software: you are free to change and redistribute it.\n"
           "There is NO WARRANTY, to the extent permitted by law.\n";
}

} // namespace app
