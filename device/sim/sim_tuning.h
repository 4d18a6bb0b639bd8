#pragma once
// The simulated stage's side of PID tuning (docs/tuning.md): per-axis gains (the
// operator's set and a power-up set), and tests that run on the device at the
// loop rate — a step test with optional trial gains, a relay or forced square
// wave — with the abort envelope checked every control period, a capture of
// setpoint, measurement and controller output, and a host-silence watchdog.
//
// Trial gains never replace the operator's: they live in the test alone, and
// whatever ends a test (settled, done, envelope, STOP, TEST_ABORT, E-stop, the
// host going quiet, a new session) leaves the axis stopped under the
// operator's gains. The device needs no host for that. One exception: a test
// run under the operator's own gains that trips its envelope has shown those
// gains to diverge, so the axis is stopped under the set in force before them
// (holding on the diverging set would drive it on, millimetres past the trip).
#include "device/protocol/messages_tuning.h"
#include "device/sim/machine_config.h"
#include "motion/control/experiment.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dev::sim {

class SimMachine;

class SimTuning {
public:
    /// A test ends when no frame came from the host for this long. The client's
    /// status poll (every 50 ms) keeps it fed.
    static constexpr double kHostSilenceS = 0.5;
    /// Samples a capture holds; a longer test halves its rate to keep all of it.
    static constexpr std::size_t kCaptureCapacity = 16384;
    static constexpr double kMaxTestS = 120;

    explicit SimTuning(SimMachine& machine);

    using Result = std::optional<dev::proto::ErrorReply>;
    Result getGains(std::uint8_t axis, dev::proto::GainsReply& out) const;
    Result setGains(const dev::proto::SetGainsRequest& r);
    Result stepTest(const dev::proto::StepTestRequest& r);
    Result relayTest(const dev::proto::RelayTestRequest& r);
    Result capture(const dev::proto::CaptureRequest& r, dev::proto::CaptureReply& out) const;
    /// TEST_ABORT (never refused); also what STOP does to a test.
    Result abort(std::uint8_t axisMask, motion::control::EndReason why);

    /// Every good frame from the host feeds the watchdog.
    void hostHeard();
    bool testRunning(int axis) const;
    const PidGains& gains(int axis) const { return m_axes[static_cast<std::size_t>(axis)].gains; }
    void setAllGains(const PidGains& g);

    /// One control period of a closed-loop axis: false when no test runs on it
    /// (the machine runs its PID), true when the test supplied the correction.
    bool controlStep(int axis, int ticksPerPeriod);
    /// The host-silence watchdog, once per tick.
    void tick();

private:
    struct Capture {
        std::uint8_t kind = 0;
        std::uint32_t testId = 0;
        double periodS = 0;
        int stride = 1;            ///< record every stride-th period
        int phase = 0;
        std::int32_t startPosition = 0;
        dev::proto::WireGains gains;
        std::vector<dev::proto::CaptureSample> samples;
    };
    struct Axis {
        PidGains gains;            ///< the operator's: in force whenever no test runs
        PidGains saved;            ///< power-up set
        PidGains previous;         ///< the operator's set before the last SET_GAINS
        bool testUsesOperatorGains = false;  ///< the running test has no trial gains
        std::optional<motion::control::Experiment> test;
        double lastU = 0;          ///< the test's output last period
        Capture capture;
        motion::control::EndReason lastReason = motion::control::EndReason::Running;
        double tripValue = 0, tripLimit = 0;  ///< axis units, or s
    };

    Result checkTestable(std::uint8_t axis, bool homedNeeded) const;
    Result checkEnvelope(int axis, const dev::proto::WireEnvelope& e, double stepMm) const;
    void start(int axis, motion::control::Experiment x, std::uint8_t kind, const dev::proto::WireGains& gains);
    void end(int axis);
    void record(int axis);

    SimMachine& m_m;
    std::vector<Axis> m_axes;
    double m_lastHeardS = 0;
    std::uint32_t m_nextTestId = 1;
};

} // namespace dev::sim
