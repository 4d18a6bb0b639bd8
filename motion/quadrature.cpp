#include "motion/quadrature.h"

namespace motion {

namespace {
int stateOf(bool a, bool b)
{
    // 00 → 0, 10 → 1, 11 → 2, 01 → 3 (Gray order with A leading)
    static constexpr int kIndex[2][2] = {{0, 3}, {1, 2}};  // [a][b]
    return kIndex[a ? 1 : 0][b ? 1 : 0];
}
}  // namespace

QuadratureDecoder::QuadratureDecoder(QuadratureMode mode, bool a, bool b) : m_mode(mode), m_state(stateOf(a, b)) {}

int QuadratureDecoder::update(bool a, bool b)
{
    const int next = stateOf(a, b);
    const int delta = (next - m_state + 4) % 4;
    const int from = m_state;
    m_state = next;
    if (delta == 0)
        return 0;
    if (delta == 2) {
        ++m_illegal;
        return 0;
    }
    const int step = delta == 1 ? +1 : -1;
    m_direction = step;
    // The pair of states this transition joins, as the lower index of the edge (edge 3 is 3↔0).
    const int edge = step > 0 ? from : next;
    bool counts = true;
    switch (m_mode) {
    case QuadratureMode::X4: counts = true; break;
    case QuadratureMode::X2: counts = edge == 0 || edge == 2; break;  // A changes on 0↔1 and 2↔3
    case QuadratureMode::X1: counts = edge == 0; break;               // A edges with B low
    }
    if (!counts)
        return 0;
    m_count += step;
    return step;
}

}  // namespace motion
