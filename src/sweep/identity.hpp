#pragma once
// The identity of a sweep, so that a resumed sweep reuses only points of the very same sweep.

#include <string>
#include <string_view>

#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace vi {

// Everything that decides the rows of a sweep, as text: the case file's contents (not its path, so
// a moved folder still resumes), every axis with its exact values, the analysis and its options.
// Thread and process counts are left out: they do not change the rows.
std::string sweep_identity_text(std::string_view case_text, const SweepGrid& grid, const SweepSettings& settings);

// 64-bit FNV-1a hash of text, as 16 lowercase hex digits.
std::string fingerprint_of(std::string_view text);

}  // namespace vi
