#pragma once
// The electrical resistance of the contacts that have a resistance model (a Hertz support with a
// resistivity), at every sample of a transient's history, and its summary: the resistance at the end
// and the time from which it stays below the contact's on threshold (docs/hertz-contact.md §4).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dynamics/transient_result.hpp"
#include "problem/beam_model.hpp"

namespace vi {

// One contact's resistance over the history's samples [ohm]: +inf where it is open (F = 0).
struct ResistanceSeries {
    std::size_t contact = 0;  // its index among the model's contacts (the history's contact<k>)
    std::string name;         // its case key, "supports[0]"
    double r_on = 0.0;        // its on threshold [ohm], NaN when none is set
    std::vector<double> ohm;
};

// The series of every contact of `model` with a resistance model, from r's sampled history (none
// where the history was not kept).
std::vector<ResistanceSeries> contact_resistances(const BeamModel& model, const TransientResult& r);

// Per series: {"contact", "closed_at_end", "resistance_end_ohm" (null while open: JSON has no
// infinity), "r_on_ohm", "below_r_on_from_s" (the first sample from which every later one is below
// r_on; null when the last is not, or without r_on)}, and the electrical bounce ledger of the run's
// conduction record (impacts/electrical_ledger.hpp): "first_closure_s", "electrical_bounces",
// "settle_time_s", "openings" [{"t_s", "duration_s", "closure_min_resistance_ohm"}], each null
// without r_on (settle_time_s also when the resistance is not below r_on at the end).
nlohmann::json contact_resistance_json(const std::vector<ResistanceSeries>& series, const TimeHistory& h,
                                       const std::vector<ContactConduction>& conduction);

}  // namespace vi
