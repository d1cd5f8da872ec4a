#pragma once
// The case-file schema: one description per key (section, name, value kind, unit, default, range,
// when it applies, meaning, accessors to the Case). It drives the reader (io/case_reader.cpp), the
// range and magnitude checks (check_case), the paths of sweeps, fits and optimisations
// (sweep/case_paths.hpp), the resolved case of summary.json and case_to_toml (io/case_writer.hpp),
// and the key tables of docs/case-files.md (model/case_schema_docs.hpp). Higher layers may register
// sections and keys of their own (register_section, register_keys), whose values live in the
// ParameterSets of model/case.hpp.

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/case.hpp"
#include "model/case_problem.hpp"
#include "model/dimension.hpp"

namespace vi {

// What a key holds in a case file.
enum class KeyKind {
    number,        // a double: a TOML number (SI) or a string with a unit of the key's dimension
    integer,       // a whole number; a TOML integer only
    number_pair,   // an array of exactly two dimensionless numbers, key[0] and key[1]
    integer_pair,  // an array of exactly two integers
    flag,          // true or false (0 or 1 through the number accessors)
    choice,        // a string, one of the key's options
    text,          // a string
    table_file,    // a CSV file name, relative to the case file: the rows t_s,<column> of a g(t)
    layer_stack,   // an array of inline tables { material = "name", thickness = length }, bottom to top
    hole_array,    // an inline table { size = length, pitch = length, shape = "square" | "circle" }
};

// True for the kinds a sweep, a fit or an optimisation can set: number, integer and the pairs.
bool is_numeric(KeyKind k);
// True for number_pair and integer_pair (addressed as key[0], key[1]).
bool is_pair(KeyKind k);

// The interval a number must lie in (either side may be open or unbounded) and its messages.
struct KeyRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;
    std::string note;      // appended to the generated message (" (x/l)")
    std::string too_low;   // the whole message below lo, in place of the generated one
    std::string too_high;  // the whole message above hi

    [[nodiscard]] bool contains(double v) const;
    // Why v is outside: "must be positive", "must lie in (0, 1] (x/l)", ...; empty when inside.
    [[nodiscard]] std::string problem(double v) const;
    // The interval as the docs write it: "> 0", ">= 0", "(0, 1]", "[1, 2000]"; "-" when unbounded.
    [[nodiscard]] std::string text() const;
};

// Common ranges.
KeyRange positive(std::string note = "");
KeyRange non_negative(std::string note = "");
KeyRange interval(double lo, bool lo_open, double hi, bool hi_open, std::string note = "");

// When a key means something for a case entry: a predicate and the sentences that say so.
struct KeyCondition {
    // Over the case and the entry's index; empty: the key always applies.
    std::function<bool(const Case&, std::size_t)> holds;
    // Keys of the same entry whose values decide it. The reader reads them first, and does not read
    // this key when one of them is present but unreadable (its problem is already reported).
    std::vector<std::string> on;
    // The reader's refusal of the key where it does not apply ("only with $.kind = \"step\"", with
    // $ standing for the entry's path), and its "only with" column in the docs (the text without
    // "$." when doc_text is empty).
    std::string file_text;
    // The refusal of a sweep, fit or optimisation path; file_text when empty.
    std::string path_text;
    std::string doc_text;
    // Whether the reader refuses the key where it does not apply; false where the condition is on a
    // value (a layer's thickness above 0) that a case file may give as 0 with the key beside it.
    bool in_file = true;

    [[nodiscard]] bool always() const { return !holds; }
};

// One key of a section.
struct KeySpec {
    std::string name;                                // "length"
    KeyKind kind = KeyKind::number;
    Dimension dimension = Dimension::dimensionless;  // numbers: the units a case file may use
    std::string unit;                                // SI unit of a number: "m", "x/l", "rad", "periods", "-"
    std::vector<std::string> options;                // choice: the accepted strings
    bool required = false;                           // required wherever it applies
    std::vector<double> default_numbers;             // numbers (two for a pair); empty: no default
    std::string default_choice;                      // choice, flag ("true"/"false"), text
    std::string default_text;                        // the docs' default; generated when empty
    KeyRange range;
    KeyCondition when;
    std::string needs;             // another key of the entry that must be present beside this one
    std::string needs_text;        // the reader's message when it is not ("needs dielectric_thickness ...")
    std::string empty_text;        // text and table_file: the message for an empty string
    std::string column;            // table_file: the second column's name ("g", "V_V")
    double whole_limit = 2147483647.0;  // integers: the largest magnitude a path may set
    bool magnitude_checked = true;      // numbers: held to the magnitude window (kMagnitudeLimit)
    // A path (sweep, fit, optimisation) refuses a value outside the range at once instead of leaving
    // it to check_case: gap and prestress, where a negative value would mean the other key.
    bool set_refuses_out_of_range = false;
    std::string meaning;           // one line for the docs
    bool in_params = false;        // registered: the value lives in the entry's ParameterSet
    // A rule between this key and others that no range states (a registered law that needs a
    // solver): appends the problems of entry i where the key is in effect. The built-in keys' rules
    // are in check_case.
    std::function<void(std::vector<CaseProblem>&, const Case&, std::size_t i)> rule;

