#include "model/case_schema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "model/case_schema_builtin.hpp"

// The schema in effect is the built-in one plus what higher layers registered. Registration is rare
// (a family at start-up, a toy section in a test) and cases are read far more often, so the schema
// is one vector changed in place under a mutex, and readers take it by reference: registering while
// another thread reads a case is not supported (and nothing does it).

namespace vi {
namespace {

// A bound as the messages and the docs write it: 1e-3, 1e9 for powers of ten from 1e4 up and 1e-3
// down, else the shortest text that reads back (1000, 0.5).
std::string bound_text(double v) {
    if (v != 0.0 && std::isfinite(v)) {
        const double e = std::round(std::log10(std::abs(v)));
        if ((e >= 4.0 || e <= -3.0) && std::abs(v) == std::pow(10.0, e)) {
            return std::string(v < 0 ? "-" : "") + "1e" + std::to_string(static_cast<int>(e));
        }
    }
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v == 0.0 ? 0.0 : v);
    return std::string(buf, r.ptr);
}

CaseSchema& mutable_schema() {
    static CaseSchema schema = builtin_case_schema();
    return schema;
}

std::mutex& registry_mutex() {
    static std::mutex m;
    return m;
}

SectionSpec* find_section(std::string_view name) {
    for (SectionSpec& s : mutable_schema().sections)
        if (s.name == name) return &s;
    return nullptr;
}

// The ParameterSet of entry i of section `section` (registered keys' values); throws when the
// section keeps none (a registration error, not a user's).
ParameterSet& params_of(const std::string& section, Case& c, std::size_t i) {
    const SectionSpec* s = case_schema().section(section);
    if (s == nullptr || !s->params) throw std::logic_error("section '" + section + "' keeps no registered keys");
    ParameterSet* p = s->params(c, i);
    if (p == nullptr) throw std::logic_error("section '" + section + "' has no entry " + std::to_string(i));
    return *p;
}

}  // namespace

// Accessors for a registered key: its value in the entry's ParameterSet, its default when absent.
void bind_to_params(KeySpec& k, const std::string& section) {
    k.in_params = true;
    const std::string name = k.name;
    if (is_numeric(k.kind) || k.kind == KeyKind::flag) {
        // A flag's default is its default_choice ("true"/"false"), a number's default_numbers.
        const std::vector<double> defaults =
            k.kind == KeyKind::flag ? std::vector<double>{k.default_choice == "true" ? 1.0 : 0.0} : k.default_numbers;
        k.get_number = [section, name, defaults](const Case& c, std::size_t i, std::size_t e) {
            const std::string key = e == 0 ? name : name + "[" + std::to_string(e) + "]";
            const double fallback = e < defaults.size() ? defaults[e] : 0.0;
            return params_of(section, const_cast<Case&>(c), i).number(key, fallback);
        };
        k.set_number = [section, name](Case& c, std::size_t i, std::size_t e, double v) {
            params_of(section, c, i).numbers[e == 0 ? name : name + "[" + std::to_string(e) + "]"] = v;
        };
        if (k.default_numbers.empty() && k.kind != KeyKind::flag) {
            k.is_set = [section, name](const Case& c, std::size_t i) {
                return params_of(section, const_cast<Case&>(c), i).numbers.count(name) > 0;
            };
        }
    } else {
        const std::string fallback = k.default_choice;
        k.get_text = [section, name, fallback](const Case& c, std::size_t i) {
            return params_of(section, const_cast<Case&>(c), i).text(name, fallback);
        };
        k.set_text = [section, name](Case& c, std::size_t i, const std::string& v) {
            params_of(section, c, i).texts[name] = v;
        };
        if (k.default_choice.empty()) {
            k.is_set = [section, name](const Case& c, std::size_t i) {
                return params_of(section, const_cast<Case&>(c), i).texts.count(name) > 0;
            };
        }
    }
}

bool is_numeric(KeyKind k) {
    return k == KeyKind::number || k == KeyKind::integer || k == KeyKind::number_pair || k == KeyKind::integer_pair;
}

bool is_pair(KeyKind k) { return k == KeyKind::number_pair || k == KeyKind::integer_pair; }

bool KeyRange::contains(double v) const {
    const bool above_lo = lo_open ? v > lo : v >= lo;
    const bool below_hi = hi_open ? v < hi : v <= hi;
    return above_lo && below_hi;
}

