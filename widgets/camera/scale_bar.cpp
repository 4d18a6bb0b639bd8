#include "widgets/camera/scale_bar.h"

#include <cmath>
#include <initializer_list>

namespace ui {

ScaleBar scaleBarFor(double pixelUm, int frameWidthPx, double shownWidthPx)
{
    if (!(pixelUm > 0) || frameWidthPx <= 0 || !(shownWidthPx > 0))
        return {};
    const double umPerScreenPx = pixelUm * double(frameWidthPx) / shownWidthPx;
    const double wantedUm = 0.2 * shownWidthPx * umPerScreenPx;
    // The largest 1, 2 or 5 × 10ⁿ not above a fifth of the width.
    const double decade = std::pow(10.0, std::floor(std::log10(wantedUm)));
    double length = decade;
    for (double step : {2.0, 5.0})
        if (step * decade <= wantedUm)
            length = step * decade;
    return {length, length / umPerScreenPx};
}

} // namespace ui
