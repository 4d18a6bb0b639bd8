#include "device/jobs/machine_model.h"

#include "device/protocol/messages_arch.h"

#include <algorithm>

namespace dev::jobs {

motion::scan::StageModel stageModelOf(const dev::DeviceIdentity& identity, const QVector<dev::SoftLimits>& limits)
{
    motion::scan::StageModel m;
    const bool reported = identity.reportsMotionLimits();
    for (int i = 0; i < 2 && i < identity.axes.size(); ++i) {
        const dev::AxisDescriptor& a = identity.axes[i];
        if (a.maxSpeed > 0)
            m.maxSpeedMmS[i] = a.maxSpeed;
        if (!reported)
            continue;  // the reference stage's acceleration and jerk (StageModel's defaults)
        if (a.maxAccel > 0)
            m.maxAccelMmS2[i] = a.maxAccel;
        m.maxJerkMmS3[i] = a.maxJerk > 0 ? a.maxJerk : kUnlimitedJerkMmS3;
    }
    if (identity.axes.size() >= 2) {
        m.travel = {identity.axes[0].travelMin, identity.axes[1].travelMin, identity.axes[0].travelMax, identity.axes[1].travelMax};
        if (limits.size() >= 2)  // the soft limits narrow the travel
            m.travel = {std::max(m.travel.x0Mm, limits[0].min), std::max(m.travel.y0Mm, limits[1].min),
                        std::min(m.travel.x1Mm, limits[0].max), std::min(m.travel.y1Mm, limits[1].max)};
    }
    return m;
}

motion::plates::Deck deckWithDeviceMotion(motion::plates::Deck deck, const dev::DeviceIdentity& identity)
{
    // An identified device blends arched travel only when its HELLO says so (a GRBL
    // controller, an older firmware: in legs); not connected, the reference firmware's.
    if (!identity.axes.isEmpty()) {
        deck.archedMoves = (identity.protocolCapabilities & dev::proto::kCapArchMove) != 0;
        deck.archPump = deck.archedMoves && (identity.protocolCapabilities & dev::proto::kCapArchPump) != 0;
    }
    const std::pair<char, motion::plates::AxisMotion*> axes[] = {{'X', &deck.x}, {'Y', &deck.y}, {'Z', &deck.z}, {'P', &deck.p}};
    for (const auto& [letter, motion] : axes) {
        const int i = identity.axisIndex(QLatin1Char(letter));
        if (i < 0)
            continue;
        const dev::AxisDescriptor& a = identity.axes[i];
        if (a.maxSpeed > 0)
            motion->maxSpeed = a.maxSpeed;
        if (!identity.reportsMotionLimits())
            continue;
        if (a.maxAccel > 0)
            motion->maxAccel = a.maxAccel;
        if (a.defaultSpeed > 0)
            motion->defaultSpeed = std::min(a.defaultSpeed, motion->maxSpeed);
        // Only seed 000's S-curve has a shortest acceleration phase; another planner is
        // timed as that curve held to its acceleration limit (motion::plates::moveTimeS).
        motion->accelTimeS = identity.motionProfile == dev::proto::MotionProfile::SeedSCurve ? a.minAccelTimeS : 0.0;
    }
    return deck;
}

} // namespace dev::jobs
