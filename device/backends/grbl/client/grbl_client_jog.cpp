// GrblClient, part 6: continuous jog and the joystick (the jogging document's method, with the
// promises of grbl_jog.h). Held axes (startJog) and the joystick's velocities (setJogVelocities)
// add up to one velocity vector over GRBL's axes; while it is not zero, short $J segments are
// kept a little ahead of the machine — topped up on a timer and on every jog line's ok — and a
// change of direction or speed changes the segments that follow. On release, 0x85 at once.
//
// A $J line that was still in GRBL's serial buffer when 0x85 arrived is read after the cancel
// (GRBL's main loop is suspended while it decelerates) and starts a new jog. So the client
// counts jog lines not yet acknowledged at the cancel, and when the last of them is answered,
// sends 0x85 once more: the leftover is at most a few short segments, stopped within the budget.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/grbl_gcode.h"

#include <QPointer>

#include <cmath>

namespace dev {

namespace {
/// The joystick's velocities stand this many refresh periods without renewal.
constexpr int kStickRenewalPeriods = 4;
} // namespace

int GrblClient::jogRefreshMs() const { return std::max(5, static_cast<int>(std::lround(m_profile.jog.refreshS * 1000))); }

bool GrblClient::isJogging(int axis) const
{
    if (m_jogs.held.contains(axis))
        return true;
    const auto it = m_jogs.stick.find(axis);
    return it != m_jogs.stick.end() && it->second != 0;
}

void GrblClient::startJog(int axis, double velocity)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(velocity) || !isReady())
        return;
    m_jogs.refusedSaid = false;
    m_jogs.held[axis] = velocity;
    updateJog();
}

void GrblClient::stopJog(int axis)
{
    if (!m_jogs.held.remove(axis))
        return;
    updateJog();
}

void GrblClient::stopAllJogs()
{
    if (m_jogs.held.isEmpty() && m_jogs.stick.empty() && !m_jogs.run)
        return;
    m_jogs.held.clear();
    m_jogs.stick.clear();
    updateJog();
}

void GrblClient::setJogVelocities(const std::map<int, double>& velocities, Callback done)
{
    for (const auto& [axis, v] : velocities)
        if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(v)) {
            refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.jog_invalid"));
            return;
        }
    if (!isReady()) {
        refuse(done, RequestError::Kind::LinkDown, motion::msg::make("request.not_sent", {motion::msg::term("request", "request.jog")}));
        return;
    }
    for (const auto& [axis, v] : velocities) {
        if (v == 0)
            m_jogs.stick.erase(axis);
        else
            m_jogs.stick[axis] = v;
    }
    if (!m_jogs.stick.empty())
        m_jogs.refusedSaid = false;
    m_jogs.stickDeadlineMs = m_clock.elapsed() + kStickRenewalPeriods * jogRefreshMs();
    updateJog();
    if (done)
        done(std::nullopt);
}

std::map<int, double> GrblClient::wantedJogVelocities() const
{
    std::map<int, double> v(m_jogs.stick.begin(), m_jogs.stick.end());
    for (auto it = m_jogs.held.cbegin(); it != m_jogs.held.cend(); ++it)
        v[it.key()] = it.value();
    return v;
}

void GrblClient::updateJog()
{
    if (m_phase != Phase::Ready)
        return;
    // The wanted velocity per GRBL axis, mm/s.
    std::vector<double> vMmS(m_controller.limits.axes.size(), 0.0);
    for (const auto& [axis, v] : wantedJogVelocities()) {
        const int g = grblIndexOf(axis);
        if (g >= 0 && g < static_cast<int>(vMmS.size()))
            vMmS[static_cast<std::size_t>(g)] = v / scaleOf(axis);
    }
    double speed = 0;
    for (const double v : vMmS)
        speed += v * v;
    speed = std::sqrt(speed);
    if (speed == 0) {
        if (m_jogs.run)
            cancelJog();
        if (!m_jogs.cancelling)
            m_jogTimer.stop();
        return;
    }
    if (m_jogs.cancelling)
        return;  // starts once the cancel has run out (onStatusReport calls back)
    if (m_jogs.run && m_jogs.velocityMmS == vMmS)
        return;
    // Along the jog direction: the slowest axis' rate and acceleration bound the jog's.
    std::vector<double> rates, accels;
    for (const auto& l : m_controller.limits.axes) {
        rates.push_back(l.maxRateMmS);
        accels.push_back(l.accelMmS2);
    }
    const auto [vmax, amax] = dev::grbl::jogLimitsAlong(vMmS, rates, accels);
    dev::grbl::JogPlanInput in;
    in.speedMmS = speed;
    in.maxRateMmS = vmax;
    in.accelMmS2 = amax;
    in.plannerBlocks = m_controller.build.plannerBlocksOrDefault();
    in.refreshPeriodS = m_profile.jog.refreshS;
    in.linkLatencyS = m_profile.jog.linkLatencyS;
    in.stopBudgetS = m_profile.jog.stopBudgetS;
    const dev::grbl::JogPlan plan = dev::grbl::planContinuousJog(in);
    if (!plan.feasible) {
        m_jogs.held.clear();
        m_jogs.stick.clear();
        RequestError e;
        e.kind = RequestError::Kind::Invalid;
        e.message = plan.problem;  // grbl.jog.budget_too_small{budget, latency, refresh}
        e.message.args.push_back(motion::msg::term("request", "request.jog"));
        emit requestFailed(e);
        return;
    }
    std::vector<double> unit(vMmS);
    for (double& u : unit)
        u /= speed;
    const std::string letters = axisLettersOfController();
    if (plan.speedLimited)
        note(motion::msg::make("grbl.jog.speed_limited", {motion::msg::real("asked", speed, motion::msg::Unit::MmPerS), motion::msg::real("speed", plan.speedMmS, motion::msg::Unit::MmPerS),
                                                  motion::msg::real("budget", in.stopBudgetS, motion::msg::Unit::S)}));
    m_jogs.velocityMmS = vMmS;
    if (m_jogs.run && m_jogs.run->active()) {
        m_jogs.run->retarget(plan, letters, unit);
        topUpJog();
        return;
    }
    m_jogs.run.emplace(plan, letters, unit);
    sendJogLines(m_jogs.run->start(m_clock.elapsed() / 1000.0));
    m_jogTimer.start();
}

