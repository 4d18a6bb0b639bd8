#pragma once
// Quadrature decoding of A/B encoder signals (seed 003's handle encoder; seed 002's grating
// scales through an HCTL-2032 at ×4).
//
// The AB states in the order they pass when A leads B (the seed's clockwise, counted up):
//   00 → 10 → 11 → 01 → 00,   i.e. index 0, 1, 2, 3.
// A change of +1 index counts up, -1 counts down, +2 means both lines changed between two
// samples: the direction is unknown, so the count is left alone and the transition is counted as
// illegal (sample faster than the encoder can move).
//   ×4: every legal transition counts.
//   ×2: only transitions where A changes (00↔10, 11↔01).
//   ×1: only 00↔10 — A rising with B low counts up, A falling with B low counts down; this is the
//       seed 003 circuit, where a D flip-flop clocked by B latches A to steer A's pulses up or down.

#include <cstdint>

namespace motion {

enum class QuadratureMode { X1, X2, X4 };

class QuadratureDecoder {
public:
    explicit QuadratureDecoder(QuadratureMode mode = QuadratureMode::X4, bool a = false, bool b = false);

    /// Feeds one sample; returns the change of count (-1, 0 or +1).
    int update(bool a, bool b);

    std::int64_t count() const { return m_count; }
    int direction() const { return m_direction; }  ///< +1 A leads B, -1 B leads A, 0 nothing yet
    std::uint64_t illegalTransitions() const { return m_illegal; }
    void reset(std::int64_t count = 0) { m_count = count; }

private:
    QuadratureMode m_mode;
    int m_state;  ///< 0..3, see the header comment
    std::int64_t m_count = 0;
    int m_direction = 0;
    std::uint64_t m_illegal = 0;
};

}  // namespace motion
