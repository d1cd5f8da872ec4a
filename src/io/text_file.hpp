#pragma once
// Whole text files for the readers, and messages kept to one line.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace vi {

// Largest text file read (case files, load tables) [bytes].
inline constexpr std::size_t kMaxTextBytes = std::size_t{64} << 20;

// The whole file as text; nullopt with the reason ("No such file or directory", "not a regular
// file", "larger than 64 MiB") when unreadable.
std::optional<std::string> file_text(const std::string& path, std::string& reason);

// s with line breaks written as \n and \r, so an error message stays one line.
std::string one_line(std::string s);

// s without leading and trailing blanks, tabs and carriage returns.
std::string trimmed(std::string_view s);

}  // namespace vi
