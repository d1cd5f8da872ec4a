#include "io/spelling.hpp"

#include <algorithm>

namespace vi {

int spelling_distance(std::string_view a, std::string_view b) {
    // Optimal string alignment: Levenshtein plus the swap of two neighbours ("lenght").
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

std::optional<std::string> closest_spelling(std::string_view word, const std::vector<std::string_view>& candidates) {
    // Names here are short (keys, commands); longer words would not be misspellings worth guessing.
    if (word.size() > 64) return std::nullopt;
    std::optional<std::string> best;
    int best_distance = 3;
    for (std::string_view c : candidates) {
        if (c.size() > 64) continue;
        const int d = spelling_distance(word, c);
        if (d < best_distance && 2 * d < static_cast<int>(std::max(word.size(), c.size()))) {
            best = std::string(c);
            best_distance = d;
        }
    }
    return best;
}

}  // namespace vi
