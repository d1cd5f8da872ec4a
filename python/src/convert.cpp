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
#include "io/csv_reader.hpp"

namespace vi::python {
namespace {

std::optional<double> number_of(const std::string& cell) {
    // An empty cell (a file from before the missing-value marker) is a number here, NaN, as "nan" is.
    return csv_cell_number(cell);
}

std::optional<std::int64_t> whole_of(const std::string& cell) {
    std::int64_t v = 0;
    const char* end = cell.data() + cell.size();
    const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return v;
}

// One column's cells as an array: int64 for a column of whole numbers (`integer`, no missing cell),
// float64 when every cell is a number or the missing-value marker (NaN), otherwise str.
py::object column_array(const std::vector<std::string>& cells, bool integer) {
    bool whole = integer;
    bool numeric = true;
    for (const std::string& c : cells) {
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
            w(i) = *number_of(c);
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
    for (CsvRow& row : split_csv(csv, "CSV")) {
        if (header.empty()) {
            header = std::move(row.cells);
            columns.resize(header.size());
            continue;
        }
        if (row.cells.size() != header.size()) throw std::logic_error("CSV row width differs from its header");
        for (std::size_t i = 0; i < row.cells.size(); ++i) columns[i].push_back(std::move(row.cells[i]));
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
