#include "device/jobs/tuning/instrument_target.h"

#include <cmath>

namespace dev {

using namespace motion::control;

InstrumentTarget::InstrumentTarget(TuningClient* tuning, int axis, const QString& name, QObject* parent)
    : TuningTarget(parent), m_tuning(tuning), m_axis(axis), m_name(name)
{
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        if (!m_running)
            return;
        // The end event never came (lost on a noisy link): end it and read what there is.
        m_tuning->abortTests(static_cast<quint8>(1u << m_axis));
        m_running = false;
        emit testRunning(false);
        fetch();
    });
    connect(tuning, &TuningClient::testEnded, this, [this](int endedAxis, dev::proto::EventKind, const QString&) {
        if (endedAxis != m_axis || !m_running)
            return;
        m_running = false;
        m_deadline.stop();
        emit testRunning(false);
        // Read on the next turn: whoever watched live telemetry has let go of it by
        // then, and the capture does not queue behind a link full of samples.
        QMetaObject::invokeMethod(this, &InstrumentTarget::fetch, Qt::QueuedConnection);
    });
    Instrument* c = tuning->instrument();
    connect(c, &Instrument::stateChanged, this, [this](LinkState s) {
        if (!m_done || s == LinkState::Ready)
            return;
        RunOutcome out;
        out.linkLost = true;
        out.error = motion::msg::make("tuning.target.link_lost", {motion::msg::verbatim("target", m_name.toStdString())});
        if (m_running)
            emit testRunning(false);
        m_running = false;
        m_deadline.stop();
        finish(out);
    });
    const auto& axes = c->identity().axes;
    if (m_axis >= 0 && m_axis < axes.size())
        m_name = QStringLiteral("%1 %2").arg(name, QString(axes[m_axis].letter));
}

QString InstrumentTarget::describe() const { return m_name; }

double InstrumentTarget::noiseFloor() const
{
    const auto& axes = m_tuning->instrument()->identity().axes;
    return m_axis >= 0 && m_axis < axes.size() ? axes[m_axis].resolution : 0.0005;
}

bool InstrumentTarget::ready() const { return m_tuning && m_tuning->instrument() && m_tuning->instrument()->isReady() && !m_done; }

void InstrumentTarget::runStep(const StepSpec& spec, bool, double, Done done)
{
    StepTestParams p;
    p.axis = m_axis;
    p.stepMm = spec.step;
    p.settleBandMm = spec.settleBand;
    p.settleHoldS = spec.settleHoldS;
    p.runS = spec.runS;
    p.envelope = spec.envelope;
    p.trialGains = spec.gains;
    launch(spec.envelope.maxDurationS, std::move(done), [this, p](TuningClient::Callback cb) { m_tuning->startStepTest(p, cb); });
}

void InstrumentTarget::runRelay(const RelaySpec& spec, bool, Done done)
{
    RelayTestParams p;
    p.axis = m_axis;
    p.amplitudeMm = spec.amplitude;
    p.hysteresisMm = spec.hysteresis;
    p.forcedPeriodS = spec.forcedPeriodS;
    p.cycles = spec.cycles;
    p.envelope = spec.envelope;
    launch(spec.envelope.maxDurationS, std::move(done), [this, p](TuningClient::Callback cb) { m_tuning->startRelayTest(p, cb); });
}

void InstrumentTarget::launch(double maxS, Done done, const std::function<void(TuningClient::Callback)>& send)
{
    m_done = std::move(done);
    QPointer<InstrumentTarget> self(this);
    send([self, maxS](const std::optional<RequestError>& e) {
        if (self)
            self->started(e, maxS);
    });
}

void InstrumentTarget::started(const std::optional<RequestError>& e, double maxS)
{
    if (!m_done)
        return;  // the link went away meanwhile: already reported
    if (e) {
        RunOutcome out;
        out.error = e->message;
        out.linkLost = e->kind == RequestError::Kind::LinkDown || e->kind == RequestError::Kind::Timeout;
        finish(out);
        return;
    }
    m_running = true;
    emit testRunning(true);
    m_deadline.start(static_cast<int>(std::ceil(maxS * 1000)) + 3000);
}

void InstrumentTarget::abort()
{
    if (m_tuning && m_running)
        m_tuning->abortTests(static_cast<quint8>(1u << m_axis));  // the end event follows; the capture is read then
}

void InstrumentTarget::fetch()
{
    QPointer<InstrumentTarget> self(this);
    emit runProgress(0, motion::msg::make("tuning.target.reading_capture"));
    m_tuning->fetchCapture(
        m_axis,
        [self](const std::optional<RequestError>& e, const TestCapture& c) {
            if (!self)
                return;
            RunOutcome out;
            if (e) {
                out.error = e->message;
                out.linkLost = e->kind == RequestError::Kind::LinkDown || e->kind == RequestError::Kind::Timeout;
            } else {
                out.ok = true;
                out.record = c.record;
            }
            self->finish(out);
        },
        [self](int received, int total) {
            if (self && total > 0)
                emit self->runProgress(double(received) / total, motion::msg::make("tuning.target.reading_capture_of", {motion::msg::integer("received", received),
                                                                                                                motion::msg::integer("total", total)}));
        });
}

void InstrumentTarget::finish(const RunOutcome& out)
{
    Done done = std::move(m_done);
    m_done = nullptr;
    if (done)
        done(out);
}

} // namespace dev