std::string KeyRange::problem(double v) const {
    if (contains(v)) return "";
    const bool low = lo_open ? !(v > lo) : !(v >= lo);
    if (low && !too_low.empty()) return too_low;
    if (!low && !too_high.empty()) return too_high;
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    std::string m;
    if (has_lo && has_hi) {
        m = "must lie in " + text();
    } else if (has_lo) {
        m = lo == 0.0 ? (lo_open ? "must be positive" : "must not be negative")
                      : (lo_open ? "must be above " : "must be at least ") + bound_text(lo);
    } else {
        m = (hi_open ? "must be below " : "must be at most ") + bound_text(hi);
    }
    return m + note;
}

std::string KeyRange::text() const {
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (has_lo && has_hi) {
        return std::string(lo_open ? "(" : "[") + bound_text(lo) + ", " + bound_text(hi) + (hi_open ? ")" : "]");
    }
    if (has_lo) return std::string(lo_open ? "> " : ">= ") + bound_text(lo);
    if (has_hi) return std::string(hi_open ? "< " : "<= ") + bound_text(hi);
    return "-";
}

KeyRange positive(std::string note) {
    KeyRange r;
    r.lo = 0.0;
    r.lo_open = true;
    r.note = std::move(note);
    return r;
}

KeyRange non_negative(std::string note) {
    KeyRange r;
    r.lo = 0.0;
    r.note = std::move(note);
    return r;
}

KeyRange interval(double lo, bool lo_open, double hi, bool hi_open, std::string note) {
    KeyRange r;
    r.lo = lo;
    r.lo_open = lo_open;
    r.hi = hi;
    r.hi_open = hi_open;
    r.note = std::move(note);
    return r;
}

KeySpec& KeySpec::means(std::string text) {
    meaning = std::move(text);
    return *this;
}
KeySpec& KeySpec::require() {
    required = true;
    return *this;
}
KeySpec& KeySpec::otherwise(double value, std::string text) {
    default_numbers.assign(is_pair(kind) ? 2 : 1, value);
    default_text = std::move(text);
    return *this;
}
KeySpec& KeySpec::otherwise(std::string choice, std::string text) {
    default_choice = std::move(choice);
    default_text = std::move(text);
    return *this;
}
KeySpec& KeySpec::in(KeyRange r) {
    range = std::move(r);
    return *this;
}
KeySpec& KeySpec::only(KeyCondition c) {
    when = std::move(c);
    return *this;
}
KeySpec& KeySpec::needing(std::string key, std::string text) {
    needs = std::move(key);
    needs_text = std::move(text);
    return *this;
}

namespace {
KeySpec make_key(std::string name, KeyKind kind, Dimension d, std::string unit) {
    KeySpec k;
    k.name = std::move(name);
    k.kind = kind;
    k.dimension = d;
    k.unit = unit.empty() ? std::string(si_unit(d)) : std::move(unit);
    return k;
}
}  // namespace

KeySpec number_key(std::string name, Dimension d, std::string unit) {
    return make_key(std::move(name), KeyKind::number, d, std::move(unit));
}
KeySpec integer_key(std::string name) { return make_key(std::move(name), KeyKind::integer, Dimension::dimensionless, "-"); }
KeySpec number_pair_key(std::string name) {
    return make_key(std::move(name), KeyKind::number_pair, Dimension::dimensionless, "-");
}
KeySpec integer_pair_key(std::string name) {
    return make_key(std::move(name), KeyKind::integer_pair, Dimension::dimensionless, "-");
}
KeySpec flag_key(std::string name) { return make_key(std::move(name), KeyKind::flag, Dimension::dimensionless, "-"); }
KeySpec choice_key(std::string name, std::vector<std::string> options) {
    KeySpec k = make_key(std::move(name), KeyKind::choice, Dimension::dimensionless, "-");
    k.options = std::move(options);
    return k;
}
KeySpec text_key(std::string name) { return make_key(std::move(name), KeyKind::text, Dimension::dimensionless, "-"); }
KeySpec table_file_key(std::string name, std::string column) {
    KeySpec k = make_key(std::move(name), KeyKind::table_file, Dimension::dimensionless, "-");
    k.column = std::move(column);
    return k;
}

KeySpec layer_stack_key(std::string name) {
    return make_key(std::move(name), KeyKind::layer_stack, Dimension::dimensionless, "-");
}

KeySpec hole_array_key(std::string name) {
    return make_key(std::move(name), KeyKind::hole_array, Dimension::dimensionless, "-");
}

std::string SectionSpec::parent() const {
    const auto dot = name.find('.');
    return dot == std::string::npos ? std::string() : name.substr(0, dot);
}

std::string SectionSpec::tail() const {
    const auto dot = name.find('.');
    return dot == std::string::npos ? name : name.substr(dot + 1);
}

