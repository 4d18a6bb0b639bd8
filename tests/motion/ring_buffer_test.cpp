// Seed 004 ring buffer: one slot kept empty, SPSC.
#include "motion/ring_buffer.h"

#include <gtest/gtest.h>

#include <thread>

using motion::RingBuffer;

TEST(RingBuffer, HoldsNMinusOneAndRejectsWhenFull)
{
    RingBuffer<int, 4> rb;
    EXPECT_EQ(rb.capacity(), 3u);
    EXPECT_TRUE(rb.empty());
    EXPECT_FALSE(rb.tryPop());
    EXPECT_TRUE(rb.tryPush(1));
    EXPECT_TRUE(rb.tryPush(2));
    EXPECT_TRUE(rb.tryPush(3));
    EXPECT_TRUE(rb.full());
    EXPECT_FALSE(rb.tryPush(4));  // overflow policy: refuse, keep what is stored
    EXPECT_EQ(rb.size(), 3u);
    EXPECT_EQ(*rb.tryPop(), 1);
    EXPECT_TRUE(rb.tryPush(4));  // wraps around
    EXPECT_EQ(*rb.tryPop(), 2);
    EXPECT_EQ(*rb.tryPop(), 3);
    EXPECT_EQ(*rb.tryPop(), 4);
    EXPECT_TRUE(rb.empty());  // head == tail again, and it means empty
}

TEST(RingBuffer, ProducerAndConsumerThreadsLoseNothing)
{
    RingBuffer<long, 16> rb;
    constexpr long kItems = 200000;
    std::thread producer([&] {
        for (long i = 0; i < kItems;)
            if (rb.tryPush(i))
                ++i;
            else
                std::this_thread::yield();
    });
    long expected = 0;
    while (expected < kItems) {
        if (auto v = rb.tryPop()) {
            ASSERT_EQ(*v, expected);
            ++expected;
        } else {
            std::this_thread::yield();
        }
    }
    producer.join();
    EXPECT_TRUE(rb.empty());
}
