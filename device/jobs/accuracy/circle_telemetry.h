#pragma once
// Feeds a circular test from raw telemetry batches: the measured X and Y the device
// streams (the GUI's history keeps them subscribed; the CLI subscribes them itself).
#include "device/client/instrument.h"
#include "device/jobs/accuracy/circle_runner.h"

namespace dev::jobs {

/// What a circular test asks of the telemetry (the CLI and the GUI alike): the history's
/// 100 Hz puts some 40 samples on a 10 mm circle at 5 mm/s; a ballbar takes hundreds.
constexpr int kCircleSampleRateHz = 250;

/// The channels a circular test samples: measured X and Y of the runner's axes.
QVector<dev::proto::ChannelRef> circleChannels(const CircleRunner& runner);
/// Hands every sample of the batch that carries both channels to the runner; returns how many.
int feedCircleBatch(CircleRunner& runner, const dev::Instrument& client, const dev::proto::TelemetryBatch& batch);

} // namespace dev::jobs
