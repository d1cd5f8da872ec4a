#pragma once
// A file built into the program (cmake/embed_files.cmake generates the definitions at build time).

#include <string_view>

namespace vi {

// One built-in file: its name without folder ("cantilever.toml") and its text.
struct EmbeddedFile {
    std::string_view name;
    std::string_view text;
};

}  // namespace vi
