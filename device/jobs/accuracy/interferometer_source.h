#pragma once
// Readings from a laser interferometer's own capture, imported after the run
// (device/files/accuracy/interferometer_csv.h). At each stop the source notes the
// target, direction, cycle and the device time the axis had settled; the reading
// itself arrives with the import. The runner writes the notes as the run's target
// sequence for the operator to capture against.
#include "device/jobs/accuracy/reading_source.h"

namespace dev::jobs {

class InterferometerSource : public ReadingSource {
    Q_OBJECT
public:
    using ReadingSource::ReadingSource;

    ReadingKind kind() const override { return ReadingKind::Interferometer; }
    motion::msg::Message describe() const override { return motion::msg::make("accuracy.source.interferometer"); }
    void take(const StopContext& stop, TakeDone done) override
    {
        (void)stop;
        TakeResult r;
        r.deferred = true;
        done(r);
    }
};

} // namespace dev::jobs
