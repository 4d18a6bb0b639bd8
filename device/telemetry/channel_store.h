#pragma once
// One telemetry channel over a rolling window: a bounded ring of samples with a
// min/max pyramid, so a plot can ask "min and max per pixel column" at a cost
// that follows the screen width, not the number of samples. Plain C++ (no Qt):
// the GUI thread reads it in place, nothing is copied per frame.
//
// Not thread-safe: one thread appends and reads (the hub and the plots both live
// on the GUI thread). Memory is fixed at construction: about 4.53 bytes per slot
// (4 for the value, 0.53 for the pyramid) plus 32 bytes per time run.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace dev::tele {

struct MinMax {
    float min = std::numeric_limits<float>::quiet_NaN();  ///< NaN when no sample fell in the column
    float max = std::numeric_limits<float>::quiet_NaN();
    bool empty() const { return min != min; }
};

struct Sample {
    double tS;   ///< device clock, seconds
    float value; ///< channel units (mm, µL, mm/s, …)
};

class ChannelStore {
public:
    /// `capacity` samples at most; when full the oldest sample is overwritten
    /// (the stated overflow policy: the window slides, nothing else is lost).
    explicit ChannelStore(std::size_t capacity);
    /// A store of `capacity` holding the newest samples of `other` (as many as fit),
    /// times kept as they were: for resizing when the window or the rate changes.
    ChannelStore(const ChannelStore& other, std::size_t capacity);

    std::size_t capacity() const;
    std::size_t size() const;
    bool empty() const { return size() == 0; }
    /// Appends in time order; a sample older than the newest is dropped and counted.
    void append(double tS, float value);
    /// Appends `n` samples t0, t0+period, … taking every `stride`-th float of `values`.
    void appendRun(double t0S, double periodS, const float* values, std::size_t n, std::size_t stride = 1);
    /// Forgets samples older than tS.
    void trimBefore(double tS);
    void clear();

    double firstTime() const;  ///< NaN when empty
    double lastTime() const;   ///< NaN when empty
    Sample at(std::size_t i) const;  ///< i-th oldest retained sample, 0 ≤ i < size()
    /// Index of the first retained sample with t ≥ tS (size() if none).
    std::size_t lowerBound(double tS) const;
    /// The sample nearest to tS, for cursor readouts.
    std::optional<Sample> nearest(double tS) const;
    /// For each of `columns` equal columns spanning [t0S, t1S), the min and max of
    /// the samples inside. Every extreme of the data in range appears in some column.
    void decimate(double t0S, double t1S, int columns, MinMax* out) const;
    std::uint64_t outOfOrderDropped() const;

    /// Edge c (0 ≤ c ≤ columns) of decimate()'s columns: column c holds the samples
    /// with edge(c) ≤ t < edge(c+1); edge(0) = t0S and edge(columns) = t1S exactly.
    static double columnEdge(double t0S, double t1S, int columns, int c);
    /// Heap bytes this store holds (fixed after construction unless time runs pile up).
    std::size_t memoryBytes() const;

private:
    /// Times are not stored per sample: samples come in periodic runs (the device
    /// clock ticks evenly), so a run keeps its first time and period and sample k of
    /// the run is at t0S + k·periodS. A gap (paused stream, new subscription, other
    /// rate) starts a new run. An aperiodic source costs one run per two samples at
    /// worst, still bounded by the capacity.
    struct Run {
        std::uint64_t firstSeq = 0;  ///< sequence number of the run's first sample
        std::uint64_t count = 0;     ///< samples in the run (retained or not)
        double t0S = 0;
        double periodS = 0;          ///< 0 while the run holds one sample
        double timeAt(std::uint64_t k) const { return t0S + static_cast<double>(k) * periodS; }
        double lastTime() const { return timeAt(count - 1); }
    };
    /// Min and max of a block of slots; +inf/−inf when it holds no number.
    struct Extent {
        float min = std::numeric_limits<float>::infinity();
        float max = -std::numeric_limits<float>::infinity();
    };
    static constexpr unsigned kFanShift = 4;  ///< 16 children per pyramid block
    static constexpr std::size_t kFan = std::size_t(1) << kFanShift;
    static constexpr std::size_t kFanMask = kFan - 1;

    std::uint64_t oldestSeq() const { return m_nextSeq - m_count; }
    std::size_t oldestSlot() const { return (m_head + m_capacity - m_count) % m_capacity; }
    /// Index into m_runs of the run holding `seq` (which must be retained).
    std::size_t runOf(std::uint64_t seq) const;
    double timeOfSeq(std::uint64_t seq) const;
    /// Writes values into the ring at m_head, finishing pyramid blocks as they fill.
    void writeValues(const float* values, std::size_t n, std::size_t stride);
    void finishBlock(std::size_t lastSlot);
    /// Adds n samples at t0S + k·periodS to the run list (joining the last run if it continues).
    void addTimes(double t0S, double periodS, std::size_t n);
    void dropRunsBeforeOldest();
    /// Min/max of physical slots [lo, hi), which must lie inside one retained stretch.
    void extentOfSlots(std::size_t lo, std::size_t hi, Extent& e) const;

    // Ring of values: m_capacity slots; m_head is the slot the next sample goes to,
    // m_count the retained samples (the newest in slot m_head−1, the oldest in
    // oldestSlot()). head == oldest happens both when empty and when full: m_count
    // tells them apart. Slots outside the retained stretch hold stale values.
    std::size_t m_capacity;
    std::unique_ptr<float[]> m_values;
    std::size_t m_head = 0;
    std::size_t m_count = 0;
    /// Every appended sample gets the next sequence number; the oldest retained one is m_nextSeq − m_count.
    std::uint64_t m_nextSeq = 0;

    // Min/max pyramid over physical slots: m_levels[k][b] covers slots
    // [b·16^(k+1), (b+1)·16^(k+1)) (the last block of a level is cut at m_capacity).
    // A block's extent is computed when its last slot is written (level 0 from the
    // values, level k+1 from the 16 children when the last child finishes), so ingest
    // costs one compare per sample amortised. A block's extent is only ever used by a
    // query whose retained stretch contains the whole block; such a block was written
    // completely, in order, in the current lap, so its extent is exact. Blocks that
    // straddle the write head, the trim point or the ring's seam are never used whole:
    // queries descend to finer levels and finally to the raw values there.
    std::vector<std::vector<Extent>> m_levels;

    std::vector<Run> m_runs;       ///< in time order; runs before m_firstRun are dead
    std::size_t m_firstRun = 0;
    std::uint64_t m_outOfOrder = 0;
};

} // namespace dev::tele
