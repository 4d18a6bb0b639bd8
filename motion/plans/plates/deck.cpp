#include "motion/plans/plates/deck.h"

#include "motion/plans/plates/labware.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace motion::plates {

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

motion::msg::Problems validateDeck(const Deck& d)
{
    motion::msg::Problems out;
    for (auto [name, v] : {std::pair{"travel_x_mm", d.travelXMm}, std::pair{"travel_y_mm", d.travelYMm},
                           std::pair{"travel_z_mm", d.travelZMm}, std::pair{"table_z_mm", d.tableZMm},
                           std::pair{"syringe_ul", d.syringeUl}})
        if (!positive(v))
            out.push_back({name, motion::msg::make("plate.not_positive", {motion::msg::real("value", v)})});
    if (d.tableZMm > d.travelZMm)
        out.push_back({"table_z_mm", motion::msg::make("plate.deck.table_beyond_travel", {mmArg("value", d.tableZMm), mmArg("max", d.travelZMm)})});
    if (!std::isfinite(d.moveOverheadS) || d.moveOverheadS < 0 || d.moveOverheadS > 1)
        out.push_back({"move_overhead_s", motion::msg::make("plate.out_of_range", {motion::msg::real("value", d.moveOverheadS, motion::msg::Unit::S), motion::msg::real("min", 0, motion::msg::Unit::S), motion::msg::real("max", 1, motion::msg::Unit::S)})});
    const std::pair<const char*, const AxisMotion*> axes[] = {{"axes.X", &d.x}, {"axes.Y", &d.y}, {"axes.Z", &d.z}, {"axes.P", &d.p}};
    for (const auto& [path, a] : axes) {
        if (!positive(a->maxSpeed))
            out.push_back({fieldPath(path, "max_speed"), motion::msg::make("plate.not_positive", {motion::msg::real("value", a->maxSpeed)})});
        if (!positive(a->defaultSpeed) || a->defaultSpeed > a->maxSpeed)
            out.push_back({fieldPath(path, "default_speed"), motion::msg::make("plate.deck.default_speed_invalid", {motion::msg::real("value", a->defaultSpeed), motion::msg::real("max", a->maxSpeed)})});
        if (!positive(a->accelTimeS))
            out.push_back({fieldPath(path, "accel_time_s"), motion::msg::make("plate.not_positive", {motion::msg::real("value", a->accelTimeS, motion::msg::Unit::S)})});
        if (!positive(a->maxAccel))
            out.push_back({fieldPath(path, "max_accel"), motion::msg::make("plate.not_positive", {motion::msg::real("value", a->maxAccel)})});
    }
    std::set<std::string> ids;
    for (std::size_t k = 0; k < d.plateSlots.size(); ++k) {
        const Slot& s = d.plateSlots[k];
        const std::string at = indexPath("slots", k);
        if (s.id.empty())
            out.push_back({fieldPath(at, "id"), motion::msg::make("plate.empty")});
        else if (!ids.insert(s.id).second)
            out.push_back({fieldPath(at, "id"), motion::msg::make("plate.deck.slot_twice", {textArg("slot", s.id)})});
        double x0, y0, x1, y1;
        footprintBox(s, &x0, &y0, &x1, &y1);
        if (!std::isfinite(x0 + y0 + x1 + y1) || x0 < -1e-9 || y0 < -1e-9 || x1 > d.travelXMm + 1e-9 || y1 > d.travelYMm + 1e-9)
            out.push_back({at, motion::msg::make("plate.deck.slot_outside_travel",
                                         {textArg("slot", s.id), mmArg("x0", x0), mmArg("x1", x1), mmArg("y0", y0), mmArg("y1", y1),
                                          mmArg("travel_x", d.travelXMm), mmArg("travel_y", d.travelYMm)})});
        for (std::size_t j = 0; j < k; ++j) {
            double a0, b0, a1, b1;
            footprintBox(d.plateSlots[j], &a0, &b0, &a1, &b1);
            if (x0 < a1 - 1e-9 && a0 < x1 - 1e-9 && y0 < b1 - 1e-9 && b0 < y1 - 1e-9)
                out.push_back({at, motion::msg::make("plate.deck.slots_overlap", {textArg("slot", s.id), textArg("other", d.plateSlots[j].id)})});
        }
    }
    for (std::size_t k = 0; k < d.stations.size(); ++k) {
        const Station& s = d.stations[k];
        const std::string at = indexPath("stations", k);
        if (s.id.empty())
            out.push_back({fieldPath(at, "id"), motion::msg::make("plate.empty")});
        else if (!ids.insert(s.id).second)
            out.push_back({fieldPath(at, "id"), motion::msg::make("plate.deck.id_taken", {textArg("id", s.id)})});
        if (!std::isfinite(s.xMm) || !std::isfinite(s.yMm) || s.xMm < 0 || s.yMm < 0 || s.xMm > d.travelXMm || s.yMm > d.travelYMm)
            out.push_back({at, motion::msg::make("plate.deck.station_outside_travel", {textArg("station", s.id), mmArg("x", s.xMm), mmArg("y", s.yMm)})});
        if (!std::isfinite(s.safeZMm) || !std::isfinite(s.depthZMm) || s.safeZMm < 0 || !(s.safeZMm < s.depthZMm)
            || s.depthZMm > d.travelZMm)
            out.push_back({at, motion::msg::make("plate.deck.station_heights", {textArg("station", s.id), mmArg("max", d.travelZMm)})});
    }
    return out;
}

} // namespace motion::plates
