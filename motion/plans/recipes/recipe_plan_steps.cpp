// The recipe's steps, one by one: where the tip goes for each type, what the
// plunger does, and what the syringe can hold (see recipe_planner.h).
#include "motion/plans/recipes/recipe_planner.h"

#include <algorithm>
#include <cmath>

namespace motion::plates::planning {

bool Planner::checkVolume(const Step& s, const std::string& path, bool capacityBound)
{
    if (!std::isfinite(s.volumeUl) || s.volumeUl <= 0) {
        error(fieldPath(path, "volume_ul"), motion::msg::make("plate.not_positive", {ulArg("value", s.volumeUl)}));
        return false;
    }
    if (capacityBound && s.volumeUl > m_cap + kEps) {
        error(fieldPath(path, "volume_ul"), motion::msg::make("recipe.volume_over_capacity", {volume("volume", s.volumeUl), volume("capacity", m_cap)}));
        return false;
    }
    return true;
}

double Planner::pumpSpeed(const Step& s, const std::string& path)
{
    if (!s.speedUlS)
        return 0;
    if (!(*s.speedUlS >= kMinSpeed) || *s.speedUlS > m_c.deck.p.maxSpeed) {
        error(fieldPath(path, "speed_ul_s"), motion::msg::make("plate.out_of_range", {motion::msg::real("value", *s.speedUlS, motion::msg::Unit::UlPerS),
                                                                              motion::msg::real("min", kMinSpeed, motion::msg::Unit::UlPerS),
                                                                              motion::msg::real("max", m_c.deck.p.maxSpeed, motion::msg::Unit::UlPerS)}));
        return 0;
    }
    return *s.speedUlS;
}

bool Planner::roomFor(double delta, const std::string& path, bool* reported)
{
    const double after = m_p + delta;
    if (after <= m_cap + 1e-6 && after >= -1e-6)
        return true;
    if (!*reported) {
        *reported = true;
        if (after > m_cap)
            error(path, m_p > 1e-6 ? motion::msg::make("recipe.syringe_overfull_holding", {volume("volume", after), volume("capacity", m_cap), volume("holding", m_p)})
                                   : motion::msg::make("recipe.syringe_overfull", {volume("volume", after), volume("capacity", m_cap)}));
        else
            error(path, motion::msg::make("recipe.plunger_past_empty", {volume("volume", after)}));
    }
    return false;
}

void Planner::aspirateAt(int step, const Place& pl, double vol, double speed, const std::string& volPath, bool* reported)
{
    roomFor(vol, volPath, reported);
    PlanOp& op = newOp(step, StepType::Aspirate, &pl, vol);
    goInto(op, pl);
    pump(op, vol, speed);
    leave(op);
    m_liquid += vol;
    if (!pl.well.empty()) {
        WellTotal& t = totalOf(pl);
        t.aspiratedUl += vol;
        ++t.visits;
    }
    m_plan.totalAspiratedUl += vol;
}

void Planner::dispenseAt(int step, const Place& pl, double vol, double speed, double touchMm, bool mayFold)
{
    PlanOp& op = newOp(step, StepType::Dispense, &pl, vol);
    goInto(op, pl);
    // A trailing air gap sits at the tip: it leaves first, with this dispense.
    const bool inArch = touchMm <= 0 && pumpInsideArch(op, pl, -(vol + m_air), speed, !mayFold);
    if (!inArch)
        pump(op, -(vol + m_air), speed);
    m_air = 0;
    if (touchMm > 0) {
        const PointMm dir = pl.transform.applyVector({touchMm, 0});
        travelTo(op, {pl.at.x + dir.x, pl.at.y + dir.y}, MoveKind::Touch);
        travelTo(op, pl.at, MoveKind::Touch);
    }
    if (!inArch || !mayFold)
        leave(op);
    m_liquid -= vol;
    if (!pl.well.empty()) {
        WellTotal& t = totalOf(pl);
        t.dispensedUl += vol;
        ++t.visits;
    }
    m_plan.totalDispensedUl += vol;
}

void Planner::planStep(int i)
{
    const Step& s = m_r.steps[static_cast<std::size_t>(i)];
    const std::string path = indexPath("steps", static_cast<std::size_t>(i));
    const double speed = pumpSpeed(s, path);
    bool reported = false;
    switch (s.type) {
    case StepType::Aspirate:
    case StepType::Dispense: {
        const bool asp = s.type == StepType::Aspirate;
        if (!s.station.empty() && !s.wells.empty()) {
            error(fieldPath(path, "station"), motion::msg::make("recipe.wells_and_station"));
            return;
        }
        if (s.station.empty() && s.wells.empty()) {
            error(fieldPath(path, "wells"), motion::msg::make(asp ? "recipe.wells_missing_aspirate" : "recipe.wells_missing_dispense"));
            return;
        }
        const bool volOk = checkVolume(s, path, true);
        std::vector<Place> places;
        if (!s.station.empty()) {
            if (s.order && *s.order != WellOrder::AsWritten)
                error(fieldPath(path, "order"), motion::msg::make("recipe.order_without_wells", {textArg("order", wellOrderName(*s.order))}));
            Place pl;
            if (stationPlace(s.station, fieldPath(path, "station"), &pl))
                places.push_back(pl);
        } else {
            places = wellPlaces(s, path);
            orderPlaces(i, s, places);
        }
        if (!volOk)
            return;
        for (const Place& pl : places)
            if (pl.w && s.volumeUl > pl.w->volumeUl + kEps) {
                error(fieldPath(path, "volume_ul"), motion::msg::make(asp ? "recipe.aspirate_over_well" : "recipe.dispense_over_well",
                                                              {volume("volume", s.volumeUl), volume("capacity", pl.w->volumeUl), textArg("plate", pl.plate)}));
                return;
            }
        if (asp) {
            if (!s.source.empty())
                error(fieldPath(path, "source"), motion::msg::make("recipe.source_only_dispense"));
            for (const Place& pl : places)
                aspirateAt(i, pl, s.volumeUl, speed, fieldPath(path, "volume_ul"), &reported);
            return;
        }
        if (s.offsetMm < 0 || !std::isfinite(s.offsetMm))
            error(fieldPath(path, "touch_off_mm"), motion::msg::make("plate.negative", {mmArg("value", s.offsetMm)}));
        for (const Place& pl : places)
            if (pl.w && s.offsetMm > pl.w->innerRadiusMm() + kEps) {
                error(fieldPath(path, "touch_off_mm"), motion::msg::make("recipe.offset_past_wall", {mmArg("value", s.offsetMm), mmArg("width", 2 * pl.w->innerRadiusMm())}));
                break;
            }
        if (s.distribute && s.source.empty())
            error(fieldPath(path, "distribute"), motion::msg::make("recipe.distribute_needs_source"));
        if (!s.distribute)
            for (const auto& [field, set] : {std::pair<const char*, bool>{"disposal_ul", s.disposalUl != 0}, {"air_gap_ul", s.airGapUl != 0},
                                             {"rest_to", !s.restTo.empty()}})
                if (set)
                    error(fieldPath(path, field), motion::msg::make("recipe.needs_distribute", {textArg("field", field)}));
        if (!s.source.empty())
            planTransfer(i, s, path, places, speed);
        else
            for (const Place& pl : places) {
                if (m_liquid < s.volumeUl - 1e-6 && !reported) {
                    reported = true;
                    error(path, motion::msg::make("recipe.dispense_without_liquid", {volume("volume", s.volumeUl), volume("holding", std::max(0.0, m_liquid))}));
                }
                dispenseAt(i, pl, s.volumeUl, speed, std::max(0.0, s.offsetMm));
            }
        return;
    }
    case StepType::Mix: {
        checkCycles(s, path);
        const bool ok = checkVolume(s, path, true);
        std::vector<Place> places = wellPlaces(s, path);
        orderPlaces(i, s, places);
        if (!ok)
            return;
        roomFor(s.volumeUl, fieldPath(path, "volume_ul"), &reported);
        for (const Place& pl : places) {
            if (pl.w && s.volumeUl > pl.w->volumeUl + kEps) {
                error(fieldPath(path, "volume_ul"), motion::msg::make("recipe.mix_over_well", {volume("volume", s.volumeUl), volume("capacity", pl.w->volumeUl)}));
                return;
            }
            PlanOp& op = newOp(i, StepType::Mix, &pl, s.volumeUl);
            goInto(op, pl);
            for (int c = 0; c < std::clamp(s.cycles, 1, kMaxCycles); ++c) {
                pump(op, s.volumeUl, speed);
                pump(op, -s.volumeUl, speed);
            }
            leave(op);
            ++totalOf(pl).visits;
        }
        return;
    }
    case StepType::Wash: {
        checkCycles(s, path);
        const bool ok = checkVolume(s, path, true);
        Place pl;
        if (s.station.empty()) {
            error(fieldPath(path, "station"), motion::msg::make("recipe.wash_station_missing"));
            return;
        }
        if (!stationPlace(s.station, fieldPath(path, "station"), &pl) || !ok)
            return;
        roomFor(s.volumeUl, fieldPath(path, "volume_ul"), &reported);
        PlanOp& op = newOp(i, StepType::Wash, &pl, s.volumeUl);
        goInto(op, pl);
        for (int c = 0; c < std::clamp(s.cycles, 1, kMaxCycles); ++c) {
            pump(op, s.volumeUl, speed);
            pump(op, -s.volumeUl, speed);
        }
        leave(op);
        return;
    }
    case StepType::AirGap: {
        if (!checkVolume(s, path, true))
            return;
        roomFor(s.volumeUl, fieldPath(path, "volume_ul"), &reported);
        PlanOp& op = newOp(i, StepType::AirGap, nullptr, s.volumeUl);
        // Air is drawn with the tip out of the liquid: at the travel height.
        raiseTo(op, m_safeZ < 1e300 ? m_safeZ : m_z);
        pump(op, s.volumeUl, speed);
        m_air += s.volumeUl;
        return;
    }
    case StepType::Wait: {
        if (!std::isfinite(s.seconds) || s.seconds < 0 || s.seconds > kMaxWaitS) {
            error(fieldPath(path, "seconds"), motion::msg::make("plate.out_of_range", {motion::msg::real("value", s.seconds, motion::msg::Unit::S), motion::msg::real("min", 0, motion::msg::Unit::S),
                                                                           motion::msg::real("max", kMaxWaitS, motion::msg::Unit::S)}));
            return;
        }
        PlanOp& op = newOp(i, StepType::Wait, nullptr, 0);
        MachineMove m;
        m.kind = MoveKind::Dwell;
        m.seconds = s.seconds;
        m.durationS = s.seconds;
        op.moves.push_back(m);
        return;
    }
    case StepType::TouchOff: {
        std::vector<Place> places = wellPlaces(s, path);
        orderPlaces(i, s, places);
        if (!(s.offsetMm > 0) || !std::isfinite(s.offsetMm)) {
            error(fieldPath(path, "offset_mm"), motion::msg::make("plate.not_positive", {mmArg("value", s.offsetMm)}));
            return;
        }
        for (const Place& pl : places) {
            if (pl.w && s.offsetMm > pl.w->innerRadiusMm() + kEps) {
                error(fieldPath(path, "offset_mm"), motion::msg::make("recipe.offset_past_wall", {mmArg("value", s.offsetMm), mmArg("width", 2 * pl.w->innerRadiusMm())}));
                return;
            }
            PlanOp& op = newOp(i, StepType::TouchOff, &pl, 0);
            goInto(op, pl);
            const PointMm dir = pl.transform.applyVector({s.offsetMm, 0});
            travelTo(op, {pl.at.x + dir.x, pl.at.y + dir.y}, MoveKind::Touch);
            travelTo(op, pl.at, MoveKind::Touch);
            leave(op);
        }
        return;
    }
    }
}

void Planner::checkCycles(const Step& s, const std::string& path)
{
    if (s.cycles < 1 || s.cycles > kMaxCycles)
        error(fieldPath(path, "cycles"), motion::msg::make("plate.out_of_range", {motion::msg::integer("value", s.cycles), motion::msg::integer("min", 1), motion::msg::integer("max", kMaxCycles)}));
}

void Planner::planTransfer(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed)
{
    const std::string srcPath = fieldPath(path, "source");
    Place src;
    if (!s.source.station.empty()) {
        if (!s.source.well.empty()) {
            error(srcPath, motion::msg::make("recipe.source_well_and_station"));
            return;
        }
        if (!stationPlace(s.source.station, fieldPath(srcPath, "station"), &src))
            return;
    } else {
        const RecipePlate* p = resolvePlate(s.source.plate, fieldPath(srcPath, "plate"));
        if (!p)
            return;
        const Labware& lw = m_c.labware.at(p->labware);
        const Well* w = lw.wellNamed(s.source.well);
        if (!w) {
            error(fieldPath(srcPath, "well"), motion::msg::make("plate.unknown_well", {textArg("well", "\"" + s.source.well + "\""),
                                                                                 motion::msg::integer("wells", static_cast<long long>(lw.wells.size()))}));
            return;
        }
        src = wellPlace(*p, *w);
        if (!reachable(src.at)) {
            error(fieldPath(srcPath, "well"), motion::msg::make("recipe.source_outside_travel"));
            return;
        }
    }
    const double room = m_cap - m_p - m_air;
    if (s.distribute) {
        planDistribute(i, s, path, targets, speed, src, room);
        return;
    }
    const int perRound = static_cast<int>(std::floor((room + 1e-6) / s.volumeUl));
    if (perRound < 1) {
        error(fieldPath(path, "volume_ul"), motion::msg::make("recipe.transfer_no_room", {volume("volume", s.volumeUl), volume("room", std::max(0.0, room)),
                                                                                  volume("capacity", m_cap)}));
        return;
    }
    bool reported = false;
    for (std::size_t k = 0; k < targets.size(); k += static_cast<std::size_t>(perRound)) {
        const std::size_t n = std::min(targets.size() - k, static_cast<std::size_t>(perRound));
        const double vol = s.volumeUl * static_cast<double>(n);
        const int round = static_cast<int>(k / static_cast<std::size_t>(perRound)) + 1;
        if (src.w && vol > src.w->volumeUl + kEps && !reported) {
            reported = true;
            warning(srcPath, motion::msg::make("recipe.round_over_source", {volume("volume", vol), volume("capacity", src.w->volumeUl)}));
        }
        aspirateAt(i, src, vol, speed, fieldPath(path, "volume_ul"), &reported);
        m_plan.ops.back().round = round;
        for (std::size_t j = k; j < k + n; ++j) {
            dispenseAt(i, targets[j], s.volumeUl, speed, std::max(0.0, s.offsetMm));
            m_plan.ops.back().round = round;
        }
    }
}

void Planner::planDistribute(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed, const Place& src,
                             double room)
{
    bool ok = true;
    for (const auto& [field, value] : {std::pair<const char*, double>{"disposal_ul", s.disposalUl}, {"air_gap_ul", s.airGapUl}})
        if (!std::isfinite(value) || value < 0) {
            error(fieldPath(path, field), motion::msg::make("plate.negative", {ulArg("value", value)}));
            ok = false;
        }
    Place rest = src;
    if (!s.restTo.empty() && s.restTo != "source" && !stationPlace(s.restTo, fieldPath(path, "rest_to"), &rest))
        ok = false;
    if (!ok)
        return;
    // Each round draws its wells plus the disposal volume, then the air gap: all of it
    // must fit the syringe's room, for one well at least.
    const double fixed = s.disposalUl + s.airGapUl;
    const int perRound = static_cast<int>(std::floor((room - fixed + 1e-6) / s.volumeUl));
    if (perRound < 1) {
        error(fieldPath(path, "volume_ul"), motion::msg::make("recipe.distribute_no_room", {volume("volume", s.volumeUl), volume("disposal", s.disposalUl),
                                                                                    volume("air_gap", s.airGapUl), volume("room", std::max(0.0, room))}));
        return;
    }
    const std::string srcPath = fieldPath(path, "source");
    bool reported = false;
    for (std::size_t k = 0; k < targets.size(); k += static_cast<std::size_t>(perRound)) {
        const std::size_t n = std::min(targets.size() - k, static_cast<std::size_t>(perRound));
        const double vol = s.volumeUl * static_cast<double>(n) + s.disposalUl;
        const int round = static_cast<int>(k / static_cast<std::size_t>(perRound)) + 1;
        if (src.w && vol > src.w->volumeUl + kEps && !reported) {
            reported = true;
            warning(srcPath, motion::msg::make("recipe.round_over_source", {volume("volume", vol), volume("capacity", src.w->volumeUl)}));
        }
        aspirateAt(i, src, vol, speed, fieldPath(path, "volume_ul"), &reported);
        m_plan.ops.back().round = round;
        if (s.airGapUl > 0) {
            roomFor(s.airGapUl, fieldPath(path, "air_gap_ul"), &reported);
            PlanOp& gap = newOp(i, StepType::AirGap, nullptr, s.airGapUl);
            raiseTo(gap, m_safeZ < 1e300 ? m_safeZ : m_z);
            pump(gap, s.airGapUl, speed);
            m_air += s.airGapUl;
            gap.round = round;
        }
        for (std::size_t j = k; j < k + n; ++j) {
            dispenseAt(i, targets[j], s.volumeUl, speed, std::max(0.0, s.offsetMm));
            m_plan.ops.back().round = round;
        }
        if (s.disposalUl > 0) {
            const bool drawsHereNext = k + n < targets.size() && rest.plate == src.plate && rest.well == src.well && rest.station == src.station;
            dispenseAt(i, rest, s.disposalUl, speed, 0, !drawsHereNext);
            m_plan.ops.back().round = round;
        }
    }
}

} // namespace motion::plates::planning
