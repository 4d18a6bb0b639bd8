#pragma once
// Accuracy and repeatability of positioning, evaluated as ISO 230-2:2014 defines
// it (docs/accuracy.md gives every formula with its clause). For target i,
// direction ↑/↓ and cycles j = 1…n, the deviation is x_ij = measured − target.
//
// Figures that do not apply are empty: a unidirectional test (only ↑ readings)
// has the ↑ figures alone, as the standard says; its M, B and B̄ and every ↓ or
// bidirectional figure are std::nullopt (null in JSON).
#include "motion/metrology/problem.h"
#include "motion/metrology/readings.h"

#include <optional>
#include <vector>

namespace motion::metrology {

/// One target's row of the ISO table. The first block is what the readings give
/// (and what a result file keeps); the rest follows from it by summarize().
struct TargetStatistics {
    double targetMm = 0;           ///< P_i
    int nUp = 0;                   ///< readings approached from below
    int nDown = 0;                 ///< readings approached from above (0: unidirectional)
    double meanUpMm = 0;           ///< x̄↑i
    double sUpMm = 0;              ///< s↑i, with n − 1
    std::optional<double> meanDownMm;  ///< x̄↓i
    std::optional<double> sDownMm;     ///< s↓i

    // Derived.
    double meanMm = 0;                 ///< x̄i = (x̄↑i + x̄↓i)/2; x̄↑i when unidirectional
    std::optional<double> reversalMm;  ///< B_i = x̄↑i − x̄↓i
    double rUpMm = 0;                  ///< R↑i = 4 s↑i
    std::optional<double> rDownMm;     ///< R↓i = 4 s↓i
    std::optional<double> rMm;         ///< R_i = max(2s↑i + 2s↓i + |B_i|, R↑i, R↓i)
};

/// The overall figures, in mm. Keys in files and JSON: A, A_up, A_down, E, E_up,
/// E_down, M, R, R_up, R_down, B, B_mean.
struct Figures {
    double aUpMm = 0;                  ///< A↑ = max(x̄↑i + 2s↑i) − min(x̄↑i − 2s↑i)
    std::optional<double> aDownMm;     ///< A↓ likewise
    std::optional<double> aMm;         ///< A: max over both of (x̄ + 2s) − min over both of (x̄ − 2s)
    double eUpMm = 0;                  ///< E↑ = max x̄↑i − min x̄↑i
    std::optional<double> eDownMm;     ///< E↓
    std::optional<double> eMm;         ///< E: max over both of x̄ − min over both of x̄
    std::optional<double> mMm;         ///< M = max x̄i − min x̄i
    double rUpMm = 0;                  ///< R↑ = max R↑i
    std::optional<double> rDownMm;     ///< R↓ = max R↓i
    std::optional<double> rMm;         ///< R = max R_i
    std::optional<double> bMm;         ///< B = max |B_i|
    std::optional<double> bMeanMm;     ///< B̄ = mean of B_i, signed
};

struct Evaluation {
    bool bidirectional = false;
    int cycles = 0;                        ///< the largest n of any target and direction
    std::vector<TargetStatistics> targets; ///< ascending target
    Figures figures;
    motion::msg::Problems problems;                     ///< paths "readings[k]" name the offending reading

    /// Figures and targets are meaningful only without errors.
    bool ok() const { return !hasErrors(problems); }
};

struct EvaluationOptions {
    /// A run in progress (a live plot) has targets with fewer cycles than others:
    /// with this set that is a warning instead of an error.
    bool allowUnequalCycles = false;
};

/// Refused (problems, empty figures): fewer than 2 targets, fewer than 2 cycles at
/// any target and direction, a number that is not finite, a cycle below 1, the same
/// target, direction and cycle twice, ↓ readings at some targets but not others,
/// unequal cycle counts (unless allowed).
///
/// Targets are told apart to the nanometre: readings whose targets round to the
/// same nanometre belong to the same target (a CSV may write 10 and 10.0000).
Evaluation evaluate(const std::vector<Reading>& readings, const EvaluationOptions& options = {});

/// The derived columns and the overall figures from the primary columns of each
/// target (targetMm, n, means and standard deviations), so a result file's figures
/// can be recomputed from its own table. Refuses fewer than 2 targets and targets
/// out of order.
Evaluation summarize(std::vector<TargetStatistics> targets, bool bidirectional);

} // namespace motion::metrology
