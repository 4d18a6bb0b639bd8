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

RequestError refusal(RequestError::Kind kind, const QString& message, proto::ErrorCode code = proto::ErrorCode::BadPayload)
{
    RequestError e;
    e.kind = kind;
    e.code = code;
    e.message = message;
    return e;
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
    return refusal(RequestError::Kind::Device,
                   tr("%1 %2 %3 is beyond the machine travel %4 … %5 %3 (the controller's $%6): refused before sending, "
                      "since GRBL would stop with ALARM:2 and need a reset")
                       .arg(m_identity.axes[axis].letter)
                       .arg(target, 0, 'f', 3)
                       .arg(m_identity.axes[axis].unitName())
                       .arg(s.min, 0, 'f', 3)
                       .arg(s.max, 0, 'f', 3)
                       .arg(grbl::setting::kMaxTravelMmX + g),
                   proto::ErrorCode::SoftLimit);
}

void GrblClient::sendMotionLines(const std::vector<std::string>& lines, quint8 axes, const QString& what, Callback done)
{
    struct Progress {
        std::size_t remaining;
        bool finished = false;
    };
    auto progress = std::make_shared<Progress>(Progress{lines.size()});
    const QPointer<GrblClient> self(this);
    m_motionAxes |= axes;
    for (const std::string& line : lines) {
        ++m_motionLinesOpen;
        const bool queued = queueLine(line, [self, progress, what, done](const std::optional<grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            self->m_motionLinesOpen = std::max(0, self->m_motionLinesOpen - 1);
            self->m_motionAckUs = self->nowUs();
            if (progress->finished)
                return;
            if (!a || !a->ok) {
                progress->finished = true;
                const RequestError e = a ? errorOf(a->errorCode, a->line, what)
                                         : refusal(self->isReady() ? RequestError::Kind::Device : RequestError::Kind::LinkDown,
                                                   tr("%1 abandoned: %2").arg(what, self->m_lostReason));
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
            --m_motionLinesOpen;
            if (!progress->finished) {
                progress->finished = true;
                GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("%1: the line \"%2\" cannot be sent").arg(what, QString::fromStdString(line))));
            }
            return;
        }
    }
}

// ---- home, unlock, zero ---------------------------------------------------------------------

void GrblClient::home(quint8 axisMask, Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("home: the instrument is not connected")));
    if (m_estopLatched)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, tr("home: the E-stop is latched: reset it first"), proto::ErrorCode::EStopActive));
    // GRBL homes its axes together ($H); a single-axis $HX exists only in some builds.
    const quint32 all = (1u << m_map.size()) - 1;
    std::string line = "$H";
    if (axisMask != 0 && (axisMask & all) != all) {
        for (int i = 0; i < m_map.size(); ++i)
            if ((axisMask >> i) & 1u)
                line.push_back(grblLetterOf(i));
        if (line.size() != 3)
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("home: GRBL homes one axis or all of them, not %1").arg(QString::fromStdString(line.substr(2)))));
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
    m_homing = true;
    const QPointer<GrblClient> self(this);
    const quint32 homedMask = axisMask == 0 ? all : (axisMask & all);
    const bool queued = queueLine(line, [self, reply, homedMask, line](const std::optional<grbl::Streamer::Ack>& a) {
        if (!self)
            return;
        self->m_homing = false;
        if (!a || !a->ok) {
            const RequestError e = a ? errorOf(a->errorCode, a->line, tr("home")) : refusal(RequestError::Kind::Device, tr("home abandoned: %1").arg(self->m_lostReason));
            emit self->requestFailed(e);
            reply(e);
            return;
        }
        self->m_established |= homedMask;
        self->m_alarm = 0;
        for (int i = 0; i < self->m_map.size(); ++i)
            if ((homedMask >> i) & 1u)
                self->emitEvent(proto::EventKind::HomeDone, i, self->m_status.axes[i].commanded);
        reply(std::nullopt);
        self->sendQuery();
    });
    if (!queued) {
        m_homing = false;
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("home: the instrument is not connected")));
    }
    // No refusal in the first moments means GRBL is homing: say "accepted" as other backends do.
    QTimer::singleShot(kHomeAcceptMs, this, [reply] { reply(std::nullopt); });
}

