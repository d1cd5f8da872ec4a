#include "model/run_estimate.hpp"

#include "model/section_scales.hpp"
#include "model/number_format.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

namespace vi {
namespace {

// beta_1 l of the first bending mode for the end conditions (0 when they do not hold the beam).
double first_root(EndCondition a, EndCondition b) {
    using E = EndCondition;
    if (a > b) std::swap(a, b);  // clamped < pinned < free
    if (a == E::clamped && b == E::clamped) return 4.730040745;
    if (a == E::clamped && b == E::pinned) return 3.926602312;
    if (a == E::clamped && b == E::free) return 1.875104069;
    if (a == E::pinned && b == E::pinned) return std::numbers::pi;
    return 0.0;
}

// Bending DOFs held by an end condition.
int held(EndCondition e) { return e == EndCondition::clamped ? 2 : e == EndCondition::pinned ? 1 : 0; }

// The cgroup (v2, then v1) memory limit of this process [bytes]; 0 when there is none.
double cgroup_memory_limit() {
    for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::ifstream in(path);
        double v = 0.0;
        if (in >> v && v > 0.0) return v;  // "max" (no limit) does not read as a number
    }
    return 0.0;
}

}  // namespace

std::string bytes_text(double bytes) {
    const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
    int k = 0;
    for (; k < 6 && bytes >= 1000.0; ++k) bytes /= 1000.0;
    if (bytes >= 1000.0) return significant(bytes * 1e18, 2) + " bytes";
    char buf[32];
    std::snprintf(buf, sizeof buf, bytes >= 10.0 ? "%.0f" : "%.2g", bytes);
    return std::string(buf) + " " + units[k];
}

RunEstimate estimate_run(const Case& c) {
    RunEstimate e;
    const Beam& b = c.beam;
    const double l = b.length;
    const double m = std::max(b.elements, 1);
    const double supports = static_cast<double>(c.supports.size());
    e.bending_dofs = 2.0 * (m + 1.0 + supports) - held(b.left) - held(b.right);

    // A beam of sections by its effective values (model/section_scales.hpp): its parts' stiffness in
    // series and mean mass per length for mode 1, its stiffest part for the mesh's top.
    const EffectiveBeam beam = effective_beam(c);
    const double ei = beam.EI;
    const double rho_a = beam.rho_A;
    const double wave = std::sqrt(ei / rho_a);  // omega = (beta l)^2 wave / l^2
    const double root = first_root(b.left, b.right);
    e.omega1 = root * root * wave / (l * l);
    // The largest generalized eigenvalue of one Hermite element with consistent mass is
    // 8400 EI / (rho A h^4), and the assembled system's cannot exceed its elements' (Rayleigh quotient).
    const double h = l / m;
    e.omega_top = std::sqrt(8400.0) * beam.wave_max / (h * h);
    e.bending_stiffness = ei / (l * l * l);

    // The slowest motions fix nothing; the shortest period to resolve is mode 1's, a contact's with
    // mode 1's smallest effective mass (rho A l / 4, at a free end), or a harmonic load's or voltage's.
    double tau = e.omega1 > 0.0 ? 2.0 * std::numbers::pi / e.omega1 : 0.0;
    std::string source = "the first free period";
    for (std::size_t k = 0; k < c.supports.size(); ++k) {
        const double kc = c.supports[k].stiffness;
        if (!(kc > 0.0)) continue;
        const double period = 2.0 * std::numbers::pi * std::sqrt(rho_a * l / 4.0 / kc);
        if (period < tau) {
            tau = period;
            source = "the contact period of supports[" + std::to_string(k) + "]";
        }
    }
    const auto drive = [&](const TimeFunction& g, const std::string& what) {
        if (g.kind == TimeFunction::Kind::harmonic && g.frequency_hz > 0.0 && 1.0 / g.frequency_hz < tau) {
            tau = 1.0 / g.frequency_hz;
            source = "the period of " + what;
        }
    };
    for (std::size_t k = 0; k < c.loads.size(); ++k) drive(c.loads[k].time, "loads[" + std::to_string(k) + "]");
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        drive(c.electrodes[k].time, "electrodes[" + std::to_string(k) + "]'s sine");
    }
    e.time_scale_source = source;
    e.shortest_time_scale = tau;

    const SolverSettings& s = c.solver;
    const double step = s.output_step > 0.0 ? s.output_step : s.horizon / 2000.0;
    // As the solvers count them (a horizon a whole number of steps long ends on a sample).
    e.samples = s.horizon > 0.0 && step > 0.0 ? std::floor(s.horizon / step * (1.0 + 1e-12)) + 1.0 : 0.0;
    // t, tip v and velocity; v, velocity and force per contact; six energy terms.
    e.history_bytes = e.samples * (9.0 + 3.0 * supports) * kHistoryBytesPerValue;
    e.solver_bytes = kSolverBytesPerDof2 * e.bending_dofs * e.bending_dofs;
    return e;
}

double memory_budget_bytes() {
    // Read again at most once a second on each thread: a sweep asks at every point, and the cgroup
    // files cost as much to open as a small point's other checks.
    struct Reading {
        double bytes = 0.0;
        std::chrono::steady_clock::time_point at;
    };
    thread_local Reading last;
    const auto now = std::chrono::steady_clock::now();
    if (last.bytes > 0.0 && now - last.at < std::chrono::seconds(1)) return last.bytes;
    last = {read_memory_budget_bytes(), now};
    return last.bytes;
}

