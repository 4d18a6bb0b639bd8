#include "motion/metrology/grid/grid_map_test.h"

#include <cmath>

namespace motion::metrology {

namespace {
constexpr int kMinGridNodes = 3;    // a straightness needs three points a line
constexpr int kMaxGridNodes = 101;

void checkPitch(motion::msg::Problems& out, const char* path, double pitchMm, double plateMm)
{
    if (!checkRange(out, path, pitchMm, 0.001, 1000, motion::msg::Unit::Mm) || !(plateMm > 0))
        return;
    const double k = pitchMm / plateMm;
    // A node between dots, or finer than the dots, would find another node's dot.
    if (k < 1 - 1e-9 || std::fabs(k - std::round(k)) > 1e-6)
        out.push_back(motion::msg::error(path, motion::msg::make("grid.pitch_not_on_plate",
                                                                 {motion::msg::real("pitch", pitchMm, motion::msg::Unit::Mm),
                                                                  motion::msg::real("plate_pitch", plateMm, motion::msg::Unit::Mm)})));
}
} // namespace

motion::msg::Problems validate(const GridMapTest& t)
{
    motion::msg::Problems out;
    checkRange(out, "plate_pitch_mm", t.platePitchMm, 0.01, 100, motion::msg::Unit::Mm);
    checkPitch(out, "pitch_mm.x", t.pitchXMm, t.platePitchMm);
    checkPitch(out, "pitch_mm.y", t.pitchYMm, t.platePitchMm);
    if (t.columns < kMinGridNodes || t.rows < kMinGridNodes)
        out.push_back(motion::msg::error(t.columns < kMinGridNodes ? "nodes.columns" : "nodes.rows",
                                         motion::msg::make("grid.too_few_nodes", {motion::msg::integer("columns", t.columns),
                                                                                  motion::msg::integer("rows", t.rows),
                                                                                  motion::msg::integer("min", kMinGridNodes)})));
    if (t.columns > kMaxGridNodes || t.rows > kMaxGridNodes)
        out.push_back(motion::msg::error(t.columns > kMaxGridNodes ? "nodes.columns" : "nodes.rows",
                                         motion::msg::make("grid.too_many_nodes", {motion::msg::integer("columns", t.columns),
                                                                                   motion::msg::integer("rows", t.rows),
                                                                                   motion::msg::integer("max", kMaxGridNodes)})));
    checkRange(out, "feed_mm_s", t.feedMmS, 0.01, 1000, motion::msg::Unit::MmPerS);
    checkRange(out, "dwell_s", t.dwellS, 0, 60, motion::msg::Unit::S);
    checkRange(out, "approach_mm", t.approachMm, 0.001, 10, motion::msg::Unit::Mm);
    if (t.startXMm)
        checkRange(out, "start_mm.x_mm", *t.startXMm, -1e6, 1e6, motion::msg::Unit::Mm);
    if (t.startYMm)
        checkRange(out, "start_mm.y_mm", *t.startYMm, -1e6, 1e6, motion::msg::Unit::Mm);
    return out;
}

motion::msg::Problems validateTravel(const GridMapTest& t, double startX, double startY, double minX, double maxX, double minY,
                                     double maxY)
{
    motion::msg::Problems out;
    auto check = [&](const char* path, const char* axis, double first, double pitch, int count, double lo, double hi) {
        const double low = first - t.approachMm, high = first + pitch * (count - 1) + (t.bidirectional ? t.approachMm : 0.0);
        constexpr double kSlackMm = 1e-6;
        if (low < lo - kSlackMm)
            out.push_back(motion::msg::error(path, motion::msg::make("grid.leaves_travel", {motion::msg::verbatim("axis", axis),
                                                                                            motion::msg::real("end", low, motion::msg::Unit::Mm),
                                                                                            motion::msg::real("limit", lo, motion::msg::Unit::Mm)})));
        else if (high > hi + kSlackMm)
            out.push_back(motion::msg::error(path, motion::msg::make("grid.leaves_travel", {motion::msg::verbatim("axis", axis),
                                                                                            motion::msg::real("end", high, motion::msg::Unit::Mm),
                                                                                            motion::msg::real("limit", hi, motion::msg::Unit::Mm)})));
    };
    check("nodes.columns", "X", startX, t.pitchXMm, t.columns, minX, maxX);
    check("nodes.rows", "Y", startY, t.pitchYMm, t.rows, minY, maxY);
    return out;
}

std::vector<GridMapStop> planGridMap(const GridMapTest& t, double startX, double startY)
{
    std::vector<GridMapStop> out;
    for (int j = 0; j < t.rows; ++j)
        for (int i = 0; i < t.columns; ++i)
            out.push_back({i, j, startX + i * t.pitchXMm, startY + j * t.pitchYMm, i == 0, false});
    if (t.bidirectional)
        for (int j = t.rows - 1; j >= 0; --j)
            for (int i = t.columns - 1; i >= 0; --i)
                out.push_back({i, j, startX + i * t.pitchXMm, startY + j * t.pitchYMm, i == t.columns - 1, true});
    return out;
}

} // namespace motion::metrology
