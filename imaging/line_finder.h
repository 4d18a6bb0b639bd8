#pragma once
// The graduation line nearest the image centre, to a fraction of a pixel: the reading
// a camera takes of a glass line scale (docs/stitching.md, "Finding lines and dots").
// Method: the image is averaged along the line's direction into one cross-section
// profile; the profile is smoothed by a Gaussian matched to a thin line and its peaks
// above the noise and the contrast floor are the candidates; the one nearest the
// centre is fitted, on the raw profile, with a Gaussian on a sloping background
// (Levenberg–Marquardt), whose centre is the answer. No threshold decides the position.
//
// Pixel (i, j) has its centre at (i, j); the image centre is ((w − 1) / 2, (h − 1) / 2).
// Plain C++ (no Qt).
#include "imaging/image.h"
#include "motion/checked.h"

namespace imaging {

/// How the line lies in the image: a Horizontal line runs along image x (its position
/// is a y), a Vertical one along image y (its position is an x).
enum class LineDirection { Horizontal, Vertical };

/// Whether the mark is darker (chrome on glass, in transmitted light) or brighter than
/// its surround; Either takes the stronger.
enum class Polarity { Dark, Bright, Either };

struct LineFinderOptions {
    LineDirection direction = LineDirection::Vertical;
    Polarity polarity = Polarity::Either;
    /// σ (px) of the smoothing that finds candidates: about the line's half-width.
    double smoothSigmaPx = 1.5;
    /// A candidate's depth (or height) against the background, as a share of the
    /// background: below it the glass is blank or the line out of focus.
    double minContrast = 0.05;
    /// A candidate must also stand this many noise σ of the profile above it.
    double minSnr = 8;
    /// A fitted line wider than this (Gaussian σ, px) is not a graduation line:
    /// it is out of focus, or a smudge.
    double maxSigmaPx = 12;
    /// Two candidates whose distances to the centre differ by less than this (px)
    /// are equally near: the reading is ambiguous.
    double ambiguousPx = 1.0;
};

struct FoundLine {
    double offsetPx = 0;  ///< the line's position minus the image centre, along the profile
    double contrast = 0;  ///< depth (dark) or height (bright) against the background, as a share of it
    double sigmaPx = 0;   ///< the fitted Gaussian's σ: how wide the line looks
    bool dark = true;     ///< darker than its surround
};

/// The line nearest the centre, or why not: imaging.line.image_too_small,
/// imaging.line.not_found (blank glass, out of focus, a smudge wider than
/// maxSigmaPx), imaging.line.ambiguous.
motion::msg::Checked<FoundLine> findLine(const ImageF& image, const LineFinderOptions& options = {});
motion::msg::Checked<FoundLine> findLine(const ImageU16& image, const LineFinderOptions& options = {});

/// The same on a profile already averaged along the line (centre at (n − 1) / 2);
/// imaging.line.too_short below 16 samples.
motion::msg::Checked<FoundLine> findLineInProfile(const std::vector<double>& profile, const LineFinderOptions& options = {});

} // namespace imaging
