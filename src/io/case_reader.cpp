#include "io/case_reader.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "io/load_table.hpp"
#include "io/text_file.hpp"
#include "io/toml_fields.hpp"
#include "io/units.hpp"
#include "model/case_checks.hpp"
#include "model/case_schema.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "model/section_checks.hpp"

// Reading happens in two passes. The first walks the schema (model/case_schema.hpp) over the TOML
// tree: each section's table, or each entry of its array, is read key by key into the Case through
// the key's accessors, and every problem with the text (unknown or missing key, wrong type, bad unit,
// value not finite, a key that does not apply) is collected at its position; the earliest in the file
// is thrown. Only when the text is clean are the table files read (CSV: their first bad line is
// thrown), and the second pass checks the values (each value read against its key's range, then
// check_case), each problem placed at the line of the key it names; again the earliest is thrown.
// Nothing here knows a key by name: a new key is a row of the schema.

namespace vi {
namespace {

using tomlio::FieldReader;
using tomlio::Position;
using tomlio::ReadLog;

// A table file named by a key, read once the case text is clean.
struct TableFile {
    const KeySpec* key = nullptr;
    std::size_t entry = 0;   // the entry's index in the Case
    std::string path;        // the key's dotted path, for messages
};

// What reading found besides the Case itself.
struct Reading {
    ReadLog log;                              // problems with the text; where each key stands
    std::vector<CaseProblem> value_problems;  // values outside their key's range
    std::vector<TableFile> tables;
};

// A sub-table of f's table and its position (its header line), or nullptr when absent or not a table.
const toml::table* sub_table(FieldReader& f, std::string_view key, bool required, Position& at) {
    const toml::table* t = f.table(key, required);
    if (t != nullptr) at = tomlio::position_of(t->source(), f.key_position(key));
    return t;
}

// True when k forms an exclusive pair with a key present beside it: that rule reports the two.
bool excluded_by_partner(const SectionSpec& s, const KeySpec& k, const FieldReader& f) {
    for (const auto& [a, b] : s.exclusive) {
        if ((a == k.name && f.has(b)) || (b == k.name && f.has(a))) return true;
    }
    return false;
}

void check_range(Reading& r, const std::string& path, const KeySpec& k, double v) {
    const std::string why = k.range.problem(v);
    if (!why.empty()) r.value_problems.push_back({path, why});
}

// Reads a number, an integer or a pair; returns whether the key was read (or absent and optional).
bool read_numeric(FieldReader& f, const KeySpec& k, std::size_t i, Reading& r, Case& c) {
    const std::string path = tomlio::child_path(f.path(), k.name);
    if (is_pair(k.kind)) {
        std::optional<std::array<double, 2>> v;
        if (k.kind == KeyKind::number_pair) {
            v = tomlio::number_pair(f, k.name, r.log);
        } else if (const auto n = tomlio::integer_pair(f, k.name, r.log)) {
            v = std::array<double, 2>{static_cast<double>((*n)[0]), static_cast<double>((*n)[1])};
        }
        if (!v) return !f.has(k.name);
        for (std::size_t e = 0; e < 2; ++e) {
            k.set_number(c, i, e, (*v)[e]);
            check_range(r, path, k, (*v)[e]);
        }
        return true;
    }
    std::optional<double> v;
    if (k.kind == KeyKind::integer) {
        if (const auto n = f.integer(k.name, k.required)) v = static_cast<double>(*n);
    } else {
        v = f.quantity(k.name, k.dimension, k.required);
    }
    if (!v) return !f.has(k.name);
    k.set_number(c, i, 0, *v);
    check_range(r, path, k, *v);
    return true;
}

// A layer stack: an array of inline tables, each with a material's name and a thickness; every
// problem is logged under key[j].material or key[j].thickness.
bool read_layers(FieldReader& f, const KeySpec& k, std::size_t i, Reading& r, Case& c) {
    const toml::array* a = f.array(k.name, k.required, "an array of { material = \"name\", thickness = \"1 um\" }");
    if (a == nullptr) return !f.has(k.name);
    const std::string path = tomlio::child_path(f.path(), k.name);
    const Position at = f.key_position(k.name);
    std::vector<Layer> layers;
    bool clean = true;
    for (std::size_t j = 0; j < a->size(); ++j) {
        const toml::node& node = *a->get(j);
        const std::string entry = path + "[" + std::to_string(j) + "]";
        const toml::table* t = node.as_table();
        if (t == nullptr) {
            r.log.problem(tomlio::position_of(node.source(), at), entry,
                          "expected a table { material = \"name\", thickness = \"1 um\" }, got " + tomlio::type_name(node));
            clean = false;
            continue;
        }
        FieldReader lf(*t, entry, tomlio::position_of(node.source(), at), r.log, {"material", "thickness"});
        const auto material = lf.string("material", true);
        const auto thickness = lf.quantity("thickness", Dimension::length, true);
        lf.finish();
        if (!material || !thickness) {
            clean = false;
            continue;
        }
        if (!(*thickness > 0.0)) r.value_problems.push_back({entry + ".thickness", "must be positive"});
        layers.push_back({*material, *thickness});
    }
    if (a->empty()) r.value_problems.push_back({path, "needs at least one layer"});
    *k.layers(c, i) = std::move(layers);
    return clean;
}

// Release holes: an inline table { size, pitch, shape }; its problems are logged under key.size, ...
bool read_holes(FieldReader& f, const KeySpec& k, std::size_t i, Reading& r, Case& c) {
    const toml::table* t = f.table(k.name, k.required);
    if (t == nullptr) return !f.has(k.name);
    const std::string path = tomlio::child_path(f.path(), k.name);
    FieldReader hf(*t, path, f.key_position(k.name), r.log, {"size", "pitch", "shape"});
    const auto size = hf.quantity("size", Dimension::length, true);
    const auto pitch = hf.quantity("pitch", Dimension::length, true);
    const std::vector<std::string> shapes{"square", "circle"};
    const auto shape = hf.has("shape") ? hf.choice("shape", shapes, false) : std::optional<std::string>("square");
    hf.finish();
    if (!size || !pitch || !shape) return false;
    if (!(*size > 0.0)) r.value_problems.push_back({path + ".size", "must be positive"});
    if (!(*pitch > 0.0)) r.value_problems.push_back({path + ".pitch", "must be positive"});
    if (*size > 0.0 && *pitch > 0.0) {
        if (std::string why = holes_pitch_problem(*size, *pitch); !why.empty()) r.value_problems.push_back({path + ".size", why});
    }
    *k.holes(c, i) = Holes{*size, *pitch, *shape == "circle" ? HoleShape::circle : HoleShape::square};
    return true;
}

// Reads one key of entry i by its kind; returns false when it is present but could not be read.
bool read_value(FieldReader& f, const KeySpec& k, std::size_t i, Reading& r, Case& c) {
    if (is_numeric(k.kind)) return read_numeric(f, k, i, r, c);
    if (k.kind == KeyKind::layer_stack) return read_layers(f, k, i, r, c);
    if (k.kind == KeyKind::hole_array) return read_holes(f, k, i, r, c);
    const std::string path = tomlio::child_path(f.path(), k.name);
    std::optional<std::string> text;
    switch (k.kind) {
        case KeyKind::flag:
            if (const auto b = f.boolean(k.name, k.required)) {
                k.set_number(c, i, 0, *b ? 1.0 : 0.0);
                return true;
            }
            return !f.has(k.name);
        case KeyKind::choice: text = f.choice(k.name, k.options, k.required); break;
        default: text = f.string(k.name, k.required); break;
    }
    if (!text) return !f.has(k.name);
    if (text->empty() && !k.empty_text.empty()) {
        // An empty file name is a problem with the text; an empty name one with the value.
        if (k.kind == KeyKind::table_file) {
            f.reject(k.name, k.empty_text);
            return false;
        }
        r.value_problems.push_back({path, k.empty_text});
    }
    k.set_text(c, i, *text);
    if (k.kind == KeyKind::table_file) r.tables.push_back({&k, i, path});
    return true;
}

// One key: refused where it does not apply or lacks the key it needs, else read.
void read_key(FieldReader& f, const SectionSpec& s, const KeySpec& k, std::size_t i, Reading& r, Case& c,
              std::set<std::string>& unreadable) {
    for (const std::string& on : k.when.on) {
        if (unreadable.count(on) > 0) return;  // the selector's own problem is reported
    }
    const bool present = f.has(k.name);
    if (present && !k.needs.empty() && !f.has(k.needs)) {
        f.reject(k.name, k.needs_text);
        return;
    }
    if (k.when.in_file && k.when.holds && !k.when.holds(c, i)) {
        if (present && !excluded_by_partner(s, k, f)) f.reject(k.name, condition_text(k.when.file_text, f.path()));
        return;
    }
    if (!read_value(f, k, i, r, c)) unreadable.insert(k.name);
}

// The keys of entry i of section s, from the table f reads. Keys whose condition depends on other
// keys of the entry are read after every other key, so that their selectors are set first.
void read_keys(FieldReader& f, const SectionSpec& s, std::size_t i, Reading& r, Case& c) {
    for (const auto& [a, b] : s.exclusive) f.exclusive(a, b);
    if (s.before) s.before(c, i, [&f](std::string_view key) { return f.has(key); });
    std::set<std::string> unreadable;
    for (const bool dependent : {false, true}) {
        for (const KeySpec& k : s.keys) {
            if ((k.when.in_file && !k.when.on.empty()) == dependent) read_key(f, s, k, i, r, c, unreadable);
        }
    }
    if (s.after) s.after(c, i);
}

// The sections nested in table section s ([[beam.sections]] in [beam]).
std::vector<const SectionSpec*> children(const SectionSpec& s) {
    std::vector<const SectionSpec*> out;
    if (s.name.empty()) return out;
    for (const SectionSpec& child : case_schema().sections) {
        if (child.parent() == s.name) out.push_back(&child);
    }
    return out;
}

// The keys of s and the keys its nested sections take in its table. The views point into the
// schema (its names), which outlives the reading.
std::vector<std::string_view> key_names(const SectionSpec& s) {
    std::vector<std::string_view> out;
    for (const KeySpec& k : s.keys) out.emplace_back(k.name);
    for (const SectionSpec* child : children(s)) out.emplace_back(std::string_view(child->name).substr(s.name.size() + 1));
    return out;
}

void read_array(FieldReader& f, const SectionSpec& s, Reading& r, Case& c);

void read_entry(const toml::table& t, const SectionSpec& s, std::size_t i, const std::string& path, Position at,
                Reading& r, Case& c) {
    FieldReader f(t, path, at, r.log, key_names(s));
    read_keys(f, s, i, r, c);
    for (const SectionSpec* child : children(s)) read_array(f, *child, r, c);
    f.finish();
}

// Every entry of an array of tables ([[name]]); an entry that is not a table still takes its place
// (the case is refused for it), so that entries and their paths keep one index.
void read_array(FieldReader& f, const SectionSpec& s, Reading& r, Case& c) {
    const std::string key = s.tail();
    const toml::array* a = f.array(key, s.required, "an array of tables ([[" + s.name + "]])");
    if (a == nullptr) return;
    const Position at = f.key_position(key);
    for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::node& node = *a->get(i);
        const std::string path = s.entry_path(i);
        const Position p = tomlio::position_of(node.source(), at);
        add_entry(s, c);
        if (const toml::table* t = node.as_table()) {
            read_entry(*t, s, i, path, p, r, c);
        } else {
            r.log.problem(p, path, "expected a table (a [[" + s.name + "]] entry), got " + tomlio::type_name(node));
        }
    }
}

Case read_root(const toml::table& root, const std::string& default_name, Reading& r) {
    const CaseSchema& schema = case_schema();
    const SectionSpec* top = schema.section("");
    std::vector<std::string_view> accepted = key_names(*top);
    for (const SectionSpec& s : schema.sections)
        if (!s.name.empty() && s.parent().empty()) accepted.emplace_back(s.name);
    FieldReader f(root, "", Position{}, r.log, accepted);
    Case c;
    c.name = default_name;
    read_keys(f, *top, 0, r, c);
    for (const SectionSpec& s : schema.sections) {
        if (s.name.empty() || !s.parent().empty()) continue;
        if (s.array) {
            read_array(f, s, r, c);
            continue;
        }
        Position at;
        if (const toml::table* t = sub_table(f, s.name, s.required, at)) {
            if (s.count(c) == 0) add_entry(s, c);
            read_entry(*t, s, 0, s.name, at, r, c);
        } else if (s.absent) {
            s.absent(c);
        }
    }
    f.finish();
    return c;
}

// Escapes line breaks so that every message is one line, whatever the file name or text holds.
[[noreturn]] void throw_problem(const std::string& source, const tomlio::SourceProblem& p) {
    throw InputError(one_line(source + ":" + std::to_string(p.at.line) + ": " + p.key + ": " + p.message));
}

std::string default_name(const std::string& source_name) {
    std::string stem = std::filesystem::path(source_name).stem().string();
    return stem.empty() ? "case" : stem;
}

// Every table file the case names, relative to the case file's folder.
void read_table_files(const std::string& source_name, Reading& r, Case& c) {
    const std::filesystem::path folder = std::filesystem::path(source_name).parent_path();
    for (const TableFile& t : r.tables) {
        const std::string file = (folder / t.key->get_text(c, t.entry)).string();
        std::string reason;
        const auto text = file_text(file, reason);
        if (!text) {
            throw_problem(source_name, {r.log.where(t.path), t.path, "cannot read " + vi::in_quotes(file) + " (" + reason + ")"});
        }
        parse_time_table(*text, file, t.key->column, *t.key->table(c, t.entry));
    }
}

}  // namespace

