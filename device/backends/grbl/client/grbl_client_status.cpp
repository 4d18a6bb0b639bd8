// GrblClient, part 4: what the client keeps up to date — the '?' poll, each status report
// turned into the instrument's status, the events GRBL never sends (MotionDone, Stopped) told
// from the reports, alarms, the $# offsets, readStatus() and the telemetry made of reports.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/grbl_codes.h"


#include <cmath>
#include <utility>

namespace dev {

namespace {
constexpr std::size_t kMaxQueriesOutstanding = 3;
}

void GrblClient::poll()
{
    if (m_phase != Phase::Ready)
        return;
    if (m_reports.querySent.empty()) {
        sendQuery();
        return;
    }
    // An unanswered '?' (an EEPROM write stalled the serial interrupt, or GRBL is homing) is
    // asked again; the silence check decides when enough is enough.
    if (nowUs() - m_reports.querySent.back() > static_cast<quint64>(kQueryRetryMs) * 1000 && m_reports.querySent.size() < kMaxQueriesOutstanding)
        sendQuery();
}

void GrblClient::sendQuery()
{
    if (m_reports.querySent.size() >= kMaxQueriesOutstanding)
        m_reports.querySent.pop_front();
    m_reports.querySent.push_back(nowUs());
    sendRealtime(dev::grbl::rt::kStatusQuery);
}

void GrblClient::readStatus(StatusCallback done)
{
    if (m_phase != Phase::Ready) {
        RequestError e;
        e.kind = RequestError::Kind::LinkDown;
        e.message = motion::msg::make("request.not_sent", {motion::msg::term("request", "grbl.request.status")});
        if (done)
            done(e, m_status);
        return;
    }
    const quint64 since = nowUs();
    m_waiters.status.push_back({since, std::move(done)});
    if (m_reports.querySent.empty())
        sendQuery();
    else
        m_reports.queryAgain = true;  // the query in flight was asked before this call: ask once more
}

void GrblClient::applyParameters(const dev::grbl::Line& l)
{
    // $# answers: [G54:x,y,z] … [G92:x,y,z] [TLO:z] (report units: inches with $13=1).
    const double k = m_reports.tracker.reportInches() ? dev::grbl::kMmPerInch : 1.0;
    auto vec = [&](std::vector<double>& into) {
        if (const auto v = dev::grbl::parseNumberList(l.payload, dev::grbl::kMaxStatusAxes)) {
            into = *v;
            for (double& x : into)
                x *= k;
        }
    };
    if (l.tag == "G54")
        vec(m_controller.g54Mm);
    else if (l.tag == "G92")
        vec(m_controller.g92Mm);
    else if (l.tag == "TLO") {
        if (const auto v = dev::grbl::parseNumber(l.payload))
            m_controller.tloMm = *v * k;
        // TLO is the last line of the offsets: the work offset is known now.
        m_controller.haveParameters = true;
        if (!m_reports.tracker.haveWorkOffset()) {
            m_reports.wcoMm = m_controller.g54Mm;
            for (std::size_t i = 0; i < m_reports.wcoMm.size() && i < m_controller.g92Mm.size(); ++i)
                m_reports.wcoMm[i] += m_controller.g92Mm[i];
            if (m_reports.wcoMm.size() > 2)
                m_reports.wcoMm[2] += m_controller.tloMm;
        }
        if (!m_map.isEmpty())
            updateTravel();
    }
}

void GrblClient::emitEvent(dev::proto::EventKind kind, int axis, double position, motion::msg::Message detail, const QString& text)
{
    // Where an axis arrived, stopped or was homed: the event's position is in work coordinates
    // (G54, as the screens show), and GRBL's machine coordinates differ by the work offset, so
    // the detail says both.
    const bool where = kind == dev::proto::EventKind::HomeDone || kind == dev::proto::EventKind::MotionDone || kind == dev::proto::EventKind::Stopped;
    if (where && detail.id.empty() && axis >= 0 && axis < m_identity.axes.size()) {
        const motion::msg::Unit unit = unitOf(axis);
        detail = motion::msg::make("grbl.event.position", {motion::msg::real("work", position, unit),
                                                   motion::msg::real("machine", instrumentValue(axis, m_reports.machineMm), unit)});
    }
    DeviceEvent e;
    e.kind = kind;
    e.axis = axis;
    e.position = position;
    e.deviceTimeUs = nowUs();
    e.text = text;
    e.hostTime = QDateTime::currentDateTime();
    e.detail = std::move(detail);
    emit eventReceived(e);
}

void GrblClient::onStatusReport(const dev::grbl::StatusReport& r)
{
    const quint64 askedUs = m_reports.querySent.empty() ? 0 : m_reports.querySent.front();
    if (!m_reports.querySent.empty())
        m_reports.querySent.pop_front();
    if (!m_reports.tracker.update(r))
        return;
    // Work and machine position: from the report and the last WCO (the report's own, or $#'s).
    if (m_reports.tracker.haveWorkOffset())
        m_reports.wcoMm = m_reports.tracker.workOffsetMm();
    std::vector<double> pos = r.position;
    const double k = m_reports.tracker.reportInches() ? dev::grbl::kMmPerInch : 1.0;
    for (double& x : pos)
        x *= k;
    m_reports.wcoMm.resize(pos.size(), 0.0);
    m_reports.machineMm = pos;
    m_reports.workMm = pos;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (r.positionIsMachine)
            m_reports.workMm[i] = pos[i] - m_reports.wcoMm[i];
        else
            m_reports.machineMm[i] = pos[i] + m_reports.wcoMm[i];
    }
    const dev::grbl::MachineState st = r.state;
    if (m_reports.first) {
        // What can be trusted at connection: a controller with homing that is not in alarm was
        // homed (or unlocked) before; without homing, only a home set here that provably still holds.
        m_reports.first = false;
        if (m_controller.limits.homingEnabled)
            m_positions.established = st != dev::grbl::MachineState::Alarm ? (1u << m_map.size()) - 1 : 0;
        else
            m_positions.established = recallHome(st);
        updateTravel();
    }
    if (st != dev::grbl::MachineState::Alarm)
        m_machine.critical = false;
    const bool active = st == dev::grbl::MachineState::Run || st == dev::grbl::MachineState::Jog || st == dev::grbl::MachineState::Home
                        || (st == dev::grbl::MachineState::Hold && r.subState != 0);
    const quint64 now = nowUs();
    m_status.deviceTimeUs = now;
    m_status.estop = m_estopLatched;
    m_status.positionLost = st == dev::grbl::MachineState::Alarm;
    m_status.fault = st == dev::grbl::MachineState::Alarm;
    const std::string letters = axisLettersOfController();
    for (int i = 0; i < m_status.axes.size(); ++i) {
        AxisReadout& a = m_status.axes[i];
        const int g = grblIndexOf(i);
        const double v = instrumentValue(i, m_reports.workMm);
        const bool changed = g < static_cast<int>(m_reports.lastWorkMm.size())
                             && std::fabs(m_reports.lastWorkMm[static_cast<std::size_t>(g)] - m_reports.workMm[static_cast<std::size_t>(g)]) > 1e-6;
        a.commanded = v;
        a.measured = v;  // GRBL reports its step count: there is no separate measurement
        a.homed = established(i) && st != dev::grbl::MachineState::Alarm;
        a.homing = st == dev::grbl::MachineState::Home;
        a.moving = active && (changed || (m_motion.axes >> i) & 1u || isJogging(i) || st == dev::grbl::MachineState::Home);
        a.jogging = st == dev::grbl::MachineState::Jog && (changed || isJogging(i));
        a.limitSwitch = g >= 0 && g < static_cast<int>(letters.size()) && r.pinTriggered(letters[static_cast<std::size_t>(g)]);
        a.homeSwitch = false;  // GRBL has one limit pin per axis: it cannot tell home from limit
        a.fault = st == dev::grbl::MachineState::Alarm;
    }
    if (m_state == LinkState::Identified)
        setState(LinkState::Ready);
    emit statusChanged(m_status);

