#pragma once
// Spelling suggestions for unknown keys and columns: the known name closest to a misspelt one.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mpdem {

// Levenshtein distance (insertions, deletions, substitutions), case-sensitive because TOML keys
// are ("a" and "A" are different motion-law keys).
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diag = up;
    }
  }
  return row[b.size()];
}

// The candidate within `max_distance` edits of `word` (the first of the nearest), or "".
template <class Names>
std::string closest_name(std::string_view word, const Names& candidates, std::size_t max_distance = 2) {
  std::string best;
  std::size_t best_d = max_distance + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = std::string(c);
    }
  }
  return best;
}

// " (did you mean 'x'?)" or "".
template <class Names>
std::string did_you_mean(std::string_view word, const Names& candidates, std::string_view prefix = "") {
  const std::string c = closest_name(word, candidates);
  return c.empty() ? std::string() : " (did you mean '" + std::string(prefix) + c + "'?)";
}

}  // namespace mpdem
