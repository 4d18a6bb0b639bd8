#pragma once
// Path segments in millimetres (motion/path) to and from the wire's nanometres. Plain C++: the
// path client, the CLI, the tests and the benchmark share it.
#include "device/protocol/messages_path.h"
#include "motion/path/path_geometry.h"

#include <vector>

namespace dev {

/// One segment as PATH_APPEND carries it (its start is implicit: where the previous one ended).
dev::proto::PathSegmentWire toWire(const motion::path::Segment& s);
/// The wire segments of a path, in order.
std::vector<dev::proto::PathSegmentWire> toWire(const std::vector<motion::path::Segment>& path);
/// Back to millimetres, given where the segment starts.
motion::path::Segment fromWire(const dev::proto::PathSegmentWire& w, motion::path::Vec2 startMm);

} // namespace dev
