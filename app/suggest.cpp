#include "suggest.hpp"

#include <algorithm>

namespace cairn {

int edit_distance(const std::string& a, const std::string& b) {
    // one row of the Levenshtein table at a time
    std::vector<int> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = int(j);
    for (size_t i = 1; i <= a.size(); ++i) {
        int diag = row[0];
        row[0] = int(i);
        for (size_t j = 1; j <= b.size(); ++j) {
            const int up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
    // names longer than this are not typos of anything shipped (and keep the table small)
    if (word.size() > 200) return "";
    const int limit = std::max(2, int(word.size()) / 3);
    std::string best;
    int best_d = limit + 1;
    for (const auto& c : candidates) {
        const int d = edit_distance(word, c);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    return best;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string c = closest_name(word, candidates);
    return c.empty() ? "" : " (did you mean '" + c + "'?)";
}

}  // namespace cairn
