#include "Runtime/FutexWord.h"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>
#include <ctime>

namespace proxima
{
namespace
{
static_assert(std::atomic<std::uint32_t>::is_always_lock_free &&
              sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t));

std::uint32_t* futexWord(std::atomic<std::uint32_t>& word)
{
  return reinterpret_cast<std::uint32_t*>(&word);
}
} // namespace

void wakeAllSleepers(std::atomic<std::uint32_t>& word)
{
  syscall(SYS_futex, futexWord(word), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

void sleepWhileUnchanged(std::atomic<std::uint32_t>& word, std::uint32_t seen,
                         std::chrono::nanoseconds limit)
{
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(limit);
  timespec relative{};
  relative.tv_sec = static_cast<time_t>(seconds.count());
  relative.tv_nsec = static_cast<long>((limit - seconds).count());
  syscall(SYS_futex, futexWord(word), FUTEX_WAIT_PRIVATE, seen, &relative, nullptr, 0);
}

} // namespace proxima
