#pragma once
// The case files of examples/paper/, built into the program (CMake generates the definition from the
// files at build time), so `vibroimpact paper` runs from any folder on a fresh machine.

#include <vector>

#include "model/embedded_file.hpp"

namespace vi {

// Every examples/paper/*.toml as it was when the program was built, sorted by name.
const std::vector<EmbeddedFile>& paper_example_files();

}  // namespace vi
