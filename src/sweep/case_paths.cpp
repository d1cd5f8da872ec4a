#include "sweep/case_paths.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "io/csv_names.hpp"
#include "io/range_spec.hpp"
#include "io/spelling.hpp"
#include "model/case_checks.hpp"
#include "model/case_schema.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// The sections and keys a path may address: every number, whole number and pair of the schema
// (model/case_schema.hpp), in its file order. Which apply to a case, their units and how they are
// set are the schema's too, so a key added there is a path here.

bool has_numbers(const SectionSpec& s) {
    if (s.name.empty()) return false;
    for (const KeySpec& k : s.keys)
        if (is_numeric(k.kind)) return true;
    return false;
}

const SectionSpec* path_section(std::string_view name) {
    const SectionSpec* s = case_schema().section(name);
    return s != nullptr && has_numbers(*s) ? s : nullptr;
}

// A number key of s, or a number inside one of its inline tables ("holes.size").
const KeySpec* path_key(const SectionSpec& s, std::string_view name) {
    const std::size_t dot = name.find('.');
    const KeySpec* k = s.key(name.substr(0, dot));
    if (k == nullptr) return nullptr;
    if (dot == std::string_view::npos) return is_numeric(k->kind) ? k : nullptr;
    for (const KeySpec& part : k->parts) {
        if (part.name == name.substr(dot + 1)) return &part;
    }
    return nullptr;
}

// The names a path may give after s's entry: its number keys and "key.part" for the numbers inside
// its inline tables, each with its key.
template <class Visit>
void for_each_path_key(const SectionSpec& s, Visit&& visit) {
    for (const KeySpec& k : s.keys) {
        if (is_numeric(k.kind)) visit(k.name, k);
        for (const KeySpec& part : k.parts) visit(k.name + "." + part.name, part);
    }
}

struct PathTarget {
    const SectionSpec* section;
    const KeySpec* key;
};

PathTarget target_of(const CasePath& p) {
    const SectionSpec* s = path_section(p.section);
    const KeySpec* k = s == nullptr ? nullptr : path_key(*s, p.field);
    if (k == nullptr) throw InputError(p.text() + ": unknown key");
    return {s, k};
}

std::string known_sections() {
    std::string out;
    for (const SectionSpec& s : case_schema().sections) {
        if (has_numbers(s)) out += (out.empty() ? "" : ", ") + s.form();
    }
    return out;
}

std::string known_fields(const SectionSpec& s) {
    std::string out;
    for_each_path_key(s, [&out](const std::string& name, const KeySpec& k) {
        out += (out.empty() ? "" : ", ") + name + (is_pair(k.kind) ? "[k]" : "");
    });
    return out;
}

// " (did you mean 'x'?)" when name is a near misspelling of a section (section null) or of a key of
// section; else " (accepted: ...)".
std::string spelling_hint(std::string_view name, const SectionSpec* section) {
    std::vector<std::string> names;
    if (section == nullptr) {
        for (const SectionSpec& s : case_schema().sections)
            if (has_numbers(s)) names.push_back(s.name);
    } else {
        for_each_path_key(*section, [&names](const std::string& n, const KeySpec&) { names.push_back(n); });
    }
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    if (const auto guess = closest_spelling(name, candidates)) return " (did you mean '" + *guess + "'?)";
    return " (accepted: " + (section == nullptr ? known_sections() : known_fields(*section)) + ")";
}

// Reads "name" or "name[digits]" from the front of s.
struct Part {
    std::string name;
    std::optional<std::size_t> index;
};

