#include "device/jobs/accuracy/gauge_source.h"

namespace dev::jobs {

GaugeSource::GaugeSource(dev::Transport* transport, const QString& port, QObject* parent)
    : ReadingSource(parent), m_transport(transport), m_link(new dev::GaugeLink(transport, port, this))
{
}

motion::msg::Message GaugeSource::describe() const { return motion::msg::make("accuracy.source.gauge", {motion::msg::verbatim("port", m_link->port().toStdString())}); }

void GaugeSource::open(OpenDone done) { m_link->open(std::move(done)); }

void GaugeSource::close() { m_link->close(); }

void GaugeSource::take(const StopContext& stop, TakeDone done)
{
    if (stop.axes.size() != 1) {
        done({{}, false, motion::msg::make("accuracy.run.gauge_one_axis", {motion::msg::verbatim("port", m_link->port().toStdString())})});
        return;
    }
    m_link->read([done](std::optional<double> valueMm, const motion::msg::Message& problem) {
        TakeResult r;
        if (valueMm)
            r.valuesMm.push_back(*valueMm);
        else
            r.problem = problem;
        done(r);
    });
}

void GaugeSource::cancel() { m_link->cancel(); }

} // namespace dev::jobs
