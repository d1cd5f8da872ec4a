#pragma once
// The designs an optimisation has computed, by the exact values of their variables, and the
// computing of a batch of them on worker threads (docs/optimization.md, "Threads").

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "design/design_problem.hpp"
#include "model/worker_pool.hpp"

namespace vi {

// One computed design: its variables [SI] and its outcome.
struct ComputedDesign {
    std::vector<double> x;
    DesignOutcome outcome;
};

// The key of a design: the bit patterns of its variables, so that two designs are the same only
// when every value is the same double (what a journal and a resumed search must agree on).
std::vector<std::uint64_t> design_key(const std::vector<double>& x);

class DesignStore {
public:
    // `computed`, if given, sees every design computed here (not those added with add_known), one
    // call at a time, as each finishes (a journal appends it there). An exception from it stops the
    // batch and is rethrown by compute().
    DesignStore(const DesignProblem& p, int threads, std::function<void(const ComputedDesign&)> computed = {});

    // A design computed before (from a journal): used, never computed again.
    void add_known(const ComputedDesign& d);
    // The outcome of x, or nullptr when it has not been computed.
    [[nodiscard]] const DesignOutcome* find(const std::vector<double>& x) const;
    // True when x came from add_known.
    [[nodiscard]] bool is_known(const std::vector<double>& x) const;

    // Computes the designs of `batch` not yet known, on the store's threads (the caller's among
    // them). A stop (StopRequested inside a design, or the stop flag) lets no further design start,
    // abandons the running ones (never stored) and is thrown once every thread is done with the
    // batch; the designs that finished before are stored and passed to `computed`.
    void compute(const std::vector<std::vector<double>>& batch);

    [[nodiscard]] int threads() const { return pool_.threads(); }
    [[nodiscard]] std::size_t size() const { return outcomes_.size(); }
    [[nodiscard]] std::size_t known() const { return known_; }          // added with add_known
    [[nodiscard]] std::size_t computed() const { return computed_; }    // computed by compute()
    [[nodiscard]] std::size_t batches() const { return batches_; }      // compute() calls that computed some

private:
    const DesignProblem& p_;
    WorkerPool pool_;  // lives as long as the store: a thread's memo of the last modes lasts
    std::function<void(const ComputedDesign&)> computed_sink_;
    struct Entry {
        DesignOutcome outcome;
        bool known = false;
    };
    std::map<std::vector<std::uint64_t>, Entry> outcomes_;
    std::size_t known_ = 0, computed_ = 0, batches_ = 0;
};

}  // namespace vi
