#pragma once
// A grid map's test as a file people keep: schema "benchpilot.grid-map-test", version 1
// (docs/accuracy.md, "Grid map test file"): the node pitch and count, where it starts
// (or the dot under the camera), the plate's pitch, feed, dwell, lead-in, what a dot
// not found does and the passes (forward only, or bidirectional: an optional field
// added within version 1, so every version-1 file reads as it did). Every problem at once with file, line, column and field; what the test
// cannot know alone (the travel it will run on) is placed in the same file by
// placeGridMapTestProblems when the instrument is known. Writing is atomic.
#include "device/files/accuracy/file_problem.h"
#include "motion/checked.h"
#include "motion/metrology/grid/grid_map_test.h"

#include <QString>

#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kGridMapTestSchema = "benchpilot.grid-map-test";
constexpr int kGridMapTestVersion = 1;

using GridMapTestRead = motion::msg::Checked<motion::metrology::GridMapTest>;

std::string gridMapTestToJson(const motion::metrology::GridMapTest& test);
/// Plain C++: what the fuzzer drives.
GridMapTestRead gridMapTestFromJson(std::string_view text, std::string_view fileName);
GridMapTestRead loadGridMapTestFile(const QString& path);
bool saveGridMapTestFile(const QString& path, const motion::metrology::GridMapTest& test, motion::msg::Message* error);

/// A model's problems found later (motion::metrology::validateTravel) placed in the file
/// they came from, at the line and column of the field their path names.
motion::msg::Problems placeGridMapTestProblems(const QString& path, const motion::msg::Problems& found);

} // namespace dev::files::accuracy
