#include "model/worker_pool.hpp"

#include "model/parallel_for.hpp"

namespace vi {

WorkerPool::WorkerPool(int threads) {
    const int n = resolve_thread_count(threads);
    for (int k = 1; k < n; ++k) workers_.emplace_back([this] { loop(); });
}

WorkerPool::~WorkerPool() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        shutdown_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void WorkerPool::run(std::size_t count, const std::function<void(std::size_t)>& body, const std::atomic<bool>* stop) {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        body_ = &body;
        count_ = count;
        stop_ = stop;
        next_ = 0;
        failed_ = false;
        error_ = nullptr;
        busy_ = workers_.size();
        ++generation_;
    }
    wake_.notify_all();
    work();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
    body_ = nullptr;
    if (error_) std::rethrow_exception(error_);
}

void WorkerPool::work() {
    for (;;) {
        if (failed_.load() || (stop_ && stop_->load())) return;
        const std::size_t i = next_.fetch_add(1);
        if (i >= count_) return;
        try {
            (*body_)(i);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (!error_) error_ = std::current_exception();
            failed_ = true;
            return;
        }
    }
}

void WorkerPool::loop() {
    std::size_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return shutdown_ || generation_ != seen; });
        if (shutdown_) return;
        seen = generation_;
        lock.unlock();
        work();
        lock.lock();
        if (--busy_ == 0) done_.notify_all();
    }
}

}  // namespace vi
