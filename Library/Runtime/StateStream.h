// Every tick's state, from the servo thread to one reader (the trainer's live scorer, a recorder):
// a preallocated single-producer, single-consumer ring. The servo thread's push never waits and
// never allocates: when the reader has fallen a whole ring behind, the state is dropped and
// counted, so a stalled window costs the haptic loop nothing. The reader drains what has arrived,
// in tick order. ThreadedRuntime owns one when RuntimeSettings::streamCapacity is not 0.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace proxima
{

/// A preallocated single-producer, single-consumer ring of trivially copyable `T`: the producer
/// never waits nor allocates, and drops what does not fit.
template <typename T>
class StateStream
{
  static_assert(std::is_trivially_copyable_v<T>, "states are copied into preallocated slots");

public:
  /// Holds up to `capacity` states not yet drained (at least 1).
  explicit StateStream(std::size_t capacity)
    : m_slots(capacity > 0 ? capacity + 1 : 2)
  {}

  /// The producer's side (one thread): false when the ring is full and `value` was dropped.
  bool push(const T& value)
  {
    const std::size_t head = m_head.load(std::memory_order_relaxed);
    const std::size_t next = head + 1 == m_slots.size() ? 0 : head + 1;
    if (next == m_tail.load(std::memory_order_acquire))
    {
      m_dropped.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    m_slots[head] = value;
    // Release: the reader that sees the new head sees the slot written.
    m_head.store(next, std::memory_order_release);
    return true;
  }

  /// The consumer's side (one thread): appends every state pushed and not yet drained to `out`,
  /// oldest first, and returns how many.
  std::size_t drain(std::vector<T>& out)
  {
    std::size_t tail = m_tail.load(std::memory_order_relaxed);
    const std::size_t head = m_head.load(std::memory_order_acquire);
    std::size_t count = 0;
    while (tail != head)
    {
      out.push_back(m_slots[tail]);
      tail = tail + 1 == m_slots.size() ? 0 : tail + 1;
      ++count;
    }
    // Release: the producer that sees the new tail may reuse the slots just copied.
    m_tail.store(tail, std::memory_order_release);
    return count;
  }

  /// States dropped because the ring was full; any thread.
  std::uint64_t dropped() const { return m_dropped.load(std::memory_order_relaxed); }

private:
  std::vector<T> m_slots;
  // Apart, so that the two threads' writes do not share a cache line.
  alignas(64) std::atomic<std::size_t> m_head{0};
  alignas(64) std::atomic<std::size_t> m_tail{0};
  alignas(64) std::atomic<std::uint64_t> m_dropped{0};
};

} // namespace proxima
