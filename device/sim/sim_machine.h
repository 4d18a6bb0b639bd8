#pragma once
// The simulated instrument's motion controller: the reference firmware's
// behaviour (segments, jog with watchdog, homing, switches, E-stop, soft limits)
// over SimAxis plants, on a virtual clock advanced in fixed ticks.
#include "device/protocol/event_reasons.h"
#include "device/protocol/messages.h"
#include "device/protocol/messages_arch.h"
#include "device/sim/machine_config.h"
#include "device/sim/sim_axis.h"
#include "device/sim/sim_compensation.h"

#include <memory>
#include <optional>
#include <vector>

namespace motion {
class Profile;
}

namespace dev::sim {

class SimTuning;
class PathQueue;
class SimCompensation2d;

class SimMachine {
public:
    static constexpr double kTickS = 100e-6;        ///< simulation tick: 10 kHz
    static constexpr double kJogWatchdogTripS = 0.200; ///< velocity move not refreshed this long starts to stop
    /// …and its reference is at rest this much later at the latest. The 250 ms
    /// promise (HELLO's jogWatchdogMs) also covers the stage's settling after the
    /// reference stops, so the ramp does not take the whole remaining 50 ms.
    static constexpr double kJogStopBudgetS = 0.025;

    /// `powerUp`: what the last power cycle left in the flash (saved compensations).
    explicit SimMachine(const MachineConfig& config, const NonVolatile& powerUp = {});
    ~SimMachine();

    const MachineConfig& config() const { return m_cfg; }
    /// How long a velocity move may go unrefreshed before it stops (kJogWatchdogTripS). A
    /// simulator run K times faster than the wall clock judges the host's refreshes on the
    /// host's clock: K times the trip (SimulatorHost::setTimeScale), or a host refreshing
    /// every 50 ms of its time could never hold a jog above 4x.
    void setJogWatchdogTripS(double seconds) { m_jogWatchdogTripS = seconds; }
    double jogWatchdogTripS() const { return m_jogWatchdogTripS; }
    dev::proto::HelloReply hello(std::uint32_t linkBaud) const;
    /// The planner's limits as HELLO's extension block states them: the numbers
    /// planSegment() works to, so a host times a move the way it will run.
    dev::proto::MotionLimits motionLimits() const;
    int axisCount() const { return static_cast<int>(m_axes.size()); }
    double timeS() const { return static_cast<double>(m_ticks) * kTickS; }
    std::uint64_t timeUs() const { return m_ticks * 100; }

    /// Runs exactly one tick.
    void tick();

    using Result = std::optional<dev::proto::ErrorReply>;  ///< nullopt = accepted
    Result home(std::uint8_t axisMask);
    Result move(const dev::proto::MoveRequest& request);
    /// ARCH_MOVE (sim_arch_move.cpp): Z up to a clearance, XY across, Z down, blended.
    Result archMove(const dev::proto::ArchMoveRequest& request);
    Result jogStep(const dev::proto::JogStepRequest& request);
    Result jogVelocity(const dev::proto::JogVelocityRequest& request);
    Result stop(std::uint8_t axisMask);
    Result estop();
    Result reset();
    Result setZero(std::uint8_t axisMask);
    Result setLimits(const dev::proto::SetLimitsRequest& request);
    dev::proto::LimitsReply limits() const;
    dev::proto::StatusReply status() const;

    /// Value of a telemetry channel now, in wire units.
    std::int32_t channelValue(const dev::proto::ChannelRef& channel) const;
    bool channelExists(const dev::proto::ChannelRef& channel) const;

    std::vector<dev::proto::EventMsg> takeEvents();

