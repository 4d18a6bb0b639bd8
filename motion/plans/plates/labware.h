#pragma once
// Labware: a plate's footprint and its wells, in the plate frame.
//
// Plate frame (ours): origin at the plate's back-left corner (the corner by
// A1), x to the right along a row (columns 1, 2, …), y toward the front along a
// column (rows A, B, …), z up from the plate's bottom. This is how a plate is
// drawn and how ANSI/SLAS 1-2004…4-2004 give well positions ("A1 is 14.38 mm
// from the left edge and 11.24 mm from the top edge"). Opentrons definitions
// put the origin at the front-left corner with y growing toward the back:
// y_ours = yDimension − y_opentrons (see device/files/plates/labware_file.h).
#include "motion/plans/plates/problem.h"
#include "motion/plans/plates/wells.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::plates {

/// SBS/ANSI footprint (ANSI/SLAS 1-2004), mm.
constexpr double kSbsLengthMm = 127.76;
constexpr double kSbsWidthMm = 85.48;

enum class WellShape { Circular, Rectangular };
const char* wellShapeName(WellShape s);  ///< "circular", "rectangular"

struct Well {
    WellId id;
    double xMm = 0, yMm = 0;   ///< centre, plate frame
    double depthMm = 0;        ///< top to bottom
    double bottomZMm = 0;      ///< the well's bottom above the plate's base
    WellShape shape = WellShape::Circular;
    double diameterMm = 0;     ///< circular
    double sizeXMm = 0, sizeYMm = 0;  ///< rectangular
    double volumeUl = 0;       ///< what the well holds when full
    /// Half the smallest opening: how far off centre the tip may go (touch-off).
    double innerRadiusMm() const;
};

class Labware {
public:
    std::string id;            ///< "sbs-96", or the load name of an imported definition
    std::string displayName;   ///< "96-well plate, 360 µL (SBS)"
    std::string brand;
    double lengthMm = kSbsLengthMm, widthMm = kSbsWidthMm;  ///< footprint, x × y
    double heightMm = 14.22;
    int rows = 0, columns = 0; ///< the grid the well names span
    std::vector<Well> wells;   ///< row by row (A1, A2, …, B1, …); irregular plates may lack some

    /// The well at `w`, or nullptr when the plate has none there.
    const Well* well(const WellId& w) const;
    const Well* wellNamed(const std::string& name) const;
    /// "96-well plate", "24-well plate".
    std::string describe() const;
    /// Sorts the wells into row order (readers call this once).
    void sortWells();
};

/// A regular grid plate. Positions are the centre of A1 and the pitch between
/// neighbouring wells, in the plate frame.
struct GridSpec {
    std::string id, displayName, brand;
    int rows = 8, columns = 12;
    double a1XMm = 14.38, a1YMm = 11.24;
    double pitchXMm = 9, pitchYMm = 9;
    double lengthMm = kSbsLengthMm, widthMm = kSbsWidthMm, heightMm = 14.22;
    WellShape shape = WellShape::Circular;
    double diameterMm = 6.86, sizeXMm = 0, sizeYMm = 0;
    double depthMm = 10.67;
    double bottomZMm = 3.55;
    double volumeUl = 360;
};
Labware gridLabware(const GridSpec& spec);

/// The built-in SBS plates: "sbs-6", "sbs-12", "sbs-24", "sbs-48", "sbs-96", "sbs-384".
std::vector<Labware> builtinLabware();
std::optional<Labware> findBuiltinLabware(const std::string& id);

/// Every problem of a definition: grid, names, wells off the footprint,
/// non-positive sizes, a well deeper than the plate.
motion::msg::Problems validateLabware(const Labware& labware);

} // namespace motion::plates
