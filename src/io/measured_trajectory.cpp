#include "io/measured_trajectory.hpp"

#include <cmath>
#include <optional>

#include "io/csv_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"

namespace vi {

MeasuredTrajectory read_measured_trajectory(const std::string& path, const std::string& column, std::size_t min_rows) {
    MeasuredTrajectory m;
    m.file = path;
    m.column = column;
    std::size_t line_no = 0;
    const auto fail = [&](const std::string& why) {
        return InputError(one_line(path + ":" + std::to_string(line_no == 0 ? 1 : line_no) + ": " + why));
    };
    std::string reason;
    const std::optional<std::string> text = file_text(path, reason);
    if (!text) throw fail("cannot read the data file: " + reason);
    const std::vector<CsvRow> rows = split_csv(*text, path, true);
    if (rows.empty()) throw fail("empty file (expected a header row naming t_s and " + column + ")");
    int it = -1, iv = -1, is = -1;
    const std::vector<std::string>& header = rows.front().cells;
    line_no = rows.front().line;
    for (std::size_t k = 0; k < header.size(); ++k) {
        int* slot = header[k] == "t_s" ? &it : header[k] == column ? &iv : header[k] == "sigma" ? &is : nullptr;
        if (!slot) continue;
        if (*slot >= 0) throw fail("column " + header[k] + " appears twice in the header");
        *slot = static_cast<int>(k);
    }
    if (it < 0 || iv < 0) throw fail("the header row must name the columns t_s and " + column);
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const std::vector<std::string>& row = rows[r].cells;
        line_no = rows[r].line;
        if (row.size() != header.size()) {
            throw fail("expected " + std::to_string(header.size()) + " comma-separated cells, got " + std::to_string(row.size()));
        }
        const auto number = [&](int k, const char* name) {
            const std::string& s = row[static_cast<std::size_t>(k)];
            const std::optional<double> v = csv_cell_number(s);
            if (v && std::isnan(*v)) {
                throw fail(std::string(name) + ": a missing value ('" + s + "'); every sample needs a finite number (leave the row out)");
            }
            if (!v || !std::isfinite(*v)) throw fail(std::string(name) + ": '" + s + "' is not a finite number");
            if (*v != 0.0 && !(std::abs(*v) >= 1.0 / kMagnitudeLimit && std::abs(*v) <= kMagnitudeLimit)) {
                throw fail(std::string(name) + ": " + s + " is outside the magnitudes the fit computes with (1e-100 to 1e100 " +
                           "in SI units; docs/case-files.md, Limits): check the column's unit");
            }
            return *v;
        };
        const double t = number(it, "t_s");
        if (!m.t.empty() && !(t > m.t.back())) throw fail("t_s: times must increase strictly down the table");
        m.t.push_back(t);
        m.line.push_back(line_no);
        m.value.push_back(number(iv, column.c_str()));
        if (is >= 0) {
            const double s = number(is, "sigma");
            if (!(s > 0.0)) throw fail("sigma: the noise level must be positive");
            m.sigma.push_back(s);
        }
    }
    if (m.t.size() < min_rows) {
        throw fail(std::to_string(m.t.size()) + " samples, fewer than the " + std::to_string(min_rows) +
                   " needed (more than the fitted parameters)");
    }
    return m;
}

}  // namespace vi
