// Character-counting streamer: the receive buffer is never overfilled, answers are matched to
// the oldest line, realtime bytes jump the queue, a reset clears the count.
#include "device/backends/grbl/grbl_streamer.h"

#include <gtest/gtest.h>

#include <deque>
#include <random>

namespace {

using namespace dev::grbl;

TEST(GrblStreamer, TheInterfaceDocumentsWorkedExample)
{
    // Lines of 25, 40, 31, 58 and 20 characters counting the line end, into a 128-byte buffer
    // (127 usable): the first three go at once (96), the fourth waits for the first ok,
    // the fifth for the second.
    Streamer s(128);
    for (int len : {25, 40, 31, 58, 20})
        ASSERT_EQ(s.enqueue(std::string(static_cast<std::size_t>(len - 1), 'G')), Streamer::Queued::Ok);
    EXPECT_EQ(s.takeOutput().size(), 96u);
    EXPECT_EQ(s.inFlightLines(), 3u);
    EXPECT_TRUE(s.takeOutput().empty());
    ASSERT_TRUE(s.acknowledge(true));
    EXPECT_TRUE(s.takeOutput().empty());  // 71 + 58 = 129 > 127
    ASSERT_TRUE(s.acknowledge(true));
    EXPECT_EQ(s.takeOutput().size(), 78u);  // 31 + 58 + 20 = 109 ≤ 127
    EXPECT_EQ(s.inFlightBytes(), 109u);
}

TEST(GrblStreamer, AnErrorNamesTheOldestLineAndStopsTheStream)
{
    Streamer s(64);
    s.enqueue("G1 X10 F600", 1);
    s.enqueue("G5 X1", 2);
    s.enqueue("G1 X20", 3);
    s.enqueue(std::string(50, 'G'), 4);
    s.takeOutput();
    EXPECT_EQ(s.inFlightLines(), 3u);
    const auto first = s.acknowledge(true);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->tag, 1u);
    const auto second = s.acknowledge(false, 20);
    ASSERT_TRUE(second);
    EXPECT_FALSE(second->ok);
    EXPECT_EQ(second->errorCode, 20);
    EXPECT_EQ(second->line, "G5 X1");
    EXPECT_EQ(second->tag, 2u);
    EXPECT_TRUE(s.stopped());
    EXPECT_TRUE(s.takeOutput().empty());  // the fourth line waits for the job's decision
    EXPECT_EQ(s.acknowledge(true)->tag, 3u);  // what was already in GRBL's buffer still runs
    s.resume();
    EXPECT_EQ(s.takeOutput(), std::string(50, 'G') + "\n");
}

TEST(GrblStreamer, RealtimeBytesGoFirstAndAreNotCounted)
{
    Streamer s(16);
    s.enqueue("G1 X1 F10");   // 10 bytes
    s.enqueue("G1 X2 F10");   // would make 20 > 15
    EXPECT_EQ(s.takeOutput(), "G1 X1 F10\n");
    EXPECT_TRUE(s.enqueueRealtime(rt::kStatusQuery));
    EXPECT_TRUE(s.enqueueRealtime(rt::kJogCancel));
    EXPECT_FALSE(s.enqueueRealtime('G'));
    EXPECT_EQ(s.takeOutput(), std::string("?\x85"));
    EXPECT_EQ(s.inFlightBytes(), 10u);
    s.acknowledge(true);
    s.enqueueRealtime(rt::kFeedHold);
    EXPECT_EQ(s.takeOutput(), "!G1 X2 F10\n");
}

TEST(GrblStreamer, LinesThatCouldHarmAreRefused)
{
    Streamer s(128);
    EXPECT_EQ(s.enqueue(""), Streamer::Queued::Empty);
    EXPECT_EQ(s.enqueue("G1 X1\nG1 X2"), Streamer::Queued::BadByte);
    EXPECT_EQ(s.enqueue("G1 X1\r"), Streamer::Queued::BadByte);
    EXPECT_EQ(s.enqueue("G1 X1 ?"), Streamer::Queued::BadByte);  // GRBL would answer a status report mid-line
    EXPECT_EQ(s.enqueue("G1 X1 !"), Streamer::Queued::BadByte);  // …or feed-hold
    EXPECT_EQ(s.enqueue(std::string(80, 'G')), Streamer::Queued::TooLong);
    EXPECT_EQ(s.enqueue(std::string(79, 'G')), Streamer::Queued::Ok);
    Streamer tiny(8);
    EXPECT_EQ(tiny.enqueue("G1 X100"), Streamer::Queued::TooLong);  // 8 bytes with '\n' > 7 usable
    EXPECT_EQ(s.queuedLines(), 1u);
}