void GrblClient::unlock(Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("unlock: the instrument is not connected")));
    const QPointer<GrblClient> self(this);
    auto sendUnlock = [self, done] {
        if (!self)
            return;
        const bool queued = self->queueLine("$X", [self, done](const std::optional<grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            if (!a || !a->ok) {
                const RequestError e = a ? errorOf(a->errorCode, a->line, tr("unlock")) : refusal(RequestError::Kind::Device, tr("unlock abandoned: %1").arg(self->m_lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            // The operator's word: the position GRBL believes is taken as true.
            self->m_established = (1u << self->m_map.size()) - 1;
            self->m_alarm = 0;
            self->sendQuery();
            if (done)
                done(std::nullopt);
        });
        if (!queued && done)
            done(refusal(RequestError::Kind::LinkDown, tr("unlock: the instrument is not connected")));
    };
    if (m_critical) {
        // A limit alarm hears nothing but a reset: reset first, then unlock.
        m_resetDone.push_back([sendUnlock, done](const std::optional<RequestError>& e) {
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
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("set zero: the instrument is not connected")));
    if (m_status.anyMoving() || !linesIdle())
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, tr("set zero: wait until the instrument is still"), proto::ErrorCode::Busy));
    const quint32 all = (1u << m_map.size()) - 1;
    const quint32 mask = axisMask == 0 ? all : (axisMask & all);
    if (mask == 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("set zero: no such axis")));
    // G10 L20 P1: the G54 offset that makes the present position read 0 (written to EEPROM:
    // the line goes alone).
    std::string line = "G10 L20 P1";
    for (int i = 0; i < m_map.size(); ++i)
        if ((mask >> i) & 1u)
            line += std::string(" ") + grblLetterOf(i) + "0";
    const QPointer<GrblClient> self(this);
    const bool queued = queueLine(
        line,
        [self, done, mask](const std::optional<grbl::Streamer::Ack>& a) {
            if (!self)
                return;
            if (!a || !a->ok) {
                const RequestError e = a ? errorOf(a->errorCode, a->line, tr("set zero")) : refusal(RequestError::Kind::Device, tr("set zero abandoned: %1").arg(self->m_lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            // Taken as home on the operator's word: absolute moves are allowed from here.
            self->m_established |= mask;
            self->queueLine("$#", {});  // the new offset, for the travel
            self->sendQuery();
            if (done)
                done(std::nullopt);
        },
        true);
    if (!queued)
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("set zero: the instrument is not connected")));
}

void GrblClient::setSoftLimits(int, double, double, Callback done)
{
    GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid,
                              tr("GRBL enforces its machine travel ($130–$132) as its soft limits; other limits cannot be set from "
                                 "here")));
}

// ---- moves -----------------------------------------------------------------------------------

void GrblClient::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    if (targets.isEmpty())
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("move: no axis given")));
    QMap<int, double> byAxis;
    for (const auto& [axis, value] : targets) {
        if (axis < 0 || axis >= m_identity.axes.size())
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("move: axis %1 does not exist on this instrument").arg(axis)));
        if (!std::isfinite(value))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("move: axis %1 target is not a number").arg(m_identity.axes[axis].letter)));
        if (byAxis.contains(axis))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("move: axis %1 named twice").arg(m_identity.axes[axis].letter)));
        byAxis[axis] = value;
    }
    if (!std::isfinite(speed) || speed < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("move: speed must be a positive number")));
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("move not sent: the instrument is not connected")));
    if (m_estopLatched)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, tr("move: the E-stop is latched: reset it first"), proto::ErrorCode::EStopActive));
    if (m_status.positionLost)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device,
                                  tr("move: the controller is in alarm (its position is not trusted): home it, or unlock it on your word"),
                                  proto::ErrorCode::NotHomed));
    std::vector<grbl::AxisValue> xy, z;
    quint8 axes = 0;
    for (auto it = byAxis.cbegin(); it != byAxis.cend(); ++it) {
        const int axis = it.key();
        if (!relative && !established(axis))
            GRBL_REFUSE(done, refusal(RequestError::Kind::Device,
                                      tr("move: axis %1 has no established position: home it, or take the present position as "
                                         "home (Set home here, `zero`) first")
                                          .arg(m_identity.axes[axis].letter),
                                      proto::ErrorCode::NotHomed));
        const double target = relative ? m_status.axes[axis].commanded + it.value() : it.value();
        if (auto e = checkTarget(axis, target))
            GRBL_REFUSE(done, *e);
        const grbl::AxisValue v{grblLetterOf(axis), it.value() / scaleOf(axis)};
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
        const grbl::GcodeLine l = grbl::moveLine(speed > 0 ? grbl::Motion::Feed : grbl::Motion::Rapid, relative, *group, feedMmMin);
        if (!l.ok()) {
            RequestError e = refusal(RequestError::Kind::Invalid, tr("move: cannot be written as G-code (%1)").arg(QString::fromStdString(msg::debugString(l.problem))));
            e.detail = l.problem;
            GRBL_REFUSE(done, e);
        }
        lines.push_back(l.text);
    }
    sendMotionLines(lines, axes, tr("move"), std::move(done));
}

