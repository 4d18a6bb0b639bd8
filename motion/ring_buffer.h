#pragma once
// Fixed-size single-producer / single-consumer ring buffer (seed 004: one planner thread inserts
// blocks, the timer interrupt consumes them).
//
// Indices: m_head is the next slot the PRODUCER writes, m_tail the next slot the CONSUMER reads;
// both only move forward modulo N. One slot is always left empty, so
//   head == tail              ⇔ empty,
//   (head + 1) % N == tail    ⇔ full,
// and capacity() is N - 1. head == tail therefore never means both. Each index is written by one
// side only (head by the producer, tail by the consumer), published with release and read with
// acquire, so no lock is needed.
// Overflow policy: tryPush() on a full buffer returns false and stores nothing; the producer keeps
// the item and retries (the seed's insert thread waits for the interrupt to free a slot).
// Underflow: tryPop() on an empty buffer returns false (the seed's interrupt waits a period).

#include <array>
#include <atomic>
#include <cstddef>
#include <optional>

namespace motion {

template <class T, std::size_t N>
class RingBuffer {
    static_assert(N >= 2, "one slot is kept empty, so N >= 2");

public:
    static constexpr std::size_t capacity() { return N - 1; }

    bool tryPush(const T& item)
    {
        const std::size_t head = m_head.load(std::memory_order_relaxed);
        const std::size_t next = (head + 1) % N;
        if (next == m_tail.load(std::memory_order_acquire))
            return false;  // full
        m_slots[head] = item;
        m_head.store(next, std::memory_order_release);
        return true;
    }

    std::optional<T> tryPop()
    {
        const std::size_t tail = m_tail.load(std::memory_order_relaxed);
        if (tail == m_head.load(std::memory_order_acquire))
            return std::nullopt;  // empty
        T item = m_slots[tail];
        m_tail.store((tail + 1) % N, std::memory_order_release);
        return item;
    }

    /// CONSUMER side: the i-th oldest item (0 = the next tryPop() would return), or nullptr when
    /// fewer are queued. For a consumer that plans over what is queued before taking it (the
    /// device's path queue looks ahead over every queued segment); the producer never writes a
    /// slot between tail and head, so reading them races with nothing.
    const T* peek(std::size_t i) const
    {
        const std::size_t tail = m_tail.load(std::memory_order_relaxed);
        const std::size_t head = m_head.load(std::memory_order_acquire);
        if (i >= (head + N - tail) % N)
            return nullptr;
        return &m_slots[(tail + i) % N];
    }
    /// CONSUMER side: forgets everything queued (tail catches up with head).
    void clear() { m_tail.store(m_head.load(std::memory_order_acquire), std::memory_order_release); }

    /// Exact only when called from one side while the other is idle; otherwise a snapshot.
    std::size_t size() const
    {
        const std::size_t head = m_head.load(std::memory_order_acquire);
        const std::size_t tail = m_tail.load(std::memory_order_acquire);
        return (head + N - tail) % N;
    }
    bool empty() const { return size() == 0; }
    bool full() const { return size() == capacity(); }

private:
    std::array<T, N> m_slots{};
    std::atomic<std::size_t> m_head{0};  ///< next write slot (producer-owned)
    std::atomic<std::size_t> m_tail{0};  ///< next read slot (consumer-owned)
};

}  // namespace motion
