#pragma once
// A live position reading as digits: a value a hair below zero (an encoder at rest on
// zero, a commanded position after an E-stop) reads 0.000, not -0.000, which looks
// like a motion the machine did not make.
#include <QString>

#include <cmath>

namespace ui {

inline QString readingText(double v, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    const double shown = std::round(v * scale) / scale;
    return QString::number(shown == 0 ? 0.0 : shown, 'f', decimals);
}

} // namespace ui
