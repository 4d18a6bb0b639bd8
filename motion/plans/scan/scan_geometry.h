#pragma once
// Plane geometry of a scan: points and rectangles in stage millimetres, and the
// exact test of a camera field (a rectangle) against a drawn polygon. Plain C++.
#include <vector>

namespace motion::scan {

struct Point2 {
    double xMm = 0, yMm = 0;
};

/// Axis-aligned, x0 ≤ x1 and y0 ≤ y1 once normalized.
struct Rect {
    double x0Mm = 0, y0Mm = 0, x1Mm = 0, y1Mm = 0;
    double widthMm() const { return x1Mm - x0Mm; }
    double heightMm() const { return y1Mm - y0Mm; }
    Point2 centre() const { return {0.5 * (x0Mm + x1Mm), 0.5 * (y0Mm + y1Mm)}; }
    bool contains(Point2 p) const { return p.xMm >= x0Mm && p.xMm <= x1Mm && p.yMm >= y0Mm && p.yMm <= y1Mm; }
};

Rect rectFromCorners(Point2 a, Point2 b);
Rect rectFromCentre(Point2 centre, double widthMm, double heightMm);
Rect boundingBox(const std::vector<Point2>& points);

/// Shoelace area; positive when the vertices run counter-clockwise.
double signedArea(const std::vector<Point2>& polygon);

/// Area of polygon ∩ rect, exact up to rounding: the polygon is clipped against the
/// rectangle's four half-planes (Sutherland–Hodgman). The clip window is convex, so
/// this holds for any simple polygon, concave ones included: the clipped outline may
/// run along the window's edges twice, but those stretches add no area.
/// `scratch` avoids two allocations per call when called for every tile of a grid.
double intersectionArea(const std::vector<Point2>& polygon, const Rect& rect, std::vector<Point2>* scratch = nullptr);

/// True when two edges that are not neighbours in the outline cross or touch, or
/// two vertices coincide: such an outline encloses no well-defined region.
bool selfIntersects(const std::vector<Point2>& polygon);

} // namespace motion::scan
