#pragma once
// Tuning experiments as a controller runs them, one control period at a time:
// a step test with given gains, a relay (self-oscillating, Åström–Hägglund) and
// a forced square wave. The same code runs on the device (the simulator's
// firmware) and in BenchPilot's model-plant loop, so what a test measures on a
// model is what the device does on the stage. The abort envelope is checked
// every period, before the output is computed.
//
// Units: positions and errors in the plant's output unit (mm on the stage),
// controller output u in its own unit (mm of motor correction on the stage).
#include "motion/control/gains.h"
#include "motion/control/pid.h"

#include <cstdint>
#include <vector>

namespace motion::control {

/// Limits the experiment may never cross; the axis stops when one is.
struct Envelope {
    double maxExcursion = 0;       ///< |y − y at start| (> 0)
    double maxFollowingError = 0;  ///< |setpoint − y| (> 0; above the step size for a step test)
    double maxDurationS = 0;       ///< (> 0)
};

/// Why an experiment ended. Values are the wire codes (docs/protocol.md).
enum class EndReason : std::uint8_t {
    Running = 0,
    Settled = 1,         ///< step test: inside the settle band for the hold time
    Completed = 2,       ///< ran its planned time or cycles
    Excursion = 3,       ///< envelope: max excursion crossed
    FollowingError = 4,  ///< envelope: max following error crossed
    Duration = 5,        ///< envelope: max duration reached
    Stopped = 6,         ///< STOP, TEST_ABORT or the tuner ended it early
    EStop = 7,
    HostSilent = 8,      ///< no frame from the host for the watchdog time
    Fault = 9,           ///< a switch, a fault or a lost axis
};
constexpr std::uint8_t kMaxEndReason = 9;
const char* endReasonName(EndReason r);  ///< the key in files and JSON: "settled", "max excursion crossed"
const char* endReasonTerm(EndReason r);  ///< for people (ui::words::term): "tuning.end.settled"
inline bool isEnvelopeTrip(EndReason r) { return r == EndReason::Excursion || r == EndReason::FollowingError || r == EndReason::Duration; }
/// Settled or completed: the experiment did what it was asked.
inline bool endedNormally(EndReason r) { return r == EndReason::Settled || r == EndReason::Completed; }

struct StepSpec {
    double step = 0;          ///< setpoint change, signed
    DiscreteGains gains;      ///< the gains the test runs with
    double settleBand = 0;    ///< |setpoint − y| inside this for settleHoldS ends the test (0: never settles)
    double settleHoldS = 0.05;
    double runS = 0;          ///< ends Completed after this long (0: runs until settled or tripped)
    Envelope envelope;
};

struct RelaySpec {
    double amplitude = 0;     ///< d: the output swings u0 ± d
    /// ε: the relay switches up when the error rises above +ε and down when it
    /// falls below −ε (noise immunity; it also shifts the oscillation, see docs/tuning.md).
    double hysteresis = 0;
    /// 0: self-oscillating relay on the error. Otherwise a square wave of this
    /// period, switched on a timer (rounded to whole control periods, at least 2):
    /// the phase-crossover refinement measures the plant at chosen frequencies with it.
    double forcedPeriodS = 0;
    int cycles = 10;          ///< ends Completed after this many full output periods
    Envelope envelope;
};

/// Problems with a spec before it runs (empty = fine). `step`/`amplitude` name the field.
std::vector<std::string> checkStepSpec(const StepSpec& s);
std::vector<std::string> checkRelaySpec(const RelaySpec& s);

class Experiment {
public:
    enum class Kind : std::uint8_t { Step = 1, Relay = 2 };

    /// Starts at y0 (measured) with the controller output at u0; periodS is the control period.
    static Experiment stepTest(const StepSpec& spec, double y0, double u0, double periodS, double deadband = 0);
    static Experiment relay(const RelaySpec& spec, double y0, double u0, double periodS);

    /// One control period: y is the measurement this period. Returns the output
    /// u_k to apply (held if the experiment has just ended).
    double control(double y);
    /// Ends it from outside (STOP, E-stop, host silence, the tuner's own early stop).
    void abort(EndReason reason);

    Kind kind() const { return m_kind; }
    bool running() const { return m_reason == EndReason::Running; }
    EndReason reason() const { return m_reason; }
    /// The value that crossed the envelope and the limit it crossed (0 otherwise).
    double tripValue() const { return m_tripValue; }
    double tripLimit() const { return m_tripLimit; }
    double setpoint() const { return m_setpoint; }
    double output() const { return m_u; }
    double startPosition() const { return m_y0; }
    double startOutput() const { return m_u0; }
    double elapsedS() const { return static_cast<double>(m_k) * m_periodS; }
    double periodS() const { return m_periodS; }
    /// Relay: full output periods completed so far.
    int cycles() const { return m_cycles; }
    const DiscreteGains& gains() const { return m_pid.gains(); }

private:
    Experiment() = default;
    bool checkEnvelope(double y);

    Kind m_kind = Kind::Step;
    StepSpec m_step;
    RelaySpec m_relay;
    double m_periodS = 1e-3;
    double m_deadband = 0;
    double m_y0 = 0, m_u0 = 0, m_u = 0, m_setpoint = 0;
    long m_k = 0;                   ///< periods run
    EndReason m_reason = EndReason::Running;
    double m_tripValue = 0, m_tripLimit = 0;
    IncrementalPid m_pid;
    double m_settledS = 0;
    int m_state = 1;                ///< relay: +1 / −1
    long m_forcedPeriods = 0;       ///< forced square wave: its period in control periods
    int m_cycles = 0;
};

/// What an experiment left behind, one entry per control period (the device's
/// capture, or a model-plant run): y_k read at t_k = k·periodS, u_k held over
/// the period after it.
struct Record {
    double periodS = 0;
    double startPosition = 0;
    double startOutput = 0;
    std::vector<double> setpoint, measured, output;
    EndReason reason = EndReason::Running;
    double tripValue = 0, tripLimit = 0;

    std::size_t size() const { return measured.size(); }
    void append(double sp, double y, double u)
    {
        setpoint.push_back(sp);
        measured.push_back(y);
        output.push_back(u);
    }
};

} // namespace motion::control
