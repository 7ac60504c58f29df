#pragma once
// The one worker pool of ensembles (MD realizations, tracer blocks, md states): slots handed out
// in increasing order to a fixed number of threads, each slot writing only its own results, so that
// merging them in slot order afterwards gives the same numbers for any thread count.
#include <atomic>
#include <cstddef>
#include <functional>

namespace coldblast::run {

/// Runs work(slot, stop) once for every slot in [0, count) on `threads` threads, the calling thread
/// among them, handing slots out in increasing order. A stop request (SIGINT/SIGTERM,
/// common/interrupt.hpp) is checked before every slot; the first exception sets `stop` (long work
/// should poll it and return), no slot starts after it, and it is rethrown once every thread has
/// joined.
void run_slots_in_parallel(std::size_t count, int threads,
                           const std::function<void(std::size_t slot, const std::atomic<bool>& stop)>& work);

}  // namespace coldblast::run
