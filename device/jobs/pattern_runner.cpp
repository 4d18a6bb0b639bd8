#include "device/jobs/pattern_runner.h"

#include "motion/path/junction_planner.h"
#include "motion/plans/pattern.h"

#include <QCoreApplication>
#include <QPointer>

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using motion::path::Segment;
using motion::path::Vec2;

namespace {
motion::msg::Arg patternMm(const char* name, double v) { return motion::msg::real(name, v, motion::msg::Unit::Mm); }
motion::msg::Arg patternCount(const char* name, std::size_t v) { return motion::msg::integer(name, static_cast<long long>(v), motion::msg::Unit::None); }
}

const char* PatternRunner::stateTerm(State s)
{
    switch (s) {
    case State::Idle: return "pattern.state.idle";
    case State::Approaching: return "pattern.state.approaching";
    case State::Running: return "pattern.state.running";
    case State::Paused: return "pattern.state.paused";
    case State::Done: return "pattern.state.done";
    case State::Aborted: return "pattern.state.aborted";
    case State::Interrupted: return "pattern.state.interrupted";
    case State::Failed: return "pattern.state.failed";
    }
    return "pattern.state.idle";
}

PatternRunner::PatternRunner(dev::Instrument* client, QObject* parent) : QObject(parent), m_client(client)
{
    qRegisterMetaType<dev::jobs::PatternRunner::State>();
    qRegisterMetaType<dev::jobs::PatternRunSummary>();
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, [this] {
        if (m_state != State::Running || m_appendInFlight || !m_paths)
            return;
        m_paths->queryStatus([this](const auto& e, const dev::PathQueueState& s) {
            if (!e && m_state == State::Running && m_t0S < 0 && m_client && s.state != dev::proto::PathState::Idle
                && s.state != dev::proto::PathState::Filling)
                m_t0S = m_client->status().deviceTimeUs / 1e6;  // PATH_STARTED was lost: no later than this
            if (!e && m_state == State::Running && s.state == dev::proto::PathState::Done && m_sent >= m_path.size() && m_client) {
                // PATH_FINISHED was lost on the line (events are not retried): the
                // queue's state says it; the end is no later than this reading.
                onPathFinished(m_client->status().deviceTimeUs);
                return;
            }
            if (!e && m_state == State::Running && !m_appendInFlight) {
                m_free = s.freeSlots;
                m_done = std::max(m_done, static_cast<std::size_t>(s.executingIndex));
                pump();
            }
        });
    });
    connect(client, &dev::Instrument::statusChanged, this, &PatternRunner::onStatus);
    connect(client, &dev::Instrument::stateChanged, this, &PatternRunner::onLinkState);
    connect(client, &dev::Instrument::partsReplaced, this, &PatternRunner::attachPaths);
    attachPaths();
}

void PatternRunner::attachPaths()
{
    dev::PathClient* paths = m_client ? m_client->paths() : nullptr;
    if (paths == m_paths && (paths || m_pathConnections.isEmpty()))
        return;
    for (const auto& c : m_pathConnections)
        disconnect(c);
    m_pathConnections.clear();
    // Another backend took over (a reconnection that found another protocol): whatever
    // ran on the old one's queue is over.
    if (busy())
        interrupt(motion::msg::make("pattern.run.replaced"));
    m_paths = paths;
    if (!paths)
        return;
    m_pathConnections << connect(paths, &dev::PathClient::startedAt, this, [this](quint64 us) {
        if (busy() && m_t0S < 0)
            m_t0S = us / 1e6;
    });
    m_pathConnections << connect(paths, &dev::PathClient::segmentDone, this, [this](quint32 index) {
        if (m_state != State::Running && m_state != State::Paused)
            return;
        m_done = std::max(m_done, static_cast<std::size_t>(index) + 1);
        ++m_free;  // an estimate until the next answer says exactly
        emit progress(m_done, m_path.size());
        pump();
    });
    m_pathConnections << connect(paths, &dev::PathClient::underrun, this, [this](quint32) {
        if (m_state != State::Running)
            return;
        ++m_underruns;
        if (!m_underrunSaid)
            emit message(motion::msg::make("pattern.run.underrun"), true);
        m_underrunSaid = true;
    });
    m_pathConnections << connect(paths, &dev::PathClient::finished, this, [this](quint32, quint64 us) { onPathFinished(us); });
    m_pathConnections << connect(paths, &dev::PathClient::held, this, [this](quint32, const QString&) {
        if (m_state != State::Running)
            return;
        setState(State::Paused);
        if (!m_pauseAsked)
            m_paths->queryStatus([this](const auto&, const dev::PathQueueState& s) {
                emit message(motion::msg::make("pattern.run.held", {motion::msg::term("reason", dev::pathReasonTerm(s.reason))}), true);
            });
        m_pauseAsked = false;
    });
    m_pathConnections << connect(paths, &dev::PathClient::aborted, this, [this](quint32 index, const QString&) {
        if (!busy())
            return;
        m_done = std::max(m_done, static_cast<std::size_t>(index));
        if (m_abortAsked) {
            m_poll.stop();
            setState(State::Aborted);
            emit message(motion::msg::make("pattern.run.aborted", {patternCount("segment", index), patternCount("total", m_path.size())}), false);
            emit finished(summary());
            return;
        }
        m_paths->queryStatus([this, index](const auto&, const dev::PathQueueState& s) {
            interrupt(motion::msg::make("pattern.run.stopped_by_instrument",
                                {patternCount("segment", index), motion::msg::term("reason", dev::pathReasonTerm(s.reason))}));
        });
        setState(State::Interrupted);
    });
}

