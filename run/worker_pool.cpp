#include "run/worker_pool.hpp"

#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "common/interrupt.hpp"

namespace coldblast::run {

void run_slots_in_parallel(std::size_t count, int threads,
                           const std::function<void(std::size_t slot, const std::atomic<bool>& stop)>& work) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  auto worker = [&] {
    while (!failed) {
      const std::size_t slot = next++;
      if (slot >= count) return;
      try {
        common::throw_if_stop_requested();  // finished slots stay done (md: saved in the checkpoint)
        work(slot, failed);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace coldblast::run
