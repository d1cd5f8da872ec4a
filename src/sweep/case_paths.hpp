#pragma once
// Numeric values of a Case addressed by a path such as "supports[0].position" (what a sweep varies).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/units.hpp"
#include "model/case.hpp"

namespace vi {

// A path to one number of a Case: section[i].field[k], the indices only where the section or the
// field is a list (supports[i], loads[i], damping.ratios[k], damping.modes[k]).
struct CasePath {
    std::string section;                       // "beam", "material", "supports", ...
    std::optional<std::size_t> section_index;  // i of supports[i] and loads[i]
    std::string field;                         // "position", "gap", "holes.size", ...
    std::optional<std::size_t> field_index;    // k of damping.ratios[k] and damping.modes[k]
    // The canonical text, e.g. "supports[0].position".
    [[nodiscard]] std::string text() const;
    friend bool operator==(const CasePath&, const CasePath&) = default;
};

// Parses `text` and checks it against the case: a known key, indices within the case's lists, and
// a key that means something for this case (damping.ratios[k] only when the case gives ratios,
// loads[i].frequency only for a harmonic load, ...). Throws InputError with a one-line reason.
CasePath resolve_case_path(std::string_view text, const Case& c);

// The path before the '=' of an option's setting "PATH=..." (the whole setting without one), resolved
// on c; an InputError names the option and the setting: "--set supports[9].gap=1:2: supports[9]: ...".
CasePath resolve_setting_path(std::string_view option, const std::string& setting, const Case& c);

// True where the value must be a whole number: beam.elements, damping.modes[k],
// initial.velocity_mode.
bool is_integer_path(const CasePath& p);

// SI unit of the value at p: "m", "Pa", "kg/m^3", "N/m", "N s/m", "N", "s", "m/s", "Hz", "1/s",
// "rad", "x/l" for positions along the beam, or "-" for other dimensionless values.
std::string case_path_unit(const CasePath& p);
// The name of p's column in a CSV file: its text and its unit's ending (io/csv_names.hpp), e.g.
// "supports[0].gap_m", "supports[0].position_over_l", "damping.ratios[0]" (dimensionless).
std::string case_path_column(const CasePath& p);
// The dimension of the value at p, whose units a command line may use ("0.5um"); nullopt for
// positions x/l, angles and other plain numbers.
std::optional<Dimension> case_path_dimension(const CasePath& p);

// The value at p (a path from resolve_case_path on a case of the same shape). gap reads as
// -surface and prestress as +surface, whichever key the case file used.
double get_case_value(const Case& c, const CasePath& p);

// Sets the value at p. Setting supports[i].gap or .prestress replaces the other; .damping clears
// .damping_ratio and .damping_ratio replaces .damping. Throws InputError("KEY: reason") for a
// value the key cannot hold at all (a negative gap or prestress, a non-integer where one is
// needed); every other check is check_case's.
void set_case_value(Case& c, const CasePath& p, double value);

// Sets the value at the path text `path` (resolve_case_path on c) from `value` as a setting of
// `sweep --set` writes one value: a plain SI number, or a quantity in a unit of the path's dimension
// ("0.5 um", "2 GPa"). Throws InputError("PATH: reason") for a bad path, number or unit, and as
// set_case_value does; every other check is check_case's.
void set_case_text(Case& c, std::string_view path, std::string_view value);

// Applies settings "PATH=VALUE" of a command-line option (`simulate --set`) in order, each value as
// set_case_text reads it, then checks the case as a whole. Throws InputError naming the option and
// the setting ("--set supports[0].gap=-1: ...") for a bad path, value or missing '=', and naming the
// option and the key for a problem check_case finds.
void apply_case_settings(Case& c, std::string_view option, const std::vector<std::string>& settings);

// Every accepted path, with i and k for the indices ("supports[i].position", ...), for help texts.
std::vector<std::string> case_path_forms();
// Each of those forms with its SI unit as case_path_unit gives it ("supports[i].gap", "m").
std::vector<std::pair<std::string, std::string>> case_path_form_units();

}  // namespace vi
