#pragma once
// Binding keys of the built-in schema to the fields of a Case's structs (model/case_keys_*.cpp): one
// reference to the field gives both the getter and the setter.

#include <algorithm>
#include <limits>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "model/case.hpp"
#include "model/case_schema.hpp"

namespace vi::schema {

// How entry i of a section is reached in a Case, per entry type.
template <class E>
struct EntryAccess;
template <> struct EntryAccess<Case> { static Case& at(Case& c, std::size_t) { return c; } };
template <> struct EntryAccess<Beam> { static Beam& at(Case& c, std::size_t) { return c.beam; } };
template <> struct EntryAccess<Material> { static Material& at(Case& c, std::size_t) { return c.material; } };
template <> struct EntryAccess<LayerMaterial> {
    static LayerMaterial& at(Case& c, std::size_t i) { return c.materials[i]; }
};
template <> struct EntryAccess<BeamSection> {
    static BeamSection& at(Case& c, std::size_t i) { return c.beam.sections[i]; }
};
template <> struct EntryAccess<Support> { static Support& at(Case& c, std::size_t i) { return c.supports[i]; } };
template <> struct EntryAccess<RayleighDamping> {
    static RayleighDamping& at(Case& c, std::size_t) { return c.damping; }
};
template <> struct EntryAccess<InitialState> { static InitialState& at(Case& c, std::size_t) { return c.initial; } };
template <> struct EntryAccess<PointLoad> { static PointLoad& at(Case& c, std::size_t i) { return c.loads[i]; } };
template <> struct EntryAccess<Electrode> { static Electrode& at(Case& c, std::size_t i) { return c.electrodes[i]; } };
template <> struct EntryAccess<Air> { static Air& at(Case& c, std::size_t) { return *c.air; } };
template <> struct EntryAccess<Film> { static Film& at(Case& c, std::size_t i) { return c.films[i]; } };
template <> struct EntryAccess<SolverSettings> { static SolverSettings& at(Case& c, std::size_t) { return c.solver; } };

// The entry for reading only (the getters never write through it).
template <class E>
E& entry(const Case& c, std::size_t i) {
    return EntryAccess<E>::at(const_cast<Case&>(c), i);
}

// v stored into a field of its type; whole-number fields take v clamped into their range, so that
// a huge value is reported by the range check as too large rather than wrapped.
inline void store(double& field, double v) { field = v; }
inline void store(bool& field, double v) { field = v != 0.0; }
template <class Int>
    requires std::is_integral_v<Int>
void store(Int& field, double v) {
    constexpr double lo = static_cast<double>(std::numeric_limits<Int>::min());
    constexpr double hi = static_cast<double>(std::numeric_limits<Int>::max());
    if (!(v == v)) {
        field = 0;
    } else if (v <= lo) {
        field = std::numeric_limits<Int>::min();
    } else if (v >= hi) {
        field = std::numeric_limits<Int>::max();
    } else {
        field = static_cast<Int>(v);
    }
}

// Binds k (a number, integer, pair or flag) to the field ref(entry, k) returns; `after` runs on the
// entry after every set (a waveform built again from its keys).
template <class E, class Ref>
KeySpec& bind(KeySpec& k, Ref ref, void (*after)(E&) = nullptr) {
    k.get_number = [ref](const Case& c, std::size_t i, std::size_t e) {
        return static_cast<double>(ref(entry<E>(c, i), e));
    };
    k.set_number = [ref, after](Case& c, std::size_t i, std::size_t e, double v) {
        E& x = EntryAccess<E>::at(c, i);
        store(ref(x, e), v);
        if (after != nullptr) after(x);
    };
    return k;
}

// Binds k to the member m of the entry (double, int, long or bool).
template <class E, class T>
KeySpec& bind_member(KeySpec& k, T E::*m, void (*after)(E&) = nullptr) {
    return bind<E>(k, [m](E& x, std::size_t) -> T& { return x.*m; }, after);
}

// Binds an optional number: unset until a value is given or set.
template <class E, class Ref>
KeySpec& bind_optional(KeySpec& k, Ref ref) {
    k.get_number = [ref](const Case& c, std::size_t i, std::size_t) { return ref(entry<E>(c, i)).value_or(0.0); };
    k.set_number = [ref](Case& c, std::size_t i, std::size_t, double v) { ref(EntryAccess<E>::at(c, i)) = v; };
    k.is_set = [ref](const Case& c, std::size_t i) { return ref(entry<E>(c, i)).has_value(); };
    return k;
}

// Binds a choice to an enum field: the key's options in order name the values listed.
template <class E, class Enum, class Ref>
KeySpec& bind_choice(KeySpec& k, Ref ref, std::vector<Enum> values) {
    const std::vector<std::string> names = k.options;
    k.get_text = [ref, values, names](const Case& c, std::size_t i) -> std::string {
        const Enum v = ref(entry<E>(c, i));
        for (std::size_t n = 0; n < values.size() && n < names.size(); ++n)
            if (values[n] == v) return names[n];
        return "";
    };
    k.set_text = [ref, values, names](Case& c, std::size_t i, const std::string& s) {
        for (std::size_t n = 0; n < values.size() && n < names.size(); ++n)
            if (names[n] == s) ref(EntryAccess<E>::at(c, i)) = values[n];
    };
    const auto get = k.get_text;
    k.is_set = [get](const Case& c, std::size_t i) { return !get(c, i).empty(); };
    return k;
}

// Binds a text (or table file name) to a string field.
template <class E, class Ref>
KeySpec& bind_text(KeySpec& k, Ref ref) {
    k.get_text = [ref](const Case& c, std::size_t i) { return ref(entry<E>(c, i)); };
    k.set_text = [ref](Case& c, std::size_t i, const std::string& s) { ref(EntryAccess<E>::at(c, i)) = s; };
    return k;
}

// A condition over entry i of type E.
template <class E, class Pred>
KeyCondition when(Pred pred, std::vector<std::string> on, std::string file_text, std::string path_text = "",
                  std::string doc_text = "") {
    KeyCondition c;
    c.holds = [pred](const Case& cs, std::size_t i) { return pred(entry<E>(cs, i)); };
    c.on = std::move(on);
    c.file_text = std::move(file_text);
    c.path_text = std::move(path_text);
    c.doc_text = std::move(doc_text);
    return c;
}

// A section of entries of type E: a table (count 1) or an array of them in the Case.
template <class E>
SectionSpec table_section(std::string name, bool required) {
    SectionSpec s;
    s.name = std::move(name);
    s.required = required;
    s.count = [](const Case&) { return std::size_t{1}; };
    s.add = [](Case&) {};
    return s;
}

template <class E>
SectionSpec array_section(std::string name, std::string word, std::vector<E> Case::*list, std::size_t max_entries) {
    SectionSpec s;
    s.name = std::move(name);
    s.array = true;
    s.entry_word = std::move(word);
    s.max_entries = max_entries;
    s.count = [list](const Case& c) { return (c.*list).size(); };
    s.add = [list](Case& c) { (c.*list).emplace_back(); };
    return s;
}

}  // namespace vi::schema