    // Accessors of entry i (k: the element of a pair). Numbers, integers, pairs and flags (0 or 1)
    // go through the number accessors; choices, texts and file names through the text ones.
    std::function<double(const Case&, std::size_t i, std::size_t k)> get_number;
    std::function<void(Case&, std::size_t i, std::size_t k, double)> set_number;
    std::function<std::string(const Case&, std::size_t i)> get_text;
    std::function<void(Case&, std::size_t i, const std::string&)> set_text;
    // Whether the entry carries a value (an optional key without a default); empty: always.
    std::function<bool(const Case&, std::size_t i)> is_set;
    // table_file: the g(t) the rows go into.
    std::function<TimeFunction*(Case&, std::size_t i)> table;
    // layer_stack: the layers the rows go into.
    std::function<std::vector<Layer>*(Case&, std::size_t i)> layers;
    // hole_array: where the holes go.
    std::function<std::optional<Holes>*(Case&, std::size_t i)> holes;
    // Numbers inside an inline-table key (holes.size, holes.pitch): a sweep, fit or optimisation
    // path reaches them as "key.part"; the reader, the writer and the docs' tables go through the key.
    std::vector<KeySpec> parts;

    // Fluent setters for the tables of keys.
    KeySpec& means(std::string text);
    KeySpec& require();
    KeySpec& otherwise(double value, std::string text = "");
    KeySpec& otherwise(std::string choice, std::string text = "");
    KeySpec& in(KeyRange r);
    KeySpec& only(KeyCondition c);
    KeySpec& needing(std::string key, std::string text);
};

// Key makers; `unit` is the SI unit shown for a dimensionless number ("x/l", "rad", "periods", "-").
KeySpec number_key(std::string name, Dimension d, std::string unit = "");
KeySpec integer_key(std::string name);
KeySpec number_pair_key(std::string name);
KeySpec integer_pair_key(std::string name);
KeySpec flag_key(std::string name);
KeySpec choice_key(std::string name, std::vector<std::string> options);
KeySpec text_key(std::string name);
KeySpec table_file_key(std::string name, std::string column);
KeySpec layer_stack_key(std::string name);
KeySpec hole_array_key(std::string name);

// One section of a case file: a table ([beam]), an array of tables ([[supports]]) or the top level
// (name ""), its keys in file order, and how its entries are reached in a Case.
struct SectionSpec {
    std::string name;
    bool array = false;
    bool required = false;
    std::size_t max_entries = 0;      // checked entries of an array (0: every one)
    std::string entry_word;           // "support": "the case has 2 supports"
    std::string absent_text;          // a path into an absent optional table: "only with an [air] table"
    std::vector<KeySpec> keys;
    std::vector<std::pair<std::string, std::string>> exclusive;  // keys that cannot be combined

    std::function<std::size_t(const Case&)> count;  // entries in c (0 or 1 for a table)
    std::function<void(Case&)> add;                 // appends an entry with the struct's defaults
    std::function<void(Case&)> absent;              // the case without the table (optional)
    // Before the keys of entry i are read: defaults that depend on which keys are present.
    std::function<void(Case&, std::size_t, const std::function<bool(std::string_view)>& has)> before;
    // After the keys of entry i are read (e.g. a waveform built from its keys).
    std::function<void(Case&, std::size_t)> after;
    // The rules between this section's keys that no single key's range states (check_case calls it;
    // the built-in sections' rules are in model/case_checks.cpp).
    std::function<void(std::vector<CaseProblem>&, const Case&)> check;
    // Where registered keys of entry i keep their values; empty: the section takes none.
    std::function<ParameterSet*(Case&, std::size_t)> params;
    bool registered = false;  // added by register_section (its entries are Case::sections[name])
    // A registered section's heading and paragraph in docs/case-files.md (model/case_schema_docs.hpp),
    // which lists it with its key table where the page gives it no block of its own.
    std::string title;
    std::string doc;

