#pragma once
// A stitching scan as a person plans it: the region to cover, the camera's field,
// the overlap, the order tiles are visited in, how each tile is approached, and
// the timing of a tile. Plain data with a validator that returns every problem at
// once; the tile grid (scan_layout.h) and the time estimate (scan_estimate.h) are
// computed from it. The file format is device/files/scan_plan_file.h, docs/scan.md.
#include "motion/message.h"
#include "motion/problem.h"
#include "motion/plans/scan/scan_geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::scan {

enum class RegionKind { Corners, CentreSize, Polygon };

struct Region {
    RegionKind kind = RegionKind::Corners;
    Point2 cornerA{10, 10}, cornerB{30, 25};  ///< Corners: two opposite corners, any two
    Point2 centre{20, 17.5};                  ///< CentreSize
    double widthMm = 20, heightMm = 15;       ///< CentreSize
    std::vector<Point2> vertices;             ///< Polygon: outline in order, closed implicitly
};

/// The region's bounding rectangle: the rectangle itself, or the polygon's box.
Rect regionBounds(const Region& region);

enum class FieldSource { Sensor, Direct };
/// Which way image rows run on the stage: the image's y axis (downwards on screen)
/// along stage −Y (the stage map's top is the image's top) or along stage +Y.
enum class ImageY { StageMinusY, StagePlusY };

struct Camera {
    FieldSource source = FieldSource::Sensor;
    int sensorWidthPx = 2048, sensorHeightPx = 2048;  ///< Sensor
    double sensorPixelUm = 6.5;                       ///< Sensor: pixel pitch on the chip
    double magnification = 10;                        ///< Sensor: objective × relay
    double fieldWidthMm = 1.3312, fieldHeightMm = 1.3312; ///< Direct: field at the sample
    double samplePixelUm = 0.65;                      ///< Direct: one pixel at the sample (exports in pixels need it)
    double rotationDeg = 0;  ///< image x axis against stage +X, counter-clockwise; a small calibration angle
    ImageY imageY = ImageY::StageMinusY;
    /// A camera profile file (path as the plan gives it, relative to the plan's folder) the
    /// geometry above is taken from when the plan is loaded; "": none.
    std::string profile;
};

/// Field at the sample and one pixel at the sample, whichever way the camera is given.
double fieldWidthMm(const Camera& c);
double fieldHeightMm(const Camera& c);
double pixelAtSampleUm(const Camera& c);

enum class ScanOrder { Rows, Columns, SnakeRows, SnakeColumns };
/// "Top" is stage +Y: the stage map draws +Y upwards.
enum class StartCorner { TopLeft, TopRight, BottomLeft, BottomRight };

struct Approach {
    /// Every tile is reached by a last move in the same direction on each axis (the
    /// direction the first row runs, and the direction rows follow each other in), so
    /// screw backlash is taken up the same way at every tile. Where a move would arrive
    /// from the other side, an overtravel point is visited first.
    bool unidirectional = false;
    double overtravelMm = 0.2;  ///< how far before the tile the overtravel point lies
};

/// The stage's own error compensation (docs/scan.md): with `enabled` the scan runs only
/// when the device has compensation enabled on X and Y (the runner checks), and the
/// device moves every target by its correction so the work point lands on the planned
/// position. The plan carries no error curve of its own: measure one on the
/// Calibration screen (or `accuracy run`), fit it and upload it to the device.
struct Compensation {
    bool enabled = false;
};

/// How the exports name tiles and devices.
struct ExportNaming {
    /// {i} is the tile's number in visiting order (from firstIndex), {row} and {col}
    /// its grid place (from 0, row 0 at the top); ":0N" pads: tile_{i:03}.tif.
    std::string filePattern = "tile_{i:03}.tif";
    int firstIndex = 1;
    std::string mmXyStage = "XYStage";  ///< Micro-Manager's label of the XY stage device
};

struct ScanPlan {
    std::string name = "Scan";
    Region region;
    Camera camera;
    double overlapX = 0.10, overlapY = 0.10;  ///< share of the field, 0 … 0.9
    ScanOrder order = ScanOrder::SnakeRows;
    StartCorner start = StartCorner::TopLeft;
    Approach approach;
    double speedMmS = 10;       ///< path speed of the moves between tiles
    double settleS = 0.02;      ///< expected wait after a move's profile until the tile is taken (the simulated stage: ~11 ms)
    double exposureS = 0.05;    ///< camera exposure: the stage dwells this long at each tile
    double toleranceUm = 1.0;   ///< a tile is taken once the grating is this close to its target
    double settleTimeoutS = 2;  ///< a tile that has not settled by then pauses the run
    Compensation compensation;
    ExportNaming naming;
};

/// What the plan is checked against: the stage's travel and motion limits. HELLO
/// gives travel and top speed; acceleration and jerk are the firmware's planner
/// settings (the simulated stage's: device/sim/machine_config.cpp).
struct StageModel {
    Rect travel{0, 0, 100, 100};
    double maxSpeedMmS[2] = {20, 20};
    double maxAccelMmS2[2] = {200, 200};
    double maxJerkMmS3[2] = {4000, 4000};
};


/// Limits a plan must respect.
constexpr double kMaxOverlap = 0.9;
constexpr std::size_t kMaxPolygonVertices = 1000;
constexpr long kMaxTiles = 250000;  ///< 500 × 500: far beyond any slide, well inside memory

/// Every problem of the plan on its own (empty = valid): what the grid needs. Each
/// problem's path is the member's path in the plan file ("camera.overlap",
/// "region.vertices_mm[3]"), so the file reader can point at it and the CLI can name
/// its option; its message is scan.* (docs/scan.md, "Messages").
motion::msg::Problems validate(const ScanPlan& plan);
/// …and against a stage: the region inside its travel, the field no larger than
/// it, the speed within its limits.
motion::msg::Problems validate(const ScanPlan& plan, const StageModel& stage);

/// The position to command for a planned one: the planned position itself. With the
/// device's compensation the device moves it by the correction; the host never does.
Point2 commandedTarget(const ScanPlan& plan, Point2 planned);

const char* orderName(ScanOrder o);         ///< "rows", "cols", "snake-rows", "snake-cols"
const char* startCornerName(StartCorner c); ///< "top-left", …
std::optional<ScanOrder> orderFromName(const std::string& name);
std::optional<StartCorner> startCornerFromName(const std::string& name);

} // namespace motion::scan
