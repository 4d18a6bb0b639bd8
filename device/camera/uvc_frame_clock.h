#pragma once
// When a USB camera's frame began to be exposed, on the host's steady clock, so that a
// capture takes the next frame whose exposure STARTED after it was asked for (camera.h).
//
// Qt gives each frame a start time on the stream's own clock (microseconds from the
// stream's start), not the host's. The offset between the two is learnt from the frames
// themselves: arrival − stream start is the offset plus the frame's delay, so its smallest
// value over the frames is the offset plus the shortest delay. The start is then placed one
// frame period earlier than that, because the shortest delay is at most about a frame
// period (the frame is read out and sent while the next is exposed); the rule errs towards
// skipping one more frame, never towards a frame already being exposed. A frame without a
// stream time is placed two periods before it arrived.
//
// Plain C++; the camera's thread owns it.
#include <algorithm>
#include <cstdint>
#include <optional>

namespace dev::camera {

class UvcFrameClock {
public:
    /// `streamStartUs`, `streamEndUs`: the frame's times on the stream's clock, −1 when not
    /// known; `framePeriodUs`: the format's frame period, used when the frame does not say.
    std::int64_t exposureStartHostUs(std::int64_t streamStartUs, std::int64_t streamEndUs, std::int64_t arrivedHostUs, std::int64_t framePeriodUs)
    {
        std::int64_t periodUs = framePeriodUs > 0 ? framePeriodUs : kFallbackPeriodUs;
        if (streamStartUs >= 0 && streamEndUs > streamStartUs)
            periodUs = streamEndUs - streamStartUs;
        if (streamStartUs < 0)
            return arrivedHostUs - 2 * periodUs;
        const std::int64_t offset = arrivedHostUs - streamStartUs;
        m_offsetUs = m_offsetUs ? std::min(*m_offsetUs, offset) : offset;
        return streamStartUs + *m_offsetUs - periodUs;
    }
    /// A new stream (the camera restarted or changed format): its clock starts again.
    void reset() { m_offsetUs.reset(); }

    static constexpr std::int64_t kFallbackPeriodUs = 100000;  ///< 10 frames a second: slower than any webcam's default

private:
    std::optional<std::int64_t> m_offsetUs;
};

} // namespace dev::camera
