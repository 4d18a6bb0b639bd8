#pragma once
// The dot nearest the image centre, its centre to a fraction of a pixel: the reading a
// camera takes of a grid plate (docs/stitching.md, "Finding lines and dots").
// Method: the image is binned 4 × 4 and its dots found as connected regions deeper
// (or brighter) than half the strongest one and than the contrast and noise floors;
// the region nearest the centre is measured at full resolution in a square window
// around it: a quadratic surface fitted to the window's border is taken as the
// background (vignetting is curved), and the centre is the centroid of the depth below
// it as a share of it, the window re-centred on each answer until it stops moving.
//
// Pixel (i, j) has its centre at (i, j); the image centre is ((w − 1) / 2, (h − 1) / 2).
// Plain C++ (no Qt).
#include "imaging/image.h"
#include "imaging/line_finder.h"
#include "motion/checked.h"

namespace imaging {

struct DotFinderOptions {
    Polarity polarity = Polarity::Either;
    /// A dot's depth (or height) against the background, as a share of it: below it
    /// the glass is blank or the dot out of focus.
    double minContrast = 0.05;
    /// A dot must also stand this many noise σ (of the binned image) above the background.
    double minSnr = 8;
    /// Regions smaller than this many binned pixels are noise or dust, not dots.
    int minBinnedArea = 2;
    /// Two dots whose distances to the centre differ by less than this (px) are
    /// equally near: the reading is ambiguous.
    double ambiguousPx = 1.0;
};

struct FoundDot {
    double xPx = 0;        ///< the dot's centre minus the image centre, along image x
    double yPx = 0;        ///< along image y (down)
    double diameterPx = 0; ///< of a disc of the same depth-weighted area
    double contrast = 0;   ///< depth (dark) or height (bright) against the background, as a share of it
    bool dark = true;
};

/// The dot nearest the centre, or why not: imaging.dot.image_too_small,
/// imaging.dot.not_found, imaging.dot.ambiguous, imaging.dot.at_edge.
motion::msg::Checked<FoundDot> findDot(const ImageF& image, const DotFinderOptions& options = {});
motion::msg::Checked<FoundDot> findDot(const ImageU16& image, const DotFinderOptions& options = {});

} // namespace imaging
