#pragma once
// Pairwise registration of two overlapping images, given where the stage says the
// second one lies relative to the first: the building block of stitching, of live
// registration of a tile against neighbours already taken, and of camera–stage
// calibration. Method (docs/stitching.md, "Registration"):
//   1. phase correlation over the expected overlap, Hann-windowed, with a
//      regularised normalisation G / (|G| + λ·mean|G|) — plain normalisation
//      (λ = 0) whitens the noise of blurred texture into false peaks;
//   2. the highest local maxima of the correlation surface, each read at its
//      wrap-around alternatives (MIST's four readings), kept only within
//      maxShiftPx of the expected offset;
//   3. each candidate scored by normalised cross-correlation (NCC) of the two
//      images over their true overlap at that offset; the best wins;
//   4. subpixel refinement by Gauss–Newton (Lucas–Kanade, translation and a
//      linear intensity change) on bicubic samples over the overlap.
// Plain C++ (no Qt); thread-safe: FFT plans are shared under a lock (fft_plans.h).
#include "imaging/image.h"

#include <Eigen/Core>

namespace imaging {

struct RegistrationOptions {
    /// How far (px, each axis) the answer may lie from the expected offset: what
    /// the stage can be wrong by. Candidates beyond it are never considered.
    double maxShiftPx = 40;
    /// Below this NCC a pair is not trusted (docs/stitching.md says why 0.3).
    double minNcc = 0.3;
    /// A second candidate more than 2 px away scoring at least this share of the
    /// best makes the pair ambiguous (a repetitive pattern): not trusted.
    double ambiguousRatio = 0.95;
    int peakCandidates = 8;
    /// λ of the regularised normalisation, as a share of the spectrum's mean magnitude.
    double regularisation = 1.0;
    /// An overlap narrower than this (px) is not registered.
    int minOverlapPx = 12;
};

enum class PairStatus {
    Accepted,    ///< trusted: placement uses it
    LowScore,    ///< best NCC below minNcc (blank, dark or out of focus)
    Ambiguous,   ///< two different offsets score alike (repetitive pattern)
    AtBound,     ///< the best offset lies on the search bound: the truth may be beyond it
    NoOverlap,   ///< the expected overlap is too small to register
    Outlier,     ///< registered, but rejected by global placement (placement.h)
};
const char* pairStatusName(PairStatus s);  ///< "accepted", "low_score", …

struct PairRegistration {
    Eigen::Vector2d shiftPx{0, 0};  ///< b's top-left in a's pixels, as measured
    double ncc = 0;                 ///< at the refined offset, −1 … 1
    double secondNcc = 0;           ///< the best candidate more than 2 px from the winner
    PairStatus status = PairStatus::NoOverlap;
    bool accepted() const { return status == PairStatus::Accepted; }
};

/// Registers `b` against `a`: `expectedPx` is where the stage puts b's top-left in
/// a's pixels. The answer lies within options.maxShiftPx of it, or the pair is not
/// accepted. Both images are whole tiles (or any two images, for calibration).
PairRegistration registerPair(const ImageF& a, const ImageF& b, const Eigen::Vector2d& expectedPx,
                              const RegistrationOptions& options = {});
/// The same on 16-bit tiles: only the expected overlap and its margin are converted.
PairRegistration registerPair(const ImageU16& a, const ImageU16& b, const Eigen::Vector2d& expectedPx,
                              const RegistrationOptions& options = {});

/// NCC of a and b over their overlap when b's top-left sits at integer `offset` in a.
double overlapNcc(const ImageF& a, const ImageF& b, int offsetX, int offsetY);

} // namespace imaging
