// A lock-free snapshot of a trivially copyable value, written by one thread and read by any: a
// sequence lock whose payload is stored as relaxed atomic words, so there is no data race for the
// compiler or ThreadSanitizer to find. The writer never waits; a reader retries only while a write
// of a few hundred bytes is in progress, so some thread always makes progress.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace proxima
{

/// A lock-free snapshot of a trivially copyable `T`: one writer thread publishes whole values,
/// any thread reads the last complete one.
template <typename T>
class SnapshotChannel
{
  static_assert(std::is_trivially_copyable_v<T>, "a snapshot is copied word by word");
  static constexpr std::size_t kWords =
    (sizeof(T) + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t);

public:
  /// Holds `T{}`, which counts as the first write.
  SnapshotChannel() { write(T{}); }

  /// Publishes `value`. One writer thread only.
  void write(const T& value)
  {
    std::uint64_t words[kWords] = {};
    std::memcpy(words, &value, sizeof(T));
    const std::uint64_t sequence = m_sequence.load(std::memory_order_relaxed);
    // Odd while writing: readers that saw the old even value will see the change and retry.
    m_sequence.store(sequence + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t i = 0; i < kWords; ++i)
    {
      m_words[i].store(words[i], std::memory_order_relaxed);
    }
    m_sequence.store(sequence + 2, std::memory_order_release);
  }

  /// The last complete value written.
  T read() const
  {
    std::uint64_t words[kWords];
    for (;;)
    {
      const std::uint64_t before = m_sequence.load(std::memory_order_acquire);
      if ((before & 1U) != 0)
      {
        continue;
      }
      for (std::size_t i = 0; i < kWords; ++i)
      {
        words[i] = m_words[i].load(std::memory_order_relaxed);
      }
      std::atomic_thread_fence(std::memory_order_acquire);
      if (m_sequence.load(std::memory_order_relaxed) == before)
      {
        break;
      }
    }
    T value;
    std::memcpy(&value, words, sizeof(T));
    return value;
  }

  /// How many writes there have been (a reader can tell whether anything new arrived).
  std::uint64_t writes() const { return m_sequence.load(std::memory_order_acquire) / 2; }

private:
  std::atomic<std::uint64_t> m_sequence{0};
  std::atomic<std::uint64_t> m_words[kWords];
};

} // namespace proxima