// ---- checks ------------------------------------------------------------------------

Vec2 PatternRunner::machineXy() const
{
    const auto& st = m_client->status();
    if (st.axes.size() < 2)
        return {};
    return {st.axes[0].commanded, st.axes[1].commanded};
}

std::vector<motion::msg::Message> PatternRunner::preflight(const std::vector<Segment>& path, const Options& options) const
{
    std::vector<motion::msg::Message> out;
    if (!m_client || !m_paths || !m_paths->available()) {
        out.push_back(motion::msg::make("pattern.run.no_path_queue"));
        return out;
    }
    const auto& id = m_client->identity();
    const auto& st = m_client->status();
    if (path.empty())
        out.push_back(motion::msg::make("pattern.run.no_segments"));
    if (st.estop)
        out.push_back(motion::msg::make("pattern.run.estop_active"));
    if (st.anyMoving())
        out.push_back(motion::msg::make("pattern.run.still_moving"));
    for (int i = 0; i < 2 && i < st.axes.size(); ++i)
        if (!st.axes[i].homed)
            out.push_back(motion::msg::make("pattern.run.not_homed", {motion::msg::verbatim("axis", QString(id.axes[i].letter).toStdString())}));
    const int z = id.axisIndex(QLatin1Char('Z'));
    if (options.zMm) {
        if (z < 0 || !m_client->capabilities().testFlag(dev::Capability::CoupledXyThenZ)) {
            out.push_back(motion::msg::make("pattern.run.no_z"));
        } else {
            if (!st.axes[z].homed)
                out.push_back(motion::msg::make("pattern.run.not_homed", {motion::msg::verbatim("axis", "Z")}));
            const auto& lim = m_client->softLimits()[z];
            if (*options.zMm < lim.min || *options.zMm > lim.max)
                out.push_back(motion::msg::make("pattern.run.z_outside_limits", {patternMm("value", *options.zMm), patternMm("min", lim.min), patternMm("max", lim.max)}));
        }
    }
    const double vmax = m_paths->limits().maxSpeedMmS;
    for (std::size_t k = 0; k < path.size(); ++k)
        if (path[k].feedMmS > vmax + 1e-9) {
            out.push_back(motion::msg::make("pattern.run.feed_too_high", {patternCount("segment", k), motion::msg::real("feed", path[k].feedMmS, motion::msg::Unit::MmPerS),
                                                                  motion::msg::real("max", vmax, motion::msg::Unit::MmPerS)}));
            break;
        }
    if (m_client->softLimits().size() >= 2 && !path.empty()) {
        const auto& lx = m_client->softLimits()[0];
        const auto& ly = m_client->softLimits()[1];
        if (auto v = motion::plans::outsideLimits(path, {lx.min, ly.min, lx.max, ly.max}))
            out.push_back(v->message);
    }
    return out;
}

double PatternRunner::approachDistanceMm(const std::vector<Segment>& path) const
{
    return path.empty() || !m_client ? 0.0 : motion::path::norm(path.front().start - machineXy());
}

double PatternRunner::estimatedS(const std::vector<Segment>& path) const
{
    return m_paths ? motion::plans::estimatedTimeS(path, m_paths->limits()) : 0.0;
}

// ---- run ---------------------------------------------------------------------------

