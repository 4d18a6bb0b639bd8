#pragma once
// One telemetry channel over a rolling window: a bounded ring of samples with a
// min/max pyramid, so a plot can ask "min and max per pixel column" at a cost
// that follows the screen width, not the number of samples. Plain C++ (no Qt):
// the GUI thread reads it in place, nothing is copied per frame.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace tele {

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

private:
    // Layout is the implementer's: a ring of samples (head/count documented) and
    // per-level min/max blocks kept up to date on append.
};

} // namespace tele
