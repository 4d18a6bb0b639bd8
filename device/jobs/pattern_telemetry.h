#pragma once
// Feeds a pattern run from raw telemetry batches (the CLI and tests, which own their client's
// subscription; the GUI feeds the runner from the shared TelemetryHub instead).
#include "device/client/instrument.h"
#include "device/jobs/pattern_runner.h"

namespace dev::jobs {

/// The channels a run needs: X and Y, commanded and measured.
QVector<dev::proto::ChannelRef> patternChannels();
/// Hands every sample of the batch that carries all four channels to the runner; returns how many.
int feedBatch(PatternRunner& runner, const dev::Instrument& client, const dev::proto::TelemetryBatch& batch);

} // namespace dev::jobs
