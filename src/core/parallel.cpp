#include "core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace t2imu {

void parallel_for(size_t n, int threads, const std::function<void(size_t)>& fn) {
    const size_t workers = std::min(n, static_cast<size_t>(std::max(1, threads)));
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto work = [&] {
        for (size_t i; !failed && (i = next++) < n;) {
            try {
                fn(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                failed = true;
            }
        }
    };
    if (workers <= 1) {
        work();
    } else {
        std::vector<std::thread> pool;
        for (size_t w = 0; w < workers; ++w) pool.emplace_back(work);
        for (std::thread& t : pool) t.join();
    }
    if (error) std::rethrow_exception(error);
}

}  // namespace t2imu