void GrblClient::jogStep(int axis, double delta, double speed, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(delta) || !std::isfinite(speed) || speed < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("jog step: bad axis, step or speed")));
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("jog step not sent: the instrument is not connected")));
    if (m_estopLatched)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Device, tr("jog step: the E-stop is latched: reset it first"), proto::ErrorCode::EStopActive));
    // A step jog's target is left to GRBL: beyond the travel it answers error:15, harmlessly.
    const double v = speed > 0 ? speed : m_identity.axes[axis].maxSpeed / 4;
    const grbl::GcodeLine l = grbl::jogLine({{grblLetterOf(axis), delta / scaleOf(axis)}}, v / scaleOf(axis) * 60);
    if (!l.ok()) {
        RequestError e = refusal(RequestError::Kind::Invalid, tr("jog step: cannot be written as G-code (%1)").arg(QString::fromStdString(msg::debugString(l.problem))));
        e.detail = l.problem;
        GRBL_REFUSE(done, e);
    }
    sendMotionLines({l.text}, static_cast<quint8>(1u << axis), tr("jog step"), std::move(done));
}

// ---- stopping ----------------------------------------------------------------------------------

void GrblClient::stop(quint8, Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("stop not sent: the instrument is not connected")));
    // GRBL stops all its axes or none.
    const bool jogging = m_jog.has_value() || m_jogCancelling || !m_heldJogs.isEmpty() || !m_stickJogs.empty()
                         || m_tracker.state() == grbl::MachineState::Jog;
    m_heldJogs.clear();
    m_stickJogs.clear();
    if (jogging)
        cancelJog();
    const bool gcodeMotion = m_motionAxes || !linesIdle() || m_tracker.state() == grbl::MachineState::Run
                             || m_tracker.state() == grbl::MachineState::Hold;
    if (!gcodeMotion || m_critical) {
        if (done)
            done(std::nullopt);
        return;
    }
    // Feed hold: GRBL slows down along its path; once at rest (Hold:0) a soft reset forgets
    // every queued line without losing the position (onStatusReport sends it).
    m_stopDone.push_back(std::move(done));
    if (m_stopping)
        return;
    m_stopping = true;
    m_stopResetSent = false;
    m_stopStartMs = m_clock.elapsed();
    m_stopAskedUs = nowUs();
    sendRealtime(grbl::rt::kFeedHold);
    sendQuery();
}

void GrblClient::holdThenFlush(Callback done)
{
    if (!isReady()) {
        if (done)
            done(refusal(RequestError::Kind::LinkDown, tr("the instrument is not connected")));
        return;
    }
    m_stopDone.push_back(std::move(done));
    if (m_stopping)
        return;
    m_stopping = true;
    m_stopResetSent = false;
    m_stopStartMs = m_clock.elapsed();
    m_stopAskedUs = nowUs();
    sendRealtime(grbl::rt::kFeedHold);
    sendQuery();
}

void GrblClient::finishStop(const std::optional<RequestError>& e)
{
    m_stopping = false;
    m_stopResetSent = false;
    const quint32 axes = m_motionAxes;
    m_motionAxes = 0;
    if (!e)
        for (int i = 0; i < m_status.axes.size(); ++i)
            if ((axes >> i) & 1u)
                emitEvent(proto::EventKind::Stopped, i, m_status.axes[i].commanded, tr("stopped"));
    auto waiting = std::move(m_stopDone);
    m_stopDone.clear();
    for (auto& d : waiting)
        if (d)
            d(e);
}

