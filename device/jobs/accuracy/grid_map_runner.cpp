// The grid map runner's motion: the start, the nodes, arrival and dwell on the device's
// clock, readings. The run log and the results are in grid_map_runner_files.cpp.
#include "device/jobs/accuracy/grid_map_runner.h"

#include "device/files/json.h"

#include <cmath>

namespace dev::jobs {

namespace {
/// Wall-clock interval between status readings while dwelling.
constexpr int kGridPollMs = 10;

/// The log names a reading by its node on the grid and its pass, not by the order it
/// was taken in: a log says what it holds without the plan beside it.
std::string nodeLine(const motion::metrology::GridMapStop& s, int columns, const GridNodeReading& n)
{
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("node", static_cast<double>(s.node(columns)));
    if (s.reverse)
        v.set("pass", dev::files::json::Value(std::string("reverse")));
    if (n.read) {
        v.set("measured_x_mm", n.measuredXMm);
        v.set("measured_y_mm", n.measuredYMm);
    } else {
        v.set("failed", dev::files::json::Value(n.failure));
        if (!n.image.empty())
            v.set("image", dev::files::json::Value(n.image));
    }
    return dev::files::json::write(v, false) + "\n";
}
} // namespace

GridMapRunner::GridMapRunner(dev::Instrument* instrument, QObject* parent) : QObject(parent), m_instrument(instrument)
{
    qRegisterMetaType<dev::jobs::GridMapRunner::State>();
    m_poll.setSingleShot(true);
    connect(&m_poll, &QTimer::timeout, this, &GridMapRunner::pollDwell);
    if (!instrument)
        return;
    m_connections << connect(instrument, &dev::Instrument::eventReceived, this, &GridMapRunner::onEvent);
    m_connections << connect(instrument, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (isActive() && s != dev::LinkState::Ready)
            stopWith(motion::msg::make("accuracy.run.link_lost"), false);
    });
    m_connections << connect(instrument, &dev::Instrument::statusChanged, this, [this](const dev::InstrumentStatus& s) {
        const bool moving = m_phase == Phase::LeadIn || m_phase == Phase::Target;
        if (!isActive() || !moving || !m_moveAccepted || m_waitingAxes == 0)
            return;
        quint64 restUs = 0;
        if (!m_arrival.feed(s, &restUs))
            return;
        m_waitingAxes = 0;
        m_arrivedUs = std::max<quint64>(m_arrivedUs, restUs);
        onArrived();
    });
}

GridMapRunner::~GridMapRunner()
{
    for (const auto& c : m_connections)
        disconnect(c);
    if (m_source && isActive())
        m_source->cancel();
}

const char* GridMapRunner::stateName(State s)
{
    switch (s) {
    case State::Idle: return "idle";
    case State::Running: return "running";
    case State::Stopped: return "stopped";
    case State::Finished: return "finished";
    }
    return "idle";
}

void GridMapRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

quint8 GridMapRunner::axisMask() const { return static_cast<quint8>((1u << m_axisX) | (1u << m_axisY)); }

int GridMapRunner::nodesRead() const
{
    int n = 0;
    for (const auto& r : m_nodes)
        n += r.read ? 1 : 0;
    return n;
}

int GridMapRunner::nodesFailed() const
{
    int n = 0;
    for (const auto& r : m_nodes)
        n += !r.read && !r.failure.empty() ? 1 : 0;
    return n;
}

bool GridMapRunner::start(motion::msg::Message* why)
{
    auto refuse = [&](motion::msg::Message m) {
        if (why)
            *why = m;
        emit problem(m);
        return false;
    };
    if (!m_prepared)
        return refuse(motion::msg::make("accuracy.run.not_prepared"));
    if (isActive())
        return refuse(motion::msg::make("accuracy.run.busy"));
    if (m_state == State::Finished && nodesRead() == totalNodes())
        return refuse(motion::msg::make("accuracy.run.finished_already"));
    if (!m_instrument || !m_instrument->isReady())
        return refuse(motion::msg::make("accuracy.run.not_connected"));
    const dev::InstrumentStatus& st = m_instrument->status();
    if (st.estop)
        return refuse(motion::msg::make("accuracy.run.estop"));
    for (int a : {m_axisX, m_axisY})
        if (a >= st.axes.size() || !st.axes[a].homed)
            return refuse(motion::msg::make("accuracy.run.not_homed",
                                            {motion::msg::verbatim("axis", QString(m_instrument->identity().axes[a].letter).toStdString())}));
    ++m_generation;
    m_previous = -1;
    // A new session tries again the nodes that failed in the last one.
    for (auto& n : m_nodes)
        if (!n.read)
            n = {};
    setState(State::Running);
    if (!m_haveStart)
        locateStart();
    else
        nextNode();
    return true;
}

void GridMapRunner::abort()
{
    if (isActive())
        stopWith(motion::msg::make("accuracy.run.aborted"), true);
}

