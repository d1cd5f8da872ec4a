#include "io/csv_names.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vi {
namespace {

struct Suffix {
    const char* suffix;
    const char* unit;
};

// Every unit ending a column name may have: SI units (what data files hold) and the few scaled ones
// that figure data in display units use (t_us, tip_nm, force_un). Lower case throughout, µ as u.
// Checked longest first, so that "_m_s" wins over "_s".
const std::vector<Suffix>& suffixes() {
    static const std::vector<Suffix> s = [] {
        std::vector<Suffix> v{
            {"_per_m_sqrt_kg", "1/(m √kg)"}, {"_per_sqrt_kg", "1/√kg"}, {"_periods", "periods"},
            // a table with one row per feature (fit --features): the unit the row's feature names
            {"_in_feature_unit", "unit of the feature"},
            {"_over_l", "x/l"}, {"_kg_m3", "kg/m³"}, {"_n_s_m", "N s/m"}, {"_rad_s", "rad/s"}, {"_per_s", "1/s"},
            {"_mm_s", "mm/s"}, {"_pa_s", "Pa s"}, {"_j_m2", "J/m²"}, {"_m_s", "m/s"}, {"_n_s", "N s"}, {"_n_m", "N/m"},
            {"_khz", "kHz"}, {"_hz", "Hz"}, {"_rad", "rad"}, {"_pa", "Pa"}, {"_kg", "kg"},
            {"_us", "µs"}, {"_ns", "ns"}, {"_ms", "ms"}, {"_um", "µm"}, {"_nm", "nm"}, {"_mm", "mm"}, {"_un", "µN"},
            {"_pj", "pJ"}, {"_ff", "fF"}, {"_s", "s"}, {"_m", "m"}, {"_n", "N"}, {"_j", "J"}, {"_w", "W"},
            {"_v", "V"}, {"_f", "F"}, {"_k", "K"}, {"_ohm_m2", "Ω m²"}, {"_ohm_m", "Ω m"}, {"_ohm", "Ω"},
            // a curvature, and a gradient of a stress through a thickness
            {"_per_m", "1/m"}, {"_pa_per_m", "Pa/m"},
            // a volume (the wear estimate of the cycles study)
            {"_m3", "m³"},
        };
        std::stable_sort(v.begin(), v.end(), [](const Suffix& a, const Suffix& b) {
            return std::string_view(a.suffix).size() > std::string_view(b.suffix).size();
        });
        return v;
    }();
    return s;
}

// Names that are dimensionless by definition, with "#" for a number: counts, indices, flags, ratios,
// the paper's dimensionless quantities, text columns.
const std::vector<std::string_view>& dimensionless() {
    static const std::vector<std::string_view> d{
        // indices, counts and flags
        "index", "mode", "mode_#", "episode", "impact", "support", "j", "impacts", "episodes", "bounces", "maxima",
        "elements", "events", "steps", "iterations", "modes", "modes[#]", "contact", "stable", "closed_at_end",
        "at_support", "feasible", "stuck", "samples", "frame",
        // a spread study's figure data: an input's path, its Sobol indices and their intervals' ends
        "input", "sobol_first", "sobol_total", "sobol_first_low", "sobol_first_high", "sobol_total_low",
        "sobol_total_high",
        // ratios and the paper's dimensionless quantities (tau = omega_1 T, z = y/l, amplitudes of
        // dimensionless mode shapes Y and Phi)
        "ratio", "ratio_#", "ratios[#]", "over_peak", "over_sigma", "tau", "tau#", "tau_p", "z_max", "z_min", "z_equilibrium",
        "z_top", "amplitude", "Y_#", "Phi_#", "Y_#_#", "Phi_#_#", "knudsen", "squeeze_number", "q_modal",
        "q_ringdown", "unproven_excess", "offset", "permittivity", "tolerance", "rtol",
        "restitution",  // a coefficient of restitution
        "wear_coefficient",  // Archard's K
        "cycle",  // an actuation cycle's index
        "level",  // a two-step drive's first level, a fraction of the voltage
        // text
        "status", "stage", "kind", "law", "verdict", "reason", "feature", "solver", "state",
    };
    return d;
}

bool ends_with(std::string_view s, std::string_view tail) {
    return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// Every run of digits as one '#'.
std::string numbers_as_hash(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (std::isdigit(static_cast<unsigned char>(s[i]))) {
            out += '#';
            while (i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]))) ++i;
        } else {
            out += s[i];
        }
    }
    return out;
}

}  // namespace

CsvColumnUnit csv_column_unit(std::string_view name) {
    for (const Suffix& s : suffixes()) {
        const std::string_view tail = s.suffix;
        if (name.size() > tail.size() && ends_with(name, tail)) {
            return {std::string(name.substr(0, name.size() - tail.size())), s.unit, s.suffix};
        }
    }
    return {std::string(name), "", ""};
}

std::string csv_unit_suffix(std::string_view unit) {
    static const std::vector<std::pair<std::string_view, std::string_view>> si{
        {"m", "_m"},         {"s", "_s"},           {"N", "_n"},         {"Pa", "_pa"},     {"kg/m^3", "_kg_m3"},
        {"N/m", "_n_m"},     {"N s/m", "_n_s_m"},   {"J/m^2", "_j_m2"},  {"1/s", "_per_s"}, {"m/s", "_m_s"},
        {"Hz", "_hz"},       {"rad", "_rad"},       {"V", "_v"},         {"K", "_k"},       {"Pa s", "_pa_s"},
        {"x/l", "_over_l"},  {"periods", "_periods"}, {"-", ""}, {"ohm", "_ohm"}, {"ohm m", "_ohm_m"},
        {"ohm m^2", "_ohm_m2"}, {"1/m", "_per_m"}, {"Pa/m", "_pa_per_m"}, {"m^3", "_m3"},
    };
    for (const auto& [u, suffix] : si) {
        if (u == unit) return std::string(suffix);
    }
    throw std::invalid_argument("no column-name ending for the unit '" + std::string(unit) + "'");
}

bool csv_column_name_ok(std::string_view name) {
    const std::size_t dot = name.rfind('.');
    const std::string_view field = dot == std::string_view::npos ? name : name.substr(dot + 1);
    if (field.empty()) return false;
    if (!csv_column_unit(field).suffix.empty()) return true;
    const std::string n = numbers_as_hash(field);
    for (std::string_view d : dimensionless()) {
        if (n == d || (n.size() > d.size() && ends_with(n, d) && n[n.size() - d.size() - 1] == '_')) return true;
    }
    return false;
}

std::vector<std::string> numbered_columns(std::string_view stem, std::size_t count, std::string_view suffix) {
    std::vector<std::string> out;
    for (std::size_t k = 1; k <= count; ++k) {
        // Built step by step: GCC 12 warns (-Wrestrict) on a chain of + here.
        std::string name(stem);
        name += std::to_string(k);
        name += suffix;
        out.push_back(std::move(name));
    }
    return out;
}

}  // namespace vi