void GrblClient::estop(Callback done)
{
    if (!m_transport || !m_transport->isOpen() || m_phase != Phase::Ready)
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("E-stop not sent: the instrument is not connected")));
    // Feed hold and soft reset at once: the steppers stop dead. GRBL keeps its position only if
    // nothing was moving; otherwise it reports ALARM:3 and the position must be re-established.
    m_heldJogs.clear();
    m_stickJogs.clear();
    m_jog.reset();
    m_jogCancelling = false;
    m_jogTimer.stop();
    m_estopLatched = true;
    m_motionAxes = 0;
    sendRealtime(grbl::rt::kFeedHold);
    if (m_stopping)
        finishStop(refusal(RequestError::Kind::Device, tr("stop overtaken by the E-stop"), proto::ErrorCode::EStopActive));
    m_resetDone.push_back(std::move(done));
    softReset(true);
    m_status.estop = true;
    emitEvent(proto::EventKind::EStop, -1, 0, tr("E-stop: feed hold and soft reset; if it was moving, the controller lost its position"));
    emit statusChanged(m_status);
}

void GrblClient::reset(Callback done)
{
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("reset not sent: the instrument is not connected")));
    const bool wasLatched = m_estopLatched;
    m_estopLatched = false;
    m_status.estop = false;
    if (wasLatched)
        emitEvent(proto::EventKind::Reset, -1, 0, tr("E-stop latch cleared"));
    emit statusChanged(m_status);
    if (m_critical) {
        // A limit alarm waits for a soft reset; the position lock (Alarm) stays until home or unlock.
        m_resetDone.push_back(std::move(done));
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
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("dwell: %1 s is not a time to wait").arg(seconds)));
    // G4's ok comes after the motion before it has finished and the time has passed.
    const grbl::GcodeLine l = grbl::dwellLine(std::max(seconds, 0.001));
    const QPointer<GrblClient> self(this);
    const bool queued = queueLine(l.text, [self, done](const std::optional<grbl::Streamer::Ack>& a) {
        if (!self || !done)
            return;
        if (!a)
            return done(refusal(self->isReady() ? RequestError::Kind::Device : RequestError::Kind::LinkDown,
                                tr("dwell abandoned: %1").arg(self->m_lostReason)));
        done(a->ok ? std::nullopt : std::optional<RequestError>(errorOf(a->errorCode, a->line, tr("dwell"))));
    });
    if (!queued)
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("dwell not sent: the instrument is not connected")));
}

void GrblClient::pulseTrigger(double widthS, Callback done)
{
    if (!m_profile.trigger)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("this instrument has no trigger output: the machine profile names none")));
    if (!std::isfinite(widthS) || widthS < 0)
        GRBL_REFUSE(done, refusal(RequestError::Kind::Invalid, tr("trigger: %1 s is not a pulse width").arg(widthS)));
    if (!isReady())
        GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("trigger not sent: the instrument is not connected")));
    // Wait for the motion before to end (G4), switch on, hold for the width, switch off. grblHAL's
    // M64/M65 act when read, and GRBL reads the next line only once a G4 is over.
    const bool coolant = m_profile.trigger->output == files::MachineProfile::TriggerOutput::CoolantFlood;
    const auto kind = coolant ? grbl::TriggerOutput::Coolant : grbl::TriggerOutput::GrblHalDigital;
    const int port = m_profile.trigger->port;
    std::vector<std::string> lines = {grbl::dwellLine(0.001).text, grbl::outputLine(kind, true, port, false).text,
                                      grbl::dwellLine(std::max(widthS, 0.001)).text, grbl::outputLine(kind, false, port, false).text};
    auto left = std::make_shared<std::size_t>(lines.size());
    auto failed = std::make_shared<bool>(false);
    const QPointer<GrblClient> self(this);
    for (const auto& line : lines) {
        const bool queued = queueLine(line, [self, left, failed, done](const std::optional<grbl::Streamer::Ack>& a) {
            if (!self || *failed)
                return;
            if (!a || !a->ok) {
                *failed = true;
                const RequestError e = a ? errorOf(a->errorCode, a->line, tr("trigger")) : refusal(RequestError::Kind::Device, tr("trigger abandoned: %1").arg(self->m_lostReason));
                emit self->requestFailed(e);
                if (done)
                    done(e);
                return;
            }
            if (--*left == 0 && done)
                done(std::nullopt);
        });
        if (!queued)
            GRBL_REFUSE(done, refusal(RequestError::Kind::LinkDown, tr("trigger not sent: the instrument is not connected")));
    }
}

#undef GRBL_REFUSE

} // namespace dev
