#include "model/parallel_for.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "model/cpu_budget.hpp"

namespace vi {

int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    return usable_cpu_count();
}

std::size_t parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                         const std::atomic<bool>* stop) {
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&]() {
        for (;;) {
            if (failed.load() || (stop && stop->load())) return;
            const std::size_t i = next.fetch_add(1);
            if (i >= count) return;
            try {
                body(i);
                done.fetch_add(1);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                failed.store(true);
                return;
            }
        }
    };
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(resolve_thread_count(threads)),
                                                std::max<std::size_t>(count, 1));
    if (n <= 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        pool.reserve(n);
        for (std::size_t k = 0; k < n; ++k) pool.emplace_back(worker);
        for (std::thread& t : pool) t.join();
    }
    if (error) std::rethrow_exception(error);
    return done.load();
}

}  // namespace vi
