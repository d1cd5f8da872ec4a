#include "model/key_checks.hpp"

#include <algorithm>
#include <cmath>

#include "model/case_schema.hpp"
#include "model/number_format.hpp"
#include "model/run_estimate.hpp"

// Why a window and not just "finite": the solvers form products of a few of these values (EI = E w t^3
// / 12, omega^2, energies 1/2 k q^2, the state matrix's omega^2 next to 1). A value of 1e-320 is
// subnormal and has lost its digits; 1e308 overflows at the first product. Nothing physical in SI
// units comes near 1e+-100, so the window refuses only values that cannot be computed with. It holds
// for every number a case file gives, from one place: the schema's list of keys.

namespace vi {
namespace {

bool within_magnitude_window(double v) { return std::abs(v) >= 1.0 / kMagnitudeLimit && std::abs(v) <= kMagnitudeLimit; }

// One number of key k: finite, in range, in the window (numbers only; whole numbers have ranges).
void check_key_number(std::vector<CaseProblem>& out, const std::string& path, const KeySpec& k, double v) {
    if (!std::isfinite(v)) {
        out.push_back({path, "must be a finite number"});
        return;
    }
    std::string why = k.range.problem(v);
    if (why.empty() && k.kind != KeyKind::integer && k.kind != KeyKind::integer_pair && k.magnitude_checked) {
        why = magnitude_problem(v);
    }
    if (!why.empty()) out.push_back({path, why});
}

// The rows of a table file (times and values) within the window.
void check_table_rows(std::vector<CaseProblem>& out, const std::string& path, const TimeFunction& g) {
    for (std::size_t r = 0; r < g.times.size() && r < g.values.size(); ++r) {
        for (const double v : {g.times[r], g.values[r]}) {
            const std::string why = magnitude_problem(v);
            if (!why.empty()) out.push_back({path, why});
        }
    }
}

void check_section_keys(std::vector<CaseProblem>& out, const Case& c, const SectionSpec& s) {
    const std::size_t n = s.count(c);
    const std::size_t checked = s.max_entries > 0 ? std::min(n, s.max_entries) : n;
    for (std::size_t i = 0; i < checked; ++i) {
        for (const KeySpec& k : s.keys) {
            if (!key_in_effect(c, s, k, i)) continue;
            const std::string path = key_path(s, i, k.name);
            if (is_numeric(k.kind)) {
                for (std::size_t e = 0; e < (is_pair(k.kind) ? 2u : 1u); ++e) check_key_number(out, path, k, k.get_number(c, i, e));
            } else if (k.kind == KeyKind::table_file && k.table) {
                if (const TimeFunction* g = k.table(const_cast<Case&>(c), i)) check_table_rows(out, path, *g);
            }
            if (k.rule) k.rule(out, c, i);
        }
    }
}

}  // namespace

std::string magnitude_problem(double v) {
    if (!std::isfinite(v) || v == 0.0 || within_magnitude_window(v)) return "";
    return significant(v, 3) + " is outside the magnitudes double precision computes with here (1e-100 to 1e100 in SI "
           "units" + (std::abs(v) < 2.2250738585072014e-308 ? ", and subnormal" : "") + "; docs/case-files.md, Limits)";
}

void check_key_values(std::vector<CaseProblem>& out, const Case& c) {
    for (const SectionSpec& s : case_schema().sections) check_section_keys(out, c, s);
}

}  // namespace vi
