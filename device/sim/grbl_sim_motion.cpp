#include "device/sim/grbl_sim_motion.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

GrblMotion::GrblMotion(int axes, int capacityBlocks)
    : m_axes(axes), m_capacity(capacityBlocks), m_pos(static_cast<std::size_t>(axes), 0.0), m_end(m_pos)
{
}

bool GrblMotion::push(const std::vector<double>& target, double feedMmS, bool jog, long line,
                      std::vector<GrblBlock::Output> outputs, const Limits& lim, std::vector<GrblBlock::Output>* firedNow)
{
    if (freeBlocks() <= 0)
        return false;
    Block b;
    b.start = m_end;
    b.target = target;
    b.target.resize(static_cast<std::size_t>(m_axes), 0.0);
    b.unit.assign(static_cast<std::size_t>(m_axes), 0.0);
    double len2 = 0;
    for (int k = 0; k < m_axes; ++k) {
        const double d = b.target[static_cast<std::size_t>(k)] - b.start[static_cast<std::size_t>(k)];
        b.unit[static_cast<std::size_t>(k)] = d;
        len2 += d * d;
    }
    b.lengthMm = std::sqrt(len2);
    if (b.lengthMm < 1e-3) {
        if (firedNow)
            firedNow->insert(firedNow->end(), outputs.begin(), outputs.end());
        return true;
    }
    // Speed and acceleration along the block: no axis may exceed its own (GRBL's
    // limit_value_by_axis_maximum).
    double vMax = 1e300, aMax = 1e300;
    for (int k = 0; k < m_axes; ++k) {
        double& u = b.unit[static_cast<std::size_t>(k)];
        u /= b.lengthMm;
        const double au = std::fabs(u);
        if (au < 1e-12)
            continue;
        vMax = std::min(vMax, lim.maxRateMmS[static_cast<std::size_t>(k)] / au);
        aMax = std::min(aMax, lim.accelMmS2[static_cast<std::size_t>(k)] / au);
    }
    b.nominalMmS = feedMmS > 0 ? std::min(feedMmS, vMax) : vMax;
    b.accelMmS2 = aMax;
    b.jog = jog;
    b.line = line;
    b.outputs = std::move(outputs);
    if (m_queue.empty()) {
        b.maxEntryMmS = m_speedMmS;  // the machine is at rest when the queue is empty
    } else {
        // Junction deviation: the corner is taken as if rounded by a circle whose closest point
        // stays $11 from it, at the speed whose centripetal acceleration there is the block's.
        const Block& p = m_queue.back();
        double cosTheta = 0;
        for (int k = 0; k < m_axes; ++k)
            cosTheta -= p.unit[static_cast<std::size_t>(k)] * b.unit[static_cast<std::size_t>(k)];
        if (cosTheta > 0.999999) {
            b.maxEntryMmS = 0;  // a reversal
        } else if (cosTheta < -0.999999) {
            b.maxEntryMmS = 1e300;  // straight on
        } else {
            const double sinHalf = std::sqrt(0.5 * (1 - cosTheta));
            const double a = std::min(p.accelMmS2, b.accelMmS2);
            b.maxEntryMmS = std::sqrt(a * lim.junctionDeviationMm * sinHalf / (1 - sinHalf));
        }
        b.maxEntryMmS = std::min({b.maxEntryMmS, b.nominalMmS, p.nominalMmS});
    }
    m_end = b.target;
    m_queue.push_back(std::move(b));
    return true;
}

double GrblMotion::exitSpeedMmS() const
{
    // Backward pass from the end of the queue, which GRBL always plans to rest.
    double v = 0;
    for (std::size_t j = m_queue.size(); j-- > 1;) {
        const Block& b = m_queue[j];
        v = std::min({b.maxEntryMmS, b.nominalMmS, std::sqrt(v * v + 2 * b.accelMmS2 * b.lengthMm)});
    }
    return v;
}

void GrblMotion::tick(double dtS, std::vector<GrblBlock::Output>& fired)
{
    if (m_queue.empty()) {
        m_speedMmS = 0;
        return;
    }
    Block* b = &m_queue.front();
    if (!b->started) {
        b->started = true;
        fired.insert(fired.end(), b->outputs.begin(), b->outputs.end());
    }
    const double remaining = b->lengthMm - m_sMm;
    if (m_hold) {
        m_speedMmS = std::max(0.0, m_speedMmS - b->accelMmS2 * dtS);
    } else {
        const double vExit = exitSpeedMmS();
        const double vCap = std::min(b->nominalMmS, std::sqrt(vExit * vExit + 2 * b->accelMmS2 * std::max(0.0, remaining)));
        m_speedMmS = m_speedMmS < vCap ? std::min(vCap, m_speedMmS + b->accelMmS2 * dtS) : vCap;
    }
    m_sMm += m_speedMmS * dtS;
    while (m_sMm >= b->lengthMm) {
        const double over = m_sMm - b->lengthMm;
        m_pos = b->target;
        m_queue.pop_front();
        if (m_queue.empty()) {
            m_sMm = 0;
            m_speedMmS = 0;
            return;
        }
        b = &m_queue.front();
        b->started = true;
        fired.insert(fired.end(), b->outputs.begin(), b->outputs.end());
        m_sMm = over;
    }
    for (int k = 0; k < m_axes; ++k) {
        const auto i = static_cast<std::size_t>(k);
        m_pos[i] = b->start[i] + b->unit[i] * m_sMm;
    }
}

std::vector<double> GrblMotion::velocityMmS() const
{
    std::vector<double> v(static_cast<std::size_t>(m_axes), 0.0);
    if (!m_queue.empty())
        for (std::size_t k = 0; k < v.size(); ++k)
            v[k] = m_queue.front().unit[k] * m_speedMmS;
    return v;
}

void GrblMotion::flush()
{
    m_queue.clear();
    m_sMm = 0;
    m_speedMmS = 0;
    m_end = m_pos;
    m_hold = false;
}

void GrblMotion::resetTo(const std::vector<double>& positionMm)
{
    m_pos = positionMm;
    m_pos.resize(static_cast<std::size_t>(m_axes), 0.0);
    flush();
}

} // namespace dev::sim