Part read_part(std::string_view& s, std::string_view whole_text) {
    Part part;
    std::size_t n = 0;
    while (n < s.size() && (std::islower(static_cast<unsigned char>(s[n])) || s[n] == '_')) ++n;
    part.name = std::string(s.substr(0, n));
    s.remove_prefix(n);
    if (part.name.empty()) {
        throw InputError("\"" + std::string(whole_text) + "\" is not a path like supports[0].position or beam.length");
    }
    if (!s.empty() && s.front() == '[') {
        const std::size_t close = s.find(']');
        const std::string_view digits = s.substr(1, close == std::string_view::npos ? 0 : close - 1);
        if (close == std::string_view::npos || digits.empty() || digits.size() > 9 ||
            digits.find_first_not_of("0123456789") != std::string_view::npos) {
            throw InputError(part.name + ": expected an index in brackets, like " + part.name + "[0]");
        }
        part.index = std::stoul(std::string(digits));
        s.remove_prefix(close + 1);
    }
    return part;
}

std::string plural(std::size_t n, const std::string& word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

std::string CasePath::text() const {
    std::string t = section;
    const auto add_index = [&t](std::size_t i) {
        t += '[';
        t += std::to_string(i);
        t += ']';
    };
    if (section_index) add_index(*section_index);
    t += '.';
    t += field;
    if (field_index) add_index(*field_index);
    return t;
}

CasePath resolve_setting_path(std::string_view option, const std::string& setting, const Case& c) {
    try {
        return resolve_case_path(setting.substr(0, setting.find('=')), c);
    } catch (const InputError& e) {
        throw InputError(option, setting, e.what());
    }
}

CasePath resolve_case_path(std::string_view text, const Case& c) {
    std::string_view rest = text;
    CasePath p;
    Part section = read_part(rest, text);
    // A section nested in a table ("beam.sections[1].thickness"): the table's name and the key under
    // it name the section.
    if (!section.index && rest.size() > 1 && rest.front() == '.') {
        std::string_view after = rest.substr(1);
        const std::string_view before = rest;
        Part nested = read_part(after, text);
        const std::string joined = section.name + "." + nested.name;
        if (const SectionSpec* n = case_schema().section(joined); n != nullptr && n->array) {
            nested.name = joined;
            section = nested;
            rest = after;
        } else {
            rest = before;
        }
    }
    p.section = section.name;
    p.section_index = section.index;
    const SectionSpec* s = path_section(p.section);
    if (s == nullptr) throw InputError("unknown key '" + p.section + "'" + spelling_hint(p.section, nullptr));
    if (rest.empty() || rest.front() != '.') {
        if (rest.empty() && !p.section_index && s->array) {
            throw InputError(p.section + ": needs an index and a key, like " + p.section + "[0].position");
        }
        if (rest.empty()) throw InputError(s->form() + ": needs a key (" + known_fields(*s) + ")");
        throw InputError("\"" + std::string(text) + "\" is not a path like supports[0].position or beam.length");
    }
    rest.remove_prefix(1);
    Part field = read_part(rest, text);
    // A number inside an inline table of the entry: "holes.size".
    if (!field.index && rest.size() > 1 && rest.front() == '.') {
        rest.remove_prefix(1);
        const Part part = read_part(rest, text);
        field.name += "." + part.name;
        field.index = part.index;
    }
    p.field = field.name;
    p.field_index = field.index;
    if (!rest.empty()) throw InputError("\"" + std::string(text) + "\" is not a path like supports[0].position or beam.length");

    if (!s->array && p.section_index) throw InputError(p.section + ": takes no index");
    const KeySpec* k = path_key(*s, p.field);
    if (k == nullptr) throw InputError("unknown key '" + p.field + "' in " + s->form() + spelling_hint(p.field, s));
    const std::size_t n = s->count(c);
    if (s->array) {
        if (!p.section_index) throw InputError(p.section + ": needs an index, like " + p.section + "[0]." + p.field);
        if (*p.section_index >= n) {
            throw InputError(p.section + "[" + std::to_string(*p.section_index) + "]: index out of range (the case has " +
                             plural(n, s->entry_word) + ")");
        }
    }
    const bool pair = is_pair(k->kind);
    if (pair && !p.field_index) throw InputError(p.section + "." + p.field + ": needs an index, [0] or [1]");
    if (!pair && p.field_index) throw InputError(p.section + "." + p.field + ": takes no index");
    if (pair && *p.field_index > 1) throw InputError(p.text() + ": index out of range (0 or 1)");
    if (!s->array && n == 0) throw InputError(p.text() + ": " + s->absent_text);
    const std::size_t i = p.section_index.value_or(0);
    if (k->when.holds && !k->when.holds(c, i)) {
        const std::string& why = k->when.path_text.empty() ? k->when.file_text : k->when.path_text;
        throw InputError(p.text() + ": " + condition_text(why, s->entry_path(i)));
    }
    return p;
}

bool is_integer_path(const CasePath& p) {
    const KeyKind kind = target_of(p).key->kind;
    return kind == KeyKind::integer || kind == KeyKind::integer_pair;
}

std::string case_path_unit(const CasePath& p) { return target_of(p).key->unit; }

std::string case_path_column(const CasePath& p) { return p.text() + csv_unit_suffix(case_path_unit(p)); }

std::optional<Dimension> case_path_dimension(const CasePath& p) {
    const KeySpec& k = *target_of(p).key;
    if (k.kind != KeyKind::number || k.dimension == Dimension::dimensionless) return std::nullopt;
    return k.dimension;
}

double get_case_value(const Case& c, const CasePath& p) {
    return target_of(p).key->get_number(c, p.section_index.value_or(0), p.field_index.value_or(0));
}

void set_case_value(Case& c, const CasePath& p, double value) {
    const KeySpec& k = *target_of(p).key;
    const bool whole = k.kind == KeyKind::integer || k.kind == KeyKind::integer_pair;
    if (whole && !(value == std::floor(value) && std::abs(value) <= k.whole_limit)) {
        throw InputError(p.text() + ": must be a whole number");
    }
    if (k.set_refuses_out_of_range && !k.range.contains(value)) throw InputError(p.text() + ": " + k.range.problem(value));
    k.set_number(c, p.section_index.value_or(0), p.field_index.value_or(0), value);
}

void set_case_text(Case& c, std::string_view path, std::string_view value) {
    CasePath p;
    try {
        p = resolve_case_path(path, c);
    } catch (const InputError& e) {
        throw InputError(std::string(path) + ": " + e.what());
    }
    double v = 0.0;
    try {
        v = parse_value(value, case_path_dimension(p));
    } catch (const std::invalid_argument& e) {
        throw InputError(p.text() + ": " + e.what());
    }
    set_case_value(c, p, v);
}

void apply_case_settings(Case& c, std::string_view option, const std::vector<std::string>& settings) {
    for (const std::string& setting : settings) {
        const std::size_t eq = setting.find('=');
        const std::string where = std::string(option) + " " + setting + ": ";
        if (eq == std::string::npos) throw InputError(where + "needs PATH=VALUE, e.g. supports[0].gap=0.5um");
        try {
            set_case_text(c, std::string_view(setting).substr(0, eq), std::string_view(setting).substr(eq + 1));
        } catch (const InputError& e) {
            throw InputError(where + e.what());
        }
    }
    const std::vector<CaseProblem> problems = check_case(c);
    if (!problems.empty()) {
        throw InputError(std::string(option) + ": " + problems.front().key + ": " + problems.front().message);
    }
}

std::vector<std::string> case_path_forms() {
    std::vector<std::string> out;
    for (const auto& [form, unit] : case_path_form_units()) out.push_back(form);
    return out;
}

std::vector<std::pair<std::string, std::string>> case_path_form_units() {
    std::vector<std::pair<std::string, std::string>> out;
    for (const SectionSpec& s : case_schema().sections) {
        if (!has_numbers(s)) continue;
        for_each_path_key(s, [&out, &s](const std::string& name, const KeySpec& k) {
            out.emplace_back(s.form() + "." + name + (is_pair(k.kind) ? "[k]" : ""), k.unit);
        });
    }
    return out;
}

}  // namespace vi