const KeySpec* SectionSpec::key(std::string_view n) const {
    for (const KeySpec& k : keys)
        if (k.name == n) return &k;
    return nullptr;
}

std::string SectionSpec::entry_path(std::size_t i) const {
    return array ? name + "[" + std::to_string(i) + "]" : name;
}

std::string SectionSpec::form() const { return array ? name + "[i]" : name; }

KeySpec& SectionSpec::add_key(KeySpec k) {
    keys.push_back(std::move(k));
    return keys.back();
}

const SectionSpec* CaseSchema::section(std::string_view n) const {
    for (const SectionSpec& s : sections)
        if (s.name == n) return &s;
    return nullptr;
}

namespace {

// The registrations waiting for the schema's first use.
struct FirstUse {
    std::mutex mutex;
    std::vector<std::function<void()>> pending;
    bool done = false;
};

FirstUse& first_use() {
    static FirstUse f;
    return f;
}

void apply_first_use() {
    static std::once_flag once;
    std::call_once(once, [] {
        FirstUse& f = first_use();
        std::vector<std::function<void()>> todo;
        {
            const std::lock_guard<std::mutex> lock(f.mutex);
            f.done = true;
            todo.swap(f.pending);
        }
        for (const std::function<void()>& fn : todo) fn();
    });
}

}  // namespace

bool register_at_first_use(std::function<void()> fn) {
    FirstUse& f = first_use();
    {
        const std::lock_guard<std::mutex> lock(f.mutex);
        if (!f.done) {
            f.pending.push_back(std::move(fn));
            return true;
        }
    }
    fn();
    return true;
}

const CaseSchema& case_schema() {
    apply_first_use();
    return mutable_schema();
}

SchemaRegistration::SchemaRegistration(std::string section, std::vector<std::string> keys)
    : section_(std::move(section)), keys_(std::move(keys)) {}

SchemaRegistration::SchemaRegistration(std::string section, std::string key, std::string option, std::string meaning)
    : section_(std::move(section)), keys_{std::move(key)}, option_(std::move(option)), meaning_(std::move(meaning)) {}

SchemaRegistration::SchemaRegistration(SchemaRegistration&& other) noexcept
    : section_(std::move(other.section_)), keys_(std::move(other.keys_)), option_(std::move(other.option_)),
      meaning_(std::move(other.meaning_)) {
    other.section_.clear();
}

SchemaRegistration& SchemaRegistration::operator=(SchemaRegistration&& other) noexcept {
    if (this != &other) {
        SchemaRegistration old(std::move(*this));
        section_ = std::move(other.section_);
        keys_ = std::move(other.keys_);
        option_ = std::move(other.option_);
        meaning_ = std::move(other.meaning_);
        other.section_.clear();
    }
    return *this;
}

SchemaRegistration::~SchemaRegistration() {
    if (section_.empty()) return;
    const std::lock_guard<std::mutex> lock(registry_mutex());
    std::vector<SectionSpec>& all = mutable_schema().sections;
    if (keys_.empty()) {
        std::erase_if(all, [&](const SectionSpec& s) { return s.name == section_ && s.registered; });
        return;
    }
    SectionSpec* s = find_section(section_);
    if (s != nullptr && !option_.empty()) {
        for (KeySpec& k : s->keys) {
            if (k.name != keys_.front()) continue;
            std::erase(k.options, option_);
            const std::size_t at = k.meaning.rfind(meaning_);
            if (at != std::string::npos) k.meaning.erase(at, meaning_.size());
        }
        return;
    }
    if (s != nullptr) {
        std::erase_if(s->keys, [&](const KeySpec& k) {
            return k.in_params && std::find(keys_.begin(), keys_.end(), k.name) != keys_.end();
        });
    }
}

SchemaRegistration register_section(SectionSpec spec) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    if (spec.name.empty() || find_section(spec.name) != nullptr) {
        throw std::invalid_argument("register_section: the section name '" + spec.name + "' is empty or taken");
    }
    const std::string name = spec.name;
    spec.registered = true;
    const bool array = spec.array;
    spec.count = [name](const Case& c) {
        const auto it = c.sections.find(name);
        return it == c.sections.end() ? std::size_t{0} : it->second.size();
    };
    spec.add = [name, array](Case& c) {
        std::vector<ParameterSet>& entries = c.sections[name];
        if (array || entries.empty()) entries.emplace_back();
    };
    spec.params = [name](Case& c, std::size_t i) -> ParameterSet* {
        const auto it = c.sections.find(name);
        return it == c.sections.end() || i >= it->second.size() ? nullptr : &it->second[i];
    };
    if (spec.entry_word.empty()) spec.entry_word = name;
    if (!array && spec.absent_text.empty()) spec.absent_text = "only with a [" + name + "] table";
    for (KeySpec& k : spec.keys) bind_to_params(k, name);
    mutable_schema().sections.push_back(std::move(spec));
    return SchemaRegistration(name, {});
}

