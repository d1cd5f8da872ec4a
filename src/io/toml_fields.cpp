#include "io/toml_fields.hpp"

#include "io/spelling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace vi::tomlio {
namespace {

bool before(Position a, Position b) {
    return a.line < b.line || (a.line == b.line && a.column < b.column);
}

std::string join(const std::vector<std::string_view>& items) {
    std::string out;
    for (const std::string_view item : items) {
        if (!out.empty()) out += ", ";
        out += key_text(item);
    }
    return out;
}

// "nan", "inf" or "-inf" for a non-finite number.
std::string non_finite_text(double v) {
    if (std::isnan(v)) return "nan";
    return v > 0 ? "inf" : "-inf";
}

// What a quantity field expects, for wrong-type messages.
std::string expected_quantity(Dimension d) {
    if (d == Dimension::dimensionless) return "a number";
    const std::string units = accepted_units(d);
    const std::string first_unit = units.substr(0, units.find(','));
    return "a number (SI) or a string with a unit such as \"1 " + first_unit + "\"";
}

// The array under key when it holds exactly two elements; else nullptr (problem logged).
const toml::array* pair_array(FieldReader& f, std::string_view key, const std::string& what) {
    const std::string expected = "an array of 2 " + what;
    const toml::array* a = f.array(key, false, expected);
    if (a == nullptr) return nullptr;
    if (a->size() != 2) {
        f.reject(key, "expected " + expected + ", got " + std::to_string(a->size()) + " element(s)");
        return nullptr;
    }
    return a;
}

std::string element_path(const FieldReader& f, std::string_view key, std::size_t i) {
    return child_path(f.path(), key) + "[" + std::to_string(i) + "]";
}

Position element_position(const FieldReader& f, std::string_view key, const toml::node& element) {
    return position_of(element.source(), f.key_position(key));
}

}  // namespace

void ReadLog::problem(Position at, std::string key, std::string message) {
    problems_.push_back({at, std::move(key), std::move(message)});
}

void ReadLog::withdraw(const std::string& key) {
    std::erase_if(problems_, [&](const SourceProblem& p) { return p.key == key && p.message.starts_with("missing required"); });
}

void ReadLog::locate(const std::string& key, Position at) { positions_[key] = at; }

std::map<std::string, int> ReadLog::lines() const {
    std::map<std::string, int> out;
    for (const auto& [key, pos] : positions_) out[key] = static_cast<int>(pos.line);
    return out;
}

Position ReadLog::where(std::string key) const {
    while (!key.empty()) {
        if (const auto it = positions_.find(key); it != positions_.end()) return it->second;
        if (key.back() == ']') {
            key.erase(key.rfind('['));
        } else if (const auto dot = key.rfind('.'); dot != std::string::npos) {
            key.erase(dot);
        } else {
            break;
        }
    }
    return {};
}

std::optional<SourceProblem> ReadLog::first() const {
    const auto it = std::min_element(problems_.begin(), problems_.end(),
                                     [](const SourceProblem& a, const SourceProblem& b) { return before(a.at, b.at); });
    if (it == problems_.end()) return std::nullopt;
    return *it;
}

std::string type_name(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::none: return "nothing";
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a floating-point number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
    }
    return "an unknown value";
}

Position position_of(const toml::source_region& region, Position fallback) {
    if (region.begin.line == 0) return fallback;
    return {static_cast<std::uint32_t>(region.begin.line), static_cast<std::uint32_t>(region.begin.column)};
}

std::string key_text(std::string_view key) {
    const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char ch) {
        return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
               ch == '-';
    });
    return bare ? std::string(key) : in_quotes(key);
}

std::string child_path(std::string_view parent, std::string_view key) {
    if (parent.empty()) return key_text(key);
    return std::string(parent) + "." + key_text(key);
}

std::optional<double> read_quantity(const toml::node& node, Dimension d, const std::string& key, Position at,
                                    ReadLog& log) {
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    if (const auto* f = node.as_floating_point()) {
        const double v = f->get();
        if (std::isfinite(v)) return v;
        log.problem(at, key, "must be a finite number, got " + non_finite_text(v));
        return std::nullopt;
    }
    if (const auto* s = node.as_string()) {
        try {
            return parse_quantity(s->get(), d);
        } catch (const std::invalid_argument& e) {
            log.problem(at, key, e.what());
            return std::nullopt;
        }
    }
    log.problem(at, key, "expected " + expected_quantity(d) + ", got " + type_name(node));
    return std::nullopt;
}

std::optional<std::int64_t> read_integer(const toml::node& node, const std::string& key, Position at,
                                         ReadLog& log) {
    if (const auto* i = node.as_integer()) return i->get();
    log.problem(at, key, "expected an integer, got " + type_name(node));
    return std::nullopt;
}

FieldReader::FieldReader(const toml::table& table, std::string path, Position at, ReadLog& log,
                         std::initializer_list<std::string_view> accepted)
    : table_(table), path_(std::move(path)), at_(at), log_(log), accepted_(accepted) {
    if (!path_.empty()) log_.locate(path_, at_);
}

FieldReader::FieldReader(const toml::table& table, std::string path, Position at, ReadLog& log,
                         std::vector<std::string_view> accepted)
    : table_(table), path_(std::move(path)), at_(at), log_(log), accepted_(std::move(accepted)) {
    if (!path_.empty()) log_.locate(path_, at_);
}

bool FieldReader::has(std::string_view key) const { return table_.find(key) != table_.end(); }

Position FieldReader::key_position(std::string_view key) const {
    const auto it = table_.find(key);
    if (it == table_.end()) return at_;
    return position_of(it->first.source(), at_);
}