void GrblClient::topUpJog()
{
    if (!m_jogs.stick.empty() && m_clock.elapsed() > m_jogs.stickDeadlineMs) {
        m_jogs.stick.clear();
        updateJog();
        return;
    }
    if (!m_jogs.run || !m_jogs.run->active() || m_jogs.cancelling)
        return;
    sendJogLines(m_jogs.run->tick(m_clock.elapsed() / 1000.0));
}

void GrblClient::sendJogLines(const std::vector<std::string>& lines)
{
    const QPointer<GrblClient> self(this);
    for (const auto& line : lines) {
        ++m_jogs.lines.open;
        auto tagHolder = std::make_shared<std::uint64_t>(0);
        const std::uint64_t tag = queueLine(line, [self, tagHolder](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            self->m_jogs.lines.tags.erase(*tagHolder);
            self->m_jogs.lines.open = std::max(0, self->m_jogs.lines.open - 1);
            if (a && !a->ok) {
                // error:15 at the travel's end, error:8 while something else runs: the hold ends
                // here, said once.
                const bool say = !self->m_jogs.refusedSaid;
                self->m_jogs.refusedSaid = true;
                self->m_jogs.held.clear();
                self->m_jogs.stick.clear();
                if (self->m_jogs.run)
                    self->cancelJog();
                if (say)
                    emit self->requestFailed(errorOf(a->errorCode, a->line, "request.jog"));
            }
            if (self->m_jogs.cancelling) {
                // The last jog line that was in flight at the cancel: if GRBL read it after the
                // cancel it is jogging again — cancel once more.
                if (self->m_jogs.linesAtCancel > 0 && self->m_jogs.lines.open == 0) {
                    self->m_jogs.linesAtCancel = 0;
                    self->m_jogs.cancelSentUs = self->nowUs();
                    self->sendRealtime(dev::grbl::rt::kJogCancel);
                    self->sendQuery();
                }
                return;
            }
            if (a && a->ok)
                self->topUpJog();  // GRBL planned a segment: room for the next
        });
        if (!tag) {
            --m_jogs.lines.open;
            break;
        }
        *tagHolder = tag;
        m_jogs.lines.tags.insert(tag);
    }
}

void GrblClient::cancelJog()
{
    if (m_jogs.run)
        m_jogs.run->stop();
    m_jogs.run.reset();
    m_jogs.velocityMmS.clear();
    // Segments not written yet are dropped here; those already in GRBL's buffer are counted.
    auto isJog = [this](std::uint64_t tag) { return m_jogs.lines.tags.count(tag) != 0; };
    std::vector<std::uint64_t> dropped = m_lines.streamer.removeQueued(isJog);
    for (auto it = m_lines.backlog.begin(); it != m_lines.backlog.end();) {
        if (isJog(it->second)) {
            dropped.push_back(it->second);
            it = m_lines.backlog.erase(it);
        } else {
            ++it;
        }
    }
    for (const std::uint64_t tag : dropped) {
        m_lines.pending.erase(tag);
        m_jogs.lines.tags.erase(tag);
    }
    m_jogs.lines.open = static_cast<int>(m_jogs.lines.tags.size());
    m_jogs.cancelling = true;
    m_jogs.linesAtCancel = m_jogs.lines.open;
    m_jogs.cancelSentUs = nowUs();
    sendRealtime(dev::grbl::rt::kJogCancel);
    sendQuery();
}

} // namespace dev
