#include "sweep/column_docs.hpp"

#include <cctype>
#include <stdexcept>

namespace vi {
namespace {

const std::vector<SweepColumnDoc>& simulate_docs() {
    static const std::vector<SweepColumnDoc> d = {
        {{"omega1_rad_s"}, "rad/s", "first circular frequency of the unsupported beam (its mesh has nodes at the supports)"},
        {{"impacts", "episodes"}, "count", "impacts (grouped episodes) and contact episodes in the horizon"},
        {{"T_s", "T1_s", "T2_s"}, "s",
         "first cycle: period, flight, impact duration (`nan` without two impacts of the cycle's support, or for an "
         "impact still closed at the horizon)"},
        {{"Tp_s"}, "s", "duration of the transient process (`nan` when the horizon ended first: see `Tp_reason`)"},
        {{"Tp_reason"}, "text", "`settled`, `persistent_contact`, `horizon` or `no_impact`"},
        {{"tau", "tau1", "tau2", "tau_p"}, "-", "omega1 times T, T1, T2, T_p"},
        {{"y_max_m", "z_max"}, "m, -", "largest rise of the free end above its final equilibrium after the first impact, and y_max / l"},
        {{"y_max_contact_m"}, "m", "the same at the first support"},
        {{"tip_min_m"}, "m", "deepest deflection of the free end"},
        {{"unproven_excess"}, "-",
         "exact solver: how far, relative to the watched signal's size, a contact narrower than the smallest "
         "event-search step could have gone unseen (docs/model.md §12; roundoff, ~1e-14, when nothing could be "
         "missed); `nan` for CVODE"},
        {{"solver"}, "text",
         "the solver that computed the point: `exact`, `cvode`, or `cvode_fallback` when the exact solver met a "
         "contact state it could not go on with (`solver.fallback`, docs/case-files.md) and CVODE computed the point "
         "instead"},
        {{"closing_time_s"}, "s",
         "switching ledger (docs/electrostatics.md §5): onset of the first contact; `nan` without electrodes or when "
         "the switch never closes"},
        {{"bounces"}, "count",
         "contact episodes that opened before stable contact, every separation counted (chatter included); `nan` "
         "without electrodes"},
        {{"stable_contact_s"}, "s",
         "onset of the contact that holds until the voltage falls (or, voltage on, to the horizon for at least one "
         "period of mode 1); `nan` when none"},
        {{"release_time_s"}, "s",
         "end of the last contact once the voltage has fallen, the switch then open; `nan` when it does not release "
         "in the horizon (or the voltage never falls)"},
        {{"grouped_bounces"}, "count",
         "the bounces followed by a flight of at least `solver.group_gap` (a quarter period of mode 1 by default) "
         "before the next contact, or by none: the bounces an oscilloscope tells apart; `nan` without electrodes"},
        {{"switching_state"}, "text",
         "the switching ledger's state at the end: `never_closed`, `closed`, `stuck`, `released`, "
         "`opened_before_voltage_off`, `bouncing` or `collapsed` (the beam reached an electrode, which ended the run: "
         "an answer, the row is ok); empty without electrodes"},
        {{"collapse_time_s"}, "s", "when the beam reached an electrode (state `collapsed`); `nan` otherwise"},
        {{"impact<k>_support"}, "index", "support hit by impact k (k = 1, 2, 3)"},
        {{"impact<k>_t_on_s"}, "s", "onset"},
        {{"impact<k>_v_in_m_s"}, "m/s", "pre-impact velocity of the contact point (signed, v up)"},
        {{"impact<k>_peak_force_n"}, "N", "largest contact force"},
        {{"impact<k>_peak_penetration_m"}, "m", "largest penetration"},
        {{"impact<k>_duration_s"}, "s", "end minus onset (`nan` if still closed at the horizon)"},
        {{"impact<k>_episodes"}, "count", "contact episodes grouped into the impact"},
        {{"electrical_bounces"}, "count",
         "electrical bounce ledger of the first support with a `resistivity` (docs/hertz-contact.md §7): every "
         "rise of its resistance to `r_on` (or opening) after it first fell below; `nan` without a resistance model "
         "or without `r_on`"},
        {{"settle_time_s"}, "s",
         "time from the start until that resistance stays below `r_on` to the end of the run; `nan` when it is not "
         "below `r_on` at the end (it never settles in the horizon), without `r_on` or a resistance model"},
        {{"resistance_end_ohm"}, "ohm",
         "that contact's resistance at the end of the run; `nan` when it is open then, or without a resistance model"},
        {{"contact_energy_j"}, "J",
         "energy dissipated in the contacts over every impact (docs/hertz-contact.md §8); `nan` from the exact "
         "solver, which does not record it"},
        {{"peak_pressure_pa"}, "Pa", "largest Hertz peak pressure p0 of any impact; `nan` without a Hertz support"},
        {{"yield_impacts"}, "count",
         "impacts whose p0 passed the yield onset 1.6 Y; `nan` without a `yield_strength`"},
        {{"support<k>_electrical_bounces", "support<k>_settle_time_s", "support<k>_resistance_end_ohm"}, "count, s, ohm",
         "as `electrical_bounces`, `settle_time_s`, `resistance_end_ohm`, for support k (k = 0, 1, ... for every "
         "support of the case); `nan` for a support without a resistance model"},
        {{"support<k>_contact_energy_j", "support<k>_peak_pressure_pa", "support<k>_yield_impacts"}, "J, Pa, count",
         "as `contact_energy_j`, `peak_pressure_pa`, `yield_impacts`, over the impacts of support k"},
    };
    return d;
}

const std::vector<SweepColumnDoc>& modes_docs() {
    static const std::vector<SweepColumnDoc> d = {
        {{"f_unsupported_<i>_hz"}, "Hz", "natural frequency of bending mode i (1..N, `--modes N`) of the beam without supports"},
        {{"f_supported_<i>_hz"}, "Hz", "with every support as a pin (or a spring with `--support-model spring`)"},
        {{"ratio_<i>"}, "-", "omega_i / omega_in, supported over unsupported"},
        {{"nodes_supported_<i>_over_l"}, "x/l", "nodal points of v of the supported mode, space separated, in one cell"},
    };
    return d;
}

const std::vector<SweepColumnDoc>& pullin_docs() {
    static const std::vector<SweepColumnDoc> d = {
        {{"rest_capacitance_f"}, "F", "capacitance of all electrodes at 0 V (the supports' static state)"},
        {{"pullin_voltage_v", "pullin_travel_m", "pullin_capacitance_f"}, "V, m, F",
         "the fold of the open branch: pull-in voltage V_PI, mean travel over electrodes[0] and capacitance there; "
         "`nan` when a support closes first"},
        {{"touchdown_voltage_v", "touchdown_travel_m", "touchdown_capacitance_f"}, "V, m, F",
         "where a contact (a support or a dielectric) first closes on the traced branch; `nan` when none does"},
        {{"release_voltage_v", "release_travel_m", "release_capacitance_f"}, "V, m, F",
         "the lowest voltage that holds a closed contact stably (below it the closed switch opens), and the state "
         "there; `nan` without a stable closed state"},
        {{"collapse_voltage_v", "collapse_travel_m", "collapse_capacitance_f"}, "V, m, F",
         "the fold of the closed branch: above it the closed beam snaps on toward the electrode; `nan` when the "
         "branch has none"},
        {{"hysteresis_v"}, "V", "closing voltage (pull-in, or touch-down when a contact closes first) less the release voltage"},
        {{"end_reason"}, "text", "why the traced branch ends (the beam collapses onto the electrode, the travel reached the gap, ...)"},
    };
    return d;
}

const std::vector<SweepColumnDoc>& stiction_docs() {
    static const std::vector<SweepColumnDoc> d = {
        {{"stuck"}, "flag",
         "1 when some adhesive support or adhesive dielectric layer holds the unloaded beam (as `vibroimpact "
         "stiction` says `sticks`), else 0"},
        {{"force_margin_n"}, "N",
         "the smallest, over the adhesive supports, of the beam's restoring force less the pull-off force: > 0 "
         "releases, < 0 sticks; `nan` without adhesive supports"},
        {{"adhesion_margin_j_m2"}, "J/m^2",
         "the smallest, over adhesive supports and layers, of the critical work of adhesion (above which the contact "
         "sticks) less the contact's own: > 0 releases; `nan` when a support is pressed on unloaded (it holds "
         "whatever the adhesion)"},
        {{"detached_length_m"}, "m",
         "closed-form detached length of the S-shaped stuck cantilever (the first adhesive support with a gap, else "
         "the first adhesive layer); `nan` when there is none (docs/adhesion.md §5)"},
    };
    return d;
}

const std::vector<SweepColumnDoc>& air_q_docs() {
    static const std::vector<SweepColumnDoc> d = {
        {{"pressure_pa"}, "Pa", "the case's air pressure (`air.pressure`; 1 atm without `[air]`)"},
        {{"knudsen", "viscosity_ratio", "squeeze_number"}, "-",
         "of the first film: mean free path over gap, mu_eff / mu, squeeze number at omega1"},
        {{"q_modal"}, "-", "quality factor of mode 1 from the films' damping at rest (docs/squeeze-film.md §5)"},
        {{"q_ringdown"}, "-",
         "the same from a ring-down transient of mode 1 (10 periods); `nan` when fewer than three maxima rise above "
         "the noise (overdamped)"},
    };
    return d;
}

// True when `name` matches `pattern`, where <k> and <i> each stand for one or more digits.
bool matches(const std::string& pattern, const std::string& name) {
    std::size_t p = 0, n = 0;
    while (p < pattern.size()) {
        if (pattern.compare(p, 3, "<k>") == 0 || pattern.compare(p, 3, "<i>") == 0) {
            const std::size_t start = n;
            while (n < name.size() && std::isdigit(static_cast<unsigned char>(name[n]))) ++n;
            if (n == start) return false;
            p += 3;
            continue;
        }
        if (n >= name.size() || pattern[p] != name[n]) return false;
        ++p;
        ++n;
    }
    return n == name.size();
}

std::string joined_names(const SweepColumnDoc& d, const char* quote) {
    std::string s;
    for (const std::string& n : d.names) s += (s.empty() ? "" : ", ") + std::string(quote) + n + quote;
    return s;
}

const std::string kBegin = "<!-- sweep-columns:";
const std::string kEnd = "<!-- /sweep-columns:";

}  // namespace

std::string sweep_analysis_summary(SweepAnalysis a) {
    switch (a) {
        case SweepAnalysis::simulate: return "the free impact or switching transient, as `vibroimpact simulate`";
        case SweepAnalysis::modes: return "the modal study, as `vibroimpact modes`";
        case SweepAnalysis::pullin: return "the static pull-in trace, as `vibroimpact pullin` (without the frequencies under bias)";
        case SweepAnalysis::stiction: return "the stiction check, as `vibroimpact stiction`";
        case SweepAnalysis::air_q: return "the quality factor of mode 1 at the case's air pressure, as one pressure of `vibroimpact air-q`";
    }
    return "";
}

const std::vector<SweepColumnDoc>& sweep_column_docs(SweepAnalysis a) {
    switch (a) {
        case SweepAnalysis::simulate: return simulate_docs();
        case SweepAnalysis::modes: return modes_docs();
        case SweepAnalysis::pullin: return pullin_docs();
        case SweepAnalysis::stiction: return stiction_docs();
        case SweepAnalysis::air_q: return air_q_docs();
    }
    return simulate_docs();
}

const SweepColumnDoc* sweep_column_doc(SweepAnalysis a, const std::string& column) {
    for (const SweepColumnDoc& d : sweep_column_docs(a)) {
        for (const std::string& n : d.names) {
            if (matches(n, column)) return &d;
        }
    }
    return nullptr;
}

std::string sweep_column_table(SweepAnalysis a) {
    std::string s = "| Column | Unit | Meaning |\n|---|---|---|\n";
    for (const SweepColumnDoc& d : sweep_column_docs(a)) s += "| " + joined_names(d, "`") + " | " + d.unit + " | " + d.meaning + " |\n";
    return s;
}

std::string sweep_column_text(SweepAnalysis a, std::size_t width) {
    std::string s = std::string(sweep_analysis_name(a)) + ": " + sweep_analysis_summary(a) + "\n";
    for (const SweepColumnDoc& d : sweep_column_docs(a)) {
        s += "  " + joined_names(d, "") + " [" + d.unit + "]\n";
        std::string line = "      ";
        std::size_t at = 0;
        while (at < d.meaning.size()) {
            std::size_t end = d.meaning.find(' ', at);
            if (end == std::string::npos) end = d.meaning.size();
            std::string word = d.meaning.substr(at, end - at);
            std::erase(word, '`');
            if (line.size() > 6 && line.size() + 1 + word.size() > width) {
                s += line + "\n";
                line = "      ";
            }
            line += (line.size() > 6 ? " " : "") + word;
            at = end + 1;
        }
        s += line + "\n";
    }
    return s;
}

std::string with_sweep_column_tables(const std::string& page) {
    std::string out;
    std::size_t at = 0;
    while (true) {
        const std::size_t begin = page.find(kBegin, at);
        if (begin == std::string::npos) break;
        const std::size_t name_end = page.find(" -->", begin);
        const std::size_t line_end = page.find('\n', begin);
        if (name_end == std::string::npos || line_end == std::string::npos) {
            throw std::invalid_argument("a sweep-columns marker without its end");
        }
        const std::string name = page.substr(begin + kBegin.size(), name_end - begin - kBegin.size());
        const SweepAnalysis a = parse_sweep_analysis(name);
        const std::size_t end = page.find(kEnd + name + " -->", line_end);
        if (end == std::string::npos) throw std::invalid_argument("sweep-columns block without its end: " + name);
        out += page.substr(at, line_end + 1 - at) + sweep_column_table(a);
        at = end;
    }
    return out + page.substr(at);
}

}  // namespace vi
