#include "design/design_store.hpp"

#include <atomic>
#include <bit>
#include <mutex>
#include <optional>

#include "model/run_control.hpp"

namespace vi {

std::vector<std::uint64_t> design_key(const std::vector<double>& x) {
    std::vector<std::uint64_t> key(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) key[i] = std::bit_cast<std::uint64_t>(x[i]);
    return key;
}

DesignStore::DesignStore(const DesignProblem& p, int threads, std::function<void(const ComputedDesign&)> computed)
    : p_(p), pool_(threads), computed_sink_(std::move(computed)) {}

void DesignStore::add_known(const ComputedDesign& d) {
    if (outcomes_.emplace(design_key(d.x), Entry{d.outcome, true}).second) ++known_;
}

const DesignOutcome* DesignStore::find(const std::vector<double>& x) const {
    const auto it = outcomes_.find(design_key(x));
    return it == outcomes_.end() ? nullptr : &it->second.outcome;
}

bool DesignStore::is_known(const std::vector<double>& x) const {
    const auto it = outcomes_.find(design_key(x));
    return it != outcomes_.end() && it->second.known;
}

void DesignStore::compute(const std::vector<std::vector<double>>& batch) {
    std::vector<const std::vector<double>*> todo;
    for (const std::vector<double>& x : batch) {
        if (!find(x)) todo.push_back(&x);
    }
    if (todo.empty()) return;
    ++batches_;
    std::mutex mutex;
    std::atomic<bool> abandoned{false};
    pool_.run(
        todo.size(),
        [&](std::size_t k) {
            std::optional<DesignOutcome> o;
            try {
                o = evaluate_design(p_, *todo[k]);
            } catch (const StopRequested&) {
                // Abandoned half-way: not a result; a resumed search computes it again.
                abandoned = true;
                return;
            }
            const std::lock_guard<std::mutex> lock(mutex);
            // The sink first (the journal): a design counts as computed once it would survive a stop.
            if (computed_sink_) computed_sink_(ComputedDesign{*todo[k], *o});
            outcomes_.emplace(design_key(*todo[k]), Entry{std::move(*o), false});
            ++computed_;
        },
        &stop_flag());
    if (abandoned || stop_flag().load()) throw StopRequested(stop_signal());
}

}  // namespace vi
