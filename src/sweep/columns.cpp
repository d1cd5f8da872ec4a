#include "sweep/columns.hpp"

#include <cmath>
#include <optional>

#include "impacts/electrical_ledger.hpp"
#include "io/number_text.hpp"
#include "model/input_error.hpp"

namespace vi {

std::optional<double> numeric_cell(const SweepCell& cell) {
    if (const double* d = std::get_if<double>(&cell)) return *d;
    if (const std::int64_t* n = std::get_if<std::int64_t>(&cell)) return static_cast<double>(*n);
    return std::nullopt;
}
bool sweep_column_is_text(const std::string& name) {
    return name.ends_with("_reason") || name == "solver" || name.rfind("nodes_supported_", 0) == 0 ||
           (name.rfind("impact", 0) == 0 && name.size() > 8 && name.ends_with("_support"));
}

namespace {

SweepCell opt_cell(const std::optional<double>& v) { return v ? SweepCell(*v) : SweepCell(); }

SweepCell scaled_cell(const std::optional<double>& v, double k) { return v ? SweepCell(*v * k) : SweepCell(); }

std::string impact_prefix(int k) { return "impact" + std::to_string(k) + "_"; }

// The electrical bounce ledger of the first contact with a resistance model: bounces and settle time
// (empty without its threshold r_on, the settle time also when it does not settle), the resistance
// at the end (empty while open); all empty without a resistance model.
void add_electrical_cells(std::vector<SweepCell>& cells, const std::vector<ContactConduction>& conduction) {
    if (conduction.empty()) {
        cells.insert(cells.end(), 3, SweepCell());
        return;
    }
    const ContactConduction& c = conduction.front();
    const std::optional<ElectricalLedger> l = electrical_ledger(c);
    cells.push_back(l ? SweepCell(static_cast<std::int64_t>(l->bounces)) : SweepCell());
    cells.push_back(l ? opt_cell(l->settle_time) : SweepCell());
    cells.push_back(std::isfinite(c.end_resistance) ? SweepCell(c.end_resistance) : SweepCell());
}

std::string support_prefix(int k) { return "support" + std::to_string(k) + "_"; }

// The impacts' damage sums: contact energy (empty where not recorded), peak pressure (empty without
// a law that has one), impacts past yield onset (empty without a yield strength).
void add_damage_cells(std::vector<SweepCell>& cells, const ContactDamage& d) {
    cells.push_back(std::isnan(d.contact_energy) ? SweepCell() : SweepCell(d.contact_energy));
    cells.push_back(std::isnan(d.peak_pressure) ? SweepCell() : SweepCell(d.peak_pressure));
    cells.push_back(d.yield_known ? SweepCell(static_cast<std::int64_t>(d.yield_impacts)) : SweepCell());
}

// Support k's own cells: its electrical ledger (as add_electrical_cells) and its impacts' damage.
void add_support_cells(std::vector<SweepCell>& cells, const SimulationRun& run, int k) {
    const std::string name = "supports[" + std::to_string(k) + "]";
    const std::vector<NamedContact>& contacts = run.built.model.contacts;
    int contact = -1;
    for (std::size_t j = 0; j < contacts.size(); ++j) {
        if (contacts[j].name == name) contact = static_cast<int>(j);
    }
    std::vector<ContactConduction> own;
    for (const ContactConduction& c : run.result.conduction) {
        if (c.contact == contact) own.push_back(c);
    }
    add_electrical_cells(cells, own);
    std::vector<Impact> impacts;
    for (const Impact& im : run.summary.impacts) {
        if (im.support == contact) impacts.push_back(im);
    }
    add_damage_cells(cells, contact_damage(impacts));
}

// x/l values as one text cell, each read back exactly, so the cell is the same wherever it is computed.
std::string positions_text(const std::vector<double>& xs) {
    std::string s;
    for (double x : xs) {
        if (!s.empty()) s += ' ';
        s += round_trip_text(x);
    }
    return s;
}

}  // namespace

const char* sweep_analysis_name(SweepAnalysis a) {
    switch (a) {
        case SweepAnalysis::simulate: return "simulate";
        case SweepAnalysis::modes: return "modes";
        case SweepAnalysis::pullin: return "pullin";
        case SweepAnalysis::stiction: return "stiction";
        case SweepAnalysis::air_q: return "air-q";
    }
    return "simulate";
}

std::string sweep_analysis_names(const char* separator) {
    std::string s;
    for (SweepAnalysis a : kSweepAnalyses) s += (s.empty() ? "" : separator) + std::string(sweep_analysis_name(a));
    return s;
}

SweepAnalysis parse_sweep_analysis(const std::string& name) {
    for (SweepAnalysis a : kSweepAnalyses) {
        if (name == sweep_analysis_name(a)) return a;
    }
    throw InputError("--analysis " + name + ": no such analysis (" + sweep_analysis_names(", ") + ")");
}

namespace {

// The point columns of the pull-in trace: voltage, mean travel and capacitance.
void add_pullin_point_columns(std::vector<SweepColumn>& cols, const std::string& point) {
    cols.push_back({point + "_voltage_v", "V"});
    cols.push_back({point + "_travel_m", "m"});
    cols.push_back({point + "_capacitance_f", "F"});
}

std::vector<SweepColumn> pullin_columns() {
    std::vector<SweepColumn> cols = {{"rest_capacitance_f", "F"}};
    for (const char* p : {"pullin", "touchdown", "release", "collapse"}) add_pullin_point_columns(cols, p);
    cols.push_back({"hysteresis_v", "V"});
    cols.push_back({"end_reason", ""});
    return cols;
}

}  // namespace

std::vector<SweepColumn> sweep_result_columns(SweepAnalysis analysis, int modes, int supports) {
    if (analysis == SweepAnalysis::pullin) return pullin_columns();
    if (analysis == SweepAnalysis::stiction) {
        return {{"stuck", ""}, {"force_margin_n", "N"}, {"adhesion_margin_j_m2", "J/m^2"}, {"detached_length_m", "m"}};
    }
    if (analysis == SweepAnalysis::air_q) {
        return {{"pressure_pa", "Pa"},    {"knudsen", "-"}, {"viscosity_ratio", "-"},
                {"squeeze_number", "-"}, {"q_modal", "-"}, {"q_ringdown", "-"}};
    }
    if (analysis == SweepAnalysis::modes) {
        std::vector<SweepColumn> cols;
        for (int i = 1; i <= modes; ++i) {
            const std::string n = std::to_string(i);
            cols.push_back({"f_unsupported_" + n + "_hz", "Hz"});
            cols.push_back({"f_supported_" + n + "_hz", "Hz"});
            cols.push_back({"ratio_" + n, "-"});
            cols.push_back({"nodes_supported_" + n + "_over_l", "x/l"});
        }
        return cols;
    }
    std::vector<SweepColumn> cols = {
        {"omega1_rad_s", "rad/s"}, {"impacts", ""}, {"episodes", ""},   {"T_s", "s"},
        {"T1_s", "s"},             {"T2_s", "s"},   {"Tp_s", "s"},      {"Tp_reason", ""},
        {"tau", "-"},              {"tau1", "-"},   {"tau2", "-"},      {"tau_p", "-"},
        {"y_max_m", "m"},          {"z_max", "-"},  {"y_max_contact_m", "m"}, {"tip_min_m", "m"},
        {"unproven_excess", "-"}, {"solver", ""},
        {"closing_time_s", "s"},   {"bounces", ""},  {"stable_contact_s", "s"}, {"release_time_s", "s"},
        {"grouped_bounces", ""},   {"switching_state", ""}, {"collapse_time_s", "s"},
    };
    for (int k = 1; k <= kSweepImpactColumns; ++k) {
        const std::string p = impact_prefix(k);
        cols.push_back({p + "support", ""});
        cols.push_back({p + "t_on_s", "s"});
        cols.push_back({p + "v_in_m_s", "m/s"});
        cols.push_back({p + "peak_force_n", "N"});
        cols.push_back({p + "peak_penetration_m", "m"});
        cols.push_back({p + "duration_s", "s"});
        cols.push_back({p + "episodes", ""});
    }
    cols.push_back({"electrical_bounces", ""});
    cols.push_back({"settle_time_s", "s"});
    cols.push_back({"resistance_end_ohm", "ohm"});
    cols.push_back({"contact_energy_j", "J"});
    cols.push_back({"peak_pressure_pa", "Pa"});
    cols.push_back({"yield_impacts", ""});
    for (int k = 0; k < supports; ++k) {
        const std::string p = support_prefix(k);
        cols.push_back({p + "electrical_bounces", ""});
        cols.push_back({p + "settle_time_s", "s"});
        cols.push_back({p + "resistance_end_ohm", "ohm"});
        cols.push_back({p + "contact_energy_j", "J"});
        cols.push_back({p + "peak_pressure_pa", "Pa"});
        cols.push_back({p + "yield_impacts", ""});
    }
    return cols;
}

std::vector<SweepCell> simulate_cells(const SimulationRun& run, int supports) {
    const ImpactSummary& s = run.summary;
    const double w1 = run.built.model.omega1;
    std::vector<SweepCell> cells = {
        w1,
        static_cast<std::int64_t>(s.impacts.size()),
        static_cast<std::int64_t>(run.result.episodes.size()),
        opt_cell(s.T_first),
        opt_cell(s.T1_first),
        opt_cell(s.T2_first),
        opt_cell(s.Tp),
        s.Tp_reason,
        scaled_cell(s.T_first, w1),
        scaled_cell(s.T1_first, w1),
        scaled_cell(s.T2_first, w1),
        scaled_cell(s.Tp, w1),
        opt_cell(s.y_max),
        opt_cell(s.z_max),
        opt_cell(s.y_max_contact),
        opt_cell(s.watched_min),
        // Only the exact solver proves its event searches (CVODE's root finding may step over a
        // sign change unseen): empty for CVODE.
        run.result.stats.method == "exact" ? SweepCell(run.result.stats.unproven_excess) : SweepCell(),
        // The solver that computed the point; "cvode_fallback" when the exact solver handed it over.
        std::string(run.result.stats.fallback_reason.empty() ? run.result.stats.method : "cvode_fallback"),
    };
    // The switching ledger's headline; empty without electrodes (and where it has no such time).
    if (const auto& l = run.switching) {
        cells.push_back(opt_cell(l->closing_time));
        cells.push_back(static_cast<std::int64_t>(l->bounces));
        cells.push_back(opt_cell(l->stable_contact));
        cells.push_back(opt_cell(l->release_time));
        cells.push_back(static_cast<std::int64_t>(l->grouped_bounces));
        cells.push_back(l->state);
        cells.push_back(l->collapse ? SweepCell(l->collapse->time) : SweepCell());
    } else {
        cells.insert(cells.end(), 7, SweepCell());
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(kSweepImpactColumns); ++k) {
        if (k >= s.impacts.size()) {
            cells.insert(cells.end(), 7, SweepCell());
            continue;
        }
        const Impact& im = s.impacts[k];
        cells.push_back(static_cast<std::int64_t>(im.support));
        cells.push_back(im.t_on);
        cells.push_back(im.v_in);
        cells.push_back(im.peak_force);
        cells.push_back(im.peak_penetration);
        // An impact still closed when the horizon ends has no duration yet.
        cells.push_back(im.closed_at_end ? SweepCell() : SweepCell(im.t_off - im.t_on));
        cells.push_back(static_cast<std::int64_t>(im.episodes));
    }
    add_electrical_cells(cells, run.result.conduction);
    add_damage_cells(cells, contact_damage(s.impacts));
    for (int k = 0; k < supports; ++k) add_support_cells(cells, run, k);
    return cells;
}

std::vector<SweepCell> modes_cells(const ModalStudy& study, int modes) {
    std::vector<SweepCell> cells;
    for (std::size_t i = 0; i < static_cast<std::size_t>(modes); ++i) {
        const auto& u = study.unsupported.bending;
        const auto& s = study.supported.bending;
        cells.push_back(i < u.size() ? SweepCell(u[i].frequency_hz) : SweepCell());
        cells.push_back(i < s.size() ? SweepCell(s[i].frequency_hz) : SweepCell());
        cells.push_back(i < study.ratios.size() ? SweepCell(study.ratios[i]) : SweepCell());
        cells.push_back(i < s.size() ? SweepCell(positions_text(s[i].features.nodes)) : SweepCell());
    }
    return cells;
}

std::vector<SweepCell> pullin_cells(const PullinResult& r) {
    std::vector<SweepCell> cells;
    cells.push_back(r.branch.empty() ? SweepCell() : SweepCell(r.branch.front().capacitance));
    const auto point = [&](const std::optional<PullinPoint>& p) {
        cells.push_back(p ? SweepCell(p->voltage) : SweepCell());
        cells.push_back(p ? SweepCell(p->travel) : SweepCell());
        cells.push_back(p ? SweepCell(p->capacitance) : SweepCell());
    };
    point(r.pullin);
    point(r.touchdown);
    // The release point: the stable closed state at the release voltage (the trace's lowest one).
    std::optional<PullinPoint> release;
    if (r.release_voltage) {
        for (const PullinPoint& p : r.branch) {
            if (p.contact && p.stable && p.voltage == *r.release_voltage) release = p;
        }
        if (!release && r.touchdown && r.touchdown->voltage == *r.release_voltage) release = r.touchdown;
    }
    point(release);
    point(r.collapse);
    const std::optional<PullinPoint>& closing = r.pullin ? r.pullin : r.touchdown;
    cells.push_back(closing && r.release_voltage ? SweepCell(closing->voltage - *r.release_voltage) : SweepCell());
    cells.emplace_back(r.end);
    return cells;
}

}  // namespace vi
