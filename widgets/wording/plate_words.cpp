// Words for the plate.* ids (docs/plates.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"plate.empty", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must not be empty", "plate.empty")},
    {"plate.not_positive", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be more than 0 (got %1)", "plate.not_positive"), "value"},
    {"plate.negative", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be 0 or more (got %1)", "plate.negative"), "value"},
    {"plate.out_of_range", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be from %1 to %2 (got %3)", "plate.out_of_range"), "min,max,value"},
    {"plate.size_out_of_range", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be more than 0 and at most %1 (got %2)", "plate.size_out_of_range"), "max,value"},
    {"plate.more_not_shown", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "more problems not shown", "plate.more_not_shown")},
    {"plate.unknown_well", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "unknown well %1 on a %2-well plate", "plate.unknown_well"), "well,wells"},
    {"plate.deck.table_beyond_travel", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be within the Z travel (at most %1, got %2)", "plate.deck.table_beyond_travel"), "max,value"},
    {"plate.deck.default_speed_invalid", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be more than 0 and at most max_speed %1 (got %2)", "plate.deck.default_speed_invalid"), "max,value"},
    {"plate.deck.slot_twice", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "slot \"%1\" is defined twice", "plate.deck.slot_twice"), "slot"},
    {"plate.deck.slot_outside_travel", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "a plate in slot \"%1\" would cover X %2–%3, Y %4–%5, outside the travel 0–%6 × 0–%7", "plate.deck.slot_outside_travel"), "slot,x0,x1,y0,y1,travel_x,travel_y"},
    {"plate.deck.slots_overlap", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "slot \"%1\" overlaps slot \"%2\"", "plate.deck.slots_overlap"), "slot,other"},
    {"plate.deck.id_taken", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "\"%1\" is already the id of a slot or station", "plate.deck.id_taken"), "id"},
    {"plate.deck.station_outside_travel", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "station \"%1\" at (%2, %3) is outside the travel", "plate.deck.station_outside_travel"), "station,x,y"},
    {"plate.deck.station_heights", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "station \"%1\" needs 0 ≤ safe_z_mm < depth_z_mm ≤ %2", "plate.deck.station_heights"), "station,max"},
    {"plate.deck.no_slots", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "a deck needs at least one slot", "plate.deck.no_slots")},
    {"plate.labware.grid_size", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the grid must have 1–%1 rows and 1–%2 columns (got %3 × %4)", "plate.labware.grid_size"), "max_rows,max_columns,rows,columns"},
    {"plate.labware.no_wells", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "a plate needs at least one well", "plate.labware.no_wells")},
    {"plate.labware.well_outside_grid", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 is outside the %2 × %3 grid", "plate.labware.well_outside_grid"), "well,rows,columns"},
    {"plate.labware.well_twice", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 is defined twice", "plate.labware.well_twice"), "well"},
    {"plate.labware.well_no_size", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 needs a size above 0", "plate.labware.well_no_size"), "well"},
    {"plate.labware.well_depth", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1: its bottom (%2) plus its depth (%3) must be above 0 and at most the plate's height %4", "plate.labware.well_depth"), "well,bottom,depth,height"},
    {"plate.labware.well_no_volume", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 needs a volume above 0 µL", "plate.labware.well_no_volume"), "well"},
    {"plate.labware.well_off_footprint", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 at (%2, %3) does not fit on the %4 × %5 footprint", "plate.labware.well_off_footprint"), "well,x,y,length,width"},
    {"plate.wells.none", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "names no wells", "plate.wells.none")},
    {"plate.wells.row_needs_letter", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "%1 needs a row letter, like \"row B\"", "plate.wells.row_needs_letter"), "text"},
    {"plate.wells.unknown_row", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "unknown row %1 on a %2-well plate (rows A–%3)", "plate.wells.unknown_row"), "row,wells,last"},
    {"plate.wells.column_needs_number", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "%1 needs a column number, like \"column 3\"", "plate.wells.column_needs_number"), "text"},
    {"plate.wells.unknown_column", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "unknown column %1 on a %2-well plate (columns 1–%3)", "plate.wells.unknown_column"), "column,wells,last"},
    {"plate.wells.bad_range", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "%1 is not a range of two wells, like \"A1:H1\"", "plate.wells.bad_range"), "text"},
    {"plate.wells.not_a_well_set", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "%1 is not a well (\"A1\"), a range (\"A1:H1\"), \"row B\", \"column 3\" or \"all\"", "plate.wells.not_a_well_set"), "text"},
    {"plate.wells.named_twice", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 is named twice; dose a well twice with two steps", "plate.wells.named_twice"), "well"},
    {"plate.calibration.too_few_wells", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "teach at least two wells (three to see a residual)", "plate.calibration.too_few_wells")},
    {"plate.calibration.no_position", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "well %1 has no position", "plate.calibration.no_position"), "well"},
    {"plate.calibration.too_close", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the taught wells are less than 1 mm apart: teach wells at the plate's corners", "plate.calibration.too_close")},
    {"plate.calibration.scaled_needs_three", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "a scale per axis needs three taught wells", "plate.calibration.scaled_needs_three")},
    {"plate.calibration.on_one_line", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the taught wells lie on one line: a scale per axis needs a row and a column", "plate.calibration.on_one_line")},
    {"plate.calibration.large_residual", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the taught wells are up to %1 off the plate's shape (%2 mm; more than %3): one was taught off centre or on the wrong well; teach them again", "plate.calibration.large_residual"), "max,list,limit"},
    {"plate.calibration.scale_off", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the fitted scale is %1: the taught wells are not as far apart as the labware says (wrong labware, or a well taught on its neighbour)", "plate.calibration.scale_off"), "scale"},
    {"plate.calibration.turned", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "the plate sits turned by %1: is it seated flat in the slot?", "plate.calibration.turned"), "angle"},
    {"plate.file.grid_and_wells", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "give either \"grid\" or \"wells\", not both", "plate.file.grid_and_wells")},
    {"plate.file.no_grid", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "is missing: give the wells as a \"grid\" (A1 and pitch) or a list of \"wells\"", "plate.file.no_grid")},
    {"plate.file.not_a_well_name", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "\"%1\" is not a well name like \"A1\"", "plate.file.not_a_well_name"), "text"},
    {"plate.file.too_many_wells", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "more than %1 wells", "plate.file.too_many_wells"), "max"},
    {"plate.file.opentrons_schema", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "is %1; only Opentrons labware schema 2 is read", "plate.file.opentrons_schema"), "value"},
    {"plate.file.tip_rack", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "this is a tip rack, not a plate: the analyzer has a fixed tip", "plate.file.tip_rack")},
    {"plate.file.ordering_not_names", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "must be an array of well names", "plate.file.ordering_not_names")},
    {"plate.file.slot_calibrated_twice", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "slot \"%1\" is calibrated twice", "plate.file.slot_calibrated_twice"), "slot"},
    {"plate.file.cannot_fit", QT_TRANSLATE_NOOP3("ui::words::PlateWords", "cannot fit the taught points: %1", "plate.file.cannot_fit"), "cause"},
};
// clang-format on

} // namespace

QString plate(const motion::msg::Message& m) { return fromRows("ui::words::PlateWords", kRows, m); }

} // namespace ui::words::areas