    [[nodiscard]] const KeySpec* key(std::string_view name) const;
    // For a section nested in a table ("beam.sections"): the table's name and the key under it;
    // empty for a section at the top of the file.
    [[nodiscard]] std::string parent() const;
    [[nodiscard]] std::string tail() const;
    // The path of entry i ("supports[1]", "beam", "" for the top level).
    [[nodiscard]] std::string entry_path(std::size_t i) const;
    // The section as a path form: "supports[i]", "beam".
    [[nodiscard]] std::string form() const;
    KeySpec& add_key(KeySpec k);
};

// The sections of a case file, in file order: the built-in ones and those registered.
struct CaseSchema {
    std::vector<SectionSpec> sections;
    [[nodiscard]] const SectionSpec* section(std::string_view name) const;
};

// The schema in effect. Registration changes it: register before cases are read and not while
// another thread reads one.
const CaseSchema& case_schema();
// Runs `fn` (registrations kept for the program's life, e.g. the element families' keys) once,
// when case_schema() is first called, or at once if it has been: a static initialiser may call it,
// since nothing is built before main. `fn` must not call case_schema(). Returns true.
bool register_at_first_use(std::function<void()> fn);
// The built-in schema alone (what docs/case-files.md documents).
const CaseSchema& builtin_case_schema();

// Undoes a registration when destroyed, unless kept (a family registered for the program's life).
class SchemaRegistration {
public:
    SchemaRegistration() = default;
    SchemaRegistration(std::string section, std::vector<std::string> keys);
    // An option added to the choice `key` of `section`, with the words added to its meaning.
    SchemaRegistration(std::string section, std::string key, std::string option, std::string meaning);
    SchemaRegistration(SchemaRegistration&& other) noexcept;
    SchemaRegistration& operator=(SchemaRegistration&& other) noexcept;
    SchemaRegistration(const SchemaRegistration&) = delete;
    SchemaRegistration& operator=(const SchemaRegistration&) = delete;
    ~SchemaRegistration();
    void keep() { section_.clear(); }

private:
    std::string section_;             // empty: nothing to undo
    std::vector<std::string> keys_;   // the keys added to a section; empty: the whole section
    std::string option_;              // an option added to the choice keys_[0]; empty: none
    std::string meaning_;             // what that option appended to the choice's meaning
};

// Adds a section whose entries are ParameterSets in Case::sections[spec.name]; its keys' accessors
// are made here (their in_params values). Throws std::invalid_argument for a name already taken.
[[nodiscard]] SchemaRegistration register_section(SectionSpec spec);
// Adds keys to a section that keeps registered keys (SectionSpec::params), e.g. a law's own keys
// beside a choice that selects it; their values live in the entries' ParameterSets.
[[nodiscard]] SchemaRegistration register_keys(std::string_view section, std::vector<KeySpec> keys);

// Adds a rule to section's check (after those it has), kept for the program's life: a rule that only
// a higher layer can judge (a beam of sections buckles at the load its finite-element model gives).
// Throws std::invalid_argument for an unknown section.
void add_section_check(std::string_view section, std::function<void(std::vector<CaseProblem>&, const Case&)> check);

// Adds `option` to the choice `key` of `section`, and " or `\"option\"` (meaning)" to the key's
// meaning: a law a force family brings to a choice that lives with its section (supports' `law`),
// so that the next law adds its own option without touching the file of the one before. Throws
// std::invalid_argument for an unknown key, a key that is not a choice, or an option it has.
[[nodiscard]] SchemaRegistration register_option(std::string_view section, std::string_view key, std::string option,
                                                 std::string meaning);

// Gives k accessors to its value in the ParameterSet of its section's entry (KeySpec::in_params):
// what register_section and register_keys do for a registered key, and what a built-in key uses
// whose value is read by a higher layer alone (supports' `law`).
void bind_to_params(KeySpec& k, const std::string& section);

// A condition for a registered key: the entry's choice (or text) key `selector` is one of `values`.
KeyCondition when_chosen(std::string section, std::string selector, std::vector<std::string> values);

// Appends an entry to the section's entries in c with every key's default set (the schema's, which
// is what a case file leaving the key out gets; the structs' own defaults serve cases built in code).
void add_entry(const SectionSpec& s, Case& c);

// Whether key k of entry i carries a value that means something: it applies and is set.
bool key_in_effect(const Case& c, const SectionSpec& s, const KeySpec& k, std::size_t i);

// The dotted path of key k of entry i: "supports[1].gap", "name".
std::string key_path(const SectionSpec& s, std::size_t i, std::string_view key);

// The condition's reader message for entry path `entry` ($ replaced).
std::string condition_text(const std::string& text, const std::string& entry);

}  // namespace vi
