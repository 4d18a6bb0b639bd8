// The plate run's waits on the device's own clock: a recipe's seconds are the
// instrument's, which a sped-up simulator runs faster than the wall.
#include "device/jobs/recipe_runner.h"

#include <QPointer>

#include <algorithm>
#include <cmath>

namespace dev::jobs {

using motion::plates::MoveKind;

double RecipeRunner::deviceRate() const
{
    // The device's seconds per wall second this stretch: 1 on the instrument, the time
    // scale on a sped-up simulator.
    const double wallS = m_clock.isValid() ? m_clock.elapsed() / 1000.0 : 0.0;
    const double deviceS = static_cast<double>(m_deviceLastUs - std::min(m_deviceStartUs, m_deviceLastUs)) / 1e6;
    return wallS > 0.5 && deviceS > 0 ? std::clamp(deviceS / wallS, 0.01, 1000.0) : 1.0;
}

void RecipeRunner::checkDwell(bool begin)
{
    // A wait lasts its seconds on the device's clock, where the plan's seconds are
    // counted: the wall clock's timer sleeps part of what is left (at the device's
    // rate), then a fresh status says what is left. Never short, and a sped-up
    // simulator's wait is its plan's.
    if (!m_inFlight || m_inFlight->kind != MoveKind::Dwell)
        return;
    const QPointer<RecipeRunner> self(this);
    const int serial = m_moveSerial;
    m_client->readStatus([this, self, serial, begin](const std::optional<dev::RequestError>& err, const dev::InstrumentStatus& st) {
        if (!self || serial != m_moveSerial || !m_inFlight || m_inFlight->kind != MoveKind::Dwell || !runActive(m_state))
            return;
        if (err) {
            stopRun(linkLostMessage());
            return;
        }
        if (st.deviceTimeUs > m_deviceLastUs)
            m_deviceLastUs = st.deviceTimeUs;
        if (begin) {
            m_dwellStartUs = st.deviceTimeUs;
            m_dwellWall.start();
        }
        const double doneS = static_cast<double>(st.deviceTimeUs - std::min(m_dwellStartUs, st.deviceTimeUs)) / 1e6;
        const double leftS = m_inFlight->seconds - doneS;
        if (leftS <= 0) {
            moveArrived();
            return;
        }
        // Half of what seems left at the device's rate, then look again. The rate is the
        // faster of the run's and the wait's own: a wait runs faster than the moves
        // before it on a simulator stepped by a loop with nothing else to do, and half
        // a wait misjudged by more than twice would overshoot it. The first look comes
        // at once, to learn the wait's own rate.
        // (At most kMoveCheckMs at a time: before the rate is known it is taken as 1.)
        const double wallS = m_dwellWall.nsecsElapsed() / 1e9;
        const double waitRate = wallS > 0 && doneS > 0 ? doneS / wallS : 0.0;
        const double rate = std::max(deviceRate(), waitRate);
        const int sleepMs = begin ? 1 : static_cast<int>(std::lround(0.5 * leftS / rate * 1000));
        m_dwellTimer.start(std::clamp(sleepMs, 1, kMoveCheckMs));
    });
}

} // namespace dev::jobs
