#include "io/case_writer.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <variant>

#include "model/case_schema.hpp"

// Both forms walk the schema the same way (case_walk below): the top level's keys, then each section
// in file order, each entry of an array, each key in effect. A section without entries (no [air],
// no [[loads]]) is left out; a table section with entries is written even when every key is at its
// default, since its presence can matter ([initial] without keys starts from a lift, not at rest).

namespace vi {
namespace {

using KeyValue = std::variant<double, std::int64_t, bool, std::string, std::array<double, 2>, std::array<std::int64_t, 2>,
                              std::vector<Layer>, Holes>;

// A table file's name as the reader opens it, made absolute: the case file's folder joined with it.
std::string table_path(const Case& c, const std::string& name) {
    if (name.empty()) return name;
    const std::filesystem::path folder = std::filesystem::path(c.origin.file).parent_path();
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(folder / name, ec);
    return ec ? (folder / name).string() : p.lexically_normal().string();
}

// A whole number held as a double, as an integer (a registered key's value may lie beyond int64's
// range, where the plain cast is undefined).
std::int64_t whole(double v) {
    if (!(v == v)) return 0;
    if (v >= 9.2233720368547758e18) return std::numeric_limits<std::int64_t>::max();
    if (v <= -9.2233720368547758e18) return std::numeric_limits<std::int64_t>::min();
    return static_cast<std::int64_t>(v);
}

KeyValue key_value(const Case& c, const KeySpec& k, std::size_t i) {
    switch (k.kind) {
        case KeyKind::number: return k.get_number(c, i, 0);
        case KeyKind::integer: return whole(k.get_number(c, i, 0));
        case KeyKind::flag: return k.get_number(c, i, 0) != 0.0;
        case KeyKind::number_pair: return std::array<double, 2>{k.get_number(c, i, 0), k.get_number(c, i, 1)};
        case KeyKind::integer_pair:
            return std::array<std::int64_t, 2>{whole(k.get_number(c, i, 0)), whole(k.get_number(c, i, 1))};
        case KeyKind::table_file: return table_path(c, k.get_text(c, i));
        case KeyKind::choice:
        case KeyKind::text: return k.get_text(c, i);
        case KeyKind::layer_stack: return *k.layers(const_cast<Case&>(c), i);
        case KeyKind::hole_array: return k.holes(const_cast<Case&>(c), i)->value_or(Holes{});
    }
    return std::string();
}

// Calls entry(section, index) for every entry and key(spec, value) for every key in effect in it.
template <class Entry, class Key>
void case_walk(const Case& c, Entry entry, Key key) {
    for (const SectionSpec& s : case_schema().sections) {
        const std::size_t n = s.count(c);
        for (std::size_t i = 0; i < n; ++i) {
            entry(s, i);
            for (const KeySpec& k : s.keys) {
                if (key_in_effect(c, s, k, i)) key(k, key_value(c, k, i));
            }
        }
    }
}

// The shortest text that reads back to v, as a TOML float (a decimal point or an exponent).
std::string toml_float(double v) {
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, r.ptr);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(const std::string& text) {
    std::string out = "\"";
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (byte < 0x20 || byte == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04X", static_cast<unsigned>(byte));
            out += buf;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

// (Built by appending: GCC 12 warns falsely, -Wrestrict, on "literal" + a temporary string.)
std::string bracketed(const std::string& a, const std::string& b) {
    std::string out = "[";
    out.append(a).append(", ").append(b).append("]");
    return out;
}

struct TomlText {
    std::string operator()(double v) const { return toml_float(v); }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return toml_string(v); }
    std::string operator()(const std::array<double, 2>& v) const {
        return bracketed(toml_float(v[0]), toml_float(v[1]));
    }
    std::string operator()(const std::array<std::int64_t, 2>& v) const {
        return bracketed(std::to_string(v[0]), std::to_string(v[1]));
    }
    std::string operator()(const std::vector<Layer>& v) const {
        std::string out = "[";
        for (std::size_t i = 0; i < v.size(); ++i) {
            out.append(i == 0 ? "" : ", ").append("{ material = ").append(toml_string(v[i].material));
            out.append(", thickness = ").append(toml_float(v[i].thickness)).append(" }");
        }
        return out + "]";
    }
    std::string operator()(const Holes& h) const {
        std::string out = "{ size = ";
        out.append(toml_float(h.size)).append(", pitch = ").append(toml_float(h.pitch)).append(", shape = ");
        return out.append(h.shape == HoleShape::circle ? "\"circle\"" : "\"square\"").append(" }");
    }
};

struct JsonValue {
    nlohmann::json operator()(double v) const { return v; }
    nlohmann::json operator()(std::int64_t v) const { return v; }
    nlohmann::json operator()(bool v) const { return v; }
    nlohmann::json operator()(const std::string& v) const { return v; }
    nlohmann::json operator()(const std::array<double, 2>& v) const { return {v[0], v[1]}; }
    nlohmann::json operator()(const std::array<std::int64_t, 2>& v) const { return {v[0], v[1]}; }
    nlohmann::json operator()(const std::vector<Layer>& v) const {
        nlohmann::json out = nlohmann::json::array();
        for (const Layer& l : v) out.push_back({{"material", l.material}, {"thickness", l.thickness}});
        return out;
    }
    nlohmann::json operator()(const Holes& h) const {
        return {{"size", h.size}, {"pitch", h.pitch}, {"shape", h.shape == HoleShape::circle ? "circle" : "square"}};
    }
};

}  // namespace

std::string case_to_toml(const Case& c) {
    std::string out = "# The case " + toml_string(c.name) + " with every key in effect, in SI units (written by vibroimpact)\n";
    case_walk(
        c,
        [&](const SectionSpec& s, std::size_t) {
            if (s.name.empty()) return;
            out.append("\n").append(s.array ? "[[" : "[").append(s.name).append(s.array ? "]]\n" : "]\n");
        },
        [&](const KeySpec& k, const KeyValue& v) {
            out.append(k.name).append(" = ").append(std::visit(TomlText{}, v));
            if (k.kind == KeyKind::number && k.unit != "-") out.append("  # ").append(k.unit);
            out.append("\n");
        });
    return out;
}

nlohmann::json case_to_json(const Case& c) {
    nlohmann::json out = nlohmann::json::object();
    nlohmann::json* at = &out;
    case_walk(
        c,
        [&](const SectionSpec& s, std::size_t) {
            if (s.name.empty()) {
                at = &out;
            } else if (s.array) {
                // A section nested in a table ([[beam.sections]]) is an array inside that table's object.
                nlohmann::json& list = s.parent().empty() ? out[s.name] : out[s.parent()][s.tail()];
                if (!list.is_array()) list = nlohmann::json::array();
                list.push_back(nlohmann::json::object());
                at = &list.back();
            } else {
                at = &out[s.name];
                *at = nlohmann::json::object();
            }
        },
        [&](const KeySpec& k, const KeyValue& v) { (*at)[k.name] = std::visit(JsonValue{}, v); });
    return out;
}

}  // namespace vi
