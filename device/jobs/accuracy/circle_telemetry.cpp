#include "device/jobs/accuracy/circle_telemetry.h"

namespace dev::jobs {

QVector<dev::proto::ChannelRef> circleChannels(const CircleRunner& runner)
{
    return {{static_cast<std::uint8_t>(runner.axisX()), dev::proto::ChannelKind::Measured},
            {static_cast<std::uint8_t>(runner.axisY()), dev::proto::ChannelKind::Measured}};
}

int feedCircleBatch(CircleRunner& runner, const dev::Instrument& client, const dev::proto::TelemetryBatch& batch)
{
    const auto wanted = circleChannels(runner);
    int column[2] = {-1, -1};
    for (int w = 0; w < 2; ++w)
        for (std::size_t c = 0; c < batch.channels.size(); ++c)
            if (batch.channels[c] == wanted[w])
                column[w] = static_cast<int>(c);
    if (column[0] < 0 || column[1] < 0)
        return 0;
    const std::size_t width = batch.channels.size();
    for (std::size_t k = 0; k < batch.sampleCount; ++k)
        runner.addSample(client.toAxisUnits(wanted[0], batch.values[k * width + static_cast<std::size_t>(column[0])]),
                         client.toAxisUnits(wanted[1], batch.values[k * width + static_cast<std::size_t>(column[1])]));
    return static_cast<int>(batch.sampleCount);
}

} // namespace dev::jobs
