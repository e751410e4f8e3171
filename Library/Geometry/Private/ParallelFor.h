// A parallel for over an index range in the shape of vtkSMPTools::For, in plain C++ (std::thread)
// so that the kernel can build its trees in parallel without VTK. A functor has
// operator()(begin, end) and, optionally, Initialize() (once on each thread before its first
// chunk) and Reduce() (once on the calling thread after every chunk is done). Chunks are fixed:
// [begin + k * grain, begin + (k + 1) * grain), so a functor that keys its output by chunk gets
// the same result whatever the number of threads or the order they ran in. Build-time code only:
// it starts threads, never for the haptic thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace proxima::detail
{

/// The threads a request for `numThreads` gets: 0 means one per hardware thread.
inline unsigned resolveThreadCount(unsigned numThreads)
{
  if (numThreads == 0)
  {
    numThreads = std::max(1u, std::thread::hardware_concurrency());
  }
  return numThreads;
}

/// Which of the threads of the running parallelFor this is: 0 on the calling thread, 1 to
/// threads - 1 on the others (0 outside any parallelFor). Indexes WorkerLocal.
inline unsigned& currentWorker()
{
  thread_local unsigned worker = 0;
  return worker;
}

/// One T per thread of a parallelFor, like vtkSMPThreadLocal: local() is the calling thread's.
template <typename T>
class WorkerLocal
{
public:
  explicit WorkerLocal(unsigned numThreads, const T& initial = T{})
    : m_values(resolveThreadCount(numThreads), initial)
  {}
  T& local() { return m_values[currentWorker()]; }
  /// Every thread's value, in thread order, for Reduce.
  std::vector<T>& all() { return m_values; }

private:
  std::vector<T> m_values;
};

/// Runs `functor` over [begin, end) in chunks of `grain` on up to `numThreads` threads (0: one
/// per hardware thread; the calling thread is one of them). One thread, or one chunk, runs
/// inline without starting a thread. The first exception a chunk throws is rethrown here after
/// every thread has stopped.
template <typename Functor>
void parallelFor(std::size_t begin, std::size_t end, std::size_t grain, Functor& functor,
                 unsigned numThreads = 0)
{
  if (end <= begin)
  {
    return;
  }
  grain = std::max<std::size_t>(1, grain);
  const std::size_t numChunks = (end - begin + grain - 1) / grain;
  const unsigned threads =
    static_cast<unsigned>(std::min<std::size_t>(resolveThreadCount(numThreads), numChunks));

  std::atomic<std::size_t> nextChunk{0};
  std::atomic<bool> failed{false};
  std::exception_ptr firstError;
  std::mutex errorMutex;
  auto work = [&](unsigned worker) {
    const unsigned outer = currentWorker();
    currentWorker() = worker;
    try
    {
      if constexpr (requires { functor.Initialize(); })
      {
        functor.Initialize();
      }
      for (std::size_t chunk = nextChunk++; chunk < numChunks && !failed; chunk = nextChunk++)
      {
        const std::size_t chunkBegin = begin + chunk * grain;
        functor(chunkBegin, std::min(end, chunkBegin + grain));
      }
    }
    catch (...)
    {
      const std::lock_guard<std::mutex> lock(errorMutex);
      if (!firstError)
      {
        firstError = std::current_exception();
      }
      failed = true;
    }
    currentWorker() = outer;
  };

  std::vector<std::thread> others;
  others.reserve(threads - 1);
  try
  {
    for (unsigned worker = 1; worker < threads; ++worker)
    {
      others.emplace_back(work, worker);
    }
  }
  catch (...)
  {
    // No thread to be had: the threads already started and this one share the chunks.
  }
  work(0);
  for (std::thread& thread : others)
  {
    thread.join();
  }
  if (firstError)
  {
    std::rethrow_exception(firstError);
  }
  if constexpr (requires { functor.Reduce(); })
  {
    functor.Reduce();
  }
}

} // namespace proxima::detail
