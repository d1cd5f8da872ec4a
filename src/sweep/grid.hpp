#pragma once
// The points of a sweep: one axis per --set PATH=SPEC, all combinations of their values.

#include <cstddef>
#include <string>
#include <vector>

#include "sweep/case_paths.hpp"
#include "model/case.hpp"

namespace vi {

// One swept value: where it goes in the case and the values it takes (SI units).
struct SweepAxis {
    std::string setting;        // "PATH=SPEC" as written on the command line
    CasePath path;
    std::vector<double> values;
};

// Parses "PATH=SPEC" against the case: the path (case_paths.hpp) and the spec (a list, a linear
// range start:stop:count or a log range log:start:stop:count, io/range_spec.hpp), whole numbers
// for integer paths. Throws InputError("--set SETTING: reason").
SweepAxis parse_sweep_setting(const std::string& setting, const Case& c);

// The full grid of several axes. Points are numbered like nested loops written in the order of
// the axes: the first axis varies slowest, the last fastest.
class SweepGrid {
public:
    SweepGrid() = default;
    // Throws InputError when two axes set the same path or the grid exceeds kMaxPoints.
    explicit SweepGrid(std::vector<SweepAxis> axes);

    static constexpr std::size_t kMaxPoints = 100'000'000;

    // A sample design (uq): point i takes value i of every axis, so every axis holds the same
    // number of values. Throws InputError as the grid does, or when the axes' lengths differ.
    static SweepGrid paired(std::vector<SweepAxis> axes);
    // True for a sample design, false for a full grid.
    [[nodiscard]] bool paired() const { return paired_; }

    [[nodiscard]] const std::vector<SweepAxis>& axes() const { return axes_; }
    [[nodiscard]] std::size_t size() const { return size_; }
    // The value of every axis at point `index`, in axis order.
    [[nodiscard]] std::vector<double> values_at(std::size_t index) const;
    // The base case with the values of point `index` set (not checked: see check_case). Throws
    // InputError for a value its key cannot hold (set_case_value).
    [[nodiscard]] Case case_at(const Case& base, std::size_t index) const;

private:
    std::vector<SweepAxis> axes_;
    std::size_t size_ = 0;
    bool paired_ = false;
};

// Parses every setting and builds the grid; throws InputError for the first bad one.
SweepGrid parse_sweep_grid(const std::vector<std::string>& settings, const Case& c);

}  // namespace vi
