#include "motion/plans/plates/recipe_plan.h"

#include "motion/plans/plates/move_time.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace plates {

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

std::string PlanOp::where() const
{
    if (!station.empty())
        return "station " + station;
    if (!well.empty())
        return plate + " " + well;
    return {};
}

std::string PlanOp::label() const
{
    const std::string v = formatMm(volumeUl) + " µL";
    switch (type) {
    case StepType::Aspirate: return "aspirate " + v + " from " + where();
    case StepType::Dispense: return "dispense " + v + " into " + where();
    case StepType::Mix: return "mix " + v + " in " + where();
    case StepType::Wash: return "wash " + v + " at " + where();
    case StepType::AirGap: return "air gap " + v;
    case StepType::Wait: return "wait " + formatMm(moves.empty() ? 0 : moves.front().seconds) + " s";
    case StepType::TouchOff: return "touch off in " + where();
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

namespace {

constexpr double kEps = 1e-9;
/// Slowest speed a recipe may ask for (mm/s or µL/s): slower is a typo, and the
/// wire's whole nanometres per second cannot carry much less.
constexpr double kMinSpeed = 0.1;

/// A place the tip visits, resolved to machine coordinates.
struct Place {
    std::string plate, well, station;
    PointMm at;
    double safeZMm = 0, depthZMm = 0;
    const Well* w = nullptr;
    PlateTransform transform;  ///< plate → machine, for touch-off directions
};

class Planner {
public:
    Planner(const Recipe& r, const PlanContext& c, const StartState& s) : m_r(r), m_c(c), m_cap(c.capacityUl())
    {
        m_x = s.xMm;
        m_y = s.yMm;
        m_z = s.zMm;
        m_p = s.pumpUl;
        m_plan.pumpStartUl = s.pumpUl;
    }

    RecipePlan run()
    {
        checkRecipe();
        if (m_r.steps.size() > kMaxSteps) {
            error("steps", "a recipe has at most " + std::to_string(kMaxSteps) + " steps (got " + std::to_string(m_r.steps.size()) + ")");
            return std::move(m_plan);
        }
        for (std::size_t i = 0; i < m_r.steps.size() && !m_tooMany; ++i)
            planStep(static_cast<int>(i));
        finish();
        return std::move(m_plan);
    }

private:
    void error(const std::string& path, const std::string& message) { m_plan.problems.push_back({path, message, false}); }
    void warning(const std::string& path, const std::string& message) { m_plan.problems.push_back({path, message, true}); }

    static std::string volumeText(double v) { return formatMm(std::round(v * 1000) / 1000) + " µL"; }

    // ---- recipe-level checks ---------------------------------------------------

    void checkRecipe()
    {
        const Deck& d = m_c.deck;
        std::set<std::string> names, usedSlots;
        for (std::size_t k = 0; k < m_r.plates.size(); ++k) {
            const RecipePlate& p = m_r.plates[k];
            const std::string at = indexPath("plates", k);
            if (p.name.empty())
                error(fieldPath(at, "name"), "must not be empty");
            else if (!names.insert(p.name).second)
                error(fieldPath(at, "name"), "plate \"" + p.name + "\" is named twice");
            if (!d.slot(p.slot)) {
                std::string list;
                for (const Slot& s : d.plateSlots)
                    list += (list.empty() ? "" : ", ") + s.id;
                error(fieldPath(at, "slot"), "unknown slot \"" + p.slot + "\": the deck has slots " + list);
            } else if (!usedSlots.insert(p.slot).second) {
                error(fieldPath(at, "slot"), "slot \"" + p.slot + "\" already holds another plate of this recipe");
            }
            if (!m_c.labware.count(p.labware)) {
                std::string list;
                for (const Labware& lw : builtinLabware())
                    list += (list.empty() ? "" : ", ") + lw.id;
                error(fieldPath(at, "labware"), "unknown labware \"" + p.labware + "\" (built in: " + list + "; or a labware file)");
            }
            if (!std::isfinite(p.safeZMm) || p.safeZMm < 0 || p.safeZMm > d.travelZMm)
                error(fieldPath(at, "safe_z_mm"), "must be from 0 to " + formatMm(d.travelZMm) + " mm (got " + formatMm(p.safeZMm) + ")");
            else if (!std::isfinite(p.depthZMm) || p.depthZMm <= p.safeZMm || p.depthZMm > d.travelZMm)
                error(fieldPath(at, "depth_z_mm"), "must be below the safe height (more than " + formatMm(p.safeZMm) + " mm) and at most "
                                                      + formatMm(d.travelZMm) + " mm (got " + formatMm(p.depthZMm) + ")");
            else if (const auto lw = m_c.labware.find(p.labware); lw != m_c.labware.end())
                checkHeights(p, lw->second, at);
        }
        if (m_r.steps.empty())
            error("steps", "a recipe needs at least one step");
        if (m_r.travelSpeedMmS) {
            const double vmax = std::min(d.x.maxSpeed, d.y.maxSpeed);
            if (!(*m_r.travelSpeedMmS >= kMinSpeed) || *m_r.travelSpeedMmS > vmax)
                error("travel_speed_mm_s", "must be from " + formatMm(kMinSpeed) + " to " + formatMm(vmax) + " mm/s (got " + formatMm(*m_r.travelSpeedMmS) + ")");
        }
        if (m_r.zSpeedMmS && (!(*m_r.zSpeedMmS >= kMinSpeed) || *m_r.zSpeedMmS > d.z.maxSpeed))
            error("z_speed_mm_s", "must be from " + formatMm(kMinSpeed) + " to " + formatMm(d.z.maxSpeed) + " mm/s (got " + formatMm(*m_r.zSpeedMmS) + ")");
    }

    /// The tip must clear the plate's top at its safe height and stay above the
    /// wells' bottoms at its depth (Z grows downward from home).
    void checkHeights(const RecipePlate& p, const Labware& lw, const std::string& at)
    {
        const double top = m_c.deck.tableZMm - lw.heightMm;
        if (p.safeZMm > top - 1e-9)
            error(fieldPath(at, "safe_z_mm"), formatMm(p.safeZMm) + " mm is not above the plate: its top is at Z " + formatMm(top)
                                                 + " mm; the safe height must be smaller");
        double bottom = m_c.deck.tableZMm;
        for (const Well& w : lw.wells)
            bottom = std::min(bottom, m_c.deck.tableZMm - w.bottomZMm);
        if (p.depthZMm > bottom + 1e-9)
            error(fieldPath(at, "depth_z_mm"), formatMm(p.depthZMm) + " mm is below the bottom of the wells (Z " + formatMm(bottom)
                                                  + " mm): the tip would hit it");
    }

    // ---- resolving places ------------------------------------------------------

    const RecipePlate* resolvePlate(const std::string& name, const std::string& path)
    {
        const RecipePlate* p = findPlate(name, path);
        if (p && (!m_c.labware.count(p->labware) || !m_c.deck.slot(p->slot)))
            return nullptr;  // already reported with the plate
        return p;
    }

    const RecipePlate* findPlate(const std::string& name, const std::string& path)
    {
        if (name.empty()) {
            if (m_r.plates.size() == 1)
                return &m_r.plates.front();
            if (m_r.plates.empty()) {
                error(path, "missing plate: the recipe has no plates");
            } else {
                std::string list;
                for (const auto& p : m_r.plates)
                    list += (list.empty() ? "" : ", ") + p.name;
                error(path, "missing plate: the recipe has " + std::to_string(m_r.plates.size()) + " plates (" + list + "); say which");
            }
            return nullptr;
        }
        const RecipePlate* p = m_r.plate(name);
        if (!p) {
            std::string list;
            for (const auto& q : m_r.plates)
                list += (list.empty() ? "" : ", ") + std::string("\"") + q.name + "\"";
            error(path, "unknown plate \"" + name + "\"" + (list.empty() ? ": the recipe has no plates" : "; the recipe's plates are " + list));
        }
        return p;
    }

    Place wellPlace(const RecipePlate& p, const Well& w)
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

    bool reachable(const PointMm& at) const
    {
        return std::isfinite(at.x) && std::isfinite(at.y) && at.x >= -kEps && at.y >= -kEps && at.x <= m_c.deck.travelXMm + kEps
            && at.y <= m_c.deck.travelYMm + kEps;
    }

    /// The wells a step names, as places; problems at `path` ("steps[2].wells").
    std::vector<Place> wellPlaces(const Step& s, const std::string& stepPath)
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
                error(wellsPath, "well " + pl.well + " of plate \"" + p->name + "\" is at (" + formatMm(pl.at.x) + ", " + formatMm(pl.at.y)
                                     + ") mm, outside the analyzer's travel (0–" + formatMm(m_c.deck.travelXMm) + " × 0–"
                                     + formatMm(m_c.deck.travelYMm) + " mm): check the slot's calibration");
            }
            out.push_back(std::move(pl));
        }
        return out;
    }

    bool stationPlace(const std::string& id, const std::string& path, Place* pl)
    {
        const Station* st = m_c.deck.station(id);
        if (!st) {
            std::string list;
            for (const Station& s : m_c.deck.stations)
                list += (list.empty() ? "" : ", ") + s.id;
            error(path, "unknown station \"" + id + "\"" + (list.empty() ? ": the deck has none" : " (the deck has " + list + ")"));
            return false;
        }
        pl->station = st->id;
        pl->at = {st->xMm, st->yMm};
        pl->safeZMm = st->safeZMm;
        pl->depthZMm = st->depthZMm;
        return true;
    }

    // ---- moves -----------------------------------------------------------------

    double overheadFor(double t) const { return t > 0 ? t + m_c.deck.moveOverheadS : 0.0; }

    void raiseTo(PlanOp& op, double z)
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

    void travelTo(PlanOp& op, const PointMm& at, MoveKind kind = MoveKind::Travel)
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

    void lowerTo(PlanOp& op, double z)
    {
        MachineMove m;
        m.kind = MoveKind::Lower;
        m.zMm = z;
        m.speed = m_r.zSpeedMmS.value_or(0);
        m.durationS = overheadFor(moveTimeS({{&m_c.deck.z, z - m_z}}, m.speed));
        m_z = z;
        op.moves.push_back(m);
    }

    void pump(PlanOp& op, double delta, double speed)
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

    /// Up to a height that clears both where the tip is and where it goes, across, down.
    void goInto(PlanOp& op, const Place& pl)
    {
        raiseTo(op, std::min(m_safeZ, pl.safeZMm));
        travelTo(op, pl.at);
        m_safeZ = pl.safeZMm;
        op.at = pl.at;
        op.safeZMm = pl.safeZMm;
        op.depthZMm = pl.depthZMm;
        lowerTo(op, pl.depthZMm);
    }

    PlanOp& newOp(int step, StepType type, const Place* pl, double volume)
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
            error("steps", "the recipe visits more than " + std::to_string(kMaxPlannedOps) + " wells; split it into several recipes");
        }
        return m_plan.ops.back();
    }

    WellTotal& totalOf(const Place& pl)
    {
        for (WellTotal& w : m_plan.wells)
            if (w.plate == pl.plate && w.well == pl.well && !pl.well.empty())
                return w;
        m_plan.wells.push_back({pl.plate, pl.well, 0, 0, 0});
        return m_plan.wells.back();
    }

    // ---- steps -----------------------------------------------------------------

    bool checkVolume(const Step& s, const std::string& path, bool capacityBound)
    {
        if (!std::isfinite(s.volumeUl) || s.volumeUl <= 0) {
            error(fieldPath(path, "volume_ul"), "must be more than 0 µL (got " + formatMm(s.volumeUl) + ")");
            return false;
        }
        if (capacityBound && s.volumeUl > m_cap + kEps) {
            error(fieldPath(path, "volume_ul"), "volume over capacity: " + volumeText(s.volumeUl) + " is more than the syringe holds ("
                                                   + volumeText(m_cap) + ")");
            return false;
        }
        return true;
    }

    double pumpSpeed(const Step& s, const std::string& path)
    {
        if (!s.speedUlS)
            return 0;
        if (!(*s.speedUlS >= kMinSpeed) || *s.speedUlS > m_c.deck.p.maxSpeed) {
            error(fieldPath(path, "speed_ul_s"), "must be from " + formatMm(kMinSpeed) + " to " + formatMm(m_c.deck.p.maxSpeed) + " µL/s (got "
                                                    + formatMm(*s.speedUlS) + ")");
            return 0;
        }
        return *s.speedUlS;
    }

    /// False (once per step) when `delta` would take the plunger past its ends.
    bool roomFor(double delta, const std::string& path, bool* reported)
    {
        const double after = m_p + delta;
        if (after <= m_cap + 1e-6 && after >= -1e-6)
            return true;
        if (!*reported) {
            *reported = true;
            if (after > m_cap)
                error(path, "volume over capacity: the syringe would hold " + volumeText(after) + ", more than its " + volumeText(m_cap)
                                + (m_p > 1e-6 ? " (it holds " + volumeText(m_p) + " at this point)" : ""));
            else
                error(path, "the plunger would pass its empty end (" + volumeText(after) + ")");
        }
        return false;
    }

    void aspirateAt(int step, const Place& pl, double vol, double speed, const std::string& volPath, bool* reported)
    {
        roomFor(vol, volPath, reported);
        PlanOp& op = newOp(step, StepType::Aspirate, &pl, vol);
        goInto(op, pl);
        pump(op, vol, speed);
        raiseTo(op, m_safeZ);
        m_liquid += vol;
        if (!pl.well.empty()) {
            WellTotal& t = totalOf(pl);
            t.aspiratedUl += vol;
            ++t.visits;
        }
        m_plan.totalAspiratedUl += vol;
    }

    void dispenseAt(int step, const Place& pl, double vol, double speed, double touchMm)
    {
        PlanOp& op = newOp(step, StepType::Dispense, &pl, vol);
        goInto(op, pl);
        // A trailing air gap sits at the tip: it leaves first, with this dispense.
        pump(op, -(vol + m_air), speed);
        m_air = 0;
        if (touchMm > 0) {
            const PointMm dir = pl.transform.applyVector({touchMm, 0});
            travelTo(op, {pl.at.x + dir.x, pl.at.y + dir.y}, MoveKind::Touch);
            travelTo(op, pl.at, MoveKind::Touch);
        }
        raiseTo(op, m_safeZ);
        m_liquid -= vol;
        if (!pl.well.empty()) {
            WellTotal& t = totalOf(pl);
            t.dispensedUl += vol;
            ++t.visits;
        }
        m_plan.totalDispensedUl += vol;
    }

    void planStep(int i)
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
                error(fieldPath(path, "station"), "give either wells or a station, not both");
                return;
            }
            if (s.station.empty() && s.wells.empty()) {
                error(fieldPath(path, "wells"), std::string("is missing: say which wells to ") + (asp ? "aspirate from" : "dispense into")
                                                    + " (or a station)");
                return;
            }
            const bool volOk = checkVolume(s, path, true);
            std::vector<Place> places;
            if (!s.station.empty()) {
                Place pl;
                if (stationPlace(s.station, fieldPath(path, "station"), &pl))
                    places.push_back(pl);
            } else {
                places = wellPlaces(s, path);
            }
            if (!volOk)
                return;
            for (const Place& pl : places)
                if (pl.w && s.volumeUl > pl.w->volumeUl + kEps) {
                    error(fieldPath(path, "volume_ul"), volumeText(s.volumeUl) + (asp ? " is more than a " : " does not fit a ")
                                                           + volumeText(pl.w->volumeUl) + " well of plate \"" + pl.plate + "\"");
                    return;
                }
            if (asp) {
                if (!s.source.empty())
                    error(fieldPath(path, "source"), "only a dispense takes a source");
                for (const Place& pl : places)
                    aspirateAt(i, pl, s.volumeUl, speed, fieldPath(path, "volume_ul"), &reported);
                return;
            }
            if (s.offsetMm < 0 || !std::isfinite(s.offsetMm))
                error(fieldPath(path, "touch_off_mm"), "must be 0 or more (got " + formatMm(s.offsetMm) + ")");
            for (const Place& pl : places)
                if (pl.w && s.offsetMm > pl.w->innerRadiusMm() + kEps) {
                    error(fieldPath(path, "touch_off_mm"), formatMm(s.offsetMm) + " mm is past the wall of a well "
                                                              + formatMm(2 * pl.w->innerRadiusMm()) + " mm wide");
                    break;
                }
            if (!s.source.empty())
                planTransfer(i, s, path, places, speed);
            else
                for (const Place& pl : places) {
                    if (m_liquid < s.volumeUl - 1e-6 && !reported) {
                        reported = true;
                        error(path, "dispensing " + volumeText(s.volumeUl) + " needs that much liquid in the syringe; it holds "
                                        + volumeText(std::max(0.0, m_liquid)) + " here: aspirate first, or give the step a \"source\"");
                    }
                    dispenseAt(i, pl, s.volumeUl, speed, std::max(0.0, s.offsetMm));
                }
            return;
        }
        case StepType::Mix: {
            checkCycles(s, path);
            const bool ok = checkVolume(s, path, true);
            const std::vector<Place> places = wellPlaces(s, path);
            if (!ok)
                return;
            roomFor(s.volumeUl, fieldPath(path, "volume_ul"), &reported);
            for (const Place& pl : places) {
                if (pl.w && s.volumeUl > pl.w->volumeUl + kEps) {
                    error(fieldPath(path, "volume_ul"), "mixing " + volumeText(s.volumeUl) + " in a " + volumeText(pl.w->volumeUl) + " well");
                    return;
                }
                PlanOp& op = newOp(i, StepType::Mix, &pl, s.volumeUl);
                goInto(op, pl);
                for (int c = 0; c < std::clamp(s.cycles, 1, kMaxCycles); ++c) {
                    pump(op, s.volumeUl, speed);
                    pump(op, -s.volumeUl, speed);
                }
                raiseTo(op, m_safeZ);
                ++totalOf(pl).visits;
            }
            return;
        }
        case StepType::Wash: {
            checkCycles(s, path);
            const bool ok = checkVolume(s, path, true);
            Place pl;
            if (s.station.empty()) {
                error(fieldPath(path, "station"), "is missing: say which station washes the tip");
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
            raiseTo(op, m_safeZ);
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
                error(fieldPath(path, "seconds"), "must be from 0 to " + formatMm(kMaxWaitS) + " s (got " + formatMm(s.seconds) + ")");
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
            const std::vector<Place> places = wellPlaces(s, path);
            if (!(s.offsetMm > 0) || !std::isfinite(s.offsetMm)) {
                error(fieldPath(path, "offset_mm"), "must be more than 0 mm (got " + formatMm(s.offsetMm) + ")");
                return;
            }
            for (const Place& pl : places) {
                if (pl.w && s.offsetMm > pl.w->innerRadiusMm() + kEps) {
                    error(fieldPath(path, "offset_mm"), formatMm(s.offsetMm) + " mm is past the wall of a well " + formatMm(2 * pl.w->innerRadiusMm())
                                                           + " mm wide");
                    return;
                }
                PlanOp& op = newOp(i, StepType::TouchOff, &pl, 0);
                goInto(op, pl);
                const PointMm dir = pl.transform.applyVector({s.offsetMm, 0});
                travelTo(op, {pl.at.x + dir.x, pl.at.y + dir.y}, MoveKind::Touch);
                travelTo(op, pl.at, MoveKind::Touch);
                raiseTo(op, m_safeZ);
            }
            return;
        }
        }
    }

    void checkCycles(const Step& s, const std::string& path)
    {
        if (s.cycles < 1 || s.cycles > kMaxCycles)
            error(fieldPath(path, "cycles"), "must be from 1 to " + std::to_string(kMaxCycles) + " (got " + std::to_string(s.cycles) + ")");
    }

    /// A dispense that refills from a source: as many wells per round as the
    /// syringe has room for, one aspirate from the source before each round.
    void planTransfer(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed)
    {
        const std::string srcPath = fieldPath(path, "source");
        Place src;
        if (!s.source.station.empty()) {
            if (!s.source.well.empty()) {
                error(srcPath, "give either a well or a station, not both");
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
                error(fieldPath(srcPath, "well"), "unknown well \"" + s.source.well + "\" on a " + lw.describe());
                return;
            }
            src = wellPlace(*p, *w);
            if (!reachable(src.at)) {
                error(fieldPath(srcPath, "well"), "the source is outside the analyzer's travel");
                return;
            }
        }
        const double room = m_cap - m_p - m_air;
        const int perRound = static_cast<int>(std::floor((room + 1e-6) / s.volumeUl));
        if (perRound < 1) {
            error(fieldPath(path, "volume_ul"), "volume over capacity: " + volumeText(s.volumeUl) + " per well, but the syringe has room for "
                                                   + volumeText(std::max(0.0, room)) + " here (" + volumeText(m_cap) + " in all)");
            return;
        }
        bool reported = false;
        for (std::size_t k = 0; k < targets.size(); k += static_cast<std::size_t>(perRound)) {
            const std::size_t n = std::min(targets.size() - k, static_cast<std::size_t>(perRound));
            const double vol = s.volumeUl * static_cast<double>(n);
            const int round = static_cast<int>(k / static_cast<std::size_t>(perRound)) + 1;
            if (src.w && vol > src.w->volumeUl + kEps && !reported) {
                reported = true;
                warning(srcPath, "a round draws " + volumeText(vol) + " from a " + volumeText(src.w->volumeUl) + " well");
            }
            aspirateAt(i, src, vol, speed, fieldPath(path, "volume_ul"), &reported);
            m_plan.ops.back().round = round;
            for (std::size_t j = k; j < k + n; ++j) {
                dispenseAt(i, targets[j], s.volumeUl, speed, std::max(0.0, s.offsetMm));
                m_plan.ops.back().round = round;
            }
        }
    }

    void finish()
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
                warning("steps", "well " + w.well + " of plate \"" + w.plate + "\" receives " + volumeText(w.dispensedUl - w.aspiratedUl)
                                     + " in all; it holds " + volumeText(well->volumeUl));
        }
    }

    const Recipe& m_r;
    const PlanContext& m_c;
    const double m_cap;
    RecipePlan m_plan;
    double m_x = 0, m_y = 0, m_z = 0, m_p = 0;
    double m_safeZ = std::numeric_limits<double>::infinity();  ///< the place the tip is over; none yet
    double m_liquid = 0, m_air = 0;
    bool m_tooMany = false;
};

} // namespace

RecipePlan planRecipe(const Recipe& recipe, const PlanContext& context, const StartState& start)
{
    return Planner(recipe, context, start).run();
}

} // namespace plates