Case read_case_text(const std::string& text, const std::string& source_name) {
    toml::table root;
    try {
        root = toml::parse(std::string_view(text), std::string_view(source_name));
    } catch (const toml::parse_error& e) {
        const auto line = e.source().begin.line;
        const std::string where = line > 0 ? source_name + ":" + std::to_string(line) : source_name;
        throw InputError(one_line(where + ": TOML syntax: " + std::string(e.description())));
    }

    Reading r;
    Case c = read_root(root, default_name(source_name), r);
    if (auto p = r.log.first()) throw_problem(source_name, *p);
    read_table_files(source_name, r, c);

    std::vector<CaseProblem> problems = r.value_problems;
    for (CaseProblem& p : check_case(c)) problems.push_back(std::move(p));
    ReadLog placed;
    for (const CaseProblem& p : problems) placed.problem(r.log.where(p.key), p.key, p.message);
    if (auto p = placed.first()) throw_problem(source_name, *p);
    c.origin.file = source_name;
    c.origin.key_lines = r.log.lines();
    return c;
}

InputError locate_in_case(const Case& c, const InputError& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    if (c.origin.file.empty() || colon == std::string::npos) return e;
    // The key, or failing that its nearest parent ("supports[1].gap" -> "supports[1]" -> "supports").
    std::string key = what.substr(0, colon);
    if (key.find(' ') != std::string::npos) return e;
    int line = 0;
    for (std::string k = key; !k.empty();) {
        const auto it = c.origin.key_lines.find(k);
        if (it != c.origin.key_lines.end()) {
            line = it->second;
            break;
        }
        const auto cut = k.find_last_of(".[");
        k = cut == std::string::npos ? std::string() : k.substr(0, cut);
    }
    return InputError(c.origin.file + ":" + std::to_string(line > 0 ? line : 1) + ": " + what);
}

Case read_case_file(const std::string& path) {
    std::string reason;
    const auto text = file_text(path, reason);
    if (!text) throw InputError(one_line(path + ": cannot read file (" + reason + ")"));
    return read_case_text(*text, path);
}

}  // namespace vi
