#include "motion/plans/recipes/recipe_plan.h"

#include "motion/plans/recipes/move_time.h"
#include "motion/plans/recipes/plan_bound.h"
#include "motion/plans/recipes/recipe_planner.h"

#include "motion/arch_timing.h"
#include "motion/plans/recipes/well_order.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace motion::plates {

PlateTransform PlanContext::transform(const std::string& slotId) const
{
    const auto it = calibration.find(slotId);
    if (it != calibration.end())
        return it->second;
    const Slot* s = deck.slot(slotId);
    return s ? s->nominal() : PlateTransform{};
}

const char* moveKindName(MoveKind k)
{
    switch (k) {
    case MoveKind::Raise: return "raise";
    case MoveKind::Travel: return "travel";
    case MoveKind::Lower: return "lower";
    case MoveKind::Pump: return "pump";
    case MoveKind::Touch: return "touch";
    case MoveKind::Dwell: return "dwell";
    }
    return "?";
}

bool PlanOp::pumps() const
{
    return std::any_of(moves.begin(), moves.end(), [](const MachineMove& m) { return m.kind == MoveKind::Pump || m.archPump; });
}

motion::msg::Message PlanOp::where() const
{
    if (!station.empty())
        return motion::msg::make("recipe.where.station", {textArg("station", station)});
    if (!well.empty())
        return motion::msg::make("recipe.where.well", {textArg("plate", plate), textArg("well", well)});
    return {};
}

motion::msg::Message PlanOp::label() const
{
    const motion::msg::Arg v = ulArg("volume", volumeUl);
    switch (type) {
    case StepType::Aspirate: return motion::msg::make("recipe.op.aspirate", {v, motion::msg::nested("where", where())});
    case StepType::Dispense: return motion::msg::make("recipe.op.dispense", {v, motion::msg::nested("where", where())});
    case StepType::Mix: return motion::msg::make("recipe.op.mix", {v, motion::msg::nested("where", where())});
    case StepType::Wash: return motion::msg::make("recipe.op.wash", {v, motion::msg::nested("where", where())});
    case StepType::AirGap: return motion::msg::make("recipe.op.air_gap", {v});
    case StepType::Wait: return motion::msg::make("recipe.op.wait", {motion::msg::real("seconds", moves.empty() ? 0 : moves.front().seconds, motion::msg::Unit::S)});
    case StepType::TouchOff: return motion::msg::make("recipe.op.touch_off", {motion::msg::nested("where", where())});
    }
    return {};
}

const WellTotal* RecipePlan::total(const std::string& plate, const std::string& well) const
{
    for (const WellTotal& w : wells)
        if (w.plate == plate && w.well == well)
            return &w;
    return nullptr;
}

std::string fingerprintHex(std::uint64_t f)
{
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(f));
    return buf;
}

double remainingTimeS(const RecipePlan& plan, int fromOp)
{
    double t = 0;
    for (std::size_t i = static_cast<std::size_t>(std::max(0, fromOp)); i < plan.ops.size(); ++i)
        t += plan.ops[i].durationS;
    return t;
}

