#include "device/jobs/accuracy/manual_source.h"

#include <cmath>
#include <utility>

namespace dev::jobs {

void ManualSource::take(const StopContext& stop, TakeDone done)
{
    m_stop = stop;
    m_done = std::move(done);
    emit entryWanted(stop);
}

void ManualSource::cancel()
{
    const bool was = m_stop.has_value();
    m_stop.reset();
    m_done = {};
    if (was)
        emit entryDone();
}

bool ManualSource::provide(const std::vector<double>& valuesMm)
{
    if (!m_stop || valuesMm.size() != m_stop->axes.size())
        return false;
    for (double v : valuesMm)
        if (!std::isfinite(v))
            return false;
    auto done = std::exchange(m_done, {});
    m_stop.reset();
    emit entryDone();
    TakeResult r;
    r.valuesMm = valuesMm;
    if (done)
        done(r);
    return true;
}

} // namespace dev::jobs
