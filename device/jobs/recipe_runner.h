#pragma once
// Runs a planned recipe on the analyzer, one op (well visit) at a time, each a
// short sequence of MOVE requests: the next is sent when the device's
// MotionDone events for the previous one have arrived (no polling). Every op is
// written to the run log (device/files/recipes/run_log.h) before the machine is
// told to do it, so a run survives anything that kills it:
//   * pause: after the current op, with the tip up;
//   * abort: STOP at once, then Z up to the safe height once everything is still;
//   * link lost, E-stop, a refusal: it stops and says so; resume() continues
//     once the link is back (the op under way is begun again when no liquid had
//     moved, or the operator decides when it had);
//   * a crash or SIGKILL: resumeFromLog() continues from the log, never doing a
//     completed op twice, and asks the operator about one interrupted mid-dispense.
#include "device/client/instrument.h"
#include "device/files/recipes/run_log.h"
#include "device/files/recipes/run_log_writer.h"
#include "motion/plans/recipes/recipe_plan.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace dev::jobs {

enum class RunState {
    Idle,      ///< nothing under way (never started, or finished)
    Running,
    Pausing,   ///< finishing the current op, then Paused
    Paused,
    Aborting,  ///< stopping, then raising Z
    Stopped,   ///< aborted, link lost, refused: resume() or resumeFromLog() can continue
    Finished,
};
/// The state's term for people ("recipe.state.running"), worded by ui::words::term.
const char* runStateTerm(RunState s);
/// Running, pausing or aborting: the run is driving the machine.
bool runActive(RunState s);

/// What the operator is asked about an op that was interrupted after its
/// plunger move had been sent.
struct InterruptedOp {
    int op = 0;
    motion::msg::Message label;                  ///< recipe.op.*: "dispense 10 µL into samples B3"
    std::optional<double> pumpStartUl;   ///< plunger when the pump move was sent
    double plannedDeltaUl = 0;           ///< what the op's pump moves add up to
    std::optional<double> plungerNowUl;  ///< where it is now
    motion::msg::Message evidence;               ///< recipe.evidence.*: "the plunger is where the dispense would leave it"
};
enum class InterruptedChoice { Skip, Redo, Cancel };
using InterruptedDecider = std::function<InterruptedChoice(const InterruptedOp&)>;

struct RunProgress {
    int opsDone = 0, opsTotal = 0;
    /// The op under way; -1 when none is (idle, finished, or paused between two ops:
    /// the op after a pause has not begun, so it is nextOp, not current).
    int currentOp = -1;
    motion::msg::Message currentWhere;  ///< recipe.where.*: "samples B3"
    motion::msg::Message currentLabel;  ///< recipe.op.*
    int nextOp = -1;            ///< while paused: the op Resume begins with
    motion::msg::Message nextLabel;     ///< recipe.op.* of nextOp
    double elapsedS = 0;    ///< running time (pauses excluded)
    double etaS = 0;        ///< remaining, from the profiles scaled by how the run is going
    double fraction = 0;    ///< of the planned time
    /// Running time on the instrument's own clock (pauses excluded): what the plan's
    /// times are comparable with, on a sped-up simulator too.
    double deviceS = 0;
};

class RecipeRunner : public QObject {
    Q_OBJECT
public:
    explicit RecipeRunner(dev::Instrument* client, QObject* parent = nullptr);
    ~RecipeRunner() override;

    /// The plan to run (planRecipe's result; refused when it has errors).
    bool setPlan(const motion::plates::RecipePlan& plan, const QString& recipeName, motion::msg::Message* error);
    const motion::plates::RecipePlan& plan() const { return m_plan; }

    /// A new run, logged to `logPath` (a new file).
    bool start(const QString& logPath, motion::msg::Message* error);
    /// Continues the run `logPath` records (same recipe: same fingerprint). Plan
    /// it from where the run began: resumeStart() says where that was.
    bool resumeFromLog(const QString& logPath, const InterruptedDecider& decide, motion::msg::Message* error);
    /// The state to plan a resumed run from: the machine as it stands, with the
    /// plunger where the logged run began (the plan's syringe accounting is the
    /// original run's). Falls back to the plunger now when the log does not say.
    static motion::plates::StartState resumeStart(const QString& logPath, const dev::Instrument& client);
    /// After a pause or a stop; `decide` is asked when the op under way had moved liquid.
    bool resume(const InterruptedDecider& decide, motion::msg::Message* error);
    void pause();
    void abort();

