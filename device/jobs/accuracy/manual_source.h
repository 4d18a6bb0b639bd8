#pragma once
// Readings a person types: at each stop the source asks (entryWanted) and waits for
// provide() — the GUI's prompt or the CLI's line on stdin — so a dial indicator
// with no data port still gives an ISO 230-2 test. Nothing times out: the axis
// waits at the stop for as long as the person needs.
#include "device/jobs/accuracy/reading_source.h"

#include <optional>

namespace dev::jobs {

class ManualSource : public ReadingSource {
    Q_OBJECT
public:
    using ReadingSource::ReadingSource;

    ReadingKind kind() const override { return ReadingKind::Manual; }
    motion::msg::Message describe() const override { return motion::msg::make("accuracy.source.manual"); }
    int maxAxes() const override { return 2; }
    void take(const StopContext& stop, TakeDone done) override;
    void cancel() override;

    /// The stop waiting for an entry, if any.
    const std::optional<StopContext>& waiting() const { return m_stop; }
    /// The reading of the stop waiting, one value per axis in mm. False (and nothing
    /// taken) when no stop waits, the count is wrong or a value is not finite.
    bool provide(const std::vector<double>& valuesMm);

signals:
    /// A stop waits for its reading.
    void entryWanted(const dev::jobs::StopContext& stop);
    /// The wait ended (provided or cancelled).
    void entryDone();

private:
    std::optional<StopContext> m_stop;
    TakeDone m_done;
};

} // namespace dev::jobs
