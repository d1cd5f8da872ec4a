#include "study/run_plots/plot_style.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>
#include <sstream>
#include <utility>

#include "io/csv_names.hpp"

namespace vi {
namespace {

std::string spaced(std::string s) {
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
}

}  // namespace

ColumnUnit column_unit(const std::string& name) {
    const CsvColumnUnit c = csv_column_unit(name);
    return {spaced(c.stem), c.unit};
}

DisplayUnit display_unit(const std::string& unit, double largest) {
    static const std::vector<std::string> prefixable{"m", "s", "N", "J", "W", "Pa", "V", "F", "C", "A", "Hz", "m/s"};
    if (std::find(prefixable.begin(), prefixable.end(), unit) == prefixable.end() || !(largest > 0.0) || !std::isfinite(largest)) {
        return {1.0, unit == "-" ? "" : unit};
    }
    // The small slack keeps 9.9999999e-7 m (a rounded 1 µm) in µm rather than 999.99999 nm.
    const int e3 = std::clamp(static_cast<int>(std::floor((std::log10(largest) + 1e-3) / 3.0)) * 3, -15, 9);
    static const char* prefix[] = {"f", "p", "n", "µ", "m", "", "k", "M", "G"};
    return {std::pow(10.0, -e3), std::string(prefix[(e3 + 15) / 3]) + unit};
}

double largest_magnitude(const std::vector<const std::vector<double>*>& columns) {
    double m = 0.0;
    for (const auto* c : columns) {
        for (double v : *c) {
            if (std::isfinite(v)) m = std::max(m, std::fabs(v));
        }
    }
    return m;
}

std::string axis_label(const std::string& quantity, const DisplayUnit& u) {
    return u.text.empty() ? quantity : quantity + "  [" + u.text + "]";
}

FigureSpec run_figure(const std::string& name, const std::string& title, const std::string& caption) {
    FigureSpec f;
    f.name = name;
    f.title = title;
    f.caption = caption;
    f.width = 2400;
    f.height = 1500;
    f.scale = 2.4;
    return f;
}

std::string gp_frame(const std::string& xlabel, const std::string& ylabel) {
    return "set grid lc rgb '#dddddd'\nset key top right noenhanced\nset format y '%g'\nset format x '%g'\n"
           "set xlabel " + gp_quote(xlabel) + " noenhanced\nset ylabel " + gp_quote(ylabel) + " noenhanced\n";
}

std::string gp_range(const std::string& axis, double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return "set " + axis + "range [-1:1]\n";
    if (hi > lo) return "";
    const double half = lo == 0.0 ? 1.0 : 0.1 * std::fabs(lo);
    return "set " + axis + "range [" + gp_number(lo - half) + ":" + gp_number(hi + half) + "]\n";
}

void finite_range(const std::vector<const std::vector<double>*>& columns, double& lo, double& hi) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const auto* c : columns) {
        for (double v : *c) {
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (lo > hi) lo = hi = std::numeric_limits<double>::quiet_NaN();
}

std::vector<std::size_t> rows_to_draw(const std::vector<const std::vector<double>*>& columns, std::size_t rows, std::size_t limit) {
    std::vector<std::size_t> keep;
    if (rows <= limit) {
        keep.resize(rows);
        for (std::size_t i = 0; i < rows; ++i) keep[i] = i;
        return keep;
    }
    const std::size_t slices = std::max<std::size_t>(1, limit / 4);
    for (std::size_t s = 0; s < slices; ++s) {
        const std::size_t a = rows * s / slices, b = rows * (s + 1) / slices;
        if (a >= b) continue;
        std::vector<std::size_t> part{a, b - 1};
        for (const auto* c : columns) {
            // Extremes among the finite values (a NaN compares false with everything, so a slice
            // that began with one would otherwise keep no peak), and the first row of a gap: a
            // missing value stays a break in the line.
            std::optional<std::size_t> lo, hi, gap;
            for (std::size_t i = a; i < b; ++i) {
                const double v = (*c)[i];
                if (!std::isfinite(v)) {
                    if (!gap) gap = i;
                    continue;
                }
                if (!lo || v < (*c)[*lo]) lo = i;
                if (!hi || v > (*c)[*hi]) hi = i;
            }
            for (const auto& kept : {lo, hi, gap}) {
                if (kept) part.push_back(*kept);
            }
        }
        std::sort(part.begin(), part.end());
        part.erase(std::unique(part.begin(), part.end()), part.end());
        keep.insert(keep.end(), part.begin(), part.end());
    }
    return keep;
}

std::string safe_name(const std::string& s) {
    std::string out;
    for (char c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-';
        if (ok) {
            out += c;
        } else if (!out.empty() && out.back() != '_') {
            out += '_';
        }
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out.empty() ? "column" : out;
}

}  // namespace vi
