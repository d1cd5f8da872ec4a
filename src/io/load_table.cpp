#include "io/load_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "model/input_error.hpp"
#include "io/text_file.hpp"
#include "io/units.hpp"

namespace vi {

void parse_load_table(const std::string& text, const std::string& file, TimeFunction& g) {
    parse_time_table(text, file, "g", g);
}

void parse_time_table(const std::string& text, const std::string& file, const std::string& column, TimeFunction& g) {
    std::size_t line_no = 0;
    const auto fail = [&](const std::string& why) {
        throw InputError(one_line(file + ":" + std::to_string(std::max<std::size_t>(line_no, 1)) + ": " + why));
    };
    const auto number = [&](const std::string& field, const std::string& name) {
        try {
            return parse_quantity(field, Dimension::dimensionless);
        } catch (const std::invalid_argument& e) {
            fail(name + ": " + e.what());
        }
        return 0.0;
    };
    bool header = false;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + begin, end - begin);
        begin = end + 1;
        ++line_no;
        if (trimmed(line).empty()) continue;
        const std::size_t comma = line.find(',');
        if (comma == std::string_view::npos || line.find(',', comma + 1) != std::string_view::npos) {
            fail("expected 2 comma-separated columns (t_s," + column + "), got " + vi::in_quotes(line));
        }
        const std::string a = trimmed(line.substr(0, comma));
        const std::string b = trimmed(line.substr(comma + 1));
        if (!header) {
            if (a != "t_s" || b != column) fail("expected the header row \"t_s," + column + "\", got " + vi::in_quotes(line));
            header = true;
            continue;
        }
        const double t = number(a, "t_s");
        const double v = number(b, column);
        if (!g.times.empty() && !(t > g.times.back())) fail("t_s: times must increase strictly down the table");
        g.times.push_back(t);
        g.values.push_back(v);
    }
    if (!header) fail("empty table (expected the header row \"t_s," + column + "\")");
    if (g.times.empty()) fail("no rows below the header");
}

// Reads every [[loads]] table file, relative to the case file's folder.
}  // namespace vi
