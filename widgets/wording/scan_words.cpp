// Words for the scan.* ids (docs/scan.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"scan.plan.camera_profile_problem", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the camera profile %1, line %2, column %3: %4", "scan.plan.camera_profile_problem"), "file,line,column,cause"},
    {"scan.stitch.running", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "a stitch is already running", "scan.stitch.running")},
    {"scan.stitch.no_run_log", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "%1 holds no scan run log: run a scan with images into it first", "scan.stitch.no_run_log"), "folder"},
    {"scan.stitch.no_images", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the scan in %1 took no images to stitch (was “Take an image at each tile” on?)", "scan.stitch.no_images"), "folder"},
    {"scan.stitch.image_missing", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the image of tile %2 (%1) is not in the folder", "scan.stitch.image_missing"), "file,tile"},
    {"scan.stitch.cannot_write", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "cannot write %1: %2", "scan.stitch.cannot_write"), "file,detail"},
    {"scan.out_of_range", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be from %1 to %2 (got %3)", "scan.out_of_range"), "min,max,value"},
    {"scan.not_positive_or_above", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be above 0 and at most %1 (got %2)", "scan.not_positive_or_above"), "max,value"},
    {"scan.not_a_position", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be a finite position in mm", "scan.not_a_position")},
    {"scan.region.corners_zero_size", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the region has zero size (%1 × %2): the corners must differ in both X and Y", "scan.region.corners_zero_size"), "width,height"},
    {"scan.region.size_zero", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the region has zero size (%1 × %2): width and height must be above 0", "scan.region.size_zero"), "width,height"},
    {"scan.region.too_few_vertices", QT_TRANSLATE_N_NOOP3("ui::words::ScanWords", "a polygon needs at least 3 vertices (got %Ln)", "scan.region.too_few_vertices"), "", "count"},
    {"scan.region.too_many_vertices", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "at most %1 vertices (got %2)", "scan.region.too_many_vertices"), "max,count"},
    {"scan.region.zero_area", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the polygon has zero area", "scan.region.zero_area")},
    {"scan.region.self_intersecting", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the outline crosses or touches itself; draw it without crossings", "scan.region.self_intersecting")},
    {"scan.camera.field_too_small", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the field at the sample must be at least %1 each way (got %2 × %3)", "scan.camera.field_too_small"), "min,width,height"},
    {"scan.overlap_out_of_range", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be from 0 to %1, a share of the field (got %2)", "scan.overlap_out_of_range"), "max,value"},
    {"scan.compensation.bad_coefficients", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must hold 1 to 6 finite coefficients, constant term first", "scan.compensation.bad_coefficients")},
    {"scan.compensation.curve_too_large", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the curve reaches %1 over the region; a positioning error above %2 is not one to compensate", "scan.compensation.curve_too_large"), "value,max"},
    {"scan.export.bad_stage_name", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must name Micro-Manager's XY stage device (not empty, one line)", "scan.export.bad_stage_name")},
    {"scan.too_many_tiles", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the field is so small for the region that the grid would have %1 tiles (at most %2)", "scan.too_many_tiles"), "count,max"},
    {"scan.too_many_tiles_over", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the field is so small for the region that the grid would have over %1 tiles (at most %1)", "scan.too_many_tiles_over"), "max"},
    {"scan.field_larger_than_travel", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the field %1 × %2 is larger than the stage's travel %3 × %4", "scan.field_larger_than_travel"), "width,height,travel_x,travel_y"},
    {"scan.region_beyond_travel", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the region X %1 … %2, Y %3 … %4 reaches beyond the stage's travel X %5 … %6, Y %7 … %8", "scan.region_beyond_travel"), "x0,x1,y0,y1,tx0,tx1,ty0,ty1"},
    {"scan.speed_above_stage", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be at most the stage's top speed %1 (got %2)", "scan.speed_above_stage"), "max,value"},
    {"scan.tile_outside_travel", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "tile %1 (%2, %3) lies outside the stage's travel X %4 … %5, Y %6 … %7; move the region inward", "scan.tile_outside_travel"), "tile,x,y,tx0,tx1,ty0,ty1"},
    {"scan.overtravel_outside_travel", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the overtravel point before tile %1 (%2, %3) lies outside the stage's travel X %4 … %5, Y %6 … %7; move the region inward", "scan.overtravel_outside_travel"), "tile,x,y,tx0,tx1,ty0,ty1"},
    {"scan.file.two_corners", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must hold two opposite corners [[x, y], [x, y]]", "scan.file.two_corners")},
    {"scan.naming.empty", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must not be empty", "scan.naming.empty")},
    {"scan.naming.edge_space", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must not start or end with a space (Fiji trims file names)", "scan.naming.edge_space")},
    {"scan.naming.starts_with_hash", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must not start with '#' (Fiji reads such a line as a comment)", "scan.naming.starts_with_hash")},
    {"scan.naming.semicolon", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must not contain ';' (it separates the fields of a TileConfiguration line)", "scan.naming.semicolon")},
    {"scan.naming.folder", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must be a file name without a folder ('/' or '\\')", "scan.naming.folder")},
    {"scan.naming.control_character", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must not contain control characters or line breaks", "scan.naming.control_character")},
    {"scan.naming.unclosed_brace", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "'{' at character %1 is never closed", "scan.naming.unclosed_brace"), "position"},
    {"scan.naming.unopened_brace", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "'}' at character %1 has no '{'", "scan.naming.unopened_brace"), "position"},
    {"scan.naming.unknown_placeholder", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "unknown placeholder %1; use {i}, {row} or {col}, optionally padded as {i:03}", "scan.naming.unknown_placeholder"), "placeholder"},
    {"scan.naming.bad_width", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "placeholder %1: the width must look like :03 (a zero and one digit)", "scan.naming.bad_width"), "placeholder"},
    {"scan.naming.no_index", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "must contain {i}, or both {row} and {col}, so every tile gets its own file", "scan.naming.no_index")},
    {"scan.run.tile", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "tile %1 of %2 (%3)", "scan.run.tile"), "tile,total,label"},
    {"scan.run.the_start", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the start", "scan.run.the_start")},
    {"scan.run.not_settled", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "%1 did not settle within %2 in %3 (X off by %4, Y by %5); the run is stopped: check the stage, then Resume to try this tile again", "scan.run.not_settled"), "tile,tolerance,timeout,off_x,off_y"},
    {"scan.run.link_lost", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The link to the stage was lost at %1. Nothing more moves from here; reconnect, then Resume to continue at that tile.", "scan.run.link_lost"), "tile"},
    {"scan.run.link_lost_cause", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The link to the stage was lost at %1 (%2). Nothing more moves from here; reconnect, then Resume to continue at that tile.", "scan.run.link_lost_cause"), "tile,cause"},
    {"scan.run.busy_preparing", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "A scan is running: stop it before preparing another.", "scan.run.busy_preparing")},
    {"scan.run.plan_problem", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "%1: %2", "scan.run.plan_problem"), "field,cause"},
    {"scan.run.log_damaged", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The run log %1 in this folder is damaged at line %2 (%3); it is left as it is.", "scan.run.log_damaged"), "log,line,cause"},
    {"scan.run.other_scans_log", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "This folder holds the run log of a different scan (%1 of %2 tiles taken). Choose another folder, or start over to keep that log aside and begin a new one.", "scan.run.other_scans_log"), "taken,tiles"},
    {"scan.run.cannot_move_log", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Cannot move the old run log aside to %1.", "scan.run.cannot_move_log"), "file"},
    {"scan.run.not_prepared", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "No scan is prepared.", "scan.run.not_prepared")},
    {"scan.run.not_connected", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The stage is not connected.", "scan.run.not_connected")},
    {"scan.run.not_a_stage", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Scans run on the microscope stage; this instrument is the %1.", "scan.run.not_a_stage"), "instrument"},
    {"scan.run.estop_latched", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The E-stop is latched: reset it first.", "scan.run.estop_latched")},
    {"scan.run.not_homed", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Home the stage first: a scan moves to absolute positions.", "scan.run.not_homed")},
    {"scan.run.no_compensation_on_stage", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The plan runs with the stage's own compensation, but this stage keeps none: run without it.", "scan.run.no_compensation_on_stage")},
    {"scan.run.compensation_being_read", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Reading whether the stage's compensation of %1 is enabled…", "scan.run.compensation_being_read"), "axis"},
    {"scan.run.compensation_not_enabled", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The plan runs with the stage's own compensation, but it is not enabled on %1: enable it (Calibration screen, or compensation enable --axis %1), or run without it.", "scan.run.compensation_not_enabled"), "axis"},
    {"scan.run.already_running", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The scan is already running.", "scan.run.already_running")},
    {"scan.run.aborted", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Aborted at %1. The tiles taken so far are kept; Resume continues at that tile.", "scan.run.aborted"), "tile"},
    {"scan.run.exports_failed", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "Every tile is taken, but the exports could not be written: %1", "scan.run.exports_failed"), "cause"},
    {"scan.run.move_refused", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The stage refused the move to %1: %2", "scan.run.move_refused"), "tile,cause"},
    {"scan.run.camera_failed", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The camera could not take %1: %2 The run is stopped; every tile taken before it is kept. Resume takes this tile again.", "scan.run.camera_failed"), "tile,cause"},
    {"scan.run.camera_silent", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "the camera %1 gave no image within %2 after the exposure", "scan.run.camera_silent"), "camera,seconds"},
    {"scan.run.estop", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "E-stop at %1: the run is stopped. Reset the E-stop and Resume to continue at that tile.", "scan.run.estop"), "tile"},
    {"scan.run.stage_event", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "The stage reported \"%1\" (%2) at %3: the run is stopped. Resume continues at that tile.", "scan.run.stage_event"), "event,detail,tile"},
    {"scan.run.log_failed", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "%1 The run is stopped so that no tile goes unrecorded.", "scan.run.log_failed"), "cause"},
};

const TermRow kTerms[] = {
    {"scan.pair.accepted", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "trusted", "scan.pair.accepted")},
    {"scan.pair.low_score", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "not trusted: score too low (blank, dark or out of focus)", "scan.pair.low_score")},
    {"scan.pair.ambiguous", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "not trusted: two offsets score alike (a repetitive pattern)", "scan.pair.ambiguous")},
    {"scan.pair.at_bound", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "not trusted: the best offset lies on the search bound", "scan.pair.at_bound")},
    {"scan.pair.no_overlap", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "not trusted: too little overlap", "scan.pair.no_overlap")},
    {"scan.pair.outlier", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "rejected: disagrees with the other pairs", "scan.pair.outlier")},
    {"scan.state.idle", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "ready", "scan.state.idle")},
    {"scan.state.running", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "running", "scan.state.running")},
    {"scan.state.pausing", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "pausing after this tile", "scan.state.pausing")},
    {"scan.state.paused", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "paused", "scan.state.paused")},
    {"scan.state.stopped", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "stopped", "scan.state.stopped")},
    {"scan.state.finished", QT_TRANSLATE_NOOP3("ui::words::ScanWords", "finished", "scan.state.finished")},
};
// clang-format on

} // namespace

QString scan(const motion::msg::Message& m) { return fromRows("ui::words::ScanWords", kRows, m); }
QString scanTerm(const std::string& id) { return fromTerms("ui::words::ScanWords", kTerms, id); }

} // namespace ui::words::areas
