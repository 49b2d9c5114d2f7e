#include "safecell/compute/parallel_chunks.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace safecell {

void parallel_chunks(std::size_t count, std::size_t chunk_size, unsigned threads,
                     const std::function<void(std::size_t, std::size_t, std::size_t)>& work,
                     const ProgressCallback& progress) {
  if (chunk_size == 0) throw std::invalid_argument("parallel_chunks: chunk size 0");
  const std::size_t chunks = (count + chunk_size - 1) / chunk_size;
  if (threads == 0) threads = std::max(1U, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(chunks, 1)));

  std::atomic<std::size_t> next_chunk{0};
  std::atomic<std::size_t> done_chunks{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // Every thread works; the calling thread also reports, between its chunks.
  const auto worker = [&](bool reports) {
    auto last_report = std::chrono::steady_clock::now();
    while (!failed.load()) {
      const std::size_t chunk = next_chunk.fetch_add(1);
      if (chunk >= chunks) return;
      try {
        const std::size_t begin = chunk * chunk_size;
        work(chunk, begin, std::min(count, begin + chunk_size));
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
      }
      const std::size_t done = done_chunks.fetch_add(1) + 1;
      const auto now = std::chrono::steady_clock::now();
      if (reports && progress && now - last_report >= std::chrono::milliseconds(100)) {
        progress(static_cast<double>(done) / static_cast<double>(chunks));
        last_report = now;
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker, false);
    worker(true);
  }
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(1.0);
}

}  // namespace safecell
