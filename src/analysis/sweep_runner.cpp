#include "analysis/sweep_runner.hpp"

#include <exception>
#include <mutex>

#include "analysis/parallel_for.hpp"
#include "io/input_error.hpp"
#include "model/case_checks.hpp"

namespace vi {
namespace {

// The status column holds one CSV cell on one line.
std::string one_line(std::string s) {
    for (char& ch : s) {
        if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
    }
    return s;
}

std::vector<SweepCell> analyse(const Case& c, const SweepSettings& settings) {
    if (settings.analysis == SweepAnalysis::modes) {
        return modes_cells(modal_study(c, settings.modes, settings.support_model), settings.modes);
    }
    // Sweeps want the summary only: the sampled history and the energy ledger cost most of a run.
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    return simulate_cells(run_simulation(c, o));
}

}  // namespace

SweepPointResult run_sweep_point(const Case& base, const SweepGrid& grid, std::size_t index,
                                 const SweepSettings& settings) {
    SweepPointResult r;
    r.index = index;
    r.parameters = grid.values_at(index);
    try {
        const Case c = grid.case_at(base, index);
        const std::vector<CaseProblem> problems = check_case(c);
        if (!problems.empty()) throw InputError(problems.front().key + ": " + problems.front().message);
        r.cells = analyse(c, settings);
        r.status = "ok";
    } catch (const std::exception& e) {
        r.cells.clear();
        r.status = one_line("error: " + std::string(e.what()));
    } catch (...) {
        r.cells.clear();
        r.status = "error: unknown failure";
    }
    return r;
}

std::size_t run_sweep_points(const Case& base, const SweepGrid& grid, const std::vector<std::size_t>& indices,
                             const SweepSettings& settings, int threads,
                             const std::function<void(const SweepPointResult&)>& done,
                             const std::atomic<bool>* stop) {
    std::mutex done_mutex;
    return parallel_for(
        indices.size(), threads,
        [&](std::size_t k) {
            const SweepPointResult r = run_sweep_point(base, grid, indices[k], settings);
            const std::lock_guard<std::mutex> lock(done_mutex);
            done(r);
        },
        stop);
}

}  // namespace vi