TEST(GrblStreamer, ASoftResetClearsTheCountAndReportsTheLostLines)
{
    Streamer s;
    s.enqueue("G1 X10 F100", 7);
    s.enqueue("G1 X20", 8);
    s.enqueue("G1 X30", 9);
    s.takeOutput();
    s.acknowledge(true);
    const auto lost = s.softReset(false);
    ASSERT_EQ(lost.size(), 2u);
    EXPECT_EQ(lost[0].tag, 8u);
    EXPECT_EQ(lost[1].line, "G1 X30");
    EXPECT_EQ(s.inFlightBytes(), 0u);
    EXPECT_FALSE(s.acknowledge(true));  // a late ok from before the reset matches nothing
    EXPECT_EQ(s.strayAcks(), 1u);
}

/// The device end of the property test: a receive buffer of `capacity` bytes that loses what
/// does not fit (like GRBL's serial ISR) and consumes whole lines at its own pace.
struct DeviceModel {
    explicit DeviceModel(std::size_t usable) : capacity(usable) {}
    std::size_t capacity;
    std::deque<std::string> lines;
    std::string partial;
    std::size_t bytes = 0;
    std::size_t lost = 0;
    std::size_t maxBytes = 0;

    void receive(const std::string& data)
    {
        for (const char c : data) {
            if (rt::isRealtime(static_cast<std::uint8_t>(c)))
                continue;  // picked off on arrival
            if (bytes + 1 > capacity) {
                ++lost;
                continue;
            }
            ++bytes;
            maxBytes = std::max(maxBytes, bytes);
            partial.push_back(c);
            if (c == '\n') {
                lines.push_back(partial);
                partial.clear();
            }
        }
    }
    /// Parses the oldest line: it leaves the buffer.
    std::string consume()
    {
        std::string l = lines.front();
        lines.pop_front();
        bytes -= l.size();
        return l;
    }
};

TEST(GrblStreamer, NeverOverfillsTheBufferUnderRandomLinesAndPace)
{
    for (std::size_t rx : {std::size_t{128}, std::size_t{1024}, std::size_t{64}}) {
        std::mt19937_64 rng(0x5EED + rx);
        Streamer s(rx);
        DeviceModel dev(rx - 1);
        std::deque<std::string> expected;  // lines in the order they must be acknowledged
        std::uniform_int_distribution<int> len(1, static_cast<int>(std::min<std::size_t>(kMaxLineChars, rx - 2)));
        std::uniform_int_distribution<int> action(0, 9);
        std::size_t queued = 0, acked = 0, errors = 0;
        for (int step = 0; step < 20000; ++step) {
            const int a = action(rng);
            if (a < 4 && queued < 5000) {
                std::string line(static_cast<std::size_t>(len(rng)), 'G');
                line[0] = static_cast<char>('A' + queued % 26);
                ASSERT_EQ(s.enqueue(line, queued), Streamer::Queued::Ok);
                ++queued;
            } else if (a == 4) {
                s.enqueueRealtime(rt::kStatusQuery);
            } else if (a < 8) {
                const std::string out = s.takeOutput();
                dev.receive(out);
                ASSERT_LE(s.inFlightBytes(), s.capacityBytes());
            } else if (!dev.lines.empty()) {
                const std::string l = dev.consume();
                const bool fail = action(rng) == 0;  // now and then an error:N instead of ok
                const auto ack = s.acknowledge(!fail, fail ? 20 : 0);
                ASSERT_TRUE(ack);
                ASSERT_EQ(ack->line + "\n", l);  // the answer belongs to the oldest line
                ASSERT_EQ(ack->tag, acked);
                ++acked;
                if (fail) {
                    ++errors;
                    s.resume();
                }
            }
        }
        EXPECT_EQ(dev.lost, 0u) << rx;
        EXPECT_LE(dev.maxBytes, rx - 1) << rx;
        EXPECT_GT(dev.maxBytes, (rx - 1) * 3 / 4) << rx;  // and it keeps the buffer well filled
        EXPECT_GT(acked, 1000u);
        EXPECT_GT(errors, 10u);
    }
}

TEST(GrblStreamer, ABiggerBufferFromDollarITakesEffect)
{
    Streamer s;  // GRBL default 128
    for (int i = 0; i < 20; ++i)
        s.enqueue(std::string(49, 'G'));
    EXPECT_EQ(s.takeOutput().size(), 100u);  // two 50-byte lines in 127
    s.setRxBufferBytes(1024);                // grblHAL's [OPT:…,35,1024]
    EXPECT_EQ(s.takeOutput().size(), 900u);  // 20 lines of 50 in 1023 bytes: 18 more fit (total 20 = 1000 ≤ 1023)
    EXPECT_EQ(s.inFlightBytes(), 1000u);
}

} // namespace