double read_memory_budget_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page = sysconf(_SC_PAGE_SIZE);
    double memory = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : kMemoryCap;
    if (const double limit = cgroup_memory_limit(); limit > 0.0) memory = std::min(memory, limit);
    return std::min(kMemoryFraction * memory, kMemoryCap);
}

std::vector<CaseProblem> check_transient_run(const Case& c, bool history, double memory_budget) {
    // In the order of their keys in a case file: beam.elements, the load and voltage tables and
    // frequencies, solver.horizon, solver.output_step.
    std::vector<CaseProblem> out;
    const RunEstimate e = estimate_run(c);
    const bool cvode = c.solver.method == SolverSettings::Method::cvode;
    const int most = cvode ? kMaxCvodeElements : kMaxExactElements;
    if (c.beam.elements > most) {
        out.push_back({"beam.elements",
                       std::to_string(c.beam.elements) + " elements are more than a transient with solver.method = \"" +
                           (cvode ? "cvode" : "exact") + "\" takes (at most " + std::to_string(most) +
                           ", docs/case-files.md, Limits): its cost grows like n^3 with n = " +
                           std::to_string(static_cast<long>(e.bending_dofs)) + " bending DOFs"});
    }
    const auto corners = [&](const std::string& key, const TimeFunction& g, bool exact) {
        if (g.kind != TimeFunction::Kind::table || c.solver.horizon <= 0.0) return;
        const std::size_t n = exact ? g.breakpoints(0.0, c.solver.horizon).size() : g.stops(0.0, c.solver.horizon).size();
        if (n <= kMaxTimeCorners) return;
        out.push_back({key, std::to_string(n) + " corners within solver.horizon, each a stop of the integrator (at most " +
                                std::to_string(kMaxTimeCorners) + ", docs/case-files.md, Limits): rows within " +
                                significant(exact ? kTableExactTolerance : kTableStopTolerance, 2) +
                                " of the table's peak of the straight line between their neighbours cost nothing; "
                                "thin or smooth the table, or shorten the horizon"});
    };
    for (std::size_t k = 0; k < c.loads.size(); ++k) corners("loads[" + std::to_string(k) + "].table", c.loads[k].time, !cvode);
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        corners("electrodes[" + std::to_string(k) + "].table", c.electrodes[k].time, false);
    }
    const auto periodic = [&](const std::string& key, const TimeFunction& g, bool integrated) {
        if (g.kind != TimeFunction::Kind::harmonic || !(g.frequency_hz > 0.0)) return;
        const double top_hz = e.omega_top / (2.0 * std::numbers::pi);
        if (g.frequency_hz > top_hz) {
            out.push_back({key, significant(g.frequency_hz, 3) + " Hz is above every bending frequency of the mesh (at most " +
                                    significant(top_hz, 3) + " Hz with " + std::to_string(c.beam.elements) +
                                    " elements; docs/case-files.md, Limits): the model has no motion at that rate; "
                                    "lower the frequency, or refine the mesh"});
            return;
        }
        const double periods = g.frequency_hz * c.solver.horizon;
        if (integrated && periods * kMinStepsPerPeriod > static_cast<double>(c.solver.max_steps)) {
            out.push_back({key, significant(g.frequency_hz, 3) + " Hz over solver.horizon (" + significant(c.solver.horizon, 3) +
                                    " s) is " + significant(periods, 3) + " periods, each at least " +
                                    significant(kMinStepsPerPeriod, 2) + " integration steps: more than solver.max_steps = " +
                                    std::to_string(c.solver.max_steps) +
                                    " (docs/case-files.md, Limits); shorten the horizon, or raise solver.max_steps"});
        }
    };
    for (std::size_t k = 0; k < c.loads.size(); ++k) {
        periodic("loads[" + std::to_string(k) + "].frequency", c.loads[k].time, cvode);
    }
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        periodic("electrodes[" + std::to_string(k) + "].frequency", c.electrodes[k].time, true);
    }
    const double tau = e.shortest_time_scale;
    if (tau > 0.0 && c.solver.horizon > kMaxHorizonRatio * tau) {
        out.push_back({"solver.horizon",
                       significant(c.solver.horizon, 2) + " s is " + significant(c.solver.horizon / tau, 2) +
                           " times the shortest time scale to resolve (" + e.time_scale_source + ", " +
                           significant(tau, 2) + " s); above " + significant(kMaxHorizonRatio, 2) +
                           " times, double precision no longer resolves event times (docs/case-files.md, Limits)"});
    }
    const bool kept = history || cvode;
    const double history_bytes = kept ? e.history_bytes : 0.0;
    const std::string budget = "this machine allows a run " + bytes_text(memory_budget);
    const bool over_memory = history_bytes + e.solver_bytes > memory_budget;
    if (kept && (e.samples > kMaxSamples || (over_memory && history_bytes > e.solver_bytes))) {
        out.push_back({"solver.output_step", significant(e.samples, 2) + " samples over solver.horizon (" +
                                                 significant(c.solver.horizon, 2) + " s), about " +
                                                 bytes_text(history_bytes) + " of time history (at most " +
                                                 significant(kMaxSamples, 2) + " samples; " + budget +
                                                 "): raise output_step or shorten horizon"});
    } else if (over_memory) {
        out.push_back({"beam.elements", std::to_string(static_cast<long>(e.bending_dofs)) +
                                            " bending DOFs need about " + bytes_text(e.solver_bytes) +
                                            " of dense matrices (" + budget + "): use fewer elements"});
    }
    return out;
}

}  // namespace vi