void PatternRunner::onPathFinished(quint64 us)
{
    if (m_state != State::Running && m_state != State::Paused)
        return;
    m_done = m_path.size();
    m_endS = us / 1e6;
    m_poll.stop();
    emit progress(m_done, m_path.size());
    setState(State::Done);
    const PatternRunSummary s = summary();
    emit message(motion::msg::make("pattern.run.done", {motion::msg::real("duration", s.durationS, motion::msg::Unit::S),
                                                motion::msg::real("max", s.maxContourMm * 1e3, motion::msg::Unit::Um),
                                                motion::msg::real("rms", s.rmsContourMm * 1e3, motion::msg::Unit::Um),
                                                // The contour error is only as fine as its samples: how many, and at what
                                                // rate (a GRBL controller's status reports against a BenchPilot telemetry).
                                                patternCount("samples", static_cast<std::size_t>(s.samples)),
                                                motion::msg::integer("rate", m_client ? m_client->subscribedRateHz() : 0, motion::msg::Unit::Hz)}),
                 false);
    emit finished(s);
}

void PatternRunner::setState(State s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

void PatternRunner::fail(const motion::msg::Message& why) { fail(std::vector<motion::msg::Message>{why}); }

void PatternRunner::fail(const std::vector<motion::msg::Message>& why)
{
    m_poll.stop();
    m_arrived = nullptr;
    setState(State::Failed);
    for (const motion::msg::Message& m : why)
        emit message(m, true);
}

void PatternRunner::interrupt(const motion::msg::Message& why) { interrupt(std::vector<motion::msg::Message>{why}); }

void PatternRunner::interrupt(const std::vector<motion::msg::Message>& why)
{
    m_poll.stop();
    m_arrived = nullptr;
    m_appendInFlight = false;
    setState(State::Interrupted);
    for (const motion::msg::Message& m : why)
        emit message(m, true);
}

bool PatternRunner::start(std::vector<Segment> path, const Options& options)
{
    if (busy())
        return false;
    const std::vector<motion::msg::Message> problems = preflight(path, options);
    if (!problems.empty()) {
        fail(problems);
        return false;
    }
    m_path = std::move(path);
    m_options = options;
    // Estimated time left from the start of each segment, for the ETA.
    const auto est = motion::path::estimatePath(m_path, m_paths->limits());
    m_remainingS.assign(m_path.size() + 1, 0.0);
    for (std::size_t k = m_path.size(); k-- > 0;)
        m_remainingS[k] = m_remainingS[k + 1] + motion::path::blockDurationS(est.blocks[k], m_paths->limits().accelMmS2);
    m_tracker.emplace(m_path);
    m_samples.clear();
    m_thin = 1;
    m_seen = 0;
    m_sent = m_done = 0;
    m_underruns = 0;
    m_underrunSaid = false;
    m_t0S = m_endS = m_lastSeenS = -1;
    m_last.reset();
    m_pauseAsked = m_abortAsked = false;
    emit progress(0, m_path.size());
    approach(m_path.front().start, options.zMm.has_value(), [this] { beginAt(0, std::nullopt); });
    return true;
}

void PatternRunner::approach(Vec2 to, bool withZ, std::function<void()> then)
{
    setState(State::Approaching);
    if (motion::path::norm(to - machineXy()) < 1e-6 && !withZ) {
        then();
        return;
    }
    QVector<QPair<int, double>> targets = {{0, to.x}, {1, to.y}};
    const int z = m_client->identity().axisIndex(QLatin1Char('Z'));
    if (withZ && z >= 0)
        targets.push_back({z, *m_options.zMm});
    m_approachTo = to;
    m_approachPolls = 0;
    // The client keeps a callback until the device answers, which may be after this
    // object is gone (a window closed, a run dropped): it must not reach a dead one.
    const QPointer<PatternRunner> self(this);
    m_client->move(targets, false, m_options.approachSpeedMmS, [this, self, then](const std::optional<dev::RequestError>& e) {
        if (!self || m_state != State::Approaching)
            return;
        if (e)
            return fail(motion::msg::make("pattern.run.approach_refused", {motion::msg::nested("cause", e->message)}));
        m_arrived = then;  // onStatus() goes on once the machine is at rest there
    });
}

void PatternRunner::onStatus()
{
    if ((m_state == State::Running || m_state == State::Paused) && m_t0S >= 0)
        m_lastSeenS = std::max(m_lastSeenS, m_client->status().deviceTimeUs / 1e6);
    if (m_state != State::Approaching || !m_arrived)
        return;
    // The move's reply comes before the axes report moving: wait two polls before judging rest.
    if (++m_approachPolls < 3 || m_client->status().anyMoving())
        return;
    auto then = std::move(m_arrived);
    m_arrived = nullptr;
    if (motion::path::norm(m_approachTo - machineXy()) > 1e-3)
        return interrupt(motion::msg::make("pattern.run.approach_stopped"));
    then();
}

void PatternRunner::beginAt(std::size_t index, std::optional<Vec2> from)
{
    if (!m_paths)
        return;
    m_paths->begin(static_cast<quint32>(index), [this, index, from](const auto& e, const dev::PathQueueState& s) {
        if (m_state != State::Approaching && m_state != State::Running)
            return;
        if (e)
            return fail(motion::msg::make("pattern.run.refused", {motion::msg::nested("cause", e->message)}));
        m_sent = index;
        m_done = index;
        m_firstFrom = from;
        m_free = s.freeSlots;
        setState(State::Running);
        m_poll.start();
        pump();
    });
}

void PatternRunner::pump()
{
    if (m_state != State::Running || m_appendInFlight || !m_paths || m_sent >= m_path.size())
        return;
    const std::size_t remaining = m_path.size() - m_sent;
    const std::size_t room = static_cast<std::size_t>(std::max(0, std::min(m_free, m_paths->maxSegmentsPerAppend())));
    const std::size_t n = std::min(room, remaining);
    // Few large appends rather than many small ones: wait for a handful of free slots unless the
    // queue is running low or this is the end of the path.
    const std::size_t queued = m_sent - m_done;
    if (n == 0 || (n < std::min<std::size_t>(8, remaining) && queued > 4))
        return;
    std::vector<Segment> batch(m_path.begin() + static_cast<std::ptrdiff_t>(m_sent),
                               m_path.begin() + static_cast<std::ptrdiff_t>(m_sent + n));
    if (m_firstFrom) {
        batch.front().start = *m_firstFrom;  // a restart: the segment goes on from where the machine stopped
        m_firstFrom.reset();
    }
    m_appendInFlight = true;
    const bool last = m_sent + n == m_path.size();
    m_paths->append(static_cast<quint32>(m_sent), batch, true, last,
                    [this, n](const auto& e, const dev::PathQueueState& s) { onReply(e, s, n); });
}

void PatternRunner::onReply(const std::optional<dev::RequestError>& e, const dev::PathQueueState& s, std::size_t asked)
{
    m_appendInFlight = false;
    if (m_state != State::Running && m_state != State::Paused)
        return;
    if (!e) {
        m_sent += asked;
        m_free = s.freeSlots;
        m_done = std::max(m_done, static_cast<std::size_t>(s.executingIndex));
        pump();
        return;
    }
    if (e->kind == dev::RequestError::Kind::Device && e->code == dev::proto::ErrorCode::PathQueueFull) {
        m_free = static_cast<int>(e->value);  // wait for segments to complete
        return;
    }
    if (e->kind == dev::RequestError::Kind::Device && e->code == dev::proto::ErrorCode::PathSequence) {
        // An answer was lost and the device already has these: go on from where it is.
        m_sent = std::clamp<std::size_t>(static_cast<std::size_t>(e->value), m_done, m_path.size());
        pump();
        return;
    }
    if (e->kind == dev::RequestError::Kind::Device) {
        m_paths->clear();
        return fail(motion::msg::make("pattern.run.refused", {motion::msg::nested("cause", e->message)}));
    }
    // Link trouble: the link handler says what happened.
}

void PatternRunner::onLinkState(dev::LinkState s)
{
    if (s == dev::LinkState::Ready || s == dev::LinkState::Connecting || s == dev::LinkState::Identified)
        return;
    if (!busy())
        return;
    interrupt(motion::msg::make("pattern.run.link_lost", {patternCount("segment", m_done), patternCount("total", m_path.size())}));
}

void PatternRunner::pause()
{
    if (m_state == State::Running && m_paths) {
        m_pauseAsked = true;
        m_paths->hold();
    } else if (m_state == State::Approaching && m_client) {
        m_client->stop(0b11);
    }
}

void PatternRunner::resume()
{
    if (!m_paths || !m_client)
        return;
    if (m_state == State::Paused) {
        m_paths->resume([this](const auto& e) {
            if (!e && m_state == State::Paused) {
                setState(State::Running);
                pump();
            }
        });
        return;
    }
    if (m_state != State::Interrupted || m_path.empty())
        return;
    if (!m_paths->available())
        return emit message(motion::msg::make("pattern.run.reconnect_first"), true);
    m_paths->queryStatus([this](const auto& e, const dev::PathQueueState& s) {
        if (e || m_state != State::Interrupted)
            return;
        if (s.state == dev::proto::PathState::Held || s.state == dev::proto::PathState::Holding) {
            // Same path still on the device (the link came back before the device gave it up).
            m_sent = std::max<std::size_t>(m_done, s.nextIndex);
            m_free = s.freeSlots;
            setState(State::Paused);
            resume();
            return;
        }
        const std::size_t k = std::min(m_path.size() - 1, std::max(m_done, static_cast<std::size_t>(s.executingIndex)));
        m_done = k;
        const std::vector<motion::msg::Message> problems = preflight({m_path.begin() + static_cast<std::ptrdiff_t>(k), m_path.end()}, m_options);
        if (!problems.empty())
            return interrupt(problems);
        m_abortAsked = m_pauseAsked = false;
        const Vec2 here = machineXy();
        const auto near = motion::path::nearestOn(m_path[k], here);
        const bool onIt = std::fabs(near.distanceMm) < kOnPathMm && near.alongMm < motion::path::lengthMm(m_path[k]);
        emit message(motion::msg::make("pattern.run.continuing", {patternCount("segment", k)}), false);
        m_tracker->seek(k);
        setState(State::Approaching);
        if (onIt)
            beginAt(k, here);
        else
            approach(m_path[k].start, m_options.zMm.has_value(), [this, k] { beginAt(k, std::nullopt); });
    });
}

void PatternRunner::abort()
{
    if (m_state == State::Approaching) {
        m_arrived = nullptr;
        if (m_client)
            m_client->stop(0);
        setState(State::Aborted);
        emit finished(summary());
        return;
    }
    if ((m_state == State::Running || m_state == State::Paused) && m_paths) {
        m_abortAsked = true;
        m_paths->clear();
        return;
    }
    if (m_state == State::Interrupted) {
        setState(State::Aborted);
        emit finished(summary());
    }
}

// ---- measurement -------------------------------------------------------------------

void PatternRunner::addSample(double deviceTimeS, Vec2 commanded, Vec2 measured)
{
    // Judged only while the path itself runs (from its first start to its end); the approach
    // is a positioning move, not part of the pattern.
    if (!m_tracker || m_t0S < 0 || deviceTimeS < m_t0S || (m_endS >= 0 && deviceTimeS > m_endS))
        return;
    if (m_state != State::Running && m_state != State::Paused && m_state != State::Done)
        return;
    const motion::path::ContourSample c = m_tracker->add(measured);
    PatternRunSample s{deviceTimeS - m_t0S, commanded, measured, c.pathMm, c.errorMm, c.segment};
    m_last = s;
    if (m_seen++ % m_thin == 0) {
        if (m_samples.size() >= kMaxStoredSamples) {
            // Bounded: halve the stored resolution, keep the whole run.
            std::vector<PatternRunSample> kept;
            kept.reserve(m_samples.size() / 2 + 1);
            for (std::size_t i = 0; i < m_samples.size(); i += 2)
                kept.push_back(m_samples[i]);
            m_samples.swap(kept);
            m_thin *= 2;
        }
        m_samples.push_back(s);
    }
    emit sampleAdded(s);
}

double PatternRunner::pathDoneMm() const
{
    const double done = m_tracker ? m_tracker->startOfMm(m_done) : 0.0;
    return m_last ? std::max(done, m_last->pathMm) : done;
}

std::size_t PatternRunner::currentSegment() const
{
    std::size_t k = m_last ? std::max(m_done, m_last->segment) : m_done;
    return m_path.empty() ? 0 : std::min(k, m_path.size() - 1);
}

double PatternRunner::remainingS() const
{
    return m_done < m_remainingS.size() ? m_remainingS[m_done] : 0.0;
}

PatternRunSummary PatternRunner::summary() const
{
    PatternRunSummary s;
    if (m_tracker) {
        const auto& t = m_tracker->summary();
        s.samples = t.samples;
        s.maxContourMm = t.maxAbsMm;
        s.rmsContourMm = t.rmsMm;
        s.maxAtPathMm = t.atPathMm;
    }
    // A run that did not reach its end (aborted, interrupted, link lost) lasted until the
    // last device time it was seen running (a sample or a status reading), not 0 s.
    const double seenS = m_t0S >= 0 && m_lastSeenS >= m_t0S ? m_lastSeenS - m_t0S : 0.0;
    s.durationS = m_t0S >= 0 && m_endS >= m_t0S ? m_endS - m_t0S : std::max(m_last ? m_last->tS : 0.0, seenS);
    s.underruns = m_underruns;
    s.complete = m_state == State::Done;
    return s;
}

} // namespace dev::jobs
