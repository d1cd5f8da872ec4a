#include "sweep/runner.hpp"

#include <exception>
#include <stdexcept>
#include <cstdint>
#include <mutex>
#include <optional>

#include "model/allocator_reuse.hpp"
#include "model/parallel_for.hpp"
#include "model/input_error.hpp"
#include "model/case_checks.hpp"
#include "model/run_control.hpp"
#include "statics/pullin.hpp"

namespace vi {
namespace {

// The status column holds one CSV cell on one line.
std::string status_on_one_line(std::string s) {
    for (char& ch : s) {
        if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
    }
    return s;
}

std::vector<SweepCell> analyse(const Case& c, const SweepSettings& settings) {
    if (settings.analysis == SweepAnalysis::modes) {
        return modes_cells(modal_study(c, settings.modes, settings.support_model), settings.modes);
    }
    if (settings.analysis == SweepAnalysis::pullin) {
        PullinOptions o;
        o.frequency_points = 0;  // no column needs the frequencies under bias
        return pullin_cells(trace_pullin(c, o));
    }
    if (settings.analysis == SweepAnalysis::stiction || settings.analysis == SweepAnalysis::air_q) {
        return settings.study_analysis(c);
    }
    // Sweeps want the summary only: the sampled history and the energy ledger cost most of a run.
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    // Their columns read the peaks of the first impacts only.
    o.peak_impacts = kSweepImpactColumns;
    return simulate_cells(run_simulation(c, o), settings.supports);
}

bool has_adhesion(const Case& c) {
    for (const Support& s : c.supports) {
        if (s.adhesion != Adhesion::none) return true;
    }
    for (const Electrode& e : c.electrodes) {
        if (e.work_of_adhesion && e.dielectric_thickness > 0.0) return true;
    }
    return false;
}

}  // namespace

void check_sweep_analysis(const Case& c, const SweepSettings& settings) {
    const std::string option = std::string("--analysis ") + sweep_analysis_name(settings.analysis) + ": ";
    switch (settings.analysis) {
        case SweepAnalysis::pullin:
            if (c.electrodes.empty()) throw InputError(option + "the case has no [[electrodes]] to pull the beam in");
            break;
        case SweepAnalysis::stiction:
            if (!has_adhesion(c)) {
                throw InputError(option + "the case has no adhesive support (supports[i].adhesion) and no adhesive "
                                          "dielectric layer (electrodes[i].work_of_adhesion)");
            }
            break;
        case SweepAnalysis::air_q:
            if (c.electrodes.empty() && c.films.empty()) {
                throw InputError(option + "the case has neither [[electrodes]] nor [[films]]: no squeeze film to "
                                          "damp the beam (air-q --gap gives a bare beam one)");
            }
            break;
        default:
            break;
    }
    const bool study = settings.analysis == SweepAnalysis::stiction || settings.analysis == SweepAnalysis::air_q;
    if (study && !settings.study_analysis) {
        throw std::logic_error(option + "computed by the studies' code, which these settings do not carry");
    }
}

SweepPointResult run_sweep_point(const Case& base, const SweepGrid& grid, std::size_t index,
                                 const SweepSettings& settings) {
    SweepPointResult r;
    r.index = index;
    r.parameters = grid.values_at(index);
    try {
        const ScopedTimeLimit limit(settings.point_timeout, "--point-timeout");
        const Case c = grid.case_at(base, index);
        const std::vector<CaseProblem> problems = check_case(c);
        if (!problems.empty()) throw InputError(problems.front().key + ": " + problems.front().message);
        r.cells = analyse(c, settings);
        r.status = "ok";
    } catch (const TimeLimitReached& e) {
        r.cells.clear();
        r.status = status_on_one_line(e.what());
    } catch (const std::exception& e) {
        r.cells.clear();
        r.status = status_on_one_line("error: " + std::string(e.what()));
    } catch (const StopRequested&) {
        throw;
    } catch (...) {
        r.cells.clear();
        r.status = "error: unknown failure";
    }
    return r;
}

void RunningPoints::started(std::size_t index) {
    const std::lock_guard<std::mutex> lock(mutex_);
    since_[index] = std::chrono::steady_clock::now();
}

void RunningPoints::finished(std::size_t index) {
    const std::lock_guard<std::mutex> lock(mutex_);
    since_.erase(index);
}

std::pair<std::size_t, double> RunningPoints::slowest() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::pair<std::size_t, double> out{SIZE_MAX, 0.0};
    const auto now = std::chrono::steady_clock::now();
    for (const auto& [index, t0] : since_) {
        const double s = std::chrono::duration<double>(now - t0).count();
        if (out.first == SIZE_MAX || s > out.second) out = {index, s};
    }
    return out;
}

std::size_t run_sweep_points(const Case& base, const SweepGrid& grid, const std::vector<std::size_t>& indices,
                             const SweepSettings& settings, int threads,
                             const std::function<void(const SweepPointResult&)>& done,
                             const std::atomic<bool>* stop, RunningPoints* running) {
    const bool study = settings.analysis == SweepAnalysis::stiction || settings.analysis == SweepAnalysis::air_q;
    if (study && !settings.study_analysis) {
        throw std::logic_error(std::string("sweep: the ") + sweep_analysis_name(settings.analysis) +
                               " analysis needs the studies' code (with_study_analyses)");
    }
    keep_freed_memory_for_reuse();
    std::mutex done_mutex;
    std::atomic<std::size_t> reported{0};
    parallel_for(
        indices.size(), threads,
        [&](std::size_t k) {
            if (running) running->started(indices[k]);
            std::optional<SweepPointResult> r;
            try {
                r = run_sweep_point(base, grid, indices[k], settings);
            } catch (const StopRequested&) {
                // Abandoned half-way: not a result, it stays to do (the journal never sees it).
            }
            if (running) running->finished(indices[k]);
            if (!r) return;
            const std::lock_guard<std::mutex> lock(done_mutex);
            done(*r);
            ++reported;
        },
        stop);
    return reported.load();
}

}  // namespace vi