void GridMapRunner::stopWith(const motion::msg::Message& why, bool stopAxes)
{
    ++m_generation;  // every callback in flight is now stale
    m_poll.stop();
    if (m_source)
        m_source->cancel();
    if (stopAxes && m_instrument && m_instrument->isReady())
        m_instrument->stop(axisMask());
    m_phase = Phase::None;
    m_waitingAxes = 0;
    setState(State::Stopped);
    emit problem(why);
}

void GridMapRunner::locateStart()
{
    // The dot under the camera where the stage stands: its reading says where the work
    // point is against a dot taken to sit at the stage's own reading, so the dot is as
    // far the other way.
    m_phase = Phase::Locating;
    const dev::InstrumentStatus& st = m_instrument->status();
    StopContext ctx;
    ctx.index = -1;
    ctx.total = totalNodes();
    ctx.axes = {m_axisX, m_axisY};
    ctx.letters = {QLatin1Char('X'), QLatin1Char('Y')};
    ctx.targetsMm = {st.axes[m_axisX].measured, st.axes[m_axisY].measured};
    ctx.deviceTimeUs = st.deviceTimeUs;
    const quint64 generation = m_generation;
    const QPointer<GridMapRunner> self(this);
    const std::vector<double> at = ctx.targetsMm;
    m_source->take(ctx, [self, generation, at](const TakeResult& r) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        TakeResult located = r;
        if (r.problem.empty() && r.valuesMm.size() == 2)
            located.valuesMm = {2 * at[0] - r.valuesMm[0], 2 * at[1] - r.valuesMm[1]};
        self->onStartFound(located);
    });
}

void GridMapRunner::onStartFound(const TakeResult& r)
{
    if (!r.problem.empty() || r.valuesMm.size() != 2) {
        stopWith(motion::msg::make("grid.run.no_start_dot", {motion::msg::nested("cause", r.problem)}), false);
        return;
    }
    const double x = r.valuesMm[0], y = r.valuesMm[1];
    const auto& lim = m_instrument->softLimits();
    if (m_axisX < lim.size() && m_axisY < lim.size()) {
        const auto travel = motion::metrology::validateTravel(m_test, x, y, lim[m_axisX].min, lim[m_axisX].max, lim[m_axisY].min,
                                                              lim[m_axisY].max);
        if (!travel.empty()) {
            stopWith(motion::msg::make("grid.run.start_leaves_travel", {motion::msg::real("x", x, motion::msg::Unit::Mm),
                                                                        motion::msg::real("y", y, motion::msg::Unit::Mm),
                                                                        motion::msg::nested("detail", travel.front().message)}),
                     false);
            return;
        }
    }
    dev::files::json::Value v = dev::files::json::Value::object();
    v.set("start_x_mm", x);
    v.set("start_y_mm", y);
    if (!appendLog(dev::files::json::write(v, false) + "\n"))
        return;
    m_haveStart = true;
    m_startXMm = x;
    m_startYMm = y;
    m_stops = motion::metrology::planGridMap(m_test, x, y);
    m_nodes.assign(m_stops.size(), {});
    nextNode();
}

int GridMapRunner::nextUnread() const
{
    for (std::size_t k = 0; k < m_nodes.size(); ++k)
        if (!m_nodes[k].read && m_nodes[k].failure.empty())
            return static_cast<int>(k);
    return -1;
}

void GridMapRunner::nextNode()
{
    if (!isActive())
        return;
    const int k = nextUnread();
    emit progress(nodesRead() + nodesFailed(), totalNodes());
    if (k < 0) {
        finish();
        return;
    }
    m_current = k;
    const auto& s = m_stops[static_cast<std::size_t>(k)];
    // From one side on both axes (below in the forward pass, above in the reverse): the
    // lost motion is then the same at every node of a pass. Within a row only X moves,
    // on towards the next node, so Y keeps the side of the row's lead-in. A node that
    // does not follow the last one visited (the first of a session, one tried again
    // after nodes already read) is led in whatever its place in the row.
    if (s.leadIn || k != m_previous + 1) {
        const double a = s.approachSide() * m_test.approachMm;
        moveTo(s.xMm + a, s.yMm + a, Phase::LeadIn);
    } else
        moveTo(s.xMm, s.yMm, Phase::Target);
    m_previous = k;
}

void GridMapRunner::moveTo(double xMm, double yMm, Phase phase)
{
    m_phase = phase;
    m_moveAccepted = false;
    m_arrivedUs = 0;
    m_waitingAxes = axisMask();
    m_arrival.expect({{m_axisX, xMm}, {m_axisY, yMm}});
    const quint64 generation = m_generation;
    const QPointer<GridMapRunner> self(this);
    m_instrument->move({{m_axisX, xMm}, {m_axisY, yMm}}, false, m_test.feedMmS, [self, generation](const std::optional<dev::RequestError>& e) {
        if (self)
            self->onMoveAccepted(e, generation);
    });
}

void GridMapRunner::onMoveAccepted(const std::optional<dev::RequestError>& error, quint64 generation)
{
    if (generation != m_generation || !isActive())
        return;
    if (error) {
        stopWith(motion::msg::make("accuracy.run.move_refused", {motion::msg::nested("detail", error->message)}), false);
        return;
    }
    m_moveAccepted = true;
    if (m_waitingAxes == 0)
        onArrived();  // the MotionDone events came before the reply
}

