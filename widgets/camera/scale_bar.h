#pragma once
// The scale bar's length: a round number of micrometres (1, 2 or 5 × 10ⁿ) whose bar is
// about a fifth of the picture's width, so it reads at a glance at any magnification.
namespace ui {

struct ScaleBar {
    double lengthUm = 0;  ///< 0: no bar (the pixel size is not known)
    double lengthPx = 0;  ///< on screen
};

/// For a picture `shownWidthPx` wide showing a frame `frameWidthPx` wide with pixels of
/// `pixelUm` at the sample.
ScaleBar scaleBarFor(double pixelUm, int frameWidthPx, double shownWidthPx);

} // namespace ui
