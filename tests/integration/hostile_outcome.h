#pragma once
// A hostile run's outcome and the judges that read the simulator's own record (the
// firmware's journal: what it executed, with where the axes stood): shared by the
// in-process runs (hostile_support.h) and the pty runs through bp-faultline
// (hostile_pty_support.h), so both paths are held to the same invariants.
#include "device/protocol/messages.h"
#include "device/sim/firmware.h"
#include "motion/records/position_record.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hostile {

using Journal = std::vector<dev::sim::Firmware::JournalEntry>;

/// What one run did and whether the lab's invariants held.
struct Outcome {
    Outcome(std::string jobName, double byteRate, std::uint64_t lineSeed) : job(std::move(jobName)), rate(byteRate), seed(lineSeed) {}
    std::string job;
    double rate = 0;
    std::uint64_t seed = 0;
    std::string end = "?";  ///< finished, or what stopped it for good
    int stops = 0;          ///< times the job stopped and was resumed
    bool held = true;       ///< every invariant held
    std::string broken;     ///< which did not
    std::string why;        ///< what the job said when it stopped (message ids)
    quint64 retransmits = 0, crcErrors = 0, duplicatesAnswered = 0;
    qint64 damagedBytes = 0;
    /// false on the pty path: the host is another process, its retransmissions are not
    /// counted (the device's CRC errors and cache answers are).
    bool hostStats = true;

    void fail(const std::string& reason)
    {
        held = false;
        broken += (broken.empty() ? "" : "; ") + reason;
    }
    /// One line the campaign's table is made from (docs/testing.md, "Hostile link").
    std::string line() const
    {
        char b[1024];
        const std::string retx = hostStats ? std::to_string(retransmits) : std::string("-");
        std::snprintf(b, sizeof b,
                      "[ hostile ] job=%s rate=%.3f seed=%llu end=%s stops=%d invariants=%s retransmits=%s crc=%llu "
                      "dup_answered=%llu damaged_bytes=%lld%s%s%s%s",
                      job.c_str(), rate * 100, static_cast<unsigned long long>(seed), end.c_str(), stops, held ? "held" : "BROKEN",
                      retx.c_str(), static_cast<unsigned long long>(crcErrors),
                      static_cast<unsigned long long>(duplicatesAnswered), static_cast<long long>(damagedBytes),
                      why.empty() ? "" : " stopped_by=", why.c_str(), broken.empty() ? "" : " broken=", broken.c_str());
        return b;
    }
};

/// The plunger moves the device executed, summed by the X/Y it stood at (µm): a well.
struct PlungerTally {
    std::map<std::pair<long, long>, double> byWell;
    double pumped = 0;  ///< µL, all wells
};

/// `wireScale`: each axis's wire units per axis unit (dev::AxisInfo::wireScale()).
inline PlungerTally plungerByWell(const Journal& j, std::size_t from, const std::vector<double>& wireScale, int ix, int iy, int ip)
{
    PlungerTally t;
    for (std::size_t k = from; k < j.size(); ++k) {
        if (j[k].type != static_cast<std::uint8_t>(dev::proto::MsgType::Move))
            continue;
        const auto m = dev::proto::decodeMoveRequest(j[k].payload);
        if (!m || !(m->axisMask & (1u << ip)))
            continue;
        std::size_t slot = 0;
        for (int a = 0; a < ip; ++a)
            slot += (m->axisMask >> a) & 1u;
        const double target = m->targets[slot] / wireScale[static_cast<std::size_t>(ip)];
        const double delta = m->relative ? target : target - j[k].commanded[static_cast<std::size_t>(ip)];
        if (std::abs(delta) < 1e-9)
            continue;
        t.byWell[{std::lround(j[k].commanded[static_cast<std::size_t>(ix)] * 1000), std::lround(j[k].commanded[static_cast<std::size_t>(iy)] * 1000)}] += delta;
        t.pumped += delta;
    }
    return t;
}

