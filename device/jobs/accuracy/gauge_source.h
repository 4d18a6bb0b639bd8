#pragma once
// Readings from an external gauge on a serial port of its own (device/link/gauge_link.h,
// the dialect in docs/accuracy.md): a digital indicator or length gauge touching the
// work point, so it sees what the instrument's own encoder or grating cannot.
// One axis per reading.
#include "device/jobs/accuracy/reading_source.h"
#include "device/link/gauge_link.h"

namespace dev::jobs {

class GaugeSource : public ReadingSource {
    Q_OBJECT
public:
    /// `transport` is not owned (give it this source as parent to tie their lives). `port`
    /// names it for people.
    GaugeSource(dev::Transport* transport, const QString& port, QObject* parent = nullptr);

    ReadingKind kind() const override { return ReadingKind::Gauge; }
    motion::msg::Message describe() const override;
    void open(OpenDone done) override;
    void close() override;
    void take(const StopContext& stop, TakeDone done) override;
    void cancel() override;

    dev::GaugeLink& link() { return *m_link; }

private:
    dev::Transport* m_transport;
    dev::GaugeLink* m_link;
};

} // namespace dev::jobs
