#pragma once
// The inputs of a spread study (case values with their distributions) and the runs that sample
// them: N base samples, or Saltelli's N (d + 2) runs for Sobol indices (docs/uq.md).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "sweep/case_paths.hpp"
#include "sweep/grid.hpp"
#include "uq/distribution.hpp"
#include "uq/sampling.hpp"

namespace vi {

// One varied value: "PATH=DIST:..." as written, its path, its distribution (SI units).
struct UqInput {
    std::string setting;
    CasePath path;
    Distribution distribution;
};

// Parses "PATH=normal:MEAN:SD" (and uniform, lognormal, truncnormal; values with units as --set)
// against the case. Throws InputError("--vary TEXT: reason"): a path the case does not have, a path
// of whole numbers (beam.elements: a distribution's values are not whole), a bad distribution.
UqInput parse_uq_input(const std::string& text, const Case& c);

// Parses every --vary; also refuses a path given twice and an empty list.
std::vector<UqInput> parse_uq_inputs(const std::vector<std::string>& texts, const Case& c);

struct SampleDesign {
    std::size_t base = 0;      // N
    bool sensitivity = false;  // Saltelli's runs: A, B, then A_B^(i) for each input i
    std::vector<UqInput> inputs;
    // Runs as a paired grid: run r sets every input to its axis's value r. Rows 0 .. N-1 are A;
    // with sensitivity N .. 2N-1 are B and (2 + i) N .. (3 + i) N - 1 are A_B^(i).
    SweepGrid grid;
    [[nodiscard]] std::size_t runs() const { return grid.size(); }
    // The rows the statistics and yields use: A, and B with sensitivity (independent samples).
    [[nodiscard]] std::size_t base_rows() const { return sensitivity ? 2 * base : base; }
};

// The runs of N base samples of the inputs by `method` from `seed`: the unit-cube points
// (sampling.hpp; 2d coordinates with sensitivity, A from the first d and B from the last d) mapped
// through each input's inverse CDF.
SampleDesign make_sample_design(const std::vector<UqInput>& inputs, std::size_t n, SamplingMethod method,
                                std::uint64_t seed, bool sensitivity);

}  // namespace vi
