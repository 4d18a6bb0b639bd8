#include "motion/plans/recipes/recipe_plan.h"

#include "motion/plans/recipes/move_time.h"
#include "motion/plans/recipes/recipe_planner.h"

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
    return std::any_of(moves.begin(), moves.end(), [](const MachineMove& m) { return m.kind == MoveKind::Pump; });
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
}

RecipePlan Planner::run()
{
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
    return true;
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
    raiseTo(op, std::min(m_safeZ, pl.safeZMm));
    travelTo(op, pl.at);
    m_safeZ = pl.safeZMm;
    op.at = pl.at;
    op.safeZMm = pl.safeZMm;
    op.depthZMm = pl.depthZMm;
    lowerTo(op, pl.depthZMm);
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
    return planning::Planner(recipe, context, start).run();
}

} // namespace motion::plates
