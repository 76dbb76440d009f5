// Data parallelism for the CPU-bound loops (bodies and sensors per job, features per recording): indices are
// handed out one at a time from a shared counter, so uneven work balances across the workers.
#pragma once
#include <cstddef>
#include <functional>

namespace t2imu {

// Runs fn(i) for every i in [0, n), each once, on min(threads, n) workers (threads < 1 counts as 1; with one
// worker, on the calling thread, in order). An exception from fn stops the hand-out of further indices; the
// first one is rethrown on the calling thread after every worker has returned.
void parallel_for(size_t n, int threads, const std::function<void(size_t i)>& fn);

}  // namespace t2imu
