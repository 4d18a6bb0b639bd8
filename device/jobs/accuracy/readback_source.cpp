#include "device/jobs/accuracy/readback_source.h"

namespace dev::jobs {

ReadbackSource::ReadbackSource(dev::Instrument* instrument, QObject* parent) : ReadingSource(parent), m_instrument(instrument) {}

motion::msg::Message ReadbackSource::describe() const
{
    if (!m_instrument)
        return motion::msg::make("accuracy.source.readback");
    return motion::msg::make(m_instrument->identity().kind == dev::proto::DeviceKind::Stage ? "accuracy.source.stage_grating"
                                                                               : "accuracy.source.analyzer_encoder");
}

void ReadbackSource::take(const StopContext& stop, TakeDone done)
{
    if (!m_instrument) {
        done({{}, false, motion::msg::make("accuracy.run.not_connected")});
        return;
    }
    const quint64 generation = ++m_generation;
    const QPointer<ReadbackSource> self(this);
    m_instrument->readStatus([self, generation, stop, done](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus& s) {
        if (!self || self->m_generation != generation)
            return;
        TakeResult r;
        if (e) {
            r.problem = motion::msg::make("accuracy.run.status_failed", {motion::msg::nested("detail", e->message)});
            return done(r);
        }
        for (std::size_t n = 0; n < stop.axes.size(); ++n) {
            const int axis = stop.axes[n];
            if (axis < 0 || axis >= s.axes.size()) {
                const std::string letter = n < stop.letters.size() ? QString(stop.letters[n]).toStdString() : std::to_string(axis);
                r.problem = motion::msg::make("accuracy.run.status_no_axis", {motion::msg::verbatim("axis", letter)});
                r.valuesMm.clear();
                return done(r);
            }
            r.valuesMm.push_back(s.axes[axis].measured);
        }
        done(r);
    });
}

} // namespace dev::jobs
