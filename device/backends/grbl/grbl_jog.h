#pragma once
// Continuous jog and the joystick on GRBL: short incremental "$J=G91 G21 …" moves kept a
// little ahead of the machine, cancelled with 0x85 on release (the jogging document's
// joystick method). Two promises, both within stopBudgetS (250 ms):
//
//   release   0x85 reaches the firmware after the link latency L, which then ramps down from
//             v at the acceleration a:           t_release = L + v/a
//   lost link GRBL cannot notice a host that is gone; it runs what is queued and stops at its
//             end (it always plans to rest at the end of its queue). The host keeps at most
//             aheadMax of motion queued, so:     t_overrun = aheadMax + v/(2a)
//
// What is queued is bounded from below too: GRBL plans to a stop at the end of what it holds,
// so the distance ahead must stay ≥ v²/(2a) or the machine never reaches v. The host tops the
// queue up every refresh period C (its status poll, or a faster timer) and must cover the
// latency L until the next line arrives:
//   aheadMin = v/(2a) + L + C         aheadMax = aheadMin + dt      (whole segments of dt)
// so t_overrun = v/a + L + C + dt. The segment time dt is ≥ 10 ms (GRBL's time to parse and
// plan one jog line, from the jogging document) and large enough that aheadMax fits the
// planner with one block to spare. planContinuousJog() lowers the speed until both promises
// hold; the figures it returns are what docs/grbl.md quotes.
#include "device/backends/grbl/grbl_protocol.h"
#include "motion/message.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace dev::grbl {

struct JogPlanInput {
    double speedMmS = 10;            ///< asked for
    double maxRateMmS = 1e300;       ///< along the jog direction (min over axes of $11x/60 ÷ |u_i|)
    double accelMmS2 = 100;          ///< along the jog direction (min over axes of $12x ÷ |u_i|)
    int plannerBlocks = kGrblDefaultPlannerBlocks;  ///< usable, from [OPT:]
    double refreshPeriodS = 0.1;     ///< C: how often the host tops the queue up (10 Hz poll)
    double linkLatencyS = 0.02;      ///< L: host write → firmware acts (USB serial, one line)
    double stopBudgetS = 0.25;
    double minSegmentS = 0.010;
};

struct JogPlan {
    bool feasible = false;
    motion::msg::Message problem;            ///< grbl.jog.budget_too_small{budget, latency, refresh} when not feasible
    double speedMmS = 0;             ///< what the jog runs at (≤ asked; lowered to keep the promises)
    bool speedLimited = false;       ///< lowered below min(asked, maxRate) for the stop budget
    double feedMmMin = 0;
    double segmentS = 0;             ///< dt
    double segmentMm = 0;            ///< v·dt: the length of each $J line
    double aheadMinS = 0;
    double aheadMaxS = 0;
    int segmentsAhead = 0;           ///< most $J lines queued at once: ceil(aheadMax/dt)
    double releaseStopS = 0;         ///< release → at rest
    double releaseStopMm = 0;        ///< distance travelled after release
    double lostLinkOverrunS = 0;     ///< last byte from the host → at rest
    double lostLinkOverrunMm = 0;    ///< distance travelled after the last byte
    double accelMmS2 = 0;
    double linkLatencyS = 0;
};

JogPlan planContinuousJog(const JogPlanInput& in);

/// Path limits of a jog direction from per-axis limits: the largest speed and acceleration
/// along `unit` that keeps every axis within its own.
std::pair<double, double> jogLimitsAlong(const std::vector<double>& unit, const std::vector<double>& maxRateMmS,
                                         const std::vector<double>& accelMmS2);

/// One continuous jog (a held key, or a joystick held in one direction at one speed): which
/// $J lines to send when. Pure: the host passes its clock in. A change of direction or speed
/// is a stop() and a new ContinuousJog (the queue is short, so the change lands within the budget).
class ContinuousJog {
public:
    /// `axes`: axis letters; `unit`: the direction, one component per letter (normalised here).
    ContinuousJog(const JogPlan& plan, std::string axes, std::vector<double> unit);
    const JogPlan& plan() const { return m_plan; }

    /// First lines, at the press.
    std::vector<std::string> start(double nowS);
    /// Lines that top the queue up; call every refresh period and on every ok of a $J line.
    std::vector<std::string> tick(double nowS);
    /// The release: the byte to send at once (0x85). Nothing more is sent afterwards.
    std::uint8_t stop();
    /// A new direction or speed while held (a joystick moving): later lines go the new way, at
    /// the new plan's speed and length; what is already queued runs out first (at most the old
    /// plan's aheadMax), so the change lands within the stop budget without a cancel.
    void retarget(const JogPlan& plan, const std::string& axes, const std::vector<double>& unit);

    bool active() const { return m_active; }
    /// Motion still queued ahead of the machine (the host's estimate), seconds at jog speed.
    double aheadS(double nowS) const { return m_queuedUntilS - nowS; }
    const std::string& segmentLine() const { return m_line; }
    std::uint64_t segmentsSent() const { return m_sent; }

private:
    JogPlan m_plan;
    std::string m_line;      ///< every segment is the same incremental move
    double m_queuedUntilS = 0;
    bool m_active = false;
    std::uint64_t m_sent = 0;
};

} // namespace dev::grbl
