#pragma once
// Writes a set of result files into a folder all together: either every file lands or none does.

#include <map>
#include <string>

namespace vi {

// File name (inside the folder; "sub/name" puts it in a sub-folder) -> full contents.
using OutputFiles = std::map<std::string, std::string>;

// Creates dir if needed and writes every file through a temporary name and a rename, so a reader
// never sees half a file; on any failure removes what it wrote and throws std::runtime_error.
void write_output_files(const std::string& dir, const OutputFiles& files);

}  // namespace vi