    // Test and fault-injection hooks: what a bench technician could do to the plant.
    SimAxis& axis(int i) { return *m_axes[static_cast<std::size_t>(i)].plant; }
    const SimAxis& axis(int i) const { return *m_axes[static_cast<std::size_t>(i)].plant; }
    double logicalOffset(int i) const { return m_axes[static_cast<std::size_t>(i)].offset; }
    /// Host coordinates (mm or µL): the step counter and the encoder/grating counter.
    double commandedLogical(int i) const;
    double measuredLogical(int i) const;
    /// Where the work point truly is, in host coordinates: the work point less the
    /// machine position where the readback reads 0. What a gauge or interferometer at
    /// the work point reads whose zero is that machine position (at it, the gauge reads
    /// the Abbe error there, not 0). The readback sees neither the scale's error nor the
    /// Abbe error; this does.
    double workPointLogical(int i) const;
    /// Where an XY stage's work point truly is, in host coordinates (mm): what a camera
    /// looking at a plate on the stage sees, as a gauge sees workPointLogical(). With
    /// stage errors (MachineConfig::stageErrors) X and Y each carry the other axis'
    /// straightness, X the squareness, and each half its lost motion against the side
    /// it was approached from (motion/metrology/grid/stage_errors.h).
    struct WorkPointMm {
        double xMm = 0;
        double yMm = 0;
    };
    WorkPointMm trueWorkPoint() const;
    /// The same for gratings that read (gratingXMm, gratingYMm) in host coordinates
    /// (the raw gratings, before a compensation's correction), the axes having last
    /// moved as they did: where the work point is when the stage stands there.
    WorkPointMm trueWorkPointAt(double gratingXMm, double gratingYMm) const;
    bool homed(int i) const { return m_axes[static_cast<std::size_t>(i)].homed; }
    bool estopActive() const { return m_estop; }
    /// Every closed-loop axis' operator gains (seed 002's per-period form).
    void setGains(const PidGains& g);
    /// Gains and tuning tests of the closed-loop axes (sim_tuning.h).
    SimTuning& tuning() { return *m_tuning; }
    const SimTuning& tuning() const { return *m_tuning; }
    /// The queued LINE/ARC path (device/sim/path_queue.h).
    PathQueue& paths() { return *m_path; }
    const PathQueue& paths() const { return *m_path; }
    /// Axis error compensation (device/sim/sim_compensation.h).
    SimCompensation& compensation() { return *m_comp; }
    const SimCompensation& compensation() const { return *m_comp; }
    /// The XY stage's 2D compensation table (device/sim/sim_compensation_2d.h).
    SimCompensation2d& compensation2d() { return *m_comp2d; }
    const SimCompensation2d& compensation2d() const { return *m_comp2d; }

private:
    friend class SimTuning;
    friend class PathQueue;  // drives the axes it has reserved (Mode::Path) through the same state
    friend class SimCompensation;  // attaches compensations to homed axes at rest
    friend class SimCompensation2d;
    enum class Mode { Idle, Segment, Jog, Decel, Homing, Settling, Tuning, Path };
    enum class HomePhase { SeekFast, BackOff, SeekSlow };

    struct AxisState {
        std::unique_ptr<SimAxis> plant;
        Mode mode = Mode::Idle;
        double v = 0;             ///< reference velocity in velocity modes
        double vTarget = 0;
        double accel = 0;         ///< ramp rate in velocity modes
        double lastRefreshS = 0;
        bool expired = false;
        HomePhase phase = HomePhase::SeekFast;
        double phaseStart = 0;    ///< machine position when the phase began
        bool homed = false;
        bool fault = false;
        double offset = 0;        ///< machine − logical, for the reference (step counter)
        /// Machine − logical for the encoder/grating counter. The stage's grating is
        /// its reference, so there both are equal; the analyzer's encoder is zeroed
        /// with the step counter, at which instant lead error and play may differ.
        double measuredOffset = 0;
        /// Soft limits in home coordinates (logical as the last homing left them), so
        /// they stay put on the machine through a set-zero and reset on re-homing.
        double softMin = 0, softMax = 0;
        double homeOffset = 0;    ///< machine reference where home coordinates are 0
        double settledS = 0;
        double settleStartS = 0;
        dev::proto::EventKind doneEvent = dev::proto::EventKind::MotionDone;
        int segment = -1;         ///< id of the segment this axis follows
        bool lostReported = false;
    };
    struct Segment {
        int id = 0;
        int after = -1;           ///< id of a segment that must finish before this starts
        /// ≥ 0: this starts once `after` has run this long (its own clock), not when it ends.
        double afterS = -1;
        /// An arched move's rise: its end hands Z to the way down, with no event.
        bool handsOver = false;
        int arch = -1;            ///< the arched move's id its three parts share; -1: none
        bool started = false;
        double t = 0;
        std::vector<int> axes;
        std::vector<double> start, dir;  ///< machine coordinates, unit direction
        std::shared_ptr<const motion::Profile> profile;
        dev::proto::EventKind doneEvent = dev::proto::EventKind::MotionDone;
    };