/// Every well once and never twice; the plunger's travel equals what the device executed
/// (`plungerMovedUl`: where the plunger ended less where it began) and, with nothing
/// skipped, wells × volume. `skipped`: wells the operator chose to skip after a cut.
inline void judgeWells(Outcome& o, const PlungerTally& t, int wellCount, double volumeUl, int skipped, double plungerMovedUl)
{
    int twice = 0, partial = 0;
    for (const auto& [xy, ul] : t.byWell) {
        if (ul > volumeUl + 1e-6)
            ++twice;
        else if (ul < volumeUl - 1e-6)
            ++partial;
    }
    if (twice)
        o.fail(std::to_string(twice) + " wells aspirated more than once");
    if (static_cast<int>(t.byWell.size()) + skipped < wellCount)
        o.fail(std::to_string(wellCount - static_cast<int>(t.byWell.size())) + " wells never visited");
    if (partial > skipped)
        o.fail(std::to_string(partial) + " wells short of their volume");
    if (std::abs(plungerMovedUl - t.pumped) > 1e-6)
        o.fail("plunger position does not match the moves the device executed");
    if (skipped == 0 && std::abs(t.pumped - wellCount * volumeUl) > 1e-6)
        o.fail("plunger moved " + std::to_string(t.pumped) + " uL, the recipe asks " + std::to_string(wellCount * volumeUl));
}

/// The X/Y positions (µm) the device executed an absolute two-axis MOVE to.
inline std::set<std::pair<long, long>> xyMovesUm(const Journal& j)
{
    std::set<std::pair<long, long>> moves;
    for (const auto& e : j) {
        if (e.type != static_cast<std::uint8_t>(dev::proto::MsgType::Move))
            continue;
        if (const auto m = dev::proto::decodeMoveRequest(e.payload); m && !m->relative && m->axisMask == 0b11)
            moves.insert({std::lround(m->targets[0] / 1e3), std::lround(m->targets[1] / 1e3)});  // nm → µm
    }
    return moves;
}

/// Every tile taken once (`taken`: tile → times taken), each with a measured position
/// within `toleranceUm` of where it was commanded, at a position the device moved to.
inline void judgeTiles(Outcome& o, const std::vector<motion::PositionRecord>& records, int tiles, const std::map<int, int>& taken,
                       double toleranceUm, const std::set<std::pair<long, long>>& moves)
{
    int twice = 0, never = 0, unmeasured = 0, notVisited = 0;
    for (int t = 0; t < tiles; ++t) {
        const int n = taken.count(t) ? taken.at(t) : 0;
        twice += n > 1;
        never += n == 0;
    }
    for (const auto& rec : records) {
        if (!rec.measured() || rec.commandedMm.size() < 2 || rec.measuredMm.size() < 2) {
            ++unmeasured;
            continue;
        }
        for (int a = 0; a < 2; ++a)
            if (std::abs(rec.measuredMm[static_cast<std::size_t>(a)] - rec.commandedMm[static_cast<std::size_t>(a)]) * 1e3 > toleranceUm)
                ++unmeasured;
        if (!moves.count({std::lround(rec.commandedMm[0] * 1e3), std::lround(rec.commandedMm[1] * 1e3)}))
            ++notVisited;
    }
    if (twice)
        o.fail(std::to_string(twice) + " tiles taken twice");
    if (never)
        o.fail(std::to_string(never) + " tiles never taken");
    if (unmeasured)
        o.fail(std::to_string(unmeasured) + " tiles without a measured position in tolerance");
    if (notVisited)
        o.fail(std::to_string(notVisited) + " tiles the device never moved to");
}

/// How long after its last velocity refresh (JOG_VELOCITY) each of `axes` came to rest
/// (its first MotionDone or Stopped event after that refresh), from the device's journal:
/// fails `o` for an axis that moved longer than `watchdogS` or never reported at rest.
inline void judgeCoast(Outcome& o, const Journal& j, const std::vector<int>& axes, double watchdogS)
{
    double lastRefreshS = -1;
    std::map<int, double> restS;
    for (const auto& e : j) {
        if (e.type == static_cast<std::uint8_t>(dev::proto::MsgType::JogVelocity)) {
            lastRefreshS = e.timeS;
            restS.clear();
        } else if (e.type == static_cast<std::uint8_t>(dev::proto::MsgType::Event)) {
            const auto ev = dev::proto::decodeEvent(e.payload);
            if (ev && (ev->kind == dev::proto::EventKind::MotionDone || ev->kind == dev::proto::EventKind::Stopped) && !restS.count(ev->axis))
                restS[ev->axis] = e.timeS;
        }
    }
    for (const int a : axes) {
        if (!restS.count(a)) {
            o.fail("axis " + std::to_string(a) + " never reported at rest");
            continue;
        }
        const double after = restS[a] - std::max(lastRefreshS, 0.0);
        if (after > watchdogS + 1e-3)
            o.fail("axis " + std::to_string(a) + " moved " + std::to_string(after * 1000) + " ms after its last refresh");
    }
}

} // namespace hostile
