#include "support/parallel_runs.hpp"

#include <chrono>
#include <memory>
#include <thread>

namespace vi::test {

void run_in_parallel(std::size_t count, std::size_t parallel, const RunLimits& limits,
                     const std::function<std::vector<std::string>(std::size_t)>& start,
                     const std::function<void(std::size_t, const CommandResult&)>& done,
                     const std::function<bool()>& keep_going) {
    struct Slot {
        std::size_t index = 0;
        std::unique_ptr<ChildProcess> child;
        double checked_s = 0.0;  // wall time of the last look at its CPU time
    };
    // Reading /proc costs more than a poll: the CPU time is looked at ten times a second.
    constexpr double kCpuCheckEvery = 0.1;
    const auto over_limit = [&](Slot& s) {
        const double wall = s.child->seconds();
        if (wall > limits.wall_s) return true;
        if (wall - s.checked_s < kCpuCheckEvery) return false;
        s.checked_s = wall;
        return s.child->cpu_seconds() > limits.cpu_s;
    };
    std::vector<Slot> running;
    std::size_t next = 0;
    bool more = true;
    // Bounded: every pass starts a run or finds one ended or past its limit, or sleeps 2 ms; each
    // run ends by its limit.
    while (more || !running.empty()) {
        while (more && running.size() < std::max<std::size_t>(parallel, 1)) {
            if (next >= count || !keep_going()) {
                more = false;
                break;
            }
            const std::size_t i = next++;
            const std::vector<std::string> argv = start(i);
            if (!argv.empty()) running.push_back(Slot{i, std::make_unique<ChildProcess>(argv, std::vector<std::string>{}, true), 0.0});
        }
        bool ended = false;
        for (std::size_t k = 0; k < running.size();) {
            Slot& s = running[k];
            if (s.child->running() && !over_limit(s)) {
                ++k;
                continue;
            }
            // wait(0) reaps an ended child, and kills one past its limit (then the result says hung).
            CommandResult r = s.child->wait(0.0);
            if (r.hung) {
                r.err = r.err.substr(0, r.err.rfind("\n[test: killed after"));
                r.err += "\n[test: killed past its limit (" + std::to_string(r.cpu_seconds) + " s of CPU, " +
                         std::to_string(r.seconds) + " s of wall time): counted as a hang]\n";
            }
            const std::size_t i = s.index;
            running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
            done(i, r);
            ended = true;
        }
        if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

}  // namespace vi::test
