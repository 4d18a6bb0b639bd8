#include "device/jobs/pattern_telemetry.h"

namespace dev::jobs {

QVector<dev::proto::ChannelRef> patternChannels()
{
    return {{0, dev::proto::ChannelKind::Commanded}, {0, dev::proto::ChannelKind::Measured},
            {1, dev::proto::ChannelKind::Commanded}, {1, dev::proto::ChannelKind::Measured}};
}

int feedBatch(PatternRunner& runner, const dev::Instrument& client, const dev::proto::TelemetryBatch& batch)
{
    const auto wanted = patternChannels();
    int column[4] = {-1, -1, -1, -1};
    for (int w = 0; w < 4; ++w)
        for (std::size_t c = 0; c < batch.channels.size(); ++c)
            if (batch.channels[c] == wanted[w])
                column[w] = static_cast<int>(c);
    for (int c : column)
        if (c < 0)
            return 0;
    const std::size_t width = batch.channels.size();
    for (std::size_t k = 0; k < batch.sampleCount; ++k) {
        auto value = [&](int w) {
            return client.toAxisUnits(wanted[w], batch.values[k * width + static_cast<std::size_t>(column[w])]);
        };
        const double t = (batch.firstSampleTimeUs + k * static_cast<double>(batch.periodUs)) / 1e6;
        runner.addSample(t, {value(0), value(2)}, {value(1), value(3)});
    }
    return batch.sampleCount;
}

} // namespace dev::jobs
