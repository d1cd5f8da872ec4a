#pragma once
// The size of a run estimated from the case alone (DOF, memory, time scales), and the limits a run
// must stay within, checked before any work (docs/case-files.md, "Limits").

#include <cstddef>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "model/case_checks.hpp"

namespace vi {

// Most elements of any analysis: the roundoff of K grows like 5 m^4 (docs/validation.md §1); at
// m = 2000 the first frequency has lost 3e-4 to it, at 5000 2 %, at 10000 16 %.
inline constexpr int kMaxElements = 2000;
// Most elements of a transient with the exact solver: it decomposes dense n x n systems (n ~ 2m),
// O(n^3) time; m = 400 with two supports took 28 s and 1 GB, m = 500 with two ended "not
// diagonalisable" after 67 s, m = 1000 after 9 minutes and 4.3 GB (docs/case-files.md, Limits).
inline constexpr int kMaxExactElements = 400;
// Most elements of a transient with CVODE (modal coordinates: a dense eigen solve of all n modes,
// then O(n) per step): the paper's transient at rtol 1e-10 takes 2.6 s at m = 100, 4.7 s at 200 and
// 8.5 s (38 MB) at 400, where roundoff in K already moves T by 7e-7. A full model with an electrode
// or a film integrates in the FE DOFs, O(n) per step: the switch example at m = 400 in 2.4 s of CPU
// and 17 MiB (bench/cvode_mesh_bench.cpp; docs/electrostatics.md, "Fine meshes").
inline constexpr int kMaxCvodeElements = 400;
// Most elements at which `pullin --dynamic` confirms its bracket on the full model with an electrode
// (above: on its finest reduced model): its bisection runs the model tens of times.
inline constexpr int kMaxFullModelBisectionElements = 100;
// Most supports: every closed set of two or more is a dense 2n x 2n eigen problem (100 took 42 s, 2 GB).
inline constexpr std::size_t kMaxSupports = 100;
// At most this many electrodes: each one is a force element integrated over its span at every step.
inline constexpr std::size_t kMaxElectrodes = 20;
// Most corners of one prescribed time function within a transient's horizon (a voltage or load
// table's rows off the straight line between their neighbours: TimeFunction::stops for CVODE,
// breakpoints for the exact solver). Each costs CVODE about 18 steps and 7 factorisations where the
// table is noise (the switch example under a table of 1e4 noisy rows over its 50 us: 8 s), the exact
// solver a piece (a 1e5-row load table on the paper's example: 15 s).
inline constexpr std::size_t kMaxTimeCorners = 5000;
// Fewest CVODE steps one period of a sine drive takes, at any rtol: the switch example under a
// 10 V sine of 10 MHz took 16 a period at rtol 1e-3, 80 at 1e-8, 180 at 1e-10. A drive whose
// periods over the horizon need more than solver.max_steps is refused before the run.
inline constexpr double kMinStepsPerPeriod = 10.0;
// Largest horizon, in the shortest time scale the solvers must resolve: event times carry a
// rounding error of a few eps t, 1e-6 of that time scale at 1e9 of it.
inline constexpr double kMaxHorizonRatio = 1e9;
// Largest contact stiffness (and damper force at omega_1), in the beam's bending stiffness EI/l^3:
// the contact force comes from a penetration that is 1e-9 of the deflection there, and keeps
// about 6 digits.
inline constexpr double kMaxContactRatio = 1e9;
// Every physical value (SI) and every derived scale must lie within [1/kMagnitudeLimit, kMagnitudeLimit]
// in magnitude (or be zero where zero is allowed): products of a few of them stay inside double's range.
inline constexpr double kMagnitudeLimit = 1e100;
// Most samples of a time history: 1.5e6 samples took 17 s and 1 GB (most of it writing a 311 MB
// CSV), more than any plot or spectrum of one run needs; a longer history costs minutes.
inline constexpr double kMaxSamples = 1e6;
// Bytes per value of the sampled history: the double, its row in the CSV table and its text.
inline constexpr double kHistoryBytesPerValue = 60.0;
// Bytes per n^2 of a transient: dense M, K, modes, state decompositions (measured: 0.8 GB at n = 1000,
// 4.3 GB at n = 2000).
inline constexpr double kSolverBytesPerDof2 = 1100.0;
// The memory a run may plan to use: this fraction of the machine's (or container's) memory, at most
// kMemoryCap bytes.
inline constexpr double kMemoryFraction = 0.5;
inline constexpr double kMemoryCap = 8.0 * 1024 * 1024 * 1024;

// What a case asks of a run, from closed forms (no mesh, no solve).
struct RunEstimate {
    double bending_dofs = 0.0;         // n, the transient's size (v and theta of every free node)
    // Of the plain beam, or of a beam of sections by its effective values (model/section_scales.hpp).
    double omega1 = 0.0;               // first bending circular frequency, unsupported beam [rad/s]; 0 if unrestrained
    double omega_top = 0.0;            // bound of the mesh's highest bending frequency [rad/s]
    double bending_stiffness = 0.0;    // EI / l^3 [N/m]
    double shortest_time_scale = 0.0;  // the shortest period the solvers must resolve [s]
    std::string time_scale_source;     // what sets it, e.g. "the first free period", "supports[0]'s contact"
    double samples = 0.0;              // time-history samples over the horizon
    double history_bytes = 0.0;        // memory of that history [bytes]
    double solver_bytes = 0.0;         // memory of the transient's dense matrices [bytes]
};

// Estimates what c asks of a transient (horizon, output step and method as in c.solver).
RunEstimate estimate_run(const Case& c);

// Memory a run may plan on [bytes]: kMemoryFraction of the physical memory (or of the cgroup's
// limit, when lower), at most kMemoryCap. memory_budget_bytes reads it at most once a second per
// thread (a limit changed since shows within a second); read_memory_budget_bytes reads it now.
double memory_budget_bytes();
double read_memory_budget_bytes();

// Problems of a transient of c that this machine or double precision cannot carry out: too many
// elements for the method, more than kMaxTimeCorners corners of a table within the horizon, a sine
// drive above the mesh's highest bending frequency or of more periods than solver.max_steps allows, a horizon beyond kMaxHorizonRatio time scales, more than kMaxSamples
// samples or more memory than `memory_budget` bytes (the history counts only when kept: the exact
// solver keeps none when `history` is false, CVODE always does). Empty when the transient may run.
std::vector<CaseProblem> check_transient_run(const Case& c, bool history, double memory_budget);

// A byte count as text with its unit, e.g. "12 TB".
std::string bytes_text(double bytes);

}  // namespace vi
