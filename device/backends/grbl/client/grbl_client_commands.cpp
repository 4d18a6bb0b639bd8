// GrblClient, part 5: the commands a person gives, as GRBL lines and realtime bytes. Each checks
// its arguments (and what the host knows: an established position, the machine travel) before
// anything is sent; a refusal from the controller comes back with its documented meaning and
// the line it answers.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/grbl_gcode.h"

#include <QPointer>

#include <cmath>

namespace dev {

namespace {

constexpr double kTravelToleranceMm = 1e-4;
/// How long home() waits for an immediate refusal (error:5 homing disabled, error:8 busy)
/// before it reports the homing as accepted: GRBL answers $H only when homing ends.
constexpr int kHomeAcceptMs = 500;

RequestError refusal(RequestError::Kind kind, motion::msg::Message message, dev::proto::ErrorCode code = dev::proto::ErrorCode::BadPayload)
{
    RequestError e;
    e.kind = kind;
    e.code = code;
    e.message = std::move(message);
    return e;
}

/// request.not_sent{request}: the link is not up.
RequestError notSent(const char* request)
{
    return refusal(RequestError::Kind::LinkDown, motion::msg::make("request.not_sent", {motion::msg::term("request", request)}));
}

/// request.abandoned{request, cause}: its lines were lost (a reset, a dropped link).
motion::msg::Message abandoned(const std::string& request, const motion::msg::Message& cause)
{
    return motion::msg::make("request.abandoned", {motion::msg::term("request", request), motion::msg::nested("cause", cause)});
}

/// grbl.estop_latched{request}.
RequestError estopLatched(const char* request)
{
    return refusal(RequestError::Kind::Device, motion::msg::make("grbl.estop_latched", {motion::msg::term("request", request)}), dev::proto::ErrorCode::EStopActive);
}

/// A line GRBL would not take (grbl.gcode.*), with the request it was for.
RequestError notGcode(motion::msg::Message problem, const char* request)
{
    problem.args.push_back(motion::msg::term("request", request));
    return refusal(RequestError::Kind::Invalid, std::move(problem));
}

} // namespace

/// A command's refusal: emitted and handed to its callback.
#define GRBL_REFUSE(done, error)            \
    do {                                    \
        const RequestError e_ = (error);    \
        emit requestFailed(e_);             \
        if (done)                           \
            (done)(e_);                     \
        return;                             \
    } while (false)

std::optional<RequestError> GrblClient::checkTarget(int axis, double target) const
{
    if (!established(axis))
        return std::nullopt;  // no anchored travel to check against
    const SoftLimits& s = m_softLimits[axis];
    const double tol = kTravelToleranceMm * scaleOf(axis);
    if (target >= s.min - tol && target <= s.max + tol)
        return std::nullopt;
    const auto g = grblIndexOf(axis);
    const motion::msg::Unit unit = unitOf(axis);
    RequestError e = refusal(RequestError::Kind::Device,
                             motion::msg::make("grbl.beyond_travel", {motion::msg::verbatim("axis", QString(m_identity.axes[axis].letter).toStdString()),
                                                              motion::msg::real("target", target, unit), motion::msg::real("min", s.min, unit),
                                                              motion::msg::real("max", s.max, unit),
                                                              motion::msg::integer("setting", dev::grbl::setting::kMaxTravelMmX + g, motion::msg::Unit::None)}),
                             dev::proto::ErrorCode::SoftLimit);
    e.axis = axis;
    e.value = target;
    return e;
}

void GrblClient::sendMotionLines(const std::vector<std::string>& lines, quint8 axes, const std::string& request, Callback done)
{
    struct Progress {
        std::size_t remaining;
        bool finished = false;
    };
    auto progress = std::make_shared<Progress>(Progress{lines.size()});
    const QPointer<GrblClient> self(this);
    m_motion.axes |= axes;
    for (const std::string& line : lines) {
        ++m_motion.linesOpen;
        const bool queued = queueLine(line, [self, progress, request, done](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            self->m_motion.linesOpen = std::max(0, self->m_motion.linesOpen - 1);
            self->m_motion.ackUs = self->nowUs();
            if (progress->finished)
                return;
            if (!a || !a->ok) {
                progress->finished = true;
                const RequestError e = a ? errorOf(a->errorCode, a->line, request)
                                         : refusal(self->isReady() ? RequestError::Kind::Device : RequestError::Kind::LinkDown,
                                                   abandoned(request, self->m_lines.lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            if (--progress->remaining == 0) {
                progress->finished = true;
                if (done)
                    done(std::nullopt);
            }
        });
        if (!queued) {
            --m_motion.linesOpen;
            if (!progress->finished) {
                progress->finished = true;
                GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.line_not_sent", {motion::msg::term("request", request), motion::msg::verbatim("line", line)})));
            }
            return;
        }
    }
}

// ---- home, unlock, zero ---------------------------------------------------------------------

void GrblClient::home(quint8 axisMask, Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.home"));
    if (m_estopLatched)
        GRBL_REFUSE(done, estopLatched("request.home"));
    // GRBL homes its axes together ($H); a single-axis $HX exists only in some builds.
    const quint32 all = (1u << m_map.size()) - 1;
    std::string line = "$H";
    if (axisMask != 0 && (axisMask & all) != all) {
        for (int i = 0; i < m_map.size(); ++i)
            if ((axisMask >> i) & 1u)
                line.push_back(grblLetterOf(i));
        if (line.size() != 3)
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.home_one_or_all", {motion::msg::verbatim("axes", line.substr(2))})));
    }
    struct Answer {
        bool replied = false;
    };
    auto answer = std::make_shared<Answer>();
    auto reply = [answer, done](const std::optional<RequestError>& e) {
        if (answer->replied)
            return;
        answer->replied = true;
        if (done)
            done(e);
    };
    m_machine.homing = true;
    const QPointer<GrblClient> self(this);
    const quint32 homedMask = axisMask == 0 ? all : (axisMask & all);
    const bool queued = queueLine(line, [self, reply, homedMask, line](const std::optional<dev::grbl::Streamer::Ack>& a) {
        if (!self)
            return;
        self->m_machine.homing = false;
        if (!a || !a->ok) {
            const RequestError e = a ? errorOf(a->errorCode, a->line, "request.home") : refusal(RequestError::Kind::Device, abandoned("request.home", self->m_lines.lostReason));
            emit self->requestFailed(e);
            reply(e);
            return;
        }
        self->m_positions.established |= homedMask;
        self->m_machine.alarm = 0;
        self->m_motion.homedAxes |= homedMask;
        self->m_motion.homedAckUs = self->nowUs();
        reply(std::nullopt);
        self->sendQuery();
    });
    if (!queued) {
        m_machine.homing = false;
        GRBL_REFUSE(done, notSent("request.home"));
    }
    // No refusal in the first moments means GRBL is homing: say "accepted" as other backends do.
    QTimer::singleShot(kHomeAcceptMs, this, [reply] { reply(std::nullopt); });
}

void GrblClient::unlock(Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, notSent("grbl.request.unlock"));
    const QPointer<GrblClient> self(this);
    auto sendUnlock = [self, done] {
        if (!self)
            return;
        const bool queued = self->queueLine("$X", [self, done](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            if (!a || !a->ok) {
                const RequestError e = a ? errorOf(a->errorCode, a->line, "grbl.request.unlock") : refusal(RequestError::Kind::Device, abandoned("grbl.request.unlock", self->m_lines.lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            // The operator's word: the position GRBL believes is taken as true.
            self->m_positions.established = (1u << self->m_map.size()) - 1;
            self->m_machine.alarm = 0;
            self->sendQuery();
            if (done)
                done(std::nullopt);
        });
        if (!queued && done)
            done(notSent("grbl.request.unlock"));
    };
    if (m_machine.critical) {
        // A limit alarm hears nothing but a reset: reset first, then unlock.
        m_waiters.reset.push_back([sendUnlock, done](const std::optional<RequestError>& e) {
            if (e) {
                if (done)
                    done(e);
                return;
            }
            sendUnlock();
        });
        softReset(true);
        return;
    }
    sendUnlock();
}

void GrblClient::setZero(quint8 axisMask, Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.set_zero"));
    if (m_status.anyMoving() || !linesIdle())
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, motion::msg::make("grbl.set_zero_while_moving"), dev::proto::ErrorCode::Busy));
    const quint32 all = (1u << m_map.size()) - 1;
    const quint32 mask = axisMask == 0 ? all : (axisMask & all);
    if (mask == 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.set_zero_no_axis")));
    // G10 L20 P1: the G54 offset that makes the present position read 0 (written to EEPROM:
    // the line goes alone).
    std::string line = "G10 L20 P1";
    for (int i = 0; i < m_map.size(); ++i)
        if ((mask >> i) & 1u)
            line += std::string(" ") + grblLetterOf(i) + "0";
    const QPointer<GrblClient> self(this);
    const bool queued = queueLine(
        line,
        [self, done, mask](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            if (!a || !a->ok) {
                const RequestError e = a ? errorOf(a->errorCode, a->line, "request.set_zero") : refusal(RequestError::Kind::Device, abandoned("request.set_zero", self->m_lines.lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            // Taken as home on the operator's word: absolute moves are allowed from here.
            self->m_positions.established |= mask;
            self->sendQuery();
            // The new offset, for the travel and for the next connection to recognise; done once
            // it is read, so a script that disconnects at once leaves it remembered.
            const bool asked = self->queueLine("$#", [self, done](const std::optional<dev::grbl::Streamer::Ack>& offsets) {
                if (self && offsets && offsets->ok)
                    self->rememberHome();
                if (done)
                    done(std::nullopt);
            });
            if (!asked && done)
                done(std::nullopt);
        },
        true);
    if (!queued)
        GRBL_REFUSE(done, notSent("request.set_zero"));
}

void GrblClient::setSoftLimits(int, double, double, Callback done)
{
    GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.soft_limits_fixed")));
}

// ---- moves -----------------------------------------------------------------------------------

void GrblClient::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    if (targets.isEmpty())
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.move_no_axis")));
    QMap<int, double> byAxis;
    for (const auto& [axis, value] : targets) {
        if (axis < 0 || axis >= m_identity.axes.size())
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.move_no_such_axis", {motion::msg::integer("index", axis, motion::msg::Unit::None)})));
        const motion::msg::Arg letter = motion::msg::verbatim("axis", QString(m_identity.axes[axis].letter).toStdString());
        if (!std::isfinite(value))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.move_target_not_number", {letter})));
        if (byAxis.contains(axis))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.move_axis_twice", {letter})));
        byAxis[axis] = value;
    }
    if (!std::isfinite(speed) || speed < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.move_bad_speed")));
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.move"));
    if (m_estopLatched)
        GRBL_REFUSE(done, estopLatched("request.move"));
    if (m_status.positionLost)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, motion::msg::make("grbl.move_in_alarm"), dev::proto::ErrorCode::NotHomed));
    std::vector<dev::grbl::AxisValue> xy, z;
    quint8 axes = 0;
    for (auto it = byAxis.cbegin(); it != byAxis.cend(); ++it) {
        const int axis = it.key();
        if (!relative && !established(axis))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Device,
                                      motion::msg::make("grbl.move_not_established", {motion::msg::verbatim("axis", QString(m_identity.axes[axis].letter).toStdString())}),
                                      dev::proto::ErrorCode::NotHomed));
        const double target = relative ? m_status.axes[axis].commanded + it.value() : it.value();
        if (auto e = checkTarget(axis, target))
            GRBL_REFUSE(done, *e);
        const dev::grbl::AxisValue v{grblLetterOf(axis), it.value() / scaleOf(axis)};
        // The analyzer moves Z once X and Y have arrived (seed 000): a line of its own, after.
        if (m_identity.axes[axis].letter == QLatin1Char('Z') && capabilities().testFlag(Capability::CoupledXyThenZ))
            z.push_back(v);
        else
            xy.push_back(v);
        axes = static_cast<quint8>(axes | (1u << axis));
    }
    const double feedMmMin = speed > 0 ? speed / scaleOf(byAxis.firstKey()) * 60 : 0;
    std::vector<std::string> lines;
    for (const auto* group : {&xy, &z}) {
        if (group->empty())
            continue;
        const dev::grbl::GcodeLine l = dev::grbl::moveLine(speed > 0 ? dev::grbl::Motion::Feed : dev::grbl::Motion::Rapid, relative, *group, feedMmMin);
        if (!l.ok())
            GRBL_REFUSE(done, notGcode(l.problem, "request.move"));
        lines.push_back(l.text);
    }
    sendMotionLines(lines, axes, "request.move", std::move(done));
}

void GrblClient::jogStep(int axis, double delta, double speed, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(delta) || !std::isfinite(speed) || speed < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.jog_step_invalid")));
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.jog_step"));
    if (m_estopLatched)
        GRBL_REFUSE(done, estopLatched("request.jog_step"));
    // A step jog's target is left to GRBL: beyond the travel it answers error:15, harmlessly.
    const double v = speed > 0 ? speed : m_identity.axes[axis].maxSpeed / 4;
    const dev::grbl::GcodeLine l = dev::grbl::jogLine({{grblLetterOf(axis), delta / scaleOf(axis)}}, v / scaleOf(axis) * 60);
    if (!l.ok())
        GRBL_REFUSE(done, notGcode(l.problem, "request.jog_step"));
    sendMotionLines({l.text}, static_cast<quint8>(1u << axis), "request.jog_step", std::move(done));
}

// ---- stopping ----------------------------------------------------------------------------------

void GrblClient::stop(quint8, Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.stop"));
    // GRBL stops all its axes or none.
    const bool jogging = m_jogs.run.has_value() || m_jogs.cancelling || !m_jogs.held.isEmpty() || !m_jogs.stick.empty()
                         || m_reports.tracker.state() == dev::grbl::MachineState::Jog;
    m_jogs.held.clear();
    m_jogs.stick.clear();
    if (jogging)
        cancelJog();
    const bool gcodeMotion = m_motion.axes || !linesIdle() || m_reports.tracker.state() == dev::grbl::MachineState::Run
                             || m_reports.tracker.state() == dev::grbl::MachineState::Hold;
    if (!gcodeMotion || m_machine.critical) {
        if (done)
            done(std::nullopt);
        return;
    }
    // Feed hold: GRBL slows down along its path; once at rest (Hold:0) a soft reset forgets
    // every queued line without losing the position (onStatusReport sends it).
    m_waiters.stop.push_back(std::move(done));
    if (m_stop.active)
        return;
    m_stop.active = true;
    m_stop.resetSent = false;
    m_stop.startMs = m_clock.elapsed();
    m_stop.askedUs = nowUs();
    sendRealtime(dev::grbl::rt::kFeedHold);
    sendQuery();
}

void GrblClient::holdThenFlush(Callback done)
{
    if (!isReady()) {
        if (done)
            done(refusal(RequestError::Kind::LinkDown, motion::msg::make("request.instrument_not_connected")));
        return;
    }
    m_waiters.stop.push_back(std::move(done));
    if (m_stop.active)
        return;
    m_stop.active = true;
    m_stop.resetSent = false;
    m_stop.startMs = m_clock.elapsed();
    m_stop.askedUs = nowUs();
    sendRealtime(dev::grbl::rt::kFeedHold);
    sendQuery();
}

void GrblClient::finishStop(const std::optional<RequestError>& e)
{
    m_stop.active = false;
    m_stop.resetSent = false;
    const quint32 axes = m_motion.axes;
    m_motion.axes = 0;
    if (!e)
        for (int i = 0; i < m_status.axes.size(); ++i)
            if ((axes >> i) & 1u)
                emitEvent(dev::proto::EventKind::Stopped, i, m_status.axes[i].commanded);
    auto waiting = std::move(m_waiters.stop);
    m_waiters.stop.clear();
    for (auto& d : waiting)
        if (d)
            d(e);
}

void GrblClient::estop(Callback done)
{
    if (!m_transport || !m_transport->isOpen() || m_phase != Phase::Ready)
        GRBL_REFUSE(done, notSent("request.estop"));
    // Feed hold and soft reset at once: the steppers stop dead. GRBL keeps its position only if
    // nothing was moving; otherwise it reports ALARM:3 and the position must be re-established.
    // No jog goes on and no motion is owed; the lines go with the soft reset below.
    m_jogs.forget();
    m_jogTimer.stop();
    m_estopLatched = true;
    m_motion.axes = 0;
    sendRealtime(dev::grbl::rt::kFeedHold);
    if (m_stop.active)
        finishStop(refusal(RequestError::Kind::Device, motion::msg::make("grbl.stop_overtaken_by_estop"), dev::proto::ErrorCode::EStopActive));
    m_waiters.reset.push_back(std::move(done));
    softReset(true);
    m_status.estop = true;
    emitEvent(dev::proto::EventKind::EStop, -1, 0, motion::msg::make("grbl.event.estop"));
    emit statusChanged(m_status);
}

void GrblClient::reset(Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, notSent("request.reset"));
    const bool wasLatched = m_estopLatched;
    m_estopLatched = false;
    m_status.estop = false;
    if (wasLatched)
        emitEvent(dev::proto::EventKind::Reset, -1, 0, motion::msg::make("grbl.event.estop_cleared"));
    emit statusChanged(m_status);
    if (m_machine.critical) {
        // A limit alarm waits for a soft reset; the position lock (Alarm) stays until home or unlock.
        m_waiters.reset.push_back(std::move(done));
        softReset(true);
        return;
    }
    if (done)
        done(std::nullopt);
}

// ---- dwell, trigger ------------------------------------------------------------------------------

void GrblClient::dwell(double seconds, Callback done)
{
    if (!std::isfinite(seconds) || seconds < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("request.dwell_invalid", {motion::msg::real("seconds", seconds, motion::msg::Unit::S)})));
    // G4's ok comes after the motion before it has finished and the time has passed.
    const dev::grbl::GcodeLine l = dev::grbl::dwellLine(std::max(seconds, 0.001));
    const QPointer<GrblClient> self(this);
    const bool queued = queueLine(l.text, [self, done](const std::optional<dev::grbl::Streamer::Ack>& a) {
        if (!self || !done)
            return;
        if (!a)
            return done(refusal(self->isReady() ? RequestError::Kind::Device : RequestError::Kind::LinkDown,
                                abandoned("grbl.request.dwell", self->m_lines.lostReason)));
        done(a->ok ? std::nullopt : std::optional<RequestError>(errorOf(a->errorCode, a->line, "grbl.request.dwell")));
    });
    if (!queued)
        GRBL_REFUSE(done, notSent("grbl.request.dwell"));
}

void GrblClient::pulseTrigger(double widthS, Callback done)
{
    if (!m_profile.trigger)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.no_trigger_output")));
    if (!std::isfinite(widthS) || widthS < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, motion::msg::make("grbl.trigger_bad_width", {motion::msg::real("width", widthS, motion::msg::Unit::S)})));
    if (!isReady())
        GRBL_REFUSE(done, notSent("grbl.request.trigger"));
    // Wait for the motion before to end (G4), switch on, hold for the width, switch off. grblHAL's
    // M64/M65 act when read, and GRBL reads the next line only once a G4 is over.
    const bool coolant = m_profile.trigger->output == dev::files::MachineProfile::TriggerOutput::CoolantFlood;
    const auto kind = coolant ? dev::grbl::TriggerOutput::Coolant : dev::grbl::TriggerOutput::GrblHalDigital;
    const int port = m_profile.trigger->port;
    std::vector<std::string> lines = {dev::grbl::dwellLine(0.001).text, dev::grbl::outputLine(kind, true, port, false).text,
                                      dev::grbl::dwellLine(std::max(widthS, 0.001)).text, dev::grbl::outputLine(kind, false, port, false).text};
    auto left = std::make_shared<std::size_t>(lines.size());
    auto failed = std::make_shared<bool>(false);
    const QPointer<GrblClient> self(this);
    for (const auto& line : lines) {
        const bool queued = queueLine(line, [self, left, failed, done](const std::optional<dev::grbl::Streamer::Ack>& a) {
            if (!self || *failed)
                return;
            if (!a || !a->ok) {
                *failed = true;
                const RequestError e = a ? errorOf(a->errorCode, a->line, "grbl.request.trigger") : refusal(RequestError::Kind::Device, abandoned("grbl.request.trigger", self->m_lines.lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            if (--*left == 0 && done)
                done(std::nullopt);
        });
        if (!queued)
            GRBL_REFUSE(done, notSent("grbl.request.trigger"));
    }
}

#undef GRBL_REFUSE

} // namespace dev
