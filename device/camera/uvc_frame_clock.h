#pragma once
// When a USB camera's frame began to be exposed, on the host's steady clock, so that a
// capture takes the next frame whose exposure STARTED after it was asked for (camera.h).
//
// Qt gives each frame a start time on the stream's own clock (under GStreamer, the
// driver's start-of-exposure time less the pipeline's base time), not the host's. The
// offset between the two is learnt from the frames: arrival − stream start is the offset
// plus the frame's delay, so its smallest value over the frames is the offset plus the
// shortest delay. That delay is not known; it is at most about the exposure, one frame's
// readout and the pipeline's own slack, and the whole of that is taken off. So the rule
// errs towards skipping a frame or two more, never towards a frame that was already being
// exposed. A frame without a stream time is placed the same allowance plus one more frame
// period before it arrived.
//
// Plain C++; the camera's thread owns it.
#include <algorithm>
#include <cstdint>
#include <optional>

namespace dev::camera {

class UvcFrameClock {
public:
    static constexpr std::int64_t kFallbackPeriodUs = 100000;  ///< 10 frames a second: slower than any webcam's default
    static constexpr std::int64_t kPipelineSlackUs = 20000;    ///< USB transfer and the pipeline, beyond the readout

    /// `streamStartUs`, `streamEndUs`: the frame's times on the stream's clock, −1 when not
    /// known; `framePeriodUs`: the format's frame period, used when the frame does not say;
    /// `exposureUs`: the exposure as far as known (0: not known, one period is assumed).
    std::int64_t exposureStartHostUs(std::int64_t streamStartUs, std::int64_t streamEndUs, std::int64_t arrivedHostUs, std::int64_t framePeriodUs,
                                     std::int64_t exposureUs = 0)
    {
        std::int64_t periodUs = framePeriodUs > 0 ? framePeriodUs : kFallbackPeriodUs;
        if (streamStartUs >= 0 && streamEndUs > streamStartUs)
            periodUs = streamEndUs - streamStartUs;
        const std::int64_t allowanceUs = (exposureUs > 0 ? exposureUs : periodUs) + periodUs + kPipelineSlackUs;
        if (streamStartUs < 0)
            return arrivedHostUs - allowanceUs - periodUs;
        const std::int64_t offset = arrivedHostUs - streamStartUs;
        m_offsetUs = m_offsetUs ? std::min(*m_offsetUs, offset) : offset;
        return streamStartUs + *m_offsetUs - allowanceUs;
    }
    /// A new stream (the camera restarted or changed format): its clock starts again.
    void reset() { m_offsetUs.reset(); }

private:
    std::optional<std::int64_t> m_offsetUs;
};

} // namespace dev::camera
