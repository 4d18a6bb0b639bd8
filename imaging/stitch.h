#pragma once
// Stitching a folder of tiles whose stage positions are known: check the files,
// register every pair of neighbours, place all tiles, fuse the mosaic
// (docs/stitching.md). What `benchpilot-cli stitch` runs; the live stitch during a
// scan uses the same pieces one tile at a time (registration.h, placement.h).
// Plain C++: the caller reads the positions (TileConfiguration, the scan's run log)
// and words the problems.
#include "imaging/flat_field.h"
#include "imaging/fusion.h"
#include "imaging/geometry_check.h"
#include "imaging/placement.h"
#include "imaging/registration.h"
#include "imaging/tile_configuration.h"
#include "motion/checked.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace imaging {

struct StitchTile {
    std::string file;          ///< the name people know (in problems, the JSON and the TileConfiguration)
    std::string path;          ///< where to read it
    Eigen::Vector2d stagePx;   ///< top-left corner from the stage, in image pixels
};

struct StitchOptions {
    RegistrationOptions registration;
    PlacementOptions placement;
    FusionOptions fusion;
    OmeTiffOptions mosaic;           ///< its pixel size and stage position go into the OME-XML
    std::string mosaicPath;          ///< "" = register and place only
    /// The stage position (mm) of a point given in the stage-pixel frame, when known:
    /// the mosaic's top-left goes into the OME-XML with it.
    std::function<std::optional<Eigen::Vector2d>(const Eigen::Vector2d& stagePx)> stageMmAt;
    /// Divides every tile (for registration and fusion) by a blank image's shading; null = none.
    std::shared_ptr<const FlatField> flatField;
    int threads = 0;                 ///< registration workers; 0 = one a core
    double cacheMegabytes = 512;     ///< tiles kept in memory while registering
    /// The plan's camera, when known: the registered shifts are checked against it.
    std::optional<PlanCameraGeometry> planCamera;
};

struct StitchResult {
    std::vector<StitchTile> tiles;
    std::vector<TilePair> pairs;
    Placement placement;
    MosaicFrame frame;               ///< the mosaic; frame.originPx is the stage-pixel frame's offset
    SampleKind kind = SampleKind::Grey16;
    int tileWidth = 0, tileHeight = 0;
    double registrationS = 0, placementS = 0, fusionS = 0;
    std::optional<PlanCameraGeometry> planCamera;  ///< as the options gave it
    std::optional<GeometryCheck> cameraCheck;      ///< with planCamera (geometry_check.h)
};

/// Whether two tiles `dPx` apart (the second's top-left less the first's) are neighbours:
/// they overlap by at least `minOverlapPx` each way and sit side by side (not only corner
/// to corner). The one rule of the batch and the live stitch.
bool areNeighbours(const Eigen::Vector2d& dPx, int tileW, int tileH, int minOverlapPx);

/// Neighbour pairs from the stage positions (areNeighbours), in the order of the later tile.
std::vector<TilePair> neighbourPairs(const std::vector<Eigen::Vector2d>& stagePx, int tileW, int tileH, int minOverlapPx);

/// Every file readable, all of one size and sample kind: or every problem at once.
motion::msg::Checked<StitchResult> checkTiles(const std::vector<StitchTile>& tiles);

/// Reads tile `t`, flat-field corrected when `flat` is given.
motion::msg::Checked<TileImage> readTile(const StitchTile& t, const FlatField* flat);

/// The whole job. Refused with problems naming the file at fault; the mosaic file
/// exists only when all went well.
motion::msg::Checked<StitchResult> stitch(const std::vector<StitchTile>& tiles, const StitchOptions& options);

/// Fuses a placed result into options.mosaicPath (the pyramidal OME-TIFF), reading each
/// tile from its file; sets r.fusionS. The file exists only when all went well.
motion::msg::Problems writeMosaic(StitchResult& r, const StitchOptions& options);

/// Fiji's TileConfiguration of the registered positions (mosaic pixels, top-left tile near 0, 0).
std::string registeredTileConfiguration(const StitchResult& r);
/// The report (docs/stitching.md, "The report"): tiles, pairs, the summary.
std::string stitchJson(const StitchResult& r, double seconds, const std::string& mosaicFile);

} // namespace imaging
