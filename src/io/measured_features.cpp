#include "io/measured_features.hpp"

#include <algorithm>
#include <cmath>

#include "io/csv_reader.hpp"
#include "io/range_spec.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"

namespace vi {
namespace {

std::string name_list() {
    std::string s;
    for (const std::string& n : feature_names()) s.append(s.empty() ? "" : ", ").append(n);
    return s;
}

}  // namespace

const std::vector<std::string>& feature_names() {
    // The last ones are the numeric columns of a pullin sweep (sweep/columns.hpp; a test holds them equal).
    static const std::vector<std::string> names = {
        "f1_hz", "q1", "T_s", "T1_s", "T2_s", "Tp_s", "y_max_m", "z_max", "impact1_peak_force_n", "closing_time_s",
        "V_PI_V", "rest_capacitance_f", "pullin_voltage_v", "pullin_travel_m", "pullin_capacitance_f",
        "touchdown_voltage_v", "touchdown_travel_m", "touchdown_capacitance_f", "release_voltage_v",
        "release_travel_m", "release_capacitance_f", "collapse_voltage_v", "collapse_travel_m",
        "collapse_capacitance_f", "hysteresis_v"};
    return names;
}

MeasuredFeatures read_measured_features(const std::string& path) {
    MeasuredFeatures m;
    m.file = path;
    std::size_t line_no = 0;
    const auto fail = [&](const std::string& why) {
        return InputError(one_line(path + ":" + std::to_string(line_no == 0 ? 1 : line_no) + ": " + why));
    };
    std::string reason;
    const std::optional<std::string> text = file_text(path, reason);
    if (!text) throw fail("cannot read the features file: " + reason);
    int in = -1, iv = -1, is = -1;
    std::size_t width = 0;
    for (const CsvRow& csv_row : split_csv(*text, path, true)) {
        const std::vector<std::string>& row = csv_row.cells;
        line_no = csv_row.line;
        if (width == 0) {
            width = row.size();
            for (std::size_t k = 0; k < row.size(); ++k) {
                int* slot = row[k] == "name" ? &in : row[k] == "value" ? &iv : row[k] == "sigma" ? &is : nullptr;
                if (!slot) continue;
                if (*slot >= 0) throw fail("column " + row[k] + " appears twice in the header");
                *slot = static_cast<int>(k);
            }
            if (in < 0 || iv < 0 || is < 0) throw fail("the header row must name the columns name, value and sigma");
            continue;
        }
        if (row.size() != width) {
            throw fail("expected " + std::to_string(width) + " comma-separated cells, got " + std::to_string(row.size()));
        }
        MeasuredFeature f;
        f.line = line_no;
        f.name = row[static_cast<std::size_t>(in)];
        const auto& names = feature_names();
        if (std::find(names.begin(), names.end(), f.name) == names.end()) {
            throw fail("name: '" + f.name + "' is not a feature (one of: " + name_list() + ")");
        }
        for (const MeasuredFeature& g : m.features) {
            if (g.name == f.name) throw fail(f.name + " is given twice (first on line " + std::to_string(g.line) + ")");
        }
        const auto number = [&](int k, const char* col) {
            const std::string& s = row[static_cast<std::size_t>(k)];
            const std::optional<double> v = finite_number(s);
            if (!v) throw fail(f.name + ": " + col + " '" + s + "' is not a finite number");
            if (*v != 0.0 && !(std::abs(*v) >= 1.0 / kMagnitudeLimit && std::abs(*v) <= kMagnitudeLimit)) {
                throw fail(f.name + ": " + col + " " + s + " is outside the magnitudes the fit computes with (1e-100 to " +
                           "1e100 in SI units; docs/case-files.md, Limits)");
            }
            return *v;
        };
        f.value = number(iv, "value");
        f.sigma = number(is, "sigma");
        if (!(f.sigma > 0.0)) throw fail(f.name + ": sigma must be positive (the value's standard uncertainty, same unit)");
        m.features.push_back(std::move(f));
    }
    if (m.features.empty()) throw fail("no feature (expected a header row name,value,sigma and one row per feature)");
    return m;
}

}  // namespace vi
