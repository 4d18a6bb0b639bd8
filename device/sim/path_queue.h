#pragma once
// The reference firmware's path queue: LINE and ARC segments (seed 002's point-by-point
// interpolation) with a feed rate each, queued in a bounded ring and run one after another
// without stopping where the junction allows it (grbl-style look-ahead over everything queued,
// motion/path/junction_planner.h). On the analyzer a segment may carry a Z target that Z runs to
// once the segment's XY part has arrived (seed 000: XY cross-coupled, Z following).
//
// Execution, every tick: the path speed v rises at the path acceleration towards the segment's
// feed, capped by √(v_exit² + 2a·remaining) so the machine can always slow to the planned exit
// speed — which the look-ahead keeps at 0 at the end of what is queued, so an empty queue (or a
// host gone quiet) always ends at rest on the path. The distance s gained this tick is turned
// into whole steps by the segment's GridWalker and the axes' references set to that grid point
// (velocity feed-forward along the tangent).
//
// Safety (docs/protocol.md, "Path queue"):
//   - append refuses a whole request if any segment is malformed, too fast, leaves the soft
//     limits or the travel, or needs an axis that is not homed — and names the segment;
//   - STOP of a path axis and PATH_CLEAR slow down along the path and discard the queue;
//   - E-stop and a limit switch end the path at once (the machine has already frozen the axes);
//   - a host that goes quiet for kPathHostSilenceMs gets a feed hold (Firmware decides that: it
//     sees the frames), and a new host session (HELLO) aborts the path it cannot know about;
//   - while a path is queued its axes are reserved: MOVE, JOG and HOME on them answer Busy.
#include "device/protocol/messages_path.h"
#include "motion/interpolation.h"
#include "motion/path/grid_walker.h"
#include "motion/path/path_geometry.h"
#include "motion/ring_buffer.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace motion {
class Profile;
}

namespace dev::sim {

class SimMachine;

class PathQueue {
public:
    static constexpr int kCapacity = dev::proto::kMaxPathSegmentsPerAppend;
    static constexpr double kDefaultJunctionDeviationMm = 0.01;
    static constexpr double kMaxJunctionDeviationMm = 1.0;
    /// Default path acceleration as a share of the slower of X and Y's maxAccel: the rest is
    /// margin for the centripetal part on arcs and for the stage's loop.
    static constexpr double kDefaultAccelShare = 0.5;
    /// Open loop (the analyzer): share of the encoders' cross-track error corrected per tick
    /// (seed 000's cross-coupled XY). Closed loop (the stage): 0, its PID already holds each axis.
    static constexpr double kDefaultCrossCouplingGain = 0.05;
    static constexpr double kMaxCrossCorrectionMm = 0.2;  ///< never steer further than this off the walk

    explicit PathQueue(SimMachine& machine);
    ~PathQueue();

    using Result = std::optional<dev::proto::ErrorReply>;  ///< nullopt = accepted
    Result begin(const dev::proto::PathBeginRequest& request);
    Result append(const dev::proto::PathAppendRequest& request);
    dev::proto::PathStatusReply status() const;
    Result hold(dev::proto::PathReason why = dev::proto::PathReason::HostHold);
    Result resume();
    Result clear();

    // ---- hooks for the machine and the firmware ----------------------------------
    /// One machine tick, before the plants move.
    void tick();
    /// STOP named a path axis: slow down along the path, then end it.
    void stop();
    /// E-stop or a limit switch: the axes are already frozen; forget the path now.
    void abortNow(dev::proto::PathReason why, const std::string& text);
    /// A host opened a new session: it does not know this path, so end it (slowing down first).
    void sessionStarted();

