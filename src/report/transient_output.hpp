#pragma once
// Transient results as files: time-history CSV, events CSV (episodes with their impact), summary JSON.

#include <nlohmann/json.hpp>
#include <string>

#include "impacts/impact_summary.hpp"
#include "impacts/switching_ledger.hpp"
#include "dynamics/transient_start.hpp"
#include "dynamics/transient_result.hpp"
#include "io/csv_writer.hpp"
#include "io/output_files.hpp"
#include "model/case.hpp"
#include "report/contact_resistance.hpp"

namespace vi {

// Every parameter of the run, defaults and derived values included, so it can be reproduced: under
// "case" the case file itself (io/case_writer.hpp) with the values the run used for keys left to their
// defaults, beside derived values (nodes, effective modulus and damping, contact stiffness, y0, ...).
nlohmann::json resolved_case_json(const Case& c, const BuiltProblem& b, const ImpactSummary& s);

// The switching ledger as JSON (times in s, forces in N, velocities in m/s; null where not applicable).
nlohmann::json switching_json(const SwitchingLedger& l);

// The summary: impacts, episodes, T, T1, T2, T_p (with its reason), tau's, y_max, z_max, energy,
// "switching" when `switching` is given (a case with electrodes), and "contact_resistance" where a
// contact has a resistance model (report/contact_resistance.hpp).
nlohmann::json transient_summary_json(const Case& c, const BuiltProblem& b, const TransientResult& r,
                                      const ImpactSummary& s, const SwitchingLedger* switching = nullptr);

// t_s, <watched>_m, <watched>_velocity_m_s (watched: "tip", "midspan" or "point", BuiltProblem),
// per contact k: contact<k>_m, contact<k>_velocity_m_s, contact<k>_force_n, then the energy terms in J
// (film_dissipated_j only where the model has squeeze films), then contact<k>_resistance_ohm of each
// series in `resistances` (inf while open).
CsvTable history_csv(const TransientResult& r, const std::string& watched = "tip", bool films = false,
                     const std::vector<ResistanceSeries>& resistances = {});

// One row per contact episode with the index of the impact it belongs to (the missing marker for an
// episode in no impact).
CsvTable events_csv(const TransientResult& r, const ImpactSummary& s);

// history.csv, events.csv and summary.json.
OutputFiles transient_files(const Case& c, const BuiltProblem& b, const TransientResult& r, const ImpactSummary& s,
                            const SwitchingLedger* switching = nullptr);

}  // namespace vi
