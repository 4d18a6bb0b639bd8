#include "motion/plans/plates/deck.h"

#include "motion/plans/plates/labware.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace plates {

const Slot* Deck::slot(const std::string& slotId) const
{
    for (const Slot& s : plateSlots)
        if (s.id == slotId)
            return &s;
    return nullptr;
}

const Station* Deck::station(const std::string& stationId) const
{
    for (const Station& s : stations)
        if (s.id == stationId)
            return &s;
    return nullptr;
}

namespace {
bool positive(double v) { return std::isfinite(v) && v > 0; }

/// The machine-frame box a seated SBS plate covers in a slot.
void footprintBox(const Slot& s, double* x0, double* y0, double* x1, double* y1)
{
    const PlateTransform t = s.nominal();
    const PointMm c[4] = {t.apply({0, 0}), t.apply({kSbsLengthMm, 0}), t.apply({0, kSbsWidthMm}),
                          t.apply({kSbsLengthMm, kSbsWidthMm})};
    *x0 = *x1 = c[0].x;
    *y0 = *y1 = c[0].y;
    for (const PointMm& p : c) {
        *x0 = std::min(*x0, p.x);
        *x1 = std::max(*x1, p.x);
        *y0 = std::min(*y0, p.y);
        *y1 = std::max(*y1, p.y);
    }
}
} // namespace

Problems validateDeck(const Deck& d)
{
    Problems out;
    for (auto [name, v] : {std::pair{"travel_x_mm", d.travelXMm}, std::pair{"travel_y_mm", d.travelYMm},
                           std::pair{"travel_z_mm", d.travelZMm}, std::pair{"table_z_mm", d.tableZMm},
                           std::pair{"syringe_ul", d.syringeUl}})
        if (!positive(v))
            out.push_back({name, "must be more than 0 (got " + formatMm(v) + ")"});
    if (d.tableZMm > d.travelZMm)
        out.push_back({"table_z_mm", "must be within the Z travel (at most " + formatMm(d.travelZMm) + " mm)"});
    if (!std::isfinite(d.moveOverheadS) || d.moveOverheadS < 0 || d.moveOverheadS > 1)
        out.push_back({"move_overhead_s", "must be from 0 to 1 s (got " + formatMm(d.moveOverheadS) + ")"});
    const std::pair<const char*, const AxisMotion*> axes[] = {{"axes.X", &d.x}, {"axes.Y", &d.y}, {"axes.Z", &d.z}, {"axes.P", &d.p}};
    for (const auto& [path, a] : axes) {
        if (!positive(a->maxSpeed))
            out.push_back({fieldPath(path, "max_speed"), "must be more than 0"});
        if (!positive(a->defaultSpeed) || a->defaultSpeed > a->maxSpeed)
            out.push_back({fieldPath(path, "default_speed"), "must be more than 0 and at most max_speed"});
        if (!positive(a->accelTimeS))
            out.push_back({fieldPath(path, "accel_time_s"), "must be more than 0"});
        if (!positive(a->maxAccel))
            out.push_back({fieldPath(path, "max_accel"), "must be more than 0"});
    }
    std::set<std::string> ids;
    for (std::size_t k = 0; k < d.plateSlots.size(); ++k) {
        const Slot& s = d.plateSlots[k];
        const std::string at = indexPath("slots", k);
        if (s.id.empty())
            out.push_back({fieldPath(at, "id"), "must not be empty"});
        else if (!ids.insert(s.id).second)
            out.push_back({fieldPath(at, "id"), "slot \"" + s.id + "\" is defined twice"});
        double x0, y0, x1, y1;
        footprintBox(s, &x0, &y0, &x1, &y1);
        if (!std::isfinite(x0 + y0 + x1 + y1) || x0 < -1e-9 || y0 < -1e-9 || x1 > d.travelXMm + 1e-9 || y1 > d.travelYMm + 1e-9)
            out.push_back({at, "a plate in slot \"" + s.id + "\" would cover X " + formatMm(x0) + "–" + formatMm(x1) + ", Y "
                                   + formatMm(y0) + "–" + formatMm(y1) + " mm, outside the travel 0–" + formatMm(d.travelXMm)
                                   + " × 0–" + formatMm(d.travelYMm) + " mm"});
        for (std::size_t j = 0; j < k; ++j) {
            double a0, b0, a1, b1;
            footprintBox(d.plateSlots[j], &a0, &b0, &a1, &b1);
            if (x0 < a1 - 1e-9 && a0 < x1 - 1e-9 && y0 < b1 - 1e-9 && b0 < y1 - 1e-9)
                out.push_back({at, "slot \"" + s.id + "\" overlaps slot \"" + d.plateSlots[j].id + "\""});
        }
    }
    for (std::size_t k = 0; k < d.stations.size(); ++k) {
        const Station& s = d.stations[k];
        const std::string at = indexPath("stations", k);
        if (s.id.empty())
            out.push_back({fieldPath(at, "id"), "must not be empty"});
        else if (!ids.insert(s.id).second)
            out.push_back({fieldPath(at, "id"), "\"" + s.id + "\" is already the id of a slot or station"});
        if (!std::isfinite(s.xMm) || !std::isfinite(s.yMm) || s.xMm < 0 || s.yMm < 0 || s.xMm > d.travelXMm || s.yMm > d.travelYMm)
            out.push_back({at, "station \"" + s.id + "\" at (" + formatMm(s.xMm) + ", " + formatMm(s.yMm) + ") mm is outside the travel"});
        if (!std::isfinite(s.safeZMm) || !std::isfinite(s.depthZMm) || s.safeZMm < 0 || !(s.safeZMm < s.depthZMm)
            || s.depthZMm > d.travelZMm)
            out.push_back({at, "station \"" + s.id + "\" needs 0 ≤ safe_z_mm < depth_z_mm ≤ " + formatMm(d.travelZMm) + " mm"});
    }
    return out;
}

} // namespace plates