    AxisState& st(int i) { return m_axes[static_cast<std::size_t>(i)]; }
    const AxisState& st(int i) const { return m_axes[static_cast<std::size_t>(i)]; }
    double scale(int i) const;  ///< wire units per axis unit
    /// A value in wire units as the wire's int32: truncated, saturated, NaN → 0.
    static std::int32_t wireInt32(double value);
    dev::proto::ErrorReply error(dev::proto::ErrorCode code, int axis, double value, const std::string& text) const;
    std::string fmt(int axis, double value) const;
    Result checkAxes(std::uint8_t mask, bool mustBeIdle) const;
    bool awaitingHoming(int i) const;  ///< in a homing stage that has not started yet
    double softMinMachine(int i) const { return st(i).homeOffset + st(i).softMin; }
    double softMaxMachine(int i) const { return st(i).homeOffset + st(i).softMax; }
    void zeroCounters(int i, double logicalHere);
    /// `fromMachine`: where the segment starts (one per axis) when not where the axes stand now.
    Result planSegment(const std::vector<int>& axes, const std::vector<double>& targetsMachine, double speed,
                       int after, dev::proto::EventKind doneEvent, int* idOut,
                       const std::vector<double>* fromMachine = nullptr);
    Segment* segmentById(int id);
    /// Forgets the parts of arched move `arch` that have not started (a stop, a switch).
    void cancelArchRest(int arch, const char* why, std::uint8_t code);
    void finishAxis(int i, dev::proto::EventKind kind, const std::string& text = {}, std::uint8_t why = 0);
    void stopAxisHard(int i);
    void cancelSegmentsAfter(int id, const char* why, std::uint8_t code);
    void advanceHomingStages();
    void cancelHoming(const char* why, std::uint8_t code);
    void startHomingStage();
    void tickSegments();
    void tickVelocityModes();
    void tickHoming(int i);
    void tickSettling(int i);
    void checkSwitches(int i);
    /// `text` for people; `why` and `values` for a host that words it (dev::proto::reason, 0: none).
    void raiseEvent(dev::proto::EventKind kind, int axis, const std::string& text = {}, std::uint8_t why = 0,
                    std::vector<double> values = {});
    double contourErrorMm() const;
    /// The work point of axis `i` (0: X, 1: Y) in machine coordinates for carriages at
    /// (carriageX, carriageY), machine coordinates: the one formula both
    /// trueWorkPoint() and trueWorkPointAt() use.
    double stageWorkPointMachine(int i, double carriageX, double carriageY) const;
    bool hasStageErrors() const;

    MachineConfig m_cfg;
    double m_jogWatchdogTripS = kJogWatchdogTripS;
    std::vector<AxisState> m_axes;
    std::vector<Segment> m_segments;
    std::vector<std::uint8_t> m_homeStages;  ///< masks still to home, in order
    std::vector<dev::proto::EventMsg> m_events;
    std::uint64_t m_ticks = 0;
    int m_nextSegmentId = 1;
    int m_nextArchId = 1;
    int m_ticksPerControl = 10;
    bool m_estop = false;
    int m_lastXySegment = -1;
    std::vector<double> m_xyLineStart, m_xyLineDir;  ///< last XY path, for contour error
    std::unique_ptr<SimTuning> m_tuning;
    std::unique_ptr<PathQueue> m_path;
    std::unique_ptr<SimCompensation> m_comp;
    std::unique_ptr<SimCompensation2d> m_comp2d;
};

} // namespace dev::sim
