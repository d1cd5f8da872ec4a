#pragma once
// Typed, line-aware reading of TOML tables: each field read records where it stands in the file, and
// every problem (unknown, missing, wrong type, bad unit, not finite) is collected with its position.

#include <array>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "io/units.hpp"

namespace vi::tomlio {

// A place in the source text, 1-based.
struct Position {
    std::uint32_t line = 1;
    std::uint32_t column = 1;
};

// One problem with the text of a case file, at a position, about a dotted key ("supports[0].gap").
struct SourceProblem {
    Position at;
    std::string key;
    std::string message;
};

// Collects the problems found while reading and the position of every key and table read.
class ReadLog {
public:
    void problem(Position at, std::string key, std::string message);
    // Drops the "missing required" problem of key (a misspelled key present explains it).
    void withdraw(const std::string& key);
    void locate(const std::string& key, Position at);
    // Position of key; else of its nearest recorded parent ("beam.right" -> "beam"); else line 1.
    [[nodiscard]] Position where(std::string key) const;
    // Line of every key and table recorded, by dotted path.
    [[nodiscard]] std::map<std::string, int> lines() const;
    // The problem that comes first in the file (ties: the one found first); none when clean.
    [[nodiscard]] std::optional<SourceProblem> first() const;

private:
    std::vector<SourceProblem> problems_;
    std::map<std::string, Position, std::less<>> positions_;
};

// "a string", "an integer", ... for "expected X, got Y" messages.
std::string type_name(const toml::node& node);

// Position of a node's source, never line 0 (fallback for nodes made without a source).
Position position_of(const toml::source_region& region, Position fallback);

// key as written in a dotted path: bare when it can be, else quoted.
std::string key_text(std::string_view key);

// parent.key, or key at the root (parent empty).
std::string child_path(std::string_view parent, std::string_view key);

// Typed reads of single values that are not table fields (array elements); the problem, if any, is
// logged at `at` under `key`.
std::optional<double> read_quantity(const toml::node& node, Dimension d, const std::string& key, Position at,
                                    ReadLog& log);
std::optional<std::int64_t> read_integer(const toml::node& node, const std::string& key, Position at,
                                         ReadLog& log);

// Reads the fields of one table. Only the accepted keys may appear (others are reported as
// unknown by finish()); a required key that is missing is reported at the table's own position.
class FieldReader {
public:
    FieldReader(const toml::table& table, std::string path, Position at, ReadLog& log,
                std::initializer_list<std::string_view> accepted);
    // The same with the accepted keys in a list (the schema's; the views must outlive the reader).
    FieldReader(const toml::table& table, std::string path, Position at, ReadLog& log,
                std::vector<std::string_view> accepted);

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] Position position() const { return at_; }
    [[nodiscard]] bool has(std::string_view key) const;

    std::optional<double> quantity(std::string_view key, Dimension d, bool required);
    std::optional<std::int64_t> integer(std::string_view key, bool required);
    std::optional<bool> boolean(std::string_view key, bool required);
    std::optional<std::string> string(std::string_view key, bool required);
    // A string that must be one of options.
    std::optional<std::string> choice(std::string_view key, std::initializer_list<std::string_view> options,
                                      bool required);
    std::optional<std::string> choice(std::string_view key, const std::vector<std::string>& options, bool required);
    const toml::table* table(std::string_view key, bool required);
    // expected describes the array in the wrong-type message ("an array of 2 numbers").
    const toml::array* array(std::string_view key, bool required, std::string_view expected = "an array");

    // When both keys are present, reports the later of the two as not combinable with the other.
    void exclusive(std::string_view a, std::string_view b);
    // Reports a problem at key's position (the key must be present).
    void reject(std::string_view key, const std::string& message);
    // Reports every key of the table that is not accepted, at its own position.
    void finish();

    // Position of a present key.
    [[nodiscard]] Position key_position(std::string_view key) const;

private:
    // The value of key (recording its position), or nullptr; reports a missing required key.
    const toml::node* find(std::string_view key, bool required, std::string_view missing = "missing required key");
    void wrong_type(std::string_view key, const std::string& expected, const toml::node& got);

    const toml::table& table_;
    std::string path_;
    Position at_;
    ReadLog& log_;
    std::vector<std::string_view> accepted_;
};

// value clamped into int's range (so that range checks report out-of-int integers as too small or large).
int clamp_to_int(std::int64_t v);

// An array of exactly two dimensionless numbers, or of two integers, under key (problems logged,
// each element under "key[i]"); nullopt when absent or wrong.
std::optional<std::array<double, 2>> number_pair(FieldReader& f, std::string_view key, ReadLog& log);
std::optional<std::array<int, 2>> integer_pair(FieldReader& f, std::string_view key, ReadLog& log);

// A key that only some variants of a table accept: when it is present and !allowed, reports it as
// "only with <condition>" (e.g. `only with initial.kind = "force"`). Returns allowed.
bool only_with(FieldReader& f, std::string_view key, bool allowed, const std::string& condition);

}  // namespace vi::tomlio