namespace planning {

Planner::Planner(const Recipe& r, const PlanContext& c, const StartState& s) : m_r(r), m_c(c), m_cap(c.capacityUl())
{
    m_x = s.xMm;
    m_y = s.yMm;
    m_z = s.zMm;
    m_p = s.pumpUl;
    m_plan.pumpStartUl = s.pumpUl;
    for (const RecipePlate& p : r.plates)
        if (const auto lw = c.labware.find(p.labware); lw != c.labware.end())
            m_tallestTopZMm = std::min(m_tallestTopZMm, c.deck.tableZMm - lw->second.heightMm);
    m_allClearZ = std::max(0.0, m_tallestTopZMm - r.travel.clearanceBetweenMm);
    for (const Station& st : c.deck.stations)
        m_allClearZ = std::min(m_allClearZ, st.safeZMm);
    m_allClearZ = std::max(0.0, m_allClearZ);
}

RecipePlan Planner::run()
{
    m_plan.orders.assign(m_r.steps.size(), WellOrder::AsWritten);
    checkRecipe();
    if (m_r.steps.size() > kMaxSteps) {
        error("steps", motion::msg::make("recipe.too_many_steps", {motion::msg::integer("max", static_cast<long long>(kMaxSteps)),
                                                          motion::msg::integer("count", static_cast<long long>(m_r.steps.size()))}));
        return std::move(m_plan);
    }
    for (std::size_t i = 0; i < m_r.steps.size() && !m_tooMany; ++i)
        planStep(static_cast<int>(i));
    finish();
    return std::move(m_plan);
}

void Planner::checkRecipe()
{
    const Deck& d = m_c.deck;
    std::set<std::string> names, usedSlots;
    for (std::size_t k = 0; k < m_r.plates.size(); ++k) {
        const RecipePlate& p = m_r.plates[k];
        const std::string at = indexPath("plates", k);
        if (p.name.empty())
            error(fieldPath(at, "name"), motion::msg::make("plate.empty"));
        else if (!names.insert(p.name).second)
            error(fieldPath(at, "name"), motion::msg::make("recipe.plate_named_twice", {textArg("plate", p.name)}));
        if (!d.slot(p.slot)) {
            std::string list;
            for (const Slot& s : d.plateSlots)
                list += (list.empty() ? "" : ", ") + s.id;
            error(fieldPath(at, "slot"), motion::msg::make("recipe.unknown_slot", {textArg("slot", p.slot), textArg("slots", list)}));
        } else if (!usedSlots.insert(p.slot).second) {
            error(fieldPath(at, "slot"), motion::msg::make("recipe.slot_taken", {textArg("slot", p.slot)}));
        }
        if (!m_c.labware.count(p.labware)) {
            std::string list;
            for (const Labware& lw : builtinLabware())
                list += (list.empty() ? "" : ", ") + lw.id;
            error(fieldPath(at, "labware"), motion::msg::make("recipe.unknown_labware", {textArg("labware", p.labware), textArg("builtin", list)}));
        }
        if (!std::isfinite(p.safeZMm) || p.safeZMm < 0 || p.safeZMm > d.travelZMm)
            error(fieldPath(at, "safe_z_mm"), motion::msg::make("plate.out_of_range", {mmArg("value", p.safeZMm), mmArg("min", 0), mmArg("max", d.travelZMm)}));
        else if (!std::isfinite(p.depthZMm) || p.depthZMm <= p.safeZMm || p.depthZMm > d.travelZMm)
            error(fieldPath(at, "depth_z_mm"), motion::msg::make("recipe.depth_not_below_safe", {mmArg("value", p.depthZMm), mmArg("safe", p.safeZMm),
                                                                                       mmArg("max", d.travelZMm)}));
        else if (const auto lw = m_c.labware.find(p.labware); lw != m_c.labware.end())
            checkHeights(p, lw->second, at);
    }
    if (m_r.steps.empty())
        error("steps", motion::msg::make("recipe.no_steps"));
    // Clearances count up from the labware's top: below 0 the tip would cross rims lower than their tops.
    for (const auto& [field, value] : {std::pair<const char*, double>{"clearance_in_plate_mm", m_r.travel.clearanceInPlateMm},
                                       {"clearance_between_mm", m_r.travel.clearanceBetweenMm}})
        if (!std::isfinite(value) || value < 0 || value > d.travelZMm)
            error(fieldPath("travel", field), motion::msg::make("recipe.clearance_below_top", {mmArg("value", value), mmArg("max", d.travelZMm)}));
    if (m_r.travelSpeedMmS) {
        const double vmax = std::min(d.x.maxSpeed, d.y.maxSpeed);
        if (!(*m_r.travelSpeedMmS >= kMinSpeed) || *m_r.travelSpeedMmS > vmax)
            error("travel_speed_mm_s", motion::msg::make("plate.out_of_range", {motion::msg::real("value", *m_r.travelSpeedMmS, motion::msg::Unit::MmPerS),
                                                                        motion::msg::real("min", kMinSpeed, motion::msg::Unit::MmPerS),
                                                                        motion::msg::real("max", vmax, motion::msg::Unit::MmPerS)}));
    }
    if (m_r.zSpeedMmS && (!(*m_r.zSpeedMmS >= kMinSpeed) || *m_r.zSpeedMmS > d.z.maxSpeed))
        error("z_speed_mm_s", motion::msg::make("plate.out_of_range", {motion::msg::real("value", *m_r.zSpeedMmS, motion::msg::Unit::MmPerS),
                                                               motion::msg::real("min", kMinSpeed, motion::msg::Unit::MmPerS),
                                                               motion::msg::real("max", d.z.maxSpeed, motion::msg::Unit::MmPerS)}));
}

void Planner::checkHeights(const RecipePlate& p, const Labware& lw, const std::string& at)
{
    const double top = m_c.deck.tableZMm - lw.heightMm;
    if (p.safeZMm > top - 1e-9)
        error(fieldPath(at, "safe_z_mm"), motion::msg::make("recipe.safe_not_above_plate", {mmArg("value", p.safeZMm), mmArg("top", top)}));
    double bottom = m_c.deck.tableZMm;
    for (const Well& w : lw.wells)
        bottom = std::min(bottom, m_c.deck.tableZMm - w.bottomZMm);
    if (p.depthZMm > bottom + 1e-9)
        error(fieldPath(at, "depth_z_mm"), motion::msg::make("recipe.depth_below_bottom", {mmArg("value", p.depthZMm), mmArg("bottom", bottom)}));
}

const RecipePlate* Planner::resolvePlate(const std::string& name, const std::string& path)
{
    const RecipePlate* p = findPlate(name, path);
    if (p && (!m_c.labware.count(p->labware) || !m_c.deck.slot(p->slot)))
        return nullptr;  // already reported with the plate
    return p;
}

const RecipePlate* Planner::findPlate(const std::string& name, const std::string& path)
{
    if (name.empty()) {
        if (m_r.plates.size() == 1)
            return &m_r.plates.front();
        if (m_r.plates.empty()) {
            error(path, motion::msg::make("recipe.no_plates"));
        } else {
            std::string list;
            for (const auto& p : m_r.plates)
                list += (list.empty() ? "" : ", ") + p.name;
            error(path, motion::msg::make("recipe.plate_ambiguous", {motion::msg::integer("count", static_cast<long long>(m_r.plates.size())), textArg("plates", list)}));
        }
        return nullptr;
    }
    const RecipePlate* p = m_r.plate(name);
    if (!p) {
        std::string list;
        for (const auto& q : m_r.plates)
            list += (list.empty() ? "" : ", ") + std::string("\"") + q.name + "\"";
        error(path, list.empty() ? motion::msg::make("recipe.unknown_plate_none", {textArg("plate", name)})
                                 : motion::msg::make("recipe.unknown_plate", {textArg("plate", name), textArg("plates", list)}));
    }
    return p;
}

Place Planner::wellPlace(const RecipePlate& p, const Well& w)
{
    Place pl;
    pl.plate = p.name;
    pl.well = wellName(w.id);
    pl.transform = m_c.transform(p.slot);
    pl.at = pl.transform.apply({w.xMm, w.yMm});
    pl.safeZMm = p.safeZMm;
    pl.depthZMm = p.depthZMm;
    if (const auto lw = m_c.labware.find(p.labware); lw != m_c.labware.end())
        pl.topZMm = m_c.deck.tableZMm - lw->second.heightMm;
    pl.w = &w;
    return pl;
}

bool Planner::reachable(const PointMm& at) const
{
    return std::isfinite(at.x) && std::isfinite(at.y) && at.x >= -kEps && at.y >= -kEps && at.x <= m_c.deck.travelXMm + kEps
        && at.y <= m_c.deck.travelYMm + kEps;
}

std::vector<Place> Planner::wellPlaces(const Step& s, const std::string& stepPath)
{
    std::vector<Place> out;
    const RecipePlate* p = resolvePlate(s.plate, fieldPath(stepPath, "plate"));
    if (!p)
        return out;
    const Labware& lw = m_c.labware.at(p->labware);
    const std::string wellsPath = fieldPath(stepPath, "wells");
    WellSet set = expandWells(s.wells, lw, wellsPath);
    for (auto& pr : set.problems)
        m_plan.problems.push_back(std::move(pr));
    bool outside = false;
    for (const WellId& id : set.wells) {
        Place pl = wellPlace(*p, *lw.well(id));
        if (!reachable(pl.at) && !outside) {
            outside = true;
            error(wellsPath, motion::msg::make("recipe.well_outside_travel", {textArg("well", pl.well), textArg("plate", p->name), mmArg("x", pl.at.x),
                                                                      mmArg("y", pl.at.y), mmArg("travel_x", m_c.deck.travelXMm),
                                                                      mmArg("travel_y", m_c.deck.travelYMm)}));
        }
        out.push_back(std::move(pl));
    }
    return out;
}

bool Planner::stationPlace(const std::string& id, const std::string& path, Place* pl)
{
    const Station* st = m_c.deck.station(id);
    if (!st) {
        std::string list;
        for (const Station& s : m_c.deck.stations)
            list += (list.empty() ? "" : ", ") + s.id;
        error(path, list.empty() ? motion::msg::make("recipe.unknown_station_none", {textArg("station", id)})
                                 : motion::msg::make("recipe.unknown_station", {textArg("station", id), textArg("stations", list)}));
        return false;
    }
    pl->station = st->id;
    pl->at = {st->xMm, st->yMm};
    pl->safeZMm = st->safeZMm;
    pl->depthZMm = st->depthZMm;
    pl->topZMm = st->safeZMm;
    return true;
}

double Planner::clearanceTo(const Place& to) const
{
    // Never above home: a clearance taller than the travel is the travel's top.
    if (!to.station.empty())
        return std::max(0.0, std::min(to.topZMm, m_tallestTopZMm - m_r.travel.clearanceBetweenMm));
    if (!m_overPlate.empty() && m_overPlate == to.plate)
        return std::max(0.0, to.topZMm - m_r.travel.clearanceInPlateMm);
    return std::max(0.0, std::min(to.topZMm - m_r.travel.clearanceInPlateMm, m_tallestTopZMm - m_r.travel.clearanceBetweenMm));
}

void Planner::orderPlaces(int step, const Step& s, std::vector<Place>& places)
{
    const WellOrder order = m_r.orderOf(s);
    m_plan.orders[static_cast<std::size_t>(step)] = order;
    if (order == WellOrder::AsWritten || places.size() < 2)
        return;
    std::vector<WellId> ids;
    std::vector<PointMm> at;
    for (const Place& pl : places) {
        ids.push_back(pl.w ? pl.w->id : WellId{});
        at.push_back(pl.at);
    }
    const double speed = m_r.travelSpeedMmS.value_or(0);
    const MoveCost cost = [this, speed](const PointMm& a, const PointMm& b) {
        return moveTimeS({{&m_c.deck.x, b.x - a.x}, {&m_c.deck.y, b.y - a.y}}, speed);
    };
    const std::vector<std::size_t> idx = wellOrderIndices(order, ids, at, cost);
    std::vector<Place> out;
    out.reserve(places.size());
    for (std::size_t i : idx)
        out.push_back(std::move(places[i]));
    places = std::move(out);
}

void Planner::raiseTo(PlanOp& op, double z)
{
    MachineMove m;
    m.kind = MoveKind::Raise;
    m.zMm = z;
    m.speed = m_r.zSpeedMmS.value_or(0);
    if (m_z > z + kEps)
        m.durationS = overheadFor(moveTimeS({{&m_c.deck.z, z - m_z}}, m.speed));
    m_z = std::min(m_z, z);
    op.moves.push_back(m);
}

void Planner::travelTo(PlanOp& op, const PointMm& at, MoveKind kind)
{
    MachineMove m;
    m.kind = kind;
    m.xMm = at.x;
    m.yMm = at.y;
    m.speed = m_r.travelSpeedMmS.value_or(0);
    m.durationS = overheadFor(moveTimeS({{&m_c.deck.x, at.x - m_x}, {&m_c.deck.y, at.y - m_y}}, m.speed));
    m_x = at.x;
    m_y = at.y;
    op.moves.push_back(m);
}

void Planner::lowerTo(PlanOp& op, double z)
{
    MachineMove m;
    m.kind = MoveKind::Lower;
    m.zMm = z;
    m.speed = m_r.zSpeedMmS.value_or(0);
    m.durationS = overheadFor(moveTimeS({{&m_c.deck.z, z - m_z}}, m.speed));
    m_z = z;
    op.moves.push_back(m);
}

void Planner::pump(PlanOp& op, double delta, double speed)
{
    MachineMove m;
    m.kind = MoveKind::Pump;
    m.pumpDeltaUl = delta;
    m.speed = speed;
    m.durationS = overheadFor(moveTimeS({{&m_c.deck.p, delta}}, speed));
    m_p += delta;
    op.pumpNetUl += delta;
    op.moves.push_back(m);
}

void Planner::goInto(PlanOp& op, const Place& pl)
{
    if (m_r.travel.mode == TravelMode::Arched) {
        goIntoArched(op, pl);
        return;
    }
    op.clearZMm = clearanceTo(pl);
    m_overPlate = pl.station.empty() ? pl.plate : std::string();
    raiseTo(op, std::min(m_safeZ, pl.safeZMm));
    travelTo(op, pl.at);
    m_safeZ = pl.safeZMm;
    op.at = pl.at;
    op.safeZMm = pl.safeZMm;
    op.depthZMm = pl.depthZMm;
    lowerTo(op, pl.depthZMm);
    op.visitMoves = static_cast<int>(op.moves.size());
}

double Planner::openingMm(const Place& pl)
{
    return pl.w ? std::max(0.0, pl.w->innerRadiusMm() - kTipWallMarginMm) : 0.0;
}

MachineMove Planner::travelWithZ(const PointMm& at, double z)
{
    MachineMove m;
    m.kind = MoveKind::Travel;
    m.xMm = at.x;
    m.yMm = at.y;
    m.zMm = z;
    m.withZ = true;
    m.speed = m_r.travelSpeedMmS.value_or(0);
    m.zSpeed = m_r.zSpeedMmS.value_or(0);
    const double xy = moveTimeS({{&m_c.deck.x, at.x - m_x}, {&m_c.deck.y, at.y - m_y}}, m.speed);
    const double zt = moveTimeS({{&m_c.deck.z, z - m_z}}, m.zSpeed);
    // Two requests go out back to back, and the move ends when both have.
    m.durationS = overheadFor(std::max(xy, zt));
    m_x = at.x;
    m_y = at.y;
    m_z = z;
    return m;
}

void Planner::goIntoBlended(PlanOp& op, const Place& pl)
{
    const double clear = clearanceTo(pl);
    op.clearZMm = clear;
    const double into = openingMm(pl);
    double depart = 0;
    if (m_inWellMm > 0 && m_departOp == op.index - 1 && op.index > 0) {
        // The op before ended with the tip going straight up out of its well: this move
        // takes it up instead, already heading here within that well's opening.
        MachineMove& up = m_plan.ops[static_cast<std::size_t>(op.index - 1)].moves.back();
        up.deferred = true;
        up.durationS = 0;
        m_z = m_departFromZ;
        depart = m_inWellMm;
    }
    m_overPlate = pl.station.empty() ? pl.plate : std::string();
    MachineMove m;
    m.kind = MoveKind::Travel;
    m.withZ = true;
    m.arch = true;
    m.xMm = pl.at.x;
    m.yMm = pl.at.y;
    m.zMm = pl.depthZMm;
    m.clearZMm = clear;
    m.departMm = depart;
    m.approachMm = into;
    m.speed = m_r.travelSpeedMmS.value_or(0);
    m.zSpeed = m_r.zSpeedMmS.value_or(0);
    const double top = std::min(m_z, clear);
    const auto rise = moveProfile({{&m_c.deck.z, top - m_z}}, m.zSpeed);
    const auto xy = moveProfile({{&m_c.deck.x, pl.at.x - m_x}, {&m_c.deck.y, pl.at.y - m_y}}, m.speed);
    const auto down = moveProfile({{&m_c.deck.z, pl.depthZMm - top}}, m.zSpeed);
    const motion::ArchTiming t = motion::archTiming(rise ? &*rise : nullptr, xy ? &*xy : nullptr, down ? &*down : nullptr, depart, into);
    m.durationS = overheadFor(t.durationS);
    m_lastArch = {rise, xy, down, depart, into, top};
    if (depart > 0 && std::hypot(pl.at.x - m_x, pl.at.y - m_y) < kEps && std::abs(pl.depthZMm - m_z) < kEps)
        m.durationS = 0;  // back into the well the tip is still down in (a disposal returned, then drawn): it stays
    m_x = pl.at.x;
    m_y = pl.at.y;
    m_z = pl.depthZMm;
    op.moves.push_back(m);
    m_safeZ = pl.station.empty() ? std::max(0.0, pl.topZMm - m_r.travel.clearanceInPlateMm) : pl.topZMm;
    m_inWellMm = into;
    op.at = pl.at;
    op.safeZMm = std::min(clear, m_allClearZ);
    op.depthZMm = pl.depthZMm;
    op.visitMoves = static_cast<int>(op.moves.size());
}

bool Planner::pumpInsideArch(PlanOp& op, const Place& pl, double delta, double speed, bool stayDown)
{
    if (m_r.travel.mode != TravelMode::Arched || !m_c.deck.archedMoves || !m_c.deck.archPump || !pl.w || op.moves.empty())
        return false;
    MachineMove& m = op.moves.back();
    const double liquid = pl.topZMm;  // below the rim, inside the opening: what leaves the tip lands in the well
    const double leaveZ = stayDown ? pl.depthZMm : m_safeZ;
    // Not when the arch does not move (back into the well the tip is still down in).
    if (!m.arch || m.durationS <= 0 || !m_lastArch.down || liquid < m_lastArch.topZ - kEps || liquid > pl.depthZMm + kEps || (!stayDown && leaveZ > liquid + kEps))
        return false;
    const auto plunger = moveProfile({{&m_c.deck.p, delta}}, speed);
    const auto up = stayDown ? std::nullopt : moveProfile({{&m_c.deck.z, leaveZ - pl.depthZMm}}, m.zSpeed);
    motion::ArchPumpParts parts;
    parts.plunger = plunger ? &*plunger : nullptr;
    parts.liquidMm = liquid - m_lastArch.topZ;
    parts.leave = up ? &*up : nullptr;
    parts.leaveLiquidMm = pl.depthZMm - liquid;
    const ArchParts& a = m_lastArch;
    const motion::ArchTiming t = motion::archTiming(a.rise ? &*a.rise : nullptr, a.xy ? &*a.xy : nullptr, &*a.down, a.departMm, a.approachMm, parts);
    m.archPump = true;
    m.pumpDeltaUl = delta;
    m.pumpSpeed = speed;
    m.liquidZMm = liquid;
    m.leaveZMm = leaveZ;
    m.durationS = overheadFor(t.durationS);
    m_p += delta;
    op.pumpNetUl += delta;
    m_z = leaveZ;
    return true;
}

void Planner::goIntoArched(PlanOp& op, const Place& pl)
{
    if (m_c.deck.archedMoves) {
        goIntoBlended(op, pl);
        return;
    }
    const double clear = clearanceTo(pl);
    op.clearZMm = clear;
    const double into = openingMm(pl);
    const double dx = pl.at.x - m_x, dy = pl.at.y - m_y, d = std::hypot(dx, dy);
    const bool crossing = d > m_inWellMm + into + kEps;
    if (crossing && m_inWellMm > 0 && m_departOp == op.index - 1 && op.index > 0) {
        // The op before ended with the tip going straight up out of its well: it
        // leaves toward this one instead, within its well's opening, while Z rises.
        PlanOp& prev = m_plan.ops[static_cast<std::size_t>(op.index - 1)];
        const double zNow = m_z;
        m_z = m_departFromZ;
        prev.moves.back() = travelWithZ({m_x + dx / d * m_inWellMm, m_y + dy / d * m_inWellMm}, std::min(clear, zNow));
    }
    m_overPlate = pl.station.empty() ? pl.plate : std::string();
    raiseTo(op, clear);
    const double ux = d > kEps ? dx / d : 0, uy = d > kEps ? dy / d : 0;
    if (crossing && into > 0) {
        travelTo(op, {pl.at.x - ux * into, pl.at.y - uy * into});
        op.moves.push_back(travelWithZ(pl.at, pl.depthZMm));
    } else {
        travelTo(op, pl.at);
        lowerTo(op, pl.depthZMm);
    }
    // An op ends with the tip up over its own place: a plate's in-plate clearance (the
    // next op's depart goes higher when it crosses to other labware), a station's safe height.
    m_safeZ = pl.station.empty() ? std::max(0.0, pl.topZMm - m_r.travel.clearanceInPlateMm) : pl.topZMm;
    m_inWellMm = into;
    op.at = pl.at;
    // Where an abort lifts the tip to, and the first raise of a run that does not know
    // where it stands: above everything on the deck.
    op.safeZMm = std::min(clear, m_allClearZ);
    op.depthZMm = pl.depthZMm;
    op.visitMoves = static_cast<int>(op.moves.size());
}

void Planner::leave(PlanOp& op)
{
    const double from = m_z;
    raiseTo(op, m_safeZ);
    if (m_r.travel.mode == TravelMode::Arched && m_inWellMm > 0 && !op.moves.empty() && op.moves.back().kind == MoveKind::Raise) {
        m_departOp = op.index;
        m_departFromZ = from;
    }
}

PlanOp& Planner::newOp(int step, StepType type, const Place* pl, double volume)
{
    PlanOp op;
    op.index = static_cast<int>(m_plan.ops.size());
    op.step = step;
    op.type = type;
    op.volumeUl = volume;
    if (pl) {
        op.plate = pl->plate;
        op.well = pl->well;
        op.station = pl->station;
    }
    op.at = {m_x, m_y};
    op.safeZMm = m_safeZ < 1e300 ? m_safeZ : 0;
    if (m_r.travel.mode == TravelMode::Arched)
        op.safeZMm = std::min(op.safeZMm, m_allClearZ);
    m_plan.ops.push_back(std::move(op));
    if (m_plan.ops.size() > kMaxPlannedOps && !m_tooMany) {
        m_tooMany = true;
        error("steps", motion::msg::make("recipe.too_many_ops", {motion::msg::integer("max", static_cast<long long>(kMaxPlannedOps))}));
    }
    return m_plan.ops.back();
}

WellTotal& Planner::totalOf(const Place& pl)
{
    for (WellTotal& w : m_plan.wells)
        if (w.plate == pl.plate && w.well == pl.well && !pl.well.empty())
            return w;
    m_plan.wells.push_back({pl.plate, pl.well, 0, 0, 0});
    return m_plan.wells.back();
}

void Planner::finish()
{
    double t = 0;
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64
    auto mix = [&h](const std::string& s) {
        for (unsigned char ch : s) {
            h ^= ch;
            h *= 1099511628211ull;
        }
        h ^= 0xFF;
        h *= 1099511628211ull;
    };
    for (PlanOp& op : m_plan.ops) {
        op.durationS = 0;
        for (const MachineMove& m : op.moves)
            op.durationS += m.durationS;
        op.startS = t;
        t += op.durationS;
        mix(stepTypeName(op.type));
        mix(op.plate);
        mix(op.well);
        mix(op.station);
        mix(std::to_string(op.round));
        mix(std::to_string(std::llround(op.volumeUl * 1000)));
        mix(std::to_string(std::llround(op.pumpNetUl * 1000)));
    }
    m_plan.totalTimeS = t;
    m_plan.pumpEndUl = m_p;
    m_plan.fingerprint = h;
    for (const WellTotal& w : m_plan.wells) {
        const RecipePlate* p = m_r.plate(w.plate);
        const auto lw = p ? m_c.labware.find(p->labware) : m_c.labware.end();
        const Well* well = lw != m_c.labware.end() ? lw->second.wellNamed(w.well) : nullptr;
        if (well && w.dispensedUl - w.aspiratedUl > well->volumeUl + kEps)
            warning("steps", motion::msg::make("recipe.well_overfilled", {textArg("well", w.well), textArg("plate", w.plate),
                                                                  volume("volume", w.dispensedUl - w.aspiratedUl), volume("capacity", well->volumeUl)}));
    }
}

} // namespace planning

RecipePlan planRecipe(const Recipe& recipe, const PlanContext& context, const StartState& start)
{
    RecipePlan plan = planning::Planner(recipe, context, start).run();
    plan.boundS = planBoundS(plan, context.deck, start);
    return plan;
}

} // namespace motion::plates