    /// A path is begun and not over: its axes are reserved.
    bool active() const;
    /// The path is moving an axis right now.
    bool moving() const;
    double speedMmS() const { return m_speedMmS; }
    double accelMmS2() const { return m_accelMmS2; }
    std::uint8_t axisMask() const;
    dev::proto::PathState state() const { return m_state; }
    /// 0 switches the cross-coupled correction off (for comparison in tests and the benchmark).
    void setCrossCouplingGain(double perTick) { m_crossCouplingGain = perTick; }
    double crossCouplingGain() const { return m_crossCouplingGain; }
    /// Signed distance of a measured machine XY point from the geometric path near where the
    /// path is now (current and previous segment), mm; nullopt when no segment is running.
    std::optional<double> contourErrorMm(double measuredX, double measuredY) const;

private:
    struct Queued {
        std::uint32_t index = 0;
        motion::path::Segment geo;       ///< machine coordinates, mm
        motion::GridPoint gridEnd, gridCenter;
        double lengthMm = 0;
        double nominalMmS = 0;
        double maxEntryMmS = 0;          ///< junction limit with the segment before it
        double zMachine = 0;             ///< with geo.zMm
    };
    struct Active {
        Queued seg;
        std::optional<motion::path::GridWalker> walker;
        double sMm = 0;                  ///< distance done along the segment
        bool zPhase = false;             ///< XY arrived, Z is moving
        std::shared_ptr<const motion::Profile> zProfile;
        double zStart = 0, zT = 0, zV = 0;
        bool zBraking = false;           ///< a hold or stop caught Z moving: brake it
    };

    Result refuse(dev::proto::ErrorCode code, int axis, double value, const std::string& text) const;
    Result check(const dev::proto::PathSegmentWire& w, std::uint32_t index, const motion::path::Vec2& from,
                 const motion::GridPoint& gridFrom, Queued& out) const;
    void startRunning();
    void replan();
    bool takeNext();
    void finishSegment();
    void tickXy(double dtS);
    void tickZ(double dtS);
    void startZ();
    void atRest();
    void setReferences();
    /// Ends the path; the event names `eventIndex` (default: the segment not completed).
    void endPath(dev::proto::PathState state, dev::proto::PathReason why, const std::string& text,
                 std::optional<std::uint32_t> eventIndex = std::nullopt);
    void reserveAxes(bool reserve);
    void event(dev::proto::EventKind kind, std::uint32_t index, const std::string& text);
    double gridToMachine(int axis, std::int64_t steps) const;
    std::string where(std::uint32_t index, const motion::path::Segment& s) const;

    SimMachine& m;
    int m_x = 0, m_y = 1, m_z = -1;      ///< axis indices; m_z only where Z follows XY
    double m_stepMm = 0.001;             ///< the grid the walk steps on
    motion::RingBuffer<Queued, kCapacity + 1> m_queue;
    std::optional<Active> m_cur;
    motion::path::Segment m_prevGeo;     ///< last completed segment, for the contour measure at a junction
    bool m_havePrev = false;
    motion::GridPoint m_gridAt;          ///< where the last completed segment's walk ended
    bool m_havePrevGrid = false;

    dev::proto::PathState m_state = dev::proto::PathState::Idle;
    dev::proto::PathReason m_reason = dev::proto::PathReason::None;
    bool m_lastQueued = false;           ///< the path's final segment has arrived
    bool m_abortAtRest = false;          ///< holding to end the path (stop, clear, new session)
    std::uint32_t m_nextIndex = 0;
    std::uint32_t m_executing = 0;
    std::uint16_t m_underruns = 0;
    double m_originX = 0, m_originY = 0; ///< machine position of grid (0, 0)
    motion::path::Vec2 m_tailEnd;        ///< machine XY where the last queued segment ends
    motion::GridPoint m_tailGrid;
    motion::path::Vec2 m_tailTangent{1, 0};
    bool m_tailStops = true;             ///< the last queued segment ends at rest (path start, Z move)
    double m_defaultAccelMmS2 = 100;
    double m_accelMmS2 = 100, m_junctionMm = kDefaultJunctionDeviationMm, m_maxSpeedMmS = 10;
    double m_speedMmS = 0;
    double m_exitMmS = 0;                ///< planned exit speed of the running segment
    double m_crossCouplingGain = 0;      ///< per tick; set in the constructor for open-loop machines
    double m_crossCorrectionMm = 0;      ///< the cross-coupled correction now, along the left normal
};

} // namespace dev::sim
