#include "support/text_checks.hpp"

#include <cctype>
#include <sstream>

namespace vi::test {
namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

}  // namespace

bool is_one_error_line(const std::string& err) {
    const std::string prefix = "vibroimpact: error: ";
    if (err.rfind(prefix, 0) != 0 || err.size() < prefix.size() + 2) return false;
    return err.back() == '\n' && err.find('\n') == err.size() - 1;
}

bool assigns_key(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos || line.compare(start, key.size(), key) != 0) continue;
        const std::size_t after = line.find_first_not_of(" \t", start + key.size());
        if (after != std::string::npos && line[after] == '=') return true;
    }
    return false;
}

std::string find_word_ignoring_case(const std::string& text, std::initializer_list<const char*> words) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i > 0 && is_word_char(text[i - 1])) continue;
        for (const char* w : words) {
            const std::string word(w);
            if (i + word.size() > text.size()) continue;
            bool same = true;
            for (std::size_t k = 0; k < word.size() && same; ++k) same = lower(text[i + k]) == lower(word[k]);
            const std::size_t end = i + word.size();
            if (same && (end == text.size() || !is_word_char(text[end]))) return text.substr(i, word.size());
        }
    }
    return {};
}

}  // namespace vi::test
