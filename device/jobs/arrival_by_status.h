#pragma once
// Events are not retransmitted, so a MotionDone lost on a noisy line would leave a job
// waiting for ever (or for a watchdog). The status is polled anyway: two readings taken
// after the move's reply, with every axis of the move at rest on its target, are the
// arrival. Events and replies share one ordered stream, so a MotionDone that was not
// lost came before those readings and the job has already gone on.
#include "device/client/instrument_types.h"

#include <cmath>
#include <utility>
#include <vector>

namespace dev::jobs {

class ArrivalByStatus {
public:
    /// A new move to `targets` (instrument axis index, position in mm): readings start over.
    void expect(std::vector<std::pair<int, double>> targets)
    {
        m_targets = std::move(targets);
        m_atRest = 0;
        m_firstRestUs = 0;
    }

    /// One status reading taken after the move was accepted. True on the second reading
    /// in a row at rest on the targets; `firstRestUs` is then the device time of the first.
    bool feed(const dev::InstrumentStatus& s, quint64* firstRestUs = nullptr)
    {
        if (m_targets.empty())
            return false;
        bool there = !s.anyMoving();
        for (const auto& [axis, mm] : m_targets)
            there = there && axis >= 0 && axis < s.axes.size() && std::fabs(s.axes[axis].commanded - mm) < kToleranceMm;
        if (!there) {
            m_atRest = 0;
            return false;
        }
        if (m_atRest++ == 0)
            m_firstRestUs = s.deviceTimeUs;
        if (m_atRest < 2)
            return false;
        if (firstRestUs)
            *firstRestUs = m_firstRestUs;
        m_targets.clear();  // once per move
        return true;
    }

private:
    /// The commanded position is the target itself once the move has ended (no rounding
    /// on the device beyond its µm resolution).
    static constexpr double kToleranceMm = 1e-3;
    std::vector<std::pair<int, double>> m_targets;
    int m_atRest = 0;
    quint64 m_firstRestUs = 0;
};

} // namespace dev::jobs
