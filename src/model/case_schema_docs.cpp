#include "model/case_schema_docs.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace vi {
namespace {

const std::string kBegin = "<!-- case-keys:";
const std::string kEnd = "<!-- /case-keys:";
const std::string kTopLevel = "top-level";
const std::string kRegisteredBegin = "<!-- registered-sections -->";
const std::string kRegisteredEnd = "<!-- /registered-sections -->";

// A default as the docs write it: 1e-10, 0.01, 200, and whole numbers in full (50000000).
std::string doc_number(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    if (v != 0.0 && std::isfinite(v)) {
        const double e = std::round(std::log10(std::abs(v)));
        if ((e >= 6.0 || e <= -3.0) && std::abs(v) == std::pow(10.0, e)) {
            return std::string(v < 0 ? "-" : "") + "1e" + std::to_string(static_cast<int>(e));
        }
    }
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string quoted_options(const std::vector<std::string>& options) {
    std::string out;
    for (std::size_t i = 0; i < options.size(); ++i) {
        out += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + ("`\"" + options[i] + "\"`");
    }
    return out;
}

std::string type_cell(const KeySpec& k) {
    switch (k.kind) {
        case KeyKind::number:
            if (k.dimension != Dimension::dimensionless) return std::string(dimension_label(k.dimension));
            if (k.unit == "-") return "dimensionless";
            // A ratio or an angle is dimensionless; a unit no Dimension has (ohm, 1/m) is read as
            // a plain number in that SI unit.
            if (k.unit == "x/l" || k.unit == "rad" || k.unit == "periods") return "dimensionless (" + k.unit + ")";
            return "a number in " + k.unit + " (SI, no unit text)";
        case KeyKind::integer: return "integer (a TOML integer: `50`, not `50.0` or `\"50\"`)";
        case KeyKind::number_pair: return "array of 2 dimensionless numbers";
        case KeyKind::integer_pair: return "array of 2 integers";
        case KeyKind::flag: return "`true` / `false`";
        case KeyKind::choice: return quoted_options(k.options);
        case KeyKind::text: return "string";
        case KeyKind::table_file: return "string: a CSV file with the columns `t_s," + k.column + "`";
        case KeyKind::layer_stack: return "array of `{ material = \"name\", thickness = length }`, bottom to top";
        case KeyKind::hole_array: return "`{ size = length, pitch = length, shape = \"square\" }` (`shape`: `\"square\"` or `\"circle\"`)";
    }
    return "-";
}

std::string default_cell(const KeySpec& k) {
    if (!k.default_text.empty()) return k.default_text;
    if (k.required) return "required";
    if (!k.default_numbers.empty()) {
        if (k.default_numbers.size() == 1) return doc_number(k.default_numbers[0]);
        std::string out = "`[";
        for (std::size_t i = 0; i < k.default_numbers.size(); ++i) out += (i ? ", " : "") + doc_number(k.default_numbers[i]);
        return out + "]`";
    }
    if (!k.default_choice.empty()) {
        return k.kind == KeyKind::choice ? "`\"" + k.default_choice + "\"`" : "`" + k.default_choice + "`";
    }
    return "-";
}

std::string range_cell(const KeySpec& k) { return is_numeric(k.kind) ? k.range.text() : "-"; }

// The condition without the reader's "only with" and the entry's path.
std::string only_with_cell(const KeySpec& k) {
    if (!k.when.doc_text.empty()) return k.when.doc_text;
    if (!k.when.holds) return "-";
    std::string t = k.when.file_text;
    const std::string prefix = "only with ";
    if (t.rfind(prefix, 0) == 0) t.erase(0, prefix.size());
    std::string out;
    for (std::size_t p = 0; p < t.size(); ++p) {
        if (t[p] == '$' && p + 1 < t.size() && t[p + 1] == '.') {
            ++p;
        } else {
            out += t[p];
        }
    }
    return "`" + out + "`";
}

// A cell's text with the table's separators escaped.
std::string cell(const std::string& text) {
    std::string out;
    for (const char ch : text) {
        if (ch == '|') out += '\\';
        out += ch;
    }
    return out;
}

std::string block_name(const SectionSpec& s) { return s.name.empty() ? kTopLevel : s.name; }

bool has_own_block(const std::string& page, const SectionSpec& s) {
    return page.find(kBegin + block_name(s) + " -->") != std::string::npos;
}

// The registered sections without a block of their own: heading, paragraph, table.
std::string registered_sections(const std::string& page, const CaseSchema& schema) {
    std::string out;
    for (const SectionSpec& s : schema.sections) {
        if (!s.registered || has_own_block(page, s)) continue;
        const std::string head = s.array ? "[[" + s.name + "]]" : "[" + s.name + "]";
        out += "\n### `" + head + "`" + (s.title.empty() ? "" : " " + s.title) + "\n\n";
        if (!s.doc.empty()) out += s.doc + "\n\n";
        out += case_key_table(s);
    }
    return out;
}

// page with its block of registered sections filled (unchanged when it has none).
std::string with_registered_sections(const std::string& page, const CaseSchema& schema) {
    const std::size_t begin = page.find(kRegisteredBegin);
    if (begin == std::string::npos) return page;
    const std::size_t line_end = page.find('\n', begin);
    const std::size_t end = page.find(kRegisteredEnd, begin);
    if (line_end == std::string::npos || end == std::string::npos || end < line_end) {
        throw std::invalid_argument("a registered-sections block without its end");
    }
    return page.substr(0, line_end + 1) + registered_sections(page, schema) + "\n" + page.substr(end);
}

}  // namespace

std::string case_key_table(const SectionSpec& s) {
    std::string out = "| Key | Meaning | Type / unit | Default | Range | Only with |\n|---|---|---|---|---|---|\n";
    for (const KeySpec& k : s.keys) {
        std::string meaning = k.meaning;
        if (!k.needs.empty()) meaning += "; needs `" + k.needs + "` beside it";
        out += "| `" + k.name + "` | " + cell(meaning) + " | " + cell(type_cell(k)) + " | " + cell(default_cell(k)) +
               " | " + cell(range_cell(k)) + " | " + cell(only_with_cell(k)) + " |\n";
    }
    return out;
}

std::string with_case_key_tables(const std::string& page, const CaseSchema& schema) {
    std::string out;
    std::size_t at = 0;
    while (true) {
        const std::size_t begin = page.find(kBegin, at);
        if (begin == std::string::npos) break;
        const std::size_t name_end = page.find(" -->", begin);
        const std::size_t line_end = page.find('\n', begin);
        if (name_end == std::string::npos || line_end == std::string::npos) {
            throw std::invalid_argument("a case-keys marker without its end");
        }
        const std::string name = page.substr(begin + kBegin.size(), name_end - begin - kBegin.size());
        const SectionSpec* s = schema.section(name == kTopLevel ? "" : name);
        if (s == nullptr) throw std::invalid_argument("case-keys block of an unknown section: " + name);
        const std::size_t end = page.find(kEnd + name + " -->", line_end);
        if (end == std::string::npos) throw std::invalid_argument("case-keys block without its end: " + name);
        out += page.substr(at, line_end + 1 - at) + case_key_table(*s);
        at = end;
    }
    return with_registered_sections(out + page.substr(at), schema);
}

std::vector<std::string> undocumented_sections(const std::string& page, const CaseSchema& schema) {
    std::vector<std::string> out;
    const bool registered_block = page.find(kRegisteredBegin) != std::string::npos;
    for (const SectionSpec& s : schema.sections) {
        if (has_own_block(page, s) || (s.registered && registered_block)) continue;
        out.push_back(block_name(s));
    }
    return out;
}

}  // namespace vi
