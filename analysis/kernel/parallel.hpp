// A work queue over all cores: task i writes only slot i of its output, so the results (and
// every byte written from them) are the same whatever the number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace steplab {

// Called (from one thread at a time) after each task with the tasks done, the total and the
// seconds since the work began; the front end shows progress with it. Null: nothing shown.
using ProgressHook = void (*)(std::size_t done, std::size_t total, double seconds);

struct WorkLog;  // analysis/kernel/shard.hpp

// How a study's work runs, handed down from the command that started it (nothing of it is
// process-wide): on how many threads, with what progress shown, and, in a shard or a merge,
// which of its tasks run here (analysis/kernel/shard.hpp; null: every task runs here).
struct Workers {
  unsigned threads = 0;  // 0: all cores
  ProgressHook progress = nullptr;
  WorkLog* log = nullptr;
};

// Set (from a signal handler) to stop the work: no task starts after it, and parallel_for
// throws Interrupted once the running tasks are done.
inline std::atomic<bool> stop_requested{false};
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

// 0 means all cores.
inline unsigned resolve_threads(unsigned requested) {
  return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

// Runs task(i) for i in [0, n) on `workers.threads` threads, each taking the next index from a
// shared counter (long and short tasks balance themselves). The first exception is rethrown.
template <class Task> void parallel_for(std::size_t n, const Workers& workers, Task&& task) {
  const ProgressHook progress_hook = workers.progress;
  const unsigned threads = std::min<unsigned>(resolve_threads(workers.threads), static_cast<unsigned>(std::max<std::size_t>(n, 1)));
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::exception_ptr error;
  std::mutex mutex;
  const auto start = std::chrono::steady_clock::now();
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < n;) {
      if (stop_requested) {
        next = n;
        break;
      }
      try {
        task(i);
        if (progress_hook) {
          const std::lock_guard lock(mutex);
          progress_hook(++done, n, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = n;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  if (stop_requested) throw Interrupted();
}

}  // namespace steplab