SchemaRegistration register_keys(std::string_view section, std::vector<KeySpec> keys) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    SectionSpec* s = find_section(section);
    if (s == nullptr || !s->params) {
        throw std::invalid_argument("register_keys: section '" + std::string(section) + "' takes no registered keys");
    }
    std::vector<std::string> names;
    for (KeySpec& k : keys) {
        if (s->key(k.name) != nullptr) {
            throw std::invalid_argument("register_keys: " + s->form() + "." + k.name + " is already a key");
        }
        bind_to_params(k, s->name);
        names.push_back(k.name);
        s->keys.push_back(std::move(k));
    }
    return SchemaRegistration(std::string(section), names);
}

void add_section_check(std::string_view section, std::function<void(std::vector<CaseProblem>&, const Case&)> check) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    SectionSpec* s = find_section(section);
    if (s == nullptr) throw std::invalid_argument("add_section_check: no section '" + std::string(section) + "'");
    if (!s->check) {
        s->check = std::move(check);
        return;
    }
    s->check = [before = std::move(s->check), after = std::move(check)](std::vector<CaseProblem>& out, const Case& c) {
        before(out, c);
        after(out, c);
    };
}

SchemaRegistration register_option(std::string_view section, std::string_view key, std::string option,
                                   std::string meaning) {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    SectionSpec* s = find_section(section);
    KeySpec* k = nullptr;
    if (s != nullptr) {
        for (KeySpec& candidate : s->keys)
            if (candidate.name == key) k = &candidate;
    }
    if (k == nullptr || k->kind != KeyKind::choice ||
        std::find(k->options.begin(), k->options.end(), option) != k->options.end()) {
        throw std::invalid_argument("register_option: " + std::string(section) + "." + std::string(key) +
                                    " is not a choice that lacks \"" + option + "\"");
    }
    const std::string added = " or `\"" + option + "\"` (" + meaning + ")";
    k->options.push_back(option);
    k->meaning += added;
    return SchemaRegistration(std::string(section), std::string(key), option, added);
}

KeyCondition when_chosen(std::string section, std::string selector, std::vector<std::string> values) {
    KeyCondition c;
    std::string list;
    for (std::size_t v = 0; v < values.size(); ++v) {
        list += (v == 0 ? "" : v + 1 == values.size() ? " or " : ", ") + ("\"" + values[v] + "\"");
    }
    c.on = {selector};
    c.file_text = "only with $." + selector + " = " + list;
    c.holds = [section, selector, values](const Case& cs, std::size_t i) {
        const SectionSpec* s = case_schema().section(section);
        const KeySpec* k = s == nullptr ? nullptr : s->key(selector);
        if (k == nullptr || !k->get_text) return false;
        return std::find(values.begin(), values.end(), k->get_text(cs, i)) != values.end();
    };
    return c;
}

void add_entry(const SectionSpec& s, Case& c) {
    s.add(c);
    const std::size_t i = s.count(c) - 1;
    for (const KeySpec& k : s.keys) {
        for (std::size_t e = 0; e < k.default_numbers.size(); ++e) k.set_number(c, i, e, k.default_numbers[e]);
        if (k.default_choice.empty()) continue;
        if (k.kind == KeyKind::flag) {
            k.set_number(c, i, 0, k.default_choice == "true" ? 1.0 : 0.0);
        } else {
            k.set_text(c, i, k.default_choice);
        }
    }
}

bool key_in_effect(const Case& c, const SectionSpec& s, const KeySpec& k, std::size_t i) {
    (void)s;
    if (k.when.holds && !k.when.holds(c, i)) return false;
    return !k.is_set || k.is_set(c, i);
}

std::string key_path(const SectionSpec& s, std::size_t i, std::string_view key) {
    const std::string entry = s.entry_path(i);
    return entry.empty() ? std::string(key) : entry + "." + std::string(key);
}

std::string condition_text(const std::string& text, const std::string& entry) {
    std::string out;
    for (std::size_t p = 0; p < text.size(); ++p) {
        if (text[p] == '$') {
            out += entry;
        } else {
            out += text[p];
        }
    }
    return out;
}

}  // namespace vi
