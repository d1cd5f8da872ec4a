#pragma once
// ParameterSet: the values of keys that a higher layer registered (model/case_schema.hpp), by key
// name: numbers in SI (whole numbers and flags as doubles), choices, texts and file names as written.

#include <map>
#include <string>
#include <string_view>

namespace vi {

struct ParameterSet {
    std::map<std::string, double, std::less<>> numbers;
    std::map<std::string, std::string, std::less<>> texts;

    // The number under key, or fallback when there is none.
    [[nodiscard]] double number(std::string_view key, double fallback = 0.0) const {
        const auto it = numbers.find(key);
        return it == numbers.end() ? fallback : it->second;
    }
    // The text under key, or fallback when there is none.
    [[nodiscard]] std::string text(std::string_view key, std::string_view fallback = {}) const {
        const auto it = texts.find(key);
        return it == texts.end() ? std::string(fallback) : it->second;
    }
    [[nodiscard]] bool empty() const { return numbers.empty() && texts.empty(); }
    friend bool operator==(const ParameterSet&, const ParameterSet&) = default;
};

}  // namespace vi