const toml::node* FieldReader::find(std::string_view key, bool required, std::string_view missing) {
    const auto it = table_.find(key);
    if (it == table_.end()) {
        if (required) log_.problem(at_, child_path(path_, key), std::string(missing));
        return nullptr;
    }
    log_.locate(child_path(path_, key), position_of(it->first.source(), at_));
    return &it->second;
}

void FieldReader::wrong_type(std::string_view key, const std::string& expected, const toml::node& got) {
    log_.problem(key_position(key), child_path(path_, key), "expected " + expected + ", got " + type_name(got));
}

std::optional<double> FieldReader::quantity(std::string_view key, Dimension d, bool required) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return std::nullopt;
    return read_quantity(*node, d, child_path(path_, key), key_position(key), log_);
}

std::optional<std::int64_t> FieldReader::integer(std::string_view key, bool required) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return std::nullopt;
    return read_integer(*node, child_path(path_, key), key_position(key), log_);
}

std::optional<bool> FieldReader::boolean(std::string_view key, bool required) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return std::nullopt;
    if (const auto* b = node->as_boolean()) return b->get();
    wrong_type(key, "true or false", *node);
    return std::nullopt;
}

std::optional<std::string> FieldReader::string(std::string_view key, bool required) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return std::nullopt;
    if (const auto* s = node->as_string()) return s->get();
    wrong_type(key, "a string", *node);
    return std::nullopt;
}

std::optional<std::string> FieldReader::choice(std::string_view key, std::initializer_list<std::string_view> options,
                                               bool required) {
    return choice(key, std::vector<std::string>(options.begin(), options.end()), required);
}

std::optional<std::string> FieldReader::choice(std::string_view key, const std::vector<std::string>& options,
                                               bool required) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return std::nullopt;
    std::string list;
    for (const std::string& option : options) {
        if (!list.empty()) list += ", ";
        list += '"';
        list += option;
        list += '"';
    }
    const auto* s = node->as_string();
    if (s == nullptr) {
        wrong_type(key, "one of " + list, *node);
        return std::nullopt;
    }
    if (std::find(options.begin(), options.end(), s->get()) == options.end()) {
        log_.problem(key_position(key), child_path(path_, key),
                     "must be one of " + list + ", got " + in_quotes(s->get()));
        return std::nullopt;
    }
    return s->get();
}

const toml::table* FieldReader::table(std::string_view key, bool required) {
    const toml::node* node = find(key, required, "missing required table [" + child_path(path_, key) + "]");
    if (node == nullptr) return nullptr;
    if (const auto* t = node->as_table()) return t;
    wrong_type(key, "a table", *node);
    return nullptr;
}

const toml::array* FieldReader::array(std::string_view key, bool required, std::string_view expected) {
    const toml::node* node = find(key, required);
    if (node == nullptr) return nullptr;
    if (const auto* a = node->as_array()) return a;
    wrong_type(key, std::string(expected), *node);
    return nullptr;
}

void FieldReader::exclusive(std::string_view a, std::string_view b) {
    if (!has(a) || !has(b)) return;
    const bool b_later = before(key_position(a), key_position(b));
    const std::string_view later = b_later ? b : a;
    const std::string_view earlier = b_later ? a : b;
    reject(later, "cannot be combined with " + child_path(path_, earlier));
}

void FieldReader::reject(std::string_view key, const std::string& message) {
    log_.problem(key_position(key), child_path(path_, key), message);
}

void FieldReader::finish() {
    for (auto&& [key, value] : table_) {
        (void)value;
        if (std::find(accepted_.begin(), accepted_.end(), key.str()) != accepted_.end()) continue;
        std::vector<std::string_view> absent;
        for (std::string_view a : accepted_)
            if (!has(a)) absent.push_back(a);
        const Position at = position_of(key.source(), at_);
        if (const auto guess = closest_spelling(key.str(), absent)) {
            // The misspelling is the cause of the missing key it stands for: report it, not that.
            log_.withdraw(child_path(path_, *guess));
            log_.problem(at, child_path(path_, key.str()),
                         "unknown key '" + std::string(key.str()) + "' (did you mean '" + *guess + "'?)");
        } else {
            log_.problem(at, child_path(path_, key.str()), "unknown key (accepted here: " + join(accepted_) + ")");
        }
    }
}

int clamp_to_int(std::int64_t v) {
    constexpr std::int64_t lo = std::numeric_limits<int>::min();
    constexpr std::int64_t hi = std::numeric_limits<int>::max();
    return static_cast<int>(std::clamp(v, lo, hi));
}

std::optional<std::array<double, 2>> number_pair(FieldReader& f, std::string_view key, ReadLog& log) {
    const toml::array* a = pair_array(f, key, "numbers");
    if (a == nullptr) return std::nullopt;
    std::array<double, 2> out{};
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        const auto v = read_quantity(e, Dimension::dimensionless, element_path(f, key, i),
                                     element_position(f, key, e), log);
        if (v) out[i] = *v;
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

std::optional<std::array<int, 2>> integer_pair(FieldReader& f, std::string_view key, ReadLog& log) {
    const toml::array* a = pair_array(f, key, "integers");
    if (a == nullptr) return std::nullopt;
    std::array<int, 2> out{};
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        const auto v = read_integer(e, element_path(f, key, i), element_position(f, key, e), log);
        if (v) out[i] = clamp_to_int(*v);
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

bool only_with(FieldReader& f, std::string_view key, bool allowed, const std::string& condition) {
    if (!allowed && f.has(key)) f.reject(key, "only with " + condition);
    return allowed;
}

}  // namespace vi::tomlio
