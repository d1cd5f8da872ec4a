#pragma once
// The result columns of a sweep, per analysis, and one point's values for them.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "impacts/simulation.hpp"
#include "modal/modal_analysis.hpp"
#include "statics/pullin.hpp"

namespace vi {

// What each point of a sweep computes: a transient, the modal study, the static pull-in, the
// stiction check, the quality factor in air (docs/sweeps.md, "Analyses").
enum class SweepAnalysis { simulate, modes, pullin, stiction, air_q };

// Every analysis, in the order the docs list them.
inline constexpr SweepAnalysis kSweepAnalyses[] = {SweepAnalysis::simulate, SweepAnalysis::modes, SweepAnalysis::pullin,
                                                   SweepAnalysis::stiction, SweepAnalysis::air_q};

// The analysis's name on the command line and in JSON: "simulate", "modes", "pullin", "stiction", "air-q".
const char* sweep_analysis_name(SweepAnalysis a);
// The analysis of that name. Throws InputError("--analysis NAME: ...") listing the names.
SweepAnalysis parse_sweep_analysis(const std::string& name);
// Every name, "simulate|modes|pullin|stiction|air-q", for help texts.
std::string sweep_analysis_names(const char* separator = "|");

// A result column: its name (units in the name, as the other CSV files) and its unit alone.
struct SweepColumn {
    std::string name;  // e.g. "T_s", "impact1_peak_force_n"
    std::string unit;  // e.g. "s", "N", "-" (dimensionless), "" (count or text)
};

// One cell: empty (no such value: T with a single impact, a mode the mesh does not have; the CSV
// writes the missing-value marker "nan"), a number, a count, or text (Tp_reason, a list of nodal
// points).
using SweepCell = std::variant<std::monostate, double, std::int64_t, std::string>;

// True for a column whose cells are text (a reason, the solver, a list of nodal points) or a
// support's index: no quantity to optimise, fit or spread.
bool sweep_column_is_text(const std::string& name);

// A cell's number (a count as a double), or nullopt for an empty or text cell.
std::optional<double> numeric_cell(const SweepCell& cell);

// How many impacts get their own columns in a simulate sweep.
inline constexpr int kSweepImpactColumns = 3;

// The columns of `analysis`; `modes` is the number of bending modes of a modes sweep, `supports` the
// number of supports of the swept case (a simulate sweep's per-support columns; a sweep sets values,
// never the number of entries).
std::vector<SweepColumn> sweep_result_columns(SweepAnalysis analysis, int modes, int supports = 0);

// A transient's values in the order of sweep_result_columns(simulate, ...): omega1_rad_s, impacts,
// episodes, T_s, T1_s, T2_s, Tp_s, Tp_reason, tau, tau1, tau2, tau_p, y_max_m, z_max,
// y_max_contact_m, tip_min_m, unproven_excess, closing_time_s, bounces, stable_contact_s,
// release_time_s, grouped_bounces, switching_state, collapse_time_s (the switching ledger, empty
// without electrodes), then per impact k = 1..3 impact<k>_support, _t_on_s, _v_in_m_s,
// _peak_force_n, _peak_penetration_m, _duration_s, _episodes; then electrical_bounces, settle_time_s,
// resistance_end_ohm (the first contact with a resistance model; empty without one); then the
// impacts' sums contact_energy_j, peak_pressure_pa, yield_impacts (empty where not recorded); then
// for each support k < supports: support<k>_electrical_bounces, _settle_time_s, _resistance_end_ohm
// (empty without its resistance model), _contact_energy_j, _peak_pressure_pa, _yield_impacts.
std::vector<SweepCell> simulate_cells(const SimulationRun& run, int supports = 0);

// A modal study's values in the order of sweep_result_columns(modes, modes): per mode i,
// f_unsupported_<i>_hz, f_supported_<i>_hz, ratio_<i>, nodes_supported_<i>_over_l (x/l, space separated).
std::vector<SweepCell> modes_cells(const ModalStudy& study, int modes);

// A pull-in trace's values in the order of sweep_result_columns(pullin, ...): rest_capacitance_f;
// pullin_, touchdown_, release_ and collapse_ voltage_v, travel_m (mean travel over electrodes[0])
// and capacitance_f (empty where the branch has no such point); hysteresis_v (the closing voltage,
// pull-in or else touch-down, less the release voltage); end_reason (why the branch ends).
std::vector<SweepCell> pullin_cells(const PullinResult& r);

}  // namespace vi
