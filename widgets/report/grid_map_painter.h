#pragma once
// A grid map drawn for a person: each node's error vector as an arrow magnified so the
// largest is about half a node pitch long, over a colour map of the error's length
// (light blue near zero through yellow to red at `colourMaxUm`), the nominal grid in grey.
// A map read both ways can be drawn with its reversal vectors instead (forward − reverse
// at each node, coloured by their length). The same drawing in the PDF report and on the
// Calibration screen; Qt Gui only.
#include "motion/metrology/grid/grid_map.h"

#include <QColor>
#include <QPainter>
#include <QRectF>

namespace ui::report {

/// What the arrows and colours of a map show.
enum class GridVectors {
    Error,     ///< each node's error (the mean of both directions when read both ways)
    Reversal,  ///< each node's reversal, forward − reverse (zero on a one-way map)
};
/// A node's vector of that kind, µm.
QPointF gridVectorUm(const motion::metrology::GridMapNode& node, GridVectors kind);

/// The colour of an error length on the map's scale from 0 to `maxUm`.
QColor gridErrorColour(double lengthUm, double maxUm);
/// The magnification that makes the longest vector of `maps` half their smallest pitch,
/// in page units per µm of error against page units per mm of travel (1 when all are zero).
double gridMagnification(const std::vector<const motion::metrology::GridMapResult*>& maps, GridVectors kind = GridVectors::Error);
/// The longest error vector of `maps`, µm (their shared colour scale).
double gridLongestErrorUm(const std::vector<const motion::metrology::GridMapResult*>& maps, GridVectors kind = GridVectors::Error);

/// Draws `map` into `rect` (any painter unit), keeping X and Y to one scale, +Y up.
void drawGridMap(QPainter& p, const QRectF& rect, const motion::metrology::GridMapResult& map, double magnification, double colourMaxUm,
                 GridVectors kind = GridVectors::Error);
/// A horizontal colour bar for 0 … `maxUm` with its ends labelled (the caller's font).
void drawGridColourBar(QPainter& p, const QRectF& rect, double maxUm);

} // namespace ui::report