    // A stop waits for the hold to reach rest, then flushes the queue with a reset.
    if (m_stop.active && !m_stop.resetSent && askedUs >= m_stop.askedUs
        && ((st == dev::grbl::MachineState::Hold && r.subState == 0) || st == dev::grbl::MachineState::Idle)) {
        m_stop.resetSent = true;
        softReset(true);
    }
    settleMotion(askedUs, st);
    if (m_motion.homedAxes && askedUs > m_motion.homedAckUs) {
        const quint32 homed = std::exchange(m_motion.homedAxes, 0u);
        for (int i = 0; i < m_status.axes.size(); ++i)
            if ((homed >> i) & 1u)
                emitEvent(dev::proto::EventKind::HomeDone, i, m_status.axes[i].commanded);
    }
    if (m_jogs.cancelling && m_jogs.lines.open == 0 && askedUs > m_jogs.cancelSentUs && st != dev::grbl::MachineState::Jog) {
        m_jogs.cancelling = false;
        updateJog();  // a jog asked for while the cancel ran starts now
    }
    auto waiters = std::move(m_waiters.status);
    m_waiters.status.clear();
    for (auto& w : waiters) {
        if (w.sinceUs <= askedUs) {
            if (w.done)
                w.done(std::nullopt, m_status);
        } else {
            m_waiters.status.push_back(std::move(w));
        }
    }
    emitTelemetry(m_reports.workMm);
    m_reports.lastWorkMm = m_reports.workMm;
    m_reports.lastUs = now;
    emit reportApplied(askedUs);
    if (m_reports.queryAgain || !m_waiters.status.empty()) {
        m_reports.queryAgain = false;
        if (m_reports.querySent.empty())
            sendQuery();
    }
}

