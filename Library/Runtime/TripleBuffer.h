// A lock-free hand-over of a value too large or too variable for a SnapshotChannel (a deforming
// surface's points): three buffers, one the writer fills, one the reader draws from, and one
// between them that an atomic exchange swaps with either side. Neither side waits or copies on
// the other's behalf, and neither allocates after construction, so the writer may be a haptic
// thread. One writer thread and one reader thread.
#pragma once

#include <atomic>
#include <cstdint>

namespace proxima
{

/// Three copies of a `T`: the writer fills back() and publish()es it; the reader take()s the
/// newest published one and reads front() until its next take(). Values the reader was too slow
/// for are skipped, never queued.
template <typename T>
class TripleBuffer
{
public:
  /// Every buffer a copy of `initial` (its size is the room each keeps: a writer that only
  /// overwrites elements in place never allocates); front() reads it until the first take().
  explicit TripleBuffer(const T& initial)
    : m_buffers{initial, initial, initial}
  {}
  TripleBuffer(const TripleBuffer&) = delete;
  TripleBuffer& operator=(const TripleBuffer&) = delete;

  /// The writer's buffer: what it held after its last-but-two publish, to be overwritten.
  T& back() { return m_buffers[m_back]; }
  /// Hands back() to the reader; back() is then another buffer.
  void publish()
  {
    const std::uint8_t given = static_cast<std::uint8_t>(m_back | kFresh);
    m_back =
      static_cast<std::uint8_t>(m_middle.exchange(given, std::memory_order_acq_rel) & kIndex);
  }

  /// The reader: makes front() the newest published value and returns true, or returns false
  /// (front() unchanged) when nothing was published since the last take.
  bool take()
  {
    if ((m_middle.load(std::memory_order_acquire) & kFresh) == 0)
    {
      return false;
    }
    m_front =
      static_cast<std::uint8_t>(m_middle.exchange(m_front, std::memory_order_acq_rel) & kIndex);
    return true;
  }
  /// The reader's buffer.
  const T& front() const { return m_buffers[m_front]; }

private:
  static constexpr std::uint8_t kIndex = 3;
  static constexpr std::uint8_t kFresh = 4;
  T m_buffers[3];
  /// The writer's index (only the writer touches it).
  std::uint8_t m_back = 0;
  /// The index between the two, with kFresh while it holds a value the reader has not taken.
  std::atomic<std::uint8_t> m_middle{1};
  /// The reader's index (only the reader touches it).
  std::uint8_t m_front = 2;
};

} // namespace proxima
