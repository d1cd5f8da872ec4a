#pragma once
// The case files of examples/paper/, built into the program (CMake generates the definition from the
// files at build time), so `vibroimpact paper` runs from any folder on a fresh machine.

#include <string_view>
#include <vector>

namespace vi {

// One built-in file: its name without folder ("cantilever.toml") and its text.
struct EmbeddedFile {
    std::string_view name;
    std::string_view text;
};

// Every examples/paper/*.toml as it was when the program was built, sorted by name.
const std::vector<EmbeddedFile>& paper_example_files();

}  // namespace vi
