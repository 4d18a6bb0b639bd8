#pragma once
// The simulated GRBL's planner and step generator, after GRBL's own: a bounded queue of
// straight blocks (arcs arrive as chords), each with a nominal speed and acceleration along
// it limited by every axis' $11x/$12x; a junction speed from $11 (junction deviation) between
// blocks; and the rule that makes GRBL safe with a host that vanishes — the queue is always
// planned to come to rest at its end. Feed hold decelerates along the path (across blocks if
// it must) and keeps the rest; resume carries on from there.
//
// Positions are GRBL machine positions in mm, one per GRBL axis; the firmware maps them onto
// the SimMachine's axes every tick.
#include "device/sim/grbl_sim_gcode.h"

#include <deque>
#include <vector>

namespace dev::sim {

class GrblMotion {
public:
    struct Limits {
        std::vector<double> maxRateMmS, accelMmS2;  ///< per axis
        double junctionDeviationMm = 0.01;
    };

    GrblMotion(int axes, int capacityBlocks);

    int capacity() const { return m_capacity; }
    int freeBlocks() const { return m_capacity - static_cast<int>(m_queue.size()); }
    bool empty() const { return m_queue.empty(); }
    bool moving() const { return !m_queue.empty(); }
    /// The queue holds jog blocks (GRBL's Jog state) rather than G-code ones.
    bool jogging() const { return !m_queue.empty() && m_queue.front().jog; }
    long currentLine() const { return m_queue.empty() ? 0 : m_queue.front().line; }

    /// Queues a straight move from where the queue ends. `feedMmS` 0 means rapid (G0: each
    /// axis' max rate). A move shorter than 1 µm is dropped, like GRBL drops zero-step blocks;
    /// its outputs then go to `firedNow`. False when the queue is full.
    bool push(const std::vector<double>& targetMm, double feedMmS, bool jog, long line,
              std::vector<GrblBlock::Output> outputs, const Limits& limits,
              std::vector<GrblBlock::Output>* firedNow = nullptr);

    /// One tick: moves along the queue and appends the outputs of blocks that began to `fired`.
    void tick(double dtS, std::vector<GrblBlock::Output>& fired);

    /// Feed hold: slow down along the path to rest (holdComplete()), keeping what is queued.
    void hold() { m_hold = true; }
    void resume() { m_hold = false; }
    bool holding() const { return m_hold; }
    bool holdComplete() const { return m_hold && m_speedMmS == 0; }
    /// Discards the queue where the machine stands (after a completed hold, or a reset).
    void flush();
    /// A new position for everything (power-up, homing, reset): queue cleared, at rest.
    void resetTo(const std::vector<double>& positionMm);

    const std::vector<double>& positionMm() const { return m_pos; }
    const std::vector<double>& plannedEndMm() const { return m_end; }
    double speedMmS() const { return m_speedMmS; }
    /// Velocity of each axis now, mm/s.
    std::vector<double> velocityMmS() const;

private:
    struct Block {
        std::vector<double> start, target, unit;
        double lengthMm = 0;
        double nominalMmS = 0;
        double accelMmS2 = 0;
        double maxEntryMmS = 0;
        bool jog = false;
        bool started = false;
        long line = 0;
        std::vector<GrblBlock::Output> outputs;
    };
    double exitSpeedMmS() const;

    int m_axes;
    int m_capacity;
    std::deque<Block> m_queue;
    std::vector<double> m_pos, m_end;
    double m_sMm = 0;       ///< distance done along the front block
    double m_speedMmS = 0;
    bool m_hold = false;
};

} // namespace dev::sim
