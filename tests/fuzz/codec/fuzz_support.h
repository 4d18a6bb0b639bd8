#pragma once
// What the protocol fuzz driver's parts share: the failure report, the
// deterministic RNG, coverage counters. fuzz_codec.cpp holds the checks,
// fuzz_inputs.cpp the standalone input generator and main().
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"

#include <array>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace fuzz {

using Bytes = std::vector<std::uint8_t>;
using dev::proto::DecoderStats;
using dev::proto::Frame;
using dev::proto::FrameDecoder;
using dev::proto::MsgType;



extern const Bytes* g_input;  ///< the input under test, saved when an invariant fails
extern std::uint64_t g_iteration;

/// What the inputs reached, printed at the end so a generator that stops
/// producing interesting inputs is noticed.
struct Coverage {
    std::uint64_t frames = 0, crcErrors = 0, malformed = 0, oversize = 0;
    std::uint64_t payloadsAccepted = 0, executed = 0, duplicates = 0, errorReplies = 0, events = 0, batches = 0;
    std::array<std::uint64_t, 16> errorByCode{}, eventByKind{};
};
extern Coverage g_cov;

[[noreturn]] void fail(const char* fmt, ...);

#define CHECK(cond, ...)         \
    do {                         \
        if (!(cond))             \
            fail(__VA_ARGS__);   \
    } while (0)

/// SplitMix64: the same sequence with every compiler and standard library.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : m_s(seed) {}
    std::uint64_t next()
    {
        std::uint64_t z = (m_s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n); n > 0.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
    std::int64_t range(std::int64_t lo, std::int64_t hi) { return lo + static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool chance(unsigned percent) { return below(100) < percent; }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }

private:
    std::uint64_t m_s;
};

inline std::uint64_t hashBytes(const std::uint8_t* p, std::size_t n)
{
    std::uint64_t h = 0xCBF29CE484222325ull;
    for (std::size_t i = 0; i < n; ++i)
        h = (h ^ p[i]) * 0x100000001B3ull;
    return h;
}

inline bool sameFrame(const Frame& a, const Frame& b) { return a.type == b.type && a.seq == b.seq && a.payload == b.payload; }
inline bool sameStats(const DecoderStats& a, const DecoderStats& b)
{
    return a.frames == b.frames && a.crcErrors == b.crcErrors && a.malformed == b.malformed && a.oversize == b.oversize
        && a.droppedBytes == b.droppedBytes;
}
inline std::string statsText(const DecoderStats& s)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, "frames %" PRIu64 " crc %" PRIu64 " malformed %" PRIu64 " oversize %" PRIu64 " dropped %" PRIu64,
                  s.frames, s.crcErrors, s.malformed, s.oversize, s.droppedBytes);
    return buf;
}

/// Runs every check on one input; exits (or aborts under libFuzzer) on a violation.
void fuzzOne(const std::uint8_t* data, std::size_t size);

} // namespace fuzz
