// Result files as Python values: CSV columns as numpy arrays named by the header, JSON as dicts.

#include <pybind11/numpy.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bindings.hpp"

namespace vi::python {
namespace {

// One CSV line split into cells; a quoted cell may hold commas and doubled quotes (RFC 4180, no
// line breaks inside a cell: the library writes none).
std::vector<std::string> cells_of(std::string_view line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted && ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            cells.back() += '"';
            ++i;
        } else if (ch == '"') {
            quoted = !quoted;
        } else if (ch == ',' && !quoted) {
            cells.emplace_back();
        } else {
            cells.back() += ch;
        }
    }
    return cells;
}

std::optional<double> number_of(const std::string& cell) {
    double v = 0.0;
    const char* end = cell.data() + cell.size();
    const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
    if (ec == std::errc::result_out_of_range) return std::nullopt;
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return v;
}

std::optional<std::int64_t> whole_of(const std::string& cell) {
    std::int64_t v = 0;
    const char* end = cell.data() + cell.size();
    const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return v;
}

// One column's cells as an array: int64 for a column of whole numbers (`integer`, no empty cell),
// float64 when every cell is a number or empty (NaN), otherwise str.
py::object column_array(const std::vector<std::string>& cells, bool integer) {
    bool whole = integer;
    bool numeric = true;
    for (const std::string& c : cells) {
        if (c.empty()) {
            whole = false;
            continue;
        }
        if (whole && !whole_of(c)) whole = false;
        if (!whole && !number_of(c)) {
            numeric = false;
            break;
        }
    }
    const auto n = static_cast<py::ssize_t>(cells.size());
    if (whole && !cells.empty()) {
        py::array_t<std::int64_t> a(n);
        auto w = a.mutable_unchecked<1>();
        for (py::ssize_t i = 0; i < n; ++i) w(i) = *whole_of(cells[static_cast<std::size_t>(i)]);
        return a;
    }
    if (numeric) {
        py::array_t<double> a(n);
        auto w = a.mutable_unchecked<1>();
        for (py::ssize_t i = 0; i < n; ++i) {
            const std::string& c = cells[static_cast<std::size_t>(i)];
            w(i) = c.empty() ? std::numeric_limits<double>::quiet_NaN() : *number_of(c);
        }
        return a;
    }
    py::list items;
    for (const std::string& c : cells) items.append(py::str(c));
    return py::module_::import("numpy").attr("array")(items, py::arg("dtype") = "str");
}

}  // namespace

py::dict csv_columns(const std::string& csv, const std::set<std::string>& integer_columns) {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> columns;
    std::size_t start = 0;
    while (start < csv.size()) {
        std::size_t end = csv.find('\n', start);
        if (end == std::string::npos) end = csv.size();
        std::string_view line(csv.data() + start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        start = end + 1;
        if (line.empty()) continue;
        std::vector<std::string> cells = cells_of(line);
        if (header.empty()) {
            header = std::move(cells);
            columns.resize(header.size());
            continue;
        }
        if (cells.size() != header.size()) throw std::logic_error("CSV row width differs from its header");
        for (std::size_t i = 0; i < cells.size(); ++i) columns[i].push_back(std::move(cells[i]));
    }
    py::dict out;
    for (std::size_t i = 0; i < header.size(); ++i) out[py::str(header[i])] = column_array(columns[i], integer_columns.count(header[i]) > 0);
    return out;
}

py::object json_value(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

py::dict files_dict(const OutputFiles& files) {
    py::dict out;
    for (const auto& [name, text] : files) {
        const auto dot = name.rfind('.');
        const std::string stem = name.substr(0, dot);
        const std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
        if (ext == "csv") {
            out[py::str(stem)] = csv_columns(text);
        } else if (ext == "json") {
            out[py::str(stem)] = json_value(text);
        } else {
            out[py::str(stem)] = py::str(text);
        }
    }
    return out;
}

}  // namespace vi::python
