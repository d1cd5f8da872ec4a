#pragma once
// The [air] table and the [[films]] entries of a case file (docs/squeeze-film.md §1). Part of the
// case reader (io/case_reader.cpp).

#include <string>
#include <vector>

#include "io/toml_fields.hpp"
#include "model/case.hpp"
#include "model/case_checks.hpp"

namespace vi {

// Reads [air]; problems with the text go to log.
Air read_air(const toml::table& t, tomlio::Position at, tomlio::ReadLog& log);

// Reads the [[films]] entry at `path` ("films[0]").
Film read_film(const toml::table& t, const std::string& path, tomlio::Position at, tomlio::ReadLog& log);

}  // namespace vi
