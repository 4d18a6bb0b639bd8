#include "motion/control/pid.h"

namespace motion::control {

double IncrementalPid::step(double e)
{
    const double du = m_gains.kp * (e - m_e1) + m_gains.ki * e + m_gains.kd * (e - 2 * m_e1 + m_e2);
    m_e2 = m_e1;
    m_e1 = e;
    m_u += du;
    return du;
}

void IncrementalPid::reset(double u)
{
    m_e1 = m_e2 = 0;
    m_u = u;
}

} // namespace motion::control
