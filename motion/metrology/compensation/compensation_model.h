#pragma once
// An axis's error compensation: what a device (or, until one does, the scan
// planner) applies to turn the position a person asks for into the position it
// commands. Two kinds, as controllers know them:
//
//  - Polynomial: the error curve e(x) = c0 + c1·x + … (µm over mm; seed 002's
//    fitted curve, "measured − nominal"), and a backlash b. Approached from below
//    the axis stops at x + (e(x) − b/2)/1000, from above at x + (e(x) + b/2)/1000;
//    the command c solves "stops at the target" by Newton's method, exactly, not by
//    seed 002's one-step subtraction (error_polynomial.h says by how much that
//    misses). Outside [validFromMm, validToMm], the range the curve was fitted on,
//    e is held at its end value: a fifth-order curve is wild beyond its data.
//  - Table: corrections k(x) in µm at nominal points, added to the command and
//    interpolated linearly between points (held at the end values outside), as
//    LinuxCNC's compensation files are; one column for both directions plus the
//    backlash (±b/2), or a column per direction (the backlash is then in the
//    columns and must be 0).
//
// Backlash b is the lost motion on a reversal: b = −B̄ (ISO 230-2's mean reversal
// value is x̄↑ − x̄↓, negative when the axis stops short coming from below).
#include "motion/calibration/error_polynomial.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/problem.h"
#include "motion/metrology/readings.h"

#include <string>
#include <vector>

namespace motion::metrology {

struct TablePoint {
    double nominalMm = 0;
    double correctionUpUm = 0;    ///< added to the command when approaching from below
    double correctionDownUm = 0;  ///< … from above; equal to Up in a single-column table
};

struct CompensationModel {
    enum class Kind { Polynomial, Table };

    std::string axis = "X";
    Kind kind = Kind::Polynomial;
    ErrorPolynomial polynomial;      ///< Kind::Polynomial: the error curve
    double validFromMm = 0;
    double validToMm = 0;
    std::vector<TablePoint> table;   ///< Kind::Table, ascending nominal
    bool perDirection = false;       ///< Table: the two columns differ
    double backlashUm = 0;

    /// The position to command so that the axis stops at `targetMm` when it arrives
    /// from `approach`'s side.
    double commandMm(double targetMm, Direction approach) const;
    /// The same without the backlash (a planner that does not know the side).
    double meanCommandMm(double targetMm) const;
    /// commandMm − target, in µm.
    double correctionUm(double targetMm, Direction approach) const;
};

/// The most points a table may have: what the device keeps, and LinuxCNC's limit.
constexpr std::size_t kMaxTablePoints = 256;
/// The largest correction or backlash taken for a compensation rather than a typo.
constexpr double kMaxCorrectionUm = 10000;
/// The steepest error curve taken for an axis's error: 100 µm/mm is a 10 % scale
/// error (seed 002's stage has 4 µm/mm). Beyond it the command is no longer a
/// position the axis can be sent to by Newton's method.
constexpr double kMaxSlopeUmPerMm = 100;
/// Table points closer than this are a typo, and LinuxCNC's file (nanometres)
/// could not keep them apart.
constexpr double kMinTableSpacingMm = 0.001;

/// Axis name, at most 6 coefficients (order ≤ 5) all finite, a valid range with
/// to − from ≥ 2 µm over which the curve stays within ±10 mm and below 100 µm/mm (checked
/// at 101 points), a table of 2–256 points with nominals increasing by 1 µm or more,
/// corrections and backlash finite and within ±10 mm, no backlash beside
/// per-direction columns.
motion::msg::Problems validate(const CompensationModel& m);

/// b = −B̄ in µm (0 for a unidirectional evaluation, which has no reversal).
double backlashUmFrom(const Evaluation& e);

/// The fitted curve over [fromMm, toMm] with a backlash.
CompensationModel polynomialModel(const std::string& axis, const ErrorPolynomial& curve, double fromMm, double toMm, double backlashUm);

/// A table at the evaluation's targets whose corrections make the axis stop on each
/// target exactly (the error is interpolated linearly between targets, and the
/// command found by Newton's method on it). Single column: from the bidirectional
/// means x̄i with the backlash −B̄; per direction: from x̄↑i and x̄↓i.
CompensationModel tableModel(const std::string& axis, const Evaluation& e, bool perDirection);

/// Corrections of any model at the given nominal points: what an export writes and
/// what a device with table compensation only is sent.
std::vector<TablePoint> sampleTable(const CompensationModel& m, const std::vector<double>& nominalsMm);

} // namespace motion::metrology