void GridMapRunner::onEvent(const dev::DeviceEvent& e)
{
    if (!isActive())
        return;
    if (e.kind == dev::proto::EventKind::EStop) {
        stopWith(motion::msg::make("accuracy.run.estop"), false);
        return;
    }
    const bool ours = e.axis >= 0 && (axisMask() & (1u << e.axis));
    if (!ours || !(m_phase == Phase::LeadIn || m_phase == Phase::Target))
        return;
    if (e.kind == dev::proto::EventKind::MotionDone) {
        m_waitingAxes &= ~(1u << e.axis);
        m_arrivedUs = std::max<quint64>(m_arrivedUs, e.deviceTimeUs);
        if (m_waitingAxes == 0 && m_moveAccepted)
            onArrived();
        return;
    }
    if (e.kind == dev::proto::EventKind::Stopped || e.kind == dev::proto::EventKind::LimitHit || e.kind == dev::proto::EventKind::Fault
        || e.kind == dev::proto::EventKind::LostSteps) {
        const QString letter = e.axis < m_instrument->identity().axes.size() ? QString(m_instrument->identity().axes[e.axis].letter) : QString();
        stopWith(motion::msg::make("accuracy.run.axis_stopped", {motion::msg::verbatim("axis", letter.toStdString()),
                                                                 motion::msg::term("event", dev::proto::eventKindTerm(e.kind)), dev::eventDetail(e)}),
                 e.kind == dev::proto::EventKind::LostSteps);
    }
}

void GridMapRunner::onArrived()
{
    if (m_phase == Phase::LeadIn) {
        const auto& s = m_stops[static_cast<std::size_t>(m_current)];
        moveTo(s.xMm, s.yMm, Phase::Target);
        return;
    }
    m_phase = Phase::Dwell;
    pollDwell();
}

void GridMapRunner::pollDwell()
{
    if (!isActive() || m_phase != Phase::Dwell)
        return;
    const quint64 generation = m_generation;
    const QPointer<GridMapRunner> self(this);
    m_instrument->readStatus([self, generation](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        if (e) {
            self->stopWith(motion::msg::make("accuracy.run.status_failed", {motion::msg::nested("detail", e->message)}), false);
            return;
        }
        if (s.estop) {
            self->stopWith(motion::msg::make("accuracy.run.estop"), false);
            return;
        }
        const quint64 until = self->m_arrivedUs + static_cast<quint64>(std::llround(self->m_test.dwellS * 1e6));
        if (s.deviceTimeUs < until) {
            self->m_poll.start(kGridPollMs);
            return;
        }
        self->takeReading();
    });
}

void GridMapRunner::takeReading()
{
    m_phase = Phase::Reading;
    const int k = m_current;
    const auto& s = m_stops[static_cast<std::size_t>(k)];
    StopContext ctx;
    ctx.index = k;
    ctx.total = totalNodes();
    ctx.axes = {m_axisX, m_axisY};
    ctx.letters = {QLatin1Char('X'), QLatin1Char('Y')};
    ctx.targetsMm = {s.xMm, s.yMm};
    const quint64 generation = m_generation;
    const QPointer<GridMapRunner> self(this);
    m_source->take(ctx, [self, generation, k](const TakeResult& r) {
        if (!self || generation != self->m_generation || !self->isActive())
            return;
        self->onReading(k, r);
    });
}

void GridMapRunner::onReading(int k, const TakeResult& r)
{
    GridNodeReading n;
    motion::msg::Message failure;
    if (!r.problem.empty()) {
        failure = r.problem;
    } else if (r.valuesMm.size() != 2) {
        failure = motion::msg::make("accuracy.run.reading_incomplete", {motion::msg::integer("count", static_cast<long long>(r.valuesMm.size())),
                                                                        motion::msg::integer("expected", 2)});
    }
    if (failure.empty()) {
        n.read = true;
        n.measuredXMm = r.valuesMm[0];
        n.measuredYMm = r.valuesMm[1];
    } else {
        n.failure = failure.id;
        n.image = failure.text("file");
    }
    if (!appendLog(nodeLine(m_stops[static_cast<std::size_t>(k)], m_test.columns, n)))
        return;  // appendLog stopped the run with its reason
    m_nodes[static_cast<std::size_t>(k)] = n;
    m_phase = Phase::None;
    if (!n.read) {
        const auto& s = m_stops[static_cast<std::size_t>(k)];
        const motion::msg::Message why = motion::msg::make("grid.run.node_failed", {motion::msg::integer("node", s.node(m_test.columns) + 1),
                                                                                    motion::msg::integer("column", s.column + 1),
                                                                                    motion::msg::integer("row", s.row + 1),
                                                                                    motion::msg::nested("cause", failure)});
        emit nodeFailed(k, why);
        if (m_test.stopOnFailure) {
            stopWith(why, false);
            return;
        }
    } else {
        emit nodeRead(k);
    }
    nextNode();
}

} // namespace dev::jobs
