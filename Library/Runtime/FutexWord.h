// A wake-up on a 32-bit atomic's own storage (Linux futex): waking its sleepers is one system
// call, with no lock and no allocation, so a haptic thread may raise it; and a sleeper that read
// the word before a change is not put to sleep after it (the kernel compares the word first).
// The threaded runtime's scene event and a tissue's solid thread (TissueDynamics) wait on one.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace proxima
{

/// Wakes every thread sleeping on `word` (sleepWhileUnchanged).
void wakeAllSleepers(std::atomic<std::uint32_t>& word);

/// Returns when `word` no longer holds `seen`, when woken, or after `limit`; a signal or a
/// spurious wake-up returns early too, so the caller checks its condition again.
void sleepWhileUnchanged(std::atomic<std::uint32_t>& word, std::uint32_t seen,
                         std::chrono::nanoseconds limit);

} // namespace proxima
