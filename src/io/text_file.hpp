#pragma once
// Whole text files for the readers, and messages kept to one line.

#include <optional>
#include <string>

namespace vi {

// The whole file as text; nullopt with the reason ("No such file or directory") when unreadable.
std::optional<std::string> file_text(const std::string& path, std::string& reason);

// s with line breaks written as \n and \r, so an error message stays one line.
std::string one_line(std::string s);

}  // namespace vi
