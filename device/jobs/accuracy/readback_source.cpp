#include "device/jobs/accuracy/readback_source.h"

namespace jobs {

ReadbackSource::ReadbackSource(dev::Instrument* instrument, QObject* parent) : ReadingSource(parent), m_instrument(instrument) {}

QString ReadbackSource::describe() const
{
    if (!m_instrument)
        return tr("readback");
    return m_instrument->identity().kind == proto::DeviceKind::Stage ? tr("the stage's grating (readback)")
                                                                     : tr("the analyzer's encoder (readback)");
}

void ReadbackSource::take(const StopContext& stop, TakeDone done)
{
    if (!m_instrument) {
        done({{}, false, msg::make("accuracy.run.not_connected")});
        return;
    }
    const quint64 generation = ++m_generation;
    const QPointer<ReadbackSource> self(this);
    m_instrument->readStatus([self, generation, stop, done](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || self->m_generation != generation)
            return;
        TakeResult r;
        if (e) {
            r.problem = msg::make("accuracy.run.status_failed", {msg::verbatim("detail", e->message.toStdString())});
            return done(r);
        }
        for (int axis : stop.axes) {
            if (axis < 0 || axis >= s.axes.size()) {
                r.problem = msg::make("accuracy.run.status_failed", {msg::verbatim("detail", "no such axis")});
                r.valuesMm.clear();
                return done(r);
            }
            r.valuesMm.push_back(s.axes[axis].measured);
        }
        done(r);
    });
}

} // namespace jobs
