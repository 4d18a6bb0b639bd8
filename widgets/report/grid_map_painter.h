#pragma once
// A grid map drawn for a person: each node's error vector as an arrow magnified so the
// largest is about half a node pitch long, over a colour map of the error's length
// (light blue near zero through yellow to red at `colourMaxUm`), the nominal grid in grey.
// The same drawing in the PDF report and on the Calibration screen; Qt Gui only.
#include "motion/metrology/grid/grid_map.h"

#include <QColor>
#include <QPainter>
#include <QRectF>

namespace ui::report {

/// The colour of an error length on the map's scale from 0 to `maxUm`.
QColor gridErrorColour(double lengthUm, double maxUm);
/// The magnification that makes the longest vector of `maps` half their smallest pitch,
/// in page units per µm of error against page units per mm of travel (1 when all are zero).
double gridMagnification(const std::vector<const motion::metrology::GridMapResult*>& maps);
/// The longest error vector of `maps`, µm (their shared colour scale).
double gridLongestErrorUm(const std::vector<const motion::metrology::GridMapResult*>& maps);

/// Draws `map` into `rect` (any painter unit), keeping X and Y to one scale, +Y up.
void drawGridMap(QPainter& p, const QRectF& rect, const motion::metrology::GridMapResult& map, double magnification, double colourMaxUm);
/// A horizontal colour bar for 0 … `maxUm` with its ends labelled (the caller's font).
void drawGridColourBar(QPainter& p, const QRectF& rect, double maxUm);

} // namespace ui::report
