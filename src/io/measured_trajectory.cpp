#include "io/measured_trajectory.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "io/text_file.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

std::vector<std::string> cells(std::string_view line) {
    std::vector<std::string> out;
    std::size_t begin = 0;
    for (;;) {
        const std::size_t comma = line.find(',', begin);
        out.push_back(trimmed(line.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin)));
        if (comma == std::string_view::npos) return out;
        begin = comma + 1;
    }
}

}  // namespace

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
    int it = -1, iv = -1, is = -1;
    std::size_t width = 0;
    std::size_t begin = 0;
    while (begin < text->size()) {
        std::size_t end = text->find('\n', begin);
        if (end == std::string::npos) end = text->size();
        const std::string_view line(text->data() + begin, end - begin);
        begin = end + 1;
        ++line_no;
        if (trimmed(line).empty() || trimmed(line)[0] == '#') continue;
        const std::vector<std::string> row = cells(line);
        if (width == 0) {
            width = row.size();
            for (std::size_t k = 0; k < row.size(); ++k) {
                int* slot = row[k] == "t_s" ? &it : row[k] == column ? &iv : row[k] == "sigma" ? &is : nullptr;
                if (!slot) continue;
                if (*slot >= 0) throw fail("column " + row[k] + " appears twice in the header");
                *slot = static_cast<int>(k);
            }
            if (it < 0 || iv < 0) throw fail("the header row must name the columns t_s and " + column);
            continue;
        }
        if (row.size() != width) {
            throw fail("expected " + std::to_string(width) + " comma-separated cells, got " + std::to_string(row.size()));
        }
        const auto number = [&](int k, const char* name) {
            const std::string& s = row[static_cast<std::size_t>(k)];
            errno = 0;
            char* stop = nullptr;
            const double v = std::strtod(s.c_str(), &stop);
            if (s.empty() || errno != 0 || stop != s.c_str() + s.size() || !std::isfinite(v)) {
                throw fail(std::string(name) + ": '" + s + "' is not a finite number");
            }
            return v;
        };
        const double t = number(it, "t_s");
        if (!m.t.empty() && !(t > m.t.back())) throw fail("t_s: times must increase strictly down the table");
        m.t.push_back(t);
        m.value.push_back(number(iv, column.c_str()));
        if (is >= 0) {
            const double s = number(is, "sigma");
            if (!(s > 0.0)) throw fail("sigma: the noise level must be positive");
            m.sigma.push_back(s);
        }
    }
    if (width == 0) throw fail("empty file (expected a header row naming t_s and " + column + ")");
    if (m.t.size() < min_rows) {
        throw fail(std::to_string(m.t.size()) + " samples, fewer than the " + std::to_string(min_rows) +
                   " needed (more than the fitted parameters)");
    }
    return m;
}

}  // namespace vi
