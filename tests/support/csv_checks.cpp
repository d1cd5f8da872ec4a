#include "support/csv_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

#include "io/csv_names.hpp"
#include "io/csv_reader.hpp"
#include "io/number_text.hpp"
#include "support/test_files.hpp"

namespace vi::test {

bool is_text_column(const std::string& name) {
    for (const char* tail : {"status", "reason", "stage", "kind", "law", "verdict", "feature", "solver", "input"}) {
        const std::string t = tail;
        if (name == t || (name.size() > t.size() && name.compare(name.size() - t.size() - 1, t.size() + 1, "_" + t) == 0)) return true;
    }
    return name.rfind("nodes_supported_", 0) == 0;
}

void expect_csv_convention(const std::string& path) {
    const std::string text = read_text(path);
    ASSERT_FALSE(text.empty()) << path << ": empty or unreadable";
    EXPECT_EQ(text.back(), '\n') << path << ": the last line has no line break";
    EXPECT_EQ(text.find('\r'), std::string::npos) << path << ": CR in a file the program wrote";
    const std::vector<CsvRow> rows = split_csv(text, path);
    ASSERT_FALSE(rows.empty()) << path;
    const std::vector<std::string>& header = rows.front().cells;
    for (const std::string& name : header) EXPECT_TRUE(csv_column_name_ok(name)) << path << ": column '" << name << "' names no unit";
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const CsvRow& row = rows[r];
        if (row.cells.size() != header.size()) {
            ADD_FAILURE() << path << ":" << row.line << ": " << row.cells.size() << " cells, the header has " << header.size();
            continue;
        }
        for (std::size_t k = 0; k < header.size(); ++k) {
            if (is_text_column(header[k])) continue;
            const std::string& cell = row.cells[k];
            const std::optional<double> v = cell.empty() ? std::nullopt : csv_cell_number(cell);
            if (!v) {
                ADD_FAILURE() << path << ":" << row.line << ": " << header[k] << ": '" << cell << "' is neither a number nor the missing marker";
                continue;
            }
            // Shortest round trip: the text is what std::to_chars writes for the double it reads as
            // ("nan" for the missing marker, so that there is one spelling of it).
            EXPECT_EQ(cell, round_trip_text(*v)) << path << ":" << row.line << ": " << header[k] << " is not in its shortest form";
        }
    }
}

std::size_t expect_csv_convention_in(const std::string& dir) {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        if (e.is_regular_file() && e.path().extension() == ".csv") files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) expect_csv_convention(f);
    return files.size();
}

}  // namespace vi::test
