#include "io/measured_trajectory.hpp"

#include <cmath>
#include <optional>

#include "io/csv_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"

namespace vi {
namespace {

// The columns of a trajectory file, found in its header row.
struct TrajectoryColumns {
    int t = -1, value = -1, sigma = -1;
    std::size_t width = 0;
};

}  // namespace

MeasuredTrajectory read_measured_trajectory(const std::string& path, const std::string& column, std::size_t min_rows) {
    MeasuredTrajectory m;
    m.file = path;
    m.column = column;
    std::size_t line_no = 0;
    const auto fail = [&](const std::string& why) {
        return InputError(one_line(path + ":" + std::to_string(line_no == 0 ? 1 : line_no) + ": " + why));
    };
    std::optional<TrajectoryColumns> columns;
    const auto header = [&](const std::vector<std::string>& cells) {
        TrajectoryColumns c;
        c.width = cells.size();
        for (std::size_t k = 0; k < cells.size(); ++k) {
            int* slot = cells[k] == "t_s" ? &c.t : cells[k] == column ? &c.value : cells[k] == "sigma" ? &c.sigma : nullptr;
            if (!slot) continue;
            if (*slot >= 0) throw fail("column " + cells[k] + " appears twice in the header");
            *slot = static_cast<int>(k);
        }
        if (c.t < 0 || c.value < 0) throw fail("the header row must name the columns t_s and " + column);
        return c;
    };
    const auto sample = [&](const std::vector<std::string>& row, const TrajectoryColumns& c) {
        if (row.size() != c.width) {
            throw fail("expected " + std::to_string(c.width) + " comma-separated cells, got " + std::to_string(row.size()));
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
        const double t = number(c.t, "t_s");
        if (!m.t.empty() && !(t > m.t.back())) throw fail("t_s: times must increase strictly down the table");
        m.t.push_back(t);
        m.line.push_back(line_no);
        m.value.push_back(number(c.value, column.c_str()));
        if (c.sigma >= 0) {
            const double s = number(c.sigma, "sigma");
            if (!(s > 0.0)) throw fail("sigma: the noise level must be positive");
            m.sigma.push_back(s);
        }
    };
    // Read block by block (io/csv_reader.hpp): a simulate history.csv of a million samples, some
    // 200 MB with its other columns, is a trajectory too.
    try {
        for_each_csv_row(path, true, [&](const CsvRow& row) {
            line_no = row.line;
            if (!columns) {
                columns = header(row.cells);
            } else {
                sample(row.cells, *columns);
            }
        });
    } catch (const InputError& e) {
        const std::string what = e.what(), unreadable = path + ": cannot read: ";
        if (what.rfind(unreadable, 0) == 0) throw fail("cannot read the data file: " + what.substr(unreadable.size()));
        throw;
    }
    if (!columns) throw fail("empty file (expected a header row naming t_s and " + column + ")");
    if (m.t.size() < min_rows) {
        throw fail(std::to_string(m.t.size()) + " samples, fewer than the " + std::to_string(min_rows) +
                   " needed (more than the fitted parameters)");
    }
    return m;
}

}  // namespace vi
