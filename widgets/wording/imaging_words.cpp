// Words for the imaging.* ids (docs/stitching.md, "Messages"): tile files, the
// mosaic, TileConfiguration and run-log positions, and the line and dot finders. One row per id, the English
// source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"imaging.camera_check.mirrored", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the images are mirrored against the plan's camera: set the camera's image y to %1 (the plan says %2)", "imaging.camera_check.mirrored"), "image_y,plan_image_y"},
    {"imaging.camera_check.rotated", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the neighbours' shifts show the camera turned %1 against the stage: set the camera's rotation to %1 (the plan says %2)", "imaging.camera_check.rotated"), "measured,plan"},
    {"imaging.camera_check.pixel", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the neighbours' shifts show a pixel of %1 at the sample: set the camera's pixel size to %1 (the plan says %2), or calibrate the camera", "imaging.camera_check.pixel"), "measured,plan"},
    {"imaging.tiff.unreadable", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "cannot be read as a TIFF image (%1)", "imaging.tiff.unreadable"), "reason"},
    {"imaging.tiff.damaged", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the image is damaged or cut short (%1)", "imaging.tiff.damaged"), "reason"},
    {"imaging.tiff.bad_size", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the image is %1 × %2 pixels: a tile must be from 1 to 65536 pixels each way", "imaging.tiff.bad_size"), "width,height"},
    {"imaging.tiff.unsupported", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the image has %2 samples of %1 bits a pixel: tiles must be 8- or 16-bit grey, or 8-bit RGB", "imaging.tiff.unsupported"), "bits,samples"},
    {"imaging.pyramid.unsupported", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the mosaic has %2 samples of %1 bits a pixel: a mosaic to view must be 8- or 16-bit grey", "imaging.pyramid.unsupported"), "bits,samples"},
    {"imaging.pyramid.bad_level", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "level %1 of the mosaic's pyramid cannot be read (%2)", "imaging.pyramid.bad_level"), "level,reason"},
    {"imaging.tiles.none", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "there are no tiles to stitch", "imaging.tiles.none")},
    {"imaging.tiles.mixed_size", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "this tile is %1 × %2 pixels but %3 is %4 × %5: every tile of a mosaic must be the same size", "imaging.tiles.mixed_size"), "width,height,first,first_width,first_height"},
    {"imaging.tiles.mixed_kind", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "this tile is %1 but %2 is %3: every tile of a mosaic must be of one kind (grey8, grey16 or rgb8)", "imaging.tiles.mixed_kind"), "kind,first,first_kind"},
    {"imaging.flat.empty", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the blank image is empty", "imaging.flat.empty")},
    {"imaging.flat.dark", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the blank image averages %1 grey levels, no more than the camera's offset of %2: take it with the light on", "imaging.flat.dark"), "mean,dark"},
    {"imaging.flat.clipped", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "%1 % of the blank image is saturated: take it with less light or a shorter exposure", "imaging.flat.clipped"), "percent"},
    {"imaging.flat.holes", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "%1 % of the blank image is darker than a tenth of its mean: a blank is evenly lit bare glass, not a specimen", "imaging.flat.holes"), "percent"},
    {"imaging.flat.size", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "this tile is %1 × %2 pixels but the blank image %3 is %4 × %5: the blank must come from the same camera and binning", "imaging.flat.size"), "width,height,flat,flat_width,flat_height"},
    {"imaging.mosaic.bad_size", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "a mosaic of %1 × %2 pixels cannot be written", "imaging.mosaic.bad_size"), "width,height"},
    {"imaging.mosaic.cannot_create", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the file cannot be created (%1)", "imaging.mosaic.cannot_create"), "reason"},
    {"imaging.mosaic.write_failed", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "writing the file failed (%1); nothing was left under its name", "imaging.mosaic.write_failed"), "reason"},
    {"imaging.mosaic.tile_changed", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "tile %1 changed size while the mosaic was being written", "imaging.mosaic.tile_changed"), "tile"},
    {"imaging.tileconfig.no_dim", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "a tile line comes before 'dim = 2'", "imaging.tileconfig.no_dim")},
    {"imaging.tileconfig.bad_dim", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the dimensions must be 'dim = 2' (or 3)", "imaging.tileconfig.bad_dim")},
    {"imaging.tileconfig.not_three_fields", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "a tile line needs three fields separated by ';' (file; name; (x, y)), this one has %1", "imaging.tileconfig.not_three_fields"), "count"},
    {"imaging.tileconfig.bad_position", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the position must be (x, y) in pixels, one number for each dimension", "imaging.tileconfig.bad_position")},
    {"imaging.tileconfig.no_file", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the tile line names no file", "imaging.tileconfig.no_file")},
    {"imaging.tileconfig.no_tiles", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the file places no tiles", "imaging.tileconfig.no_tiles")},
    {"imaging.positions.bad_image_name", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "'%1' is not a file name in the folder (empty, or with a folder in it)", "imaging.positions.bad_image_name"), "file"},
    {"imaging.positions.duplicate", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "%1 (or its tile number) is taken twice in the log", "imaging.positions.duplicate"), "file"},
    {"imaging.positions.no_tiles", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "%1 records no tile taken yet", "imaging.positions.no_tiles"), "file"},
    {"imaging.live.incomplete", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "%1 of the %2 tiles were taken: the live mosaic is placed only when every tile is there", "imaging.live.incomplete"), "taken,total"},
    {"imaging.live.cancelled", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the live stitch was stopped before it finished", "imaging.live.cancelled")},
    {"imaging.line.image_too_small", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the image is %1 × %2 pixels: finding a line needs at least %3 pixels each way", "imaging.line.image_too_small"), "width,height,minimum"},
    {"imaging.line.too_short", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the profile has %1 samples: finding a line needs at least %2", "imaging.line.too_short"), "length,minimum"},
    {"imaging.line.not_found", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "no graduation line found: the strongest mark stands out by %1 and a line needs %2 (blank glass, or out of focus)", "imaging.line.not_found"), "contrast,minimum"},
    {"imaging.line.ambiguous", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "two lines are equally near the image centre (at %1 px and %2 px from it): which one to read cannot be told", "imaging.line.ambiguous"), "first,second"},
    {"imaging.dot.image_too_small", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the image is %1 × %2 pixels: finding a dot needs at least %3 pixels each way", "imaging.dot.image_too_small"), "width,height,minimum"},
    {"imaging.dot.not_found", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "no dot found: the strongest mark stands out by %1 and a dot needs %2 (blank glass, or out of focus)", "imaging.dot.not_found"), "contrast,minimum"},
    {"imaging.dot.ambiguous", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "two dots are equally near the image centre (%1 px and %2 px from it): which one to read cannot be told", "imaging.dot.ambiguous"), "first,second"},
    {"imaging.dot.at_edge", QT_TRANSLATE_NOOP3("ui::words::ImagingWords", "the dot nearest the centre (%1 px, %2 px from it) is cut by the edge of the image: its centre cannot be measured", "imaging.dot.at_edge"), "x,y"},
};
// clang-format on

} // namespace

QString imaging(const motion::msg::Message& m) { return fromRows("ui::words::ImagingWords", kRows, m); }

} // namespace ui::words::areas
