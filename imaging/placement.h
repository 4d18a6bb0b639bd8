#pragma once
// Global placement of a set of tiles from their stage positions and the pairwise
// registrations between neighbours (docs/stitching.md, "Placement"):
//   minimise  Σ_tiles  w_s·|p_i − s_i|²  +  Σ_trusted pairs  w_ij·|p_j − p_i − m_ij|²
// with w_s = 1/σ_stage² (the stage's repeatability, in px) and w_ij = (ncc/σ_reg)².
// x and y separate: one sparse Cholesky factorisation solves both.
// Outliers are rejected one at a time, worst first, re-solving after each (Fiji's
// iterative rule, with a robust threshold): a pair whose residual exceeds
// max(outlierFloorPx, outlierMedians × the median trusted residual). A tile
// the solution moves further than maxCorrectionPx from its stage position has its
// pairs rejected. A tile left without a trusted pair sits at its stage position
// (the prior alone) and is flagged; a group of tiles joined only among themselves
// keeps the stage's centroid, so disconnected groups keep their stage offsets.
//
// The stage model: a grating whose scale differs from the camera's pixel size, or axes
// not quite square to the camera, put every stage position off by an amount that
// grows across the mosaic (MIST fits such a stage model from the data too). Left in
// the priors it pulls against the pairs, and on a large mosaic it trips the bound.
// So before the solve the pairs' shifts fit a 2×2 matrix M with shift ≈ M·(stage
// difference); when M differs from the identity by more than three standard errors
// and moves some tile by more than half a pixel, the priors become c + M·(s − c)
// (c the stage positions' centroid) and the bound counts from them.
#include "imaging/registration.h"

#include <Eigen/Core>

#include <vector>

namespace imaging {

struct TilePair {
    int a = 0;  ///< tile index
    int b = 0;  ///< tile index
    PairRegistration reg;  ///< reg.shiftPx = position of b − position of a
};

struct PlacementOptions {
    double stageSigmaPx = 2.0;         ///< the stage's repeatability (1σ) in image px
    double registrationSigmaPx = 0.2;  ///< a pair's own uncertainty at NCC 1
    double outlierFloorPx = 1.0;       ///< residuals below this are never outliers
    /// Residuals are 2-D norms: for Gaussian errors their median is 1.18σ, so 3 medians ≈ 3.5σ.
    double outlierMedians = 3.0;
    double maxCorrectionPx = 40;       ///< no tile moves further (each axis) from its (modelled) stage position
    bool fitStageModel = true;         ///< see StageModel; false: the stage positions as they are
};

/// What the pairs say of the stage's positions as a whole (see above).
struct StageModel {
    bool used = false;                  ///< significant, and applied to the priors
    Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
    Eigen::Vector2d centrePx{0, 0};     ///< c: the centroid of the stage positions
    int pairs = 0;                      ///< pairs the fit rests on
    /// M − I read as figures, in the image's axes: scale of x and y (ppm), the
    /// rotation of the stage's axes against the camera and their shear (µrad).
    double scaleXPpm() const { return (m(0, 0) - 1) * 1e6; }
    double scaleYPpm() const { return (m(1, 1) - 1) * 1e6; }
    double rotationUrad() const { return (m(1, 0) - m(0, 1)) / 2 * 1e6; }
    double shearUrad() const { return (m(1, 0) + m(0, 1)) / 2 * 1e6; }
    Eigen::Vector2d apply(const Eigen::Vector2d& stagePx) const { return centrePx + m * (stagePx - centrePx); }
};

/// The stage model from trusted pairs (weighted by score, one refit without residuals
/// beyond three medians); `used` says whether it is significant.
StageModel fitStageModel(const std::vector<Eigen::Vector2d>& stagePx, const std::vector<TilePair>& pairs);

struct Placement {
    std::vector<Eigen::Vector2d> positionsPx;  ///< each tile's top-left
    std::vector<bool> placedByStage;           ///< no trusted pair: at its stage position, flagged
    std::vector<double> residualPx;            ///< per pair: |p_b − p_a − m_ab| after the solve
    int rejectedPairs = 0;                     ///< turned to Outlier here
    double rmsCorrectionPx = 0;                ///< over tiles placed by registration: |p − s|
    double worstCorrectionPx = 0;
    StageModel stageModel;                     ///< the priors are stageModel.apply(stage) when used
    double rmsBeyondModelPx = 0;               ///< the same, counted from the model's positions
    double worstBeyondModelPx = 0;
};

/// Places the tiles; marks rejected pairs' status Outlier in `pairs`.
Placement placeTiles(const std::vector<Eigen::Vector2d>& stagePx, std::vector<TilePair>& pairs, const PlacementOptions& options = {});

} // namespace imaging
