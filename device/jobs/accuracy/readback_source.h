#pragma once
// Readings from the instrument itself: the measured position of each axis (the
// analyzer's encoder, the stage's grating) in one status reading taken at the stop.
// On the stage this is the very reading the position loop closes on, so it shows
// almost no error whatever the work point does (docs/accuracy.md, "Why an external
// reference").
#include "device/client/instrument.h"
#include "device/jobs/accuracy/reading_source.h"

#include <QPointer>

namespace dev::jobs {

class ReadbackSource : public ReadingSource {
    Q_OBJECT
public:
    explicit ReadbackSource(dev::Instrument* instrument, QObject* parent = nullptr);

    ReadingKind kind() const override { return ReadingKind::Readback; }
    motion::msg::Message describe() const override;
    int maxAxes() const override { return 8; }
    void take(const StopContext& stop, TakeDone done) override;
    void cancel() override { ++m_generation; }

private:
    QPointer<dev::Instrument> m_instrument;
    quint64 m_generation = 0;  ///< a cancelled take's answer is dropped
};

} // namespace dev::jobs
