#pragma once
// Checks on command output and file text for tests (plain string scans: std::regex draws
// -Wmaybe-uninitialized warnings from libstdc++ under the sanitizer build).

#include <initializer_list>
#include <string>

namespace vi::test {

// True when err is exactly one non-empty line "vibroimpact: error: ...\n".
bool is_one_error_line(const std::string& err);

// True when a line of text (leading blanks skipped, not a comment) assigns `key`: `key =` or `key=`.
bool assigns_key(const std::string& text, const std::string& key);

// The first of `words` found in text as a whole word, ignoring case (letters, digits and '_' bound a
// word); empty when none is.
std::string find_word_ignoring_case(const std::string& text, std::initializer_list<const char*> words);

}  // namespace vi::test