void GrblClient::settleMotion(quint64 askedUs, dev::grbl::MachineState st)
{
    // GRBL says nothing when a move ends. A report asked for after the last line of the move was
    // acknowledged (so GRBL had started the cycle: it auto-starts once its serial buffer is empty)
    // that shows Idle means every axis of it has arrived.
    if (!m_motion.axes || m_motion.linesOpen > 0 || m_stop.active || askedUs <= m_motion.ackUs || st != dev::grbl::MachineState::Idle)
        return;
    const quint32 axes = m_motion.axes;
    m_motion.axes = 0;
    for (int i = 0; i < m_status.axes.size(); ++i)
        if ((axes >> i) & 1u)
            emitEvent(dev::proto::EventKind::MotionDone, i, m_status.axes[i].commanded);
}

void GrblClient::onAlarm(int code)
{
    m_machine.alarm = code;
    // Positions survive a soft-limit alarm and a failed probe; every other alarm (a hard limit, a
    // reset in motion, a failed homing, grblHAL's E-stop) leaves them untrusted.
    if (code != dev::grbl::alarm::kSoftLimit && code != dev::grbl::alarm::kProbeFailInitial && code != dev::grbl::alarm::kProbeFailContact)
        loseEstablished();
    if (code == dev::grbl::alarm::kHardLimit || code == dev::grbl::alarm::kSoftLimit)
        m_machine.critical = true;
    m_machine.homing = false;
    dev::proto::EventKind kind = dev::proto::EventKind::Fault;
    if (code == dev::grbl::alarm::kHardLimit || code == dev::grbl::alarm::kSoftLimit)
        kind = dev::proto::EventKind::LimitHit;
    else if (code == dev::grbl::alarm::kGrblHalEStop)
        kind = dev::proto::EventKind::EStop;
    // A hard limit names its axis by the pin that tripped, when the last report showed one.
    int axis = -1;
    if (kind == dev::proto::EventKind::LimitHit)
        for (int i = 0; i < m_status.axes.size() && axis < 0; ++i)
            if (m_status.axes[i].limitSwitch)
                axis = i;
    // GRBL stopped: no motion is owed and no jog goes on. Lines still in flight are answered
    // (error:9 in the alarm lock), so they keep their counts.
    m_motion.axes = 0;
    m_jogs.forget();
    // The event's text is what the controller said; its detail, grbl.alarm{code}, is worded with the meaning.
    emitEvent(kind, axis, axis >= 0 ? m_status.axes[axis].commanded : 0, dev::grbl::alarmMessage(code), QStringLiteral("ALARM:%1").arg(code));
    emit alarmRaised(code);
    sendQuery();
}

void GrblClient::subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done)
{
    // Telemetry is the status reports: one sample each, at the poll rate at most.
    dev::proto::SubscribeReply reply;
    if (m_phase != Phase::Ready) {
        RequestError e;
        e.kind = RequestError::Kind::LinkDown;
        e.message = motion::msg::make("request.telemetry_refused", {motion::msg::nested("cause", motion::msg::make("request.instrument_not_connected"))});
        if (done)
            done(e, reply);
        return;
    }
    m_rateHz = rateHz <= 0 ? 0 : static_cast<int>(std::lround(std::min<double>(rateHz, m_profile.statusPollHz)));
    m_channels = m_rateHz ? channels : QVector<dev::proto::ChannelRef>{};
    reply.rateHz = static_cast<std::uint32_t>(m_rateHz);
    reply.samplesPerBatch = 1;
    if (done)
        done(std::nullopt, reply);
}

void GrblClient::emitTelemetry(const std::vector<double>& workMm)
{
    if (!m_rateHz || m_channels.isEmpty())
        return;
    dev::proto::TelemetryBatch b;
    b.firstSampleIndex = m_sampleIndex++;
    b.firstSampleTimeUs = m_status.deviceTimeUs;
    b.periodUs = static_cast<std::uint32_t>(std::lround(1e6 / m_profile.statusPollHz));
    b.sampleCount = 1;
    const double dtS = m_reports.lastUs > 0 && m_status.deviceTimeUs > m_reports.lastUs ? (m_status.deviceTimeUs - m_reports.lastUs) / 1e6 : 0;
    for (const auto& c : m_channels) {
        if (c.axis >= m_identity.axes.size())
            continue;
        const int i = c.axis;
        const double k = m_identity.axes[i].wireScale();
        double v = 0;
        switch (c.kind) {
        case dev::proto::ChannelKind::Commanded:
        case dev::proto::ChannelKind::Measured: v = instrumentValue(i, workMm) * k; break;
        case dev::proto::ChannelKind::Velocity:
            v = dtS > 0 ? (instrumentValue(i, workMm) - instrumentValue(i, m_reports.lastWorkMm)) / dtS * k : 0;
            break;
        case dev::proto::ChannelKind::Switches: v = m_status.axes[i].limitSwitch ? 2 : 0; break;
        default: continue;  // no following error, controller output or contour on GRBL: left out, not faked
        }
        b.channels.push_back(c);
        b.values.push_back(static_cast<std::int32_t>(std::llround(std::clamp(v, -2.1e9, 2.1e9))));
    }
    if (b.channels.empty())
        return;
    emit telemetryReceived(b);
}

} // namespace dev
