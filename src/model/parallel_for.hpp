#pragma once
// parallel_for: runs one function over an index range on worker threads (sweeps, figure scans).

#include <atomic>
#include <cstddef>
#include <functional>

namespace vi {

// Number of worker threads for a request: `requested` if positive, else the CPUs this process may
// run on (usable_cpu_count, model/cpu_budget.hpp: its affinity set and cgroup CPU quota).
int resolve_thread_count(int requested);

// Calls body(i) once for every i in [0, count), on resolve_thread_count(threads) threads. Indices
// are handed out in increasing order; a body writes its result into slot i of a caller's vector, so
// results do not depend on the thread count. When *stop becomes true no further index is started
// (those already running finish); returns how many bodies ran. body must not throw: an exception
// escaping it is caught, stops the loop, and is rethrown here after every worker has joined.
std::size_t parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                         const std::atomic<bool>* stop = nullptr);

}  // namespace vi
