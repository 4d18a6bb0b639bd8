#pragma once
// Where the files BenchPilot ships beside its programs live: examples, labware
// definitions and machine profiles. Found relative to the running program, never
// by a path compiled in: <folder of the program>/../share/benchpilot. An installed
// copy has /usr/bin/benchpilot-cli and /usr/share/benchpilot/; a build tree mirrors
// that layout (build/app/ and build/share/benchpilot/, links into resources/), so
// a copy moved or installed under another prefix finds its own files.
#include <QString>

namespace dev::files {

/// <program folder>/../share/benchpilot (as installed: bin/ to the data folder), or
/// empty when there is none.
QString shippedDataDirectory();
QString shippedExamplesDirectory();  ///< share/benchpilot/examples
QString shippedLabwareDirectory();   ///< share/benchpilot/labware: *.labware.json, Opentrons labware
QString shippedMachinesDirectory();  ///< share/benchpilot/machines: *.machine.json, the deck

/// The data folder relative to the programs' folder, from the install layout
/// (shipped_data_location.cpp, generated at configure time).
const char* shippedDataFromProgram();

/// Tests: look here instead of beside the program (empty: beside the program again).
void setShippedDataDirectory(const QString& directory);

/// A machine profile as the user typed it: a path that exists is that file; a bare
/// name that does not (`stage-grbl-uno` or `stage-grbl-uno.machine.json`) is the
/// shipped profile of that name when there is one; anything else is returned as it
/// is, so opening it reports the name the user typed.
QString resolveMachineProfile(const QString& typed);

/// A labware file a recipe names without a folder and that is not beside the recipe:
/// the shipped one of that name, or empty.
QString shippedLabwareFile(const QString& fileName);

} // namespace dev::files