    RunState state() const { return m_state; }
    RunProgress progress() const;
    const std::vector<dev::files::plates::OpState>& opStates() const { return m_opStates; }
    QString logPath() const { return m_log.path(); }
    /// The run's per-move watchdog: a MotionDone lost on the link is noticed after
    /// the move's planned time × this + kMoveGraceMs on the device's clock, counted from
    /// the device's answer to the move, and the status decides whether the move arrived.
    static constexpr double kMoveTimeFactor = 3.0;
    static constexpr int kMoveGraceMs = 3000;
    /// The budget is looked at this often (wall clock), so a simulator faster than the
    /// wall clock is judged when its own clock has spent it, not seconds later.
    static constexpr int kMoveCheckMs = 250;

signals:
    void stateChanged(dev::jobs::RunState state);
    void progressChanged();
    void opStarted(int op);
    void opFinished(int op);
    /// A message for the operator (recipe.run.*, worded by ui::words::text); `problem` for
    /// what stopped the run.
    void message(const motion::msg::Message& text, bool problem);
    void finished(bool completed);

private:
    bool checkMachine(motion::msg::Message* error) const;
    bool preflight(motion::msg::Message* error) const;
    void setState(RunState s);
    /// Running from m_op; `newSession`: the pace is judged afresh (not after a pause).
    void beginRunning(bool newSession = true);
    void nextMove();
    void sendMove(const motion::plates::MachineMove& planned);
    /// The current op's arched move as legs (raise, travel, lower) on a device that does not
    /// blend them (recipe_runner_arch.cpp).
    void archAsLegs();
    /// An arched move that runs the plunger, on a device that cannot: the arch, then the
    /// plunger and the rise as moves of their own.
    void archPumpApart();
    bool canArchPump() const;
    /// The arched move as sent: from an unknown place, or not from the well the plan
    /// leaves, it starts from the op's safe height without leaving sideways.
    motion::plates::MachineMove archAsSent(const motion::plates::MachineMove& planned) const;
    void moveArrived();
    /// A wait: asks the device's clock, then sleeps what is left of it (`begin`: it starts now).
    void checkDwell(bool begin);
    double deviceRate() const;
    void onEvent(const dev::DeviceEvent& e);
    void onLinkState(dev::LinkState s);
    void onMoveTimeout();
    void stopRun(const motion::msg::Message& reason, dev::files::json::Value detail = {});
    motion::msg::Message linkLostMessage() const;
    /// The op's label as the `op` argument ("the run" when none is under way).
    motion::msg::Arg opArg(int op) const;
    void finishOp();
    bool logLine(dev::files::json::Value line);
    bool decideInterrupted(int op, const InterruptedDecider& decide, bool* redo, motion::msg::Message* error);
    bool applyDecision(int op, bool redo);
    /// preflight() as the run will be once the operator's (op, redo) decisions apply.
    bool preflightDecided(const std::vector<std::pair<int, bool>>& decisions, motion::msg::Message* error);
    int nextOpenOp(int from) const;
    int axis(char letter) const;
    double plungerNow() const;
    /// After a reconnect: the same instrument as the run began on, its plunger where the
    /// run left it; says what it found (message), or why not (error).
    bool checkResumedInstrument(motion::msg::Message* error);

    dev::Instrument* m_client;
    motion::plates::RecipePlan m_plan;
    QString m_recipeName;
    dev::files::plates::RunLogWriter m_log;
    std::vector<dev::files::plates::OpState> m_opStates;
    RunState m_state = RunState::Idle;
    int m_op = -1;             ///< op under way
    int m_move = 0;            ///< next move of it
    bool m_pumpLogged = false; ///< the op's "pump" line is written
    bool m_pauseAsked = false;
    // The move in flight: which axes' MotionDone we wait for, and its reply.
    quint8 m_waitMask = 0;
    bool m_replied = false;    ///< every request of the move answered
    int m_repliesPending = 0;  ///< requests of the move not answered yet (two for an arched leg)
    int m_moveSerial = 0;      ///< callbacks of an abandoned move are ignored
    std::optional<motion::plates::MachineMove> m_inFlight;
    // What we last commanded (valid once commanded since the (re)start).
    bool m_knowXy = false, m_knowZ = false;
    double m_x = 0, m_y = 0, m_z = 0;
    /// The op whose deferred raise was left to the next op's arched move: the tip is still
    /// down in its well (-1: none). Only then may that move leave the well sideways.
    int m_deferredFrom = -1;
    double m_pumpUl = 0;       ///< plunger (µL), from the status at (re)start plus our moves
    double m_pumpStartUl = 0;  ///< plunger when the op's "pump" line was written
    std::string m_runInstrument;  ///< model and firmware the run was (re)started on
    std::optional<dev::files::plates::RunLogState> m_logState;  ///< the log being resumed, while deciding
    QTimer m_moveTimer, m_dwellTimer;
    quint64 m_moveSentUs = 0;  ///< device clock of the first status after the move was answered (sent, until then)
    bool m_budgetStartPending = false;  ///< answered, no status since
    QElapsedTimer m_clock;
    double m_elapsedBeforeS = 0;    ///< running time of earlier stretches
    double m_deviceBeforeS = 0;     ///< the same on the device's clock
    quint64 m_deviceStartUs = 0;    ///< device clock when this stretch began
    quint64 m_deviceLastUs = 0;     ///< device clock of the latest event or status of this stretch
    quint64 m_dwellStartUs = 0;     ///< device clock the wait counts from
    QElapsedTimer m_dwellWall;      ///< wall clock since the wait began: the device's rate during it
    /// The pace of this session: planned time of the ops it closed against the running time
    /// it took. A pause does not end a session (the pause is not running time, and the pace
    /// before it still holds); a resume after a stop or from a log starts a new one.
    double m_plannedDoneS = 0;      ///< planned time of ops closed in this session
    double m_sessionStartS = 0;     ///< running time when this session's first op began
    QMetaObject::Connection m_events, m_link;
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::RunState)
